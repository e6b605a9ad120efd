// LiveChartsPanel: the charts exported as CSV (every sample) and PNG (as drawn).
#include "app/panels/LiveChartsPanel.h"

#include "app/OperatorText.h"

#include "app/widgets/ModalDialog.h"

#include "app/MessageLog.h"

#include "app/plot/ChartDecimation.h"
#include "core/FileIo.h"

#include <QBuffer>
#include <QCategoryAxis>
#include <QChart>
#include <QChartView>
#include <QCheckBox>
#include <QCoreApplication>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPainter>
#include <QPixmap>
#include <QPushButton>
#include <QTabWidget>
#include <QTimer>
#include <QToolTip>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prisca::app {

bool LiveChartsPanel::exportCsv(const QString& path, QString* error) const {
    QByteArray text = "# PRISCA Lab live chart export\n";
    if (!caption_.isEmpty()) {
        text += "# " + caption_.toUtf8() + '\n';
    }
    // The run log's layout: a "# units:" line, then the columns, the trial first.
    const QString errorUnit = info_.pose ? QStringLiteral("m") : QStringLiteral("rad");
    QStringList units = {QStringLiteral("1"), QStringLiteral("s"), errorUnit, errorUnit};
    for (int i = 0; i < theta_.size(); ++i) {
        units << QStringLiteral("1");
    }
    for (int twice = 0; twice < 2; ++twice) {
        for (int l = 0; l < action_.size(); ++l) {
            const QString unit = info_.actionUnits.value(l);
            units << (unit.isEmpty() ? QStringLiteral("1") : unit);
        }
    }
    text += "# units: " + units.join(QLatin1Char(',')).toUtf8() + '\n';
    text += "trial,t,error,error_smoothed";
    for (int i = 0; i < theta_.size(); ++i) {
        text += ",theta_" + QByteArray::number(i);
    }
    for (int l = 0; l < action_.size(); ++l) {
        text += ",u_" + info_.actionNames.value(l).toUtf8();
    }
    for (int l = 0; l < reference_.size(); ++l) {
        text += ",ustar_" + info_.actionNames.value(l).toUtf8();
    }
    text += '\n';
    for (int k = 0; k < error_.size(); ++k) {
        QByteArray line = QByteArray::number(trial_.value(k)) + ',';  // 0-based, as the run log
        core::appendCsvNumber(line, error_[k].x());
        line += ',';
        core::appendCsvNumber(line, error_[k].y());
        line += ',';
        core::appendCsvNumber(line, smooth_[k].y());
        for (const auto* group : {&theta_, &action_, &reference_}) {
            for (const QVector<QPointF>& series : *group) {
                line += ',';
                if (k < series.size()) {
                    core::appendCsvNumber(line, series[k].y());
                }
            }
        }
        text += line;
        text += '\n';
    }
    core::FileError fileError;
    if (!core::writeFileAtomically(path, text, &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

bool LiveChartsPanel::exportPng(const QString& path, QString* error) {
    // Each chart as the operator sees it on its tab (a hidden tab's view has no valid size or
    // layout of its own), one under the other; the tab on show is given back.
    forceAll_ = true;
    redraw();
    forceAll_ = false;
    const int shown = tabs_->currentIndex();
    QList<QPixmap> pictures;
    for (int i = 0; i < tabs_->count(); ++i) {
        tabs_->setCurrentIndex(i);
        QWidget* page = tabs_->currentWidget();
        page->resize(tabs_->contentsRect().size());
        QCoreApplication::sendPostedEvents();  // the chart's layout for its size
        QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
        pictures << page->grab();
    }
    tabs_->setCurrentIndex(shown);
    const int captionHeight = caption_.isEmpty() ? 0 : fontMetrics().height() + 12;
    int width = 0, height = captionHeight;
    for (const QPixmap& picture : pictures) {
        width = std::max(width, picture.width());
        height += picture.height();
    }
    QImage image(std::max(width, 1), std::max(height, 1), QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter painter(&image);
    if (captionHeight > 0) {
        painter.setPen(Qt::black);
        painter.setFont(font());
        painter.drawText(QRect(8, 0, width - 16, captionHeight), Qt::AlignVCenter | Qt::AlignLeft,
                         caption_);
    }
    int y = captionHeight;
    for (const QPixmap& picture : pictures) {
        painter.drawPixmap(0, y, picture);
        y += picture.height();
    }
    painter.end();
    // Encoded in memory, then written atomically with every byte checked (a full disk).
    QByteArray png;
    QBuffer buffer(&png);
    buffer.open(QIODevice::WriteOnly);
    if (!image.save(&buffer, "PNG")) {
        *error = tr("cannot encode the picture for %1").arg(QDir::toNativeSeparators(path));
        return false;
    }
    core::FileError fileError;
    if (!core::writeFileAtomically(path, png, &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

namespace {
// The extension the filter promised, if the operator typed none.
QString withSuffix(QString path, const QString& suffix) {
    if (!path.isEmpty() && QFileInfo(path).suffix().compare(suffix, Qt::CaseInsensitive) != 0) {
        path += QLatin1Char('.') + suffix;
    }
    return path;
}
}  // namespace

void LiveChartsPanel::askExportCsv() {
    const QString path = withSuffix(ModalDialog::saveFileName(this, tr("Export chart data"),
                                                              QString(), tr("CSV files (*.csv)")),
                                    QStringLiteral("csv"));
    QString error;
    if (!path.isEmpty() && !exportCsv(path, &error)) {
        warningBox(this, tr("Export chart data"), error);
    }
}

void LiveChartsPanel::askExportPng() {
    const QString path =
        withSuffix(ModalDialog::saveFileName(this, tr("Export charts as picture"), QString(),
                                             tr("PNG pictures (*.png)")),
                   QStringLiteral("png"));
    QString error;
    if (!path.isEmpty() && !exportPng(path, &error)) {
        warningBox(this, tr("Export charts as picture"), error);
    }
}

}  // namespace prisca::app
