// ExperimentsPanel: the result's table and figure exported, and the figure opened large.
#include "app/panels/ExperimentsPanel.h"

#include "app/widgets/ModalDialog.h"

#include "app/MessageLog.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/OperatorText.h"
#include "app/figures/PaperFigures.h"
#include "app/plot/FigureFile.h"
#include "core/FileIo.h"
#include "devices/ThreadHandOff.h"
#include "sim/MethodCatalog.h"

#include <QComboBox>
#include <QDialog>
#include <QDir>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QThread>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>

namespace prisca::app {

QString ExperimentsPanel::tableText(core::TableFormat format) const {
    if (caption_.isEmpty()) {
        return {};
    }
    if (!rows_.empty()) {
        return core::formatTable1(rows_, format, caption_);
    }
    // Learning curves: the table as shown, in the format asked for.
    const bool csv = format == core::TableFormat::Csv;
    const bool latex = format == core::TableFormat::Latex;
    QString out;
    if (latex) {
        out += QStringLiteral("\\begin{tabular}{llll}\n");
    } else if (!csv) {
        out += QStringLiteral("%1\n\n").arg(caption_);
    }
    for (int r = -1; r < table_->rowCount(); ++r) {
        QStringList cells;
        for (int c = 0; c < table_->columnCount(); ++c) {
            cells << (r < 0 ? table_->horizontalHeaderItem(c)->text() : table_->item(r, c)->text());
        }
        if (csv) {
            for (QString& cell : cells) {
                cell = QStringLiteral("\"%1\"").arg(cell.replace('"', QStringLiteral("\"\"")));
            }
            out += cells.join(',') + '\n';
        } else if (latex) {
            out += cells.join(QStringLiteral(" & ")) + QStringLiteral(" \\\\\n");
        } else {
            out += QStringLiteral("| %1 |\n").arg(cells.join(QStringLiteral(" | ")));
            if (r < 0) {
                out += QStringLiteral("|%1\n").arg(QStringLiteral(" --- |").repeated(cells.size()));
            }
        }
    }
    if (latex) {
        out += QStringLiteral("\\end{tabular}\n");
    }
    return out;
}

bool ExperimentsPanel::exportTable(const QString& path, QString* error) const {
    const QString suffix = QFileInfo(path).suffix().toLower();
    const core::TableFormat format = suffix == QLatin1String("csv")   ? core::TableFormat::Csv
                                     : suffix == QLatin1String("tex") ? core::TableFormat::Latex
                                                                      : core::TableFormat::Markdown;
    const QString text = tableText(format);
    if (text.isEmpty()) {
        *error = tr("There is no result to export yet.");
        return false;
    }
    core::FileError fileError;
    if (!core::writeFileAtomically(path, text.toUtf8(), &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

bool ExperimentsPanel::exportFigure(const QString& path, QString* error) const {
    if (!hasFigure_) {
        *error = tr("There is no figure to export yet.");
        return false;
    }
    return plot::saveFigure(figure_, path, error);
}

void ExperimentsPanel::askExportTable() {
    QString filter;
    QString path =
        ModalDialog::saveFileName(this, tr("Export table"), QString(),
                                  tr("Markdown (*.md);;CSV (*.csv);;LaTeX (*.tex)"), &filter);
    if (path.isEmpty()) {
        return;
    }
    if (QFileInfo(path).suffix().isEmpty()) {
        path += filter.contains(QLatin1String("csv"))   ? QStringLiteral(".csv")
                : filter.contains(QLatin1String("tex")) ? QStringLiteral(".tex")
                                                        : QStringLiteral(".md");
    }
    QString error;
    if (!exportTable(path, &error)) {
        warningBox(this, tr("Export table"), error);
    }
}

void ExperimentsPanel::askExportFigure() {
    QString path = ModalDialog::saveFileName(this, tr("Export figure"), QString(),
                                             tr("PNG pictures (*.png);;SVG drawings (*.svg)"));
    if (path.isEmpty()) {
        return;
    }
    if (QFileInfo(path).suffix().isEmpty()) {
        path += QStringLiteral(".png");
    }
    QString error;
    if (!exportFigure(path, &error)) {
        warningBox(this, tr("Export figure"), error);
    }
}

void ExperimentsPanel::openFigure() {
    if (!hasFigure_) {
        return;
    }
    // A window of its own, drawn at its size (text at its normal size), never over E-STOP.
    auto* window = findChild<QDialog*>(QStringLiteral("figureWindow"));
    if (!window) {
        window = new QDialog(this);
        window->setObjectName(QStringLiteral("figureWindow"));
        auto* picture = new QLabel(window);
        picture->setObjectName(QStringLiteral("figureLarge"));
        picture->setAlignment(Qt::AlignCenter);
        picture->setMinimumSize(320, 240);
        picture->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
        auto* layout = new QVBoxLayout(window);
        layout->setContentsMargins(4, 4, 4, 4);
        layout->addWidget(picture);
        picture->installEventFilter(this);
        window->resize(1000, 660);
    }
    window->setWindowTitle(caption_);
    window->show();
    ModalDialog::placeClear(window);
    renderLargeFigure();
}

void ExperimentsPanel::renderLargeFigure() {
    auto* picture = findChild<QLabel*>(QStringLiteral("figureLarge"));
    if (!picture || !hasFigure_) {
        return;
    }
    plot::Figure large = figure_;
    large.size = picture->size().expandedTo(QSize(480, 320));
    picture->setPixmap(QPixmap::fromImage(plot::renderFigure(large)));
}

}  // namespace prisca::app
