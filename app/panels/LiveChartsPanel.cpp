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

namespace {

constexpr int kRedrawMs = 40;
constexpr int kBuckets = 800;              // decimation slices per chart
constexpr double kSmoothingSeconds = 1.0;  // time constant of the smoothed error [s]

void attachAxes(QChart* chart, QLineSeries* series) {
    const auto axes = chart->axes();
    for (QAbstractAxis* axis : axes) {
        series->attachAxis(axis);
    }
}

// About five round ticks (1, 2 or 5 times a power of ten apart) over the axis's range, placed
// and labelled here: QValueAxis's dynamic ticks add the interval up from the first tick, and the
// rounding made a zero tick read "-5.55112e-17".
void labelRoundTicks(QCategoryAxis* axis) {
    const double lo = axis->min();
    const double hi = axis->max();
    for (const QString& label : axis->categoriesLabels()) {
        axis->remove(label);
    }
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) {
        return;
    }
    // About one tick per 45 px of axis (set by setRange from the plot area), at least four.
    const double target = std::max(4.0, axis->property("targetTicks").toDouble());
    const double raw = (hi - lo) / target;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    // The smallest round step at least `raw`: at most about target + 1 ticks.
    const double ratio = raw / power;
    const double step = ratio <= 1.0   ? power
                        : ratio <= 2.0 ? 2 * power
                        : ratio <= 5.0 ? 5 * power
                                       : 10 * power;
    const double first = std::ceil(lo / step - 1e-9);
    const double last = std::floor(hi / step + 1e-9);
    axis->setStartValue(lo - 1e-9 * (hi - lo));
    for (double k = first; k <= last && k - first < 50; k += 1.0) {
        const double value = std::abs(k) < 0.5 ? 0.0 : k * step;
        axis->append(QString::number(value, 'g', 10), value);
    }
}

QCategoryAxis* makeAxis() {
    auto* axis = new QCategoryAxis;
    axis->setLabelsPosition(QCategoryAxis::AxisLabelsPositionOnValue);
    QObject::connect(axis, &QValueAxis::rangeChanged, axis, [axis] { labelRoundTicks(axis); });
    return axis;
}

void setRange(QChart* chart, double x0, double x1, double y0, double y1) {
    const auto horizontal = chart->axes(Qt::Horizontal);
    const auto vertical = chart->axes(Qt::Vertical);
    if (horizontal.isEmpty() || vertical.isEmpty()) {
        return;
    }
    if (!(x1 > x0)) {
        x1 = x0 + 1.0;
    }
    // A span lost in the values' rounding counts as none.
    if (!(y1 - y0 > 1e-12 * std::max({1.0, std::abs(y0), std::abs(y1)}))) {
        y0 -= 0.5;
        y1 += 0.5;
    }
    const double pad = 0.05 * (y1 - y0);
    const QRectF area = chart->plotArea();
    horizontal.first()->setProperty("targetTicks", area.width() > 0 ? area.width() / 90.0 : 5.0);
    vertical.first()->setProperty("targetTicks", area.height() > 0 ? area.height() / 45.0 : 5.0);
    horizontal.first()->setRange(x0, x1);
    vertical.first()->setRange(y0 - pad, y1 + pad);
}

}  // namespace

LiveChartsPanel::LiveChartsPanel(QWidget* parent)
    : QWidget(parent),
      tabs_(new QTabWidget(this)),
      errorChart_(new QChart),
      thetaChart_(new QChart),
      actionChart_(new QChart),
      errorSeries_(new QLineSeries),
      smoothSeries_(new QLineSeries),
      freeze_(new QCheckBox(this)),
      fit_(new QPushButton(this)),
      exportCsv_(new QPushButton(this)),
      exportPng_(new QPushButton(this)),
      redrawTimer_(new QTimer(this)) {
    setObjectName(QStringLiteral("liveChartsPanel"));
    freeze_->setObjectName(QStringLiteral("freezeCharts"));
    exportCsv_->setObjectName(QStringLiteral("exportChartsCsv"));
    exportPng_->setObjectName(QStringLiteral("exportChartsPng"));
    for (QChart* chart : {errorChart_, thetaChart_, actionChart_}) {
        chart->legend()->setAlignment(Qt::AlignRight);
        // A short piece of each line, dashed where the line is: u and u* apart at a glance.
        chart->legend()->setMarkerShape(QLegend::MarkerShapeFromSeries);
        chart->setMargins(QMargins(4, 4, 4, 4));
        chart->addAxis(makeAxis(), Qt::AlignBottom);
        chart->addAxis(makeAxis(), Qt::AlignLeft);
    }
    errorSeries_->setPen(QPen(QColor(0xd6, 0x27, 0x28, 110), 1));
    smoothSeries_->setPen(QPen(QColor(0x8b, 0x00, 0x00), 2));
    errorChart_->addSeries(errorSeries_);
    errorChart_->addSeries(smoothSeries_);
    attachAxes(errorChart_, errorSeries_);
    attachAxes(errorChart_, smoothSeries_);
    errorView_ = makeView(errorChart_);
    thetaView_ = makeView(thetaChart_);
    actionView_ = makeView(actionChart_);
    tabs_->addTab(errorView_, QString());
    tabs_->addTab(thetaView_, QString());
    tabs_->addTab(actionView_, QString());

    redrawTimer_->setSingleShot(true);
    redrawTimer_->setInterval(kRedrawMs);
    connect(redrawTimer_, &QTimer::timeout, this, &LiveChartsPanel::redraw);
    connect(tabs_, &QTabWidget::currentChanged, this, &LiveChartsPanel::redraw);
    connect(freeze_, &QCheckBox::toggled, this, [this](bool frozen) {
        if (!frozen) {
            scheduleRedraw();
        }
    });
    connect(fit_, &QPushButton::clicked, this, [this] {
        zoomed_ = false;
        redraw();
    });
    connect(exportCsv_, &QPushButton::clicked, this, &LiveChartsPanel::askExportCsv);
    connect(exportPng_, &QPushButton::clicked, this, &LiveChartsPanel::askExportPng);

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(freeze_);
    buttons->addStretch(1);
    buttons->addWidget(fit_);
    buttons->addWidget(exportCsv_);
    buttons->addWidget(exportPng_);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs_, 1);
    layout->addLayout(buttons);
    retranslateUi();
}

QChartView* LiveChartsPanel::makeView(QChart* chart) {
    auto* view = new QChartView(chart, this);
    view->setRenderHint(QPainter::Antialiasing);
    view->setRubberBand(QChartView::RectangleRubberBand);
    view->setMinimumHeight(160);
    view->viewport()->setMouseTracking(true);
    view->viewport()->installEventFilter(this);  // the hover readout
    // A zoom by the operator means "hold this view": live redraws stop moving the axes.
    auto* axis = qobject_cast<QValueAxis*>(chart->axes(Qt::Horizontal).first());
    connect(axis, &QValueAxis::rangeChanged, this, [this] {
        if (!fitting_) {
            zoomed_ = true;
        }
    });
    return view;
}

void LiveChartsPanel::setPlant(const sim::PlantInfo& info, int parameterCount) {
    info_ = info;
    for (QLineSeries* s : thetaSeries_ + actionSeries_ + referenceSeries_) {
        s->chart()->removeSeries(s);
        delete s;
    }
    thetaSeries_.clear();
    actionSeries_.clear();
    referenceSeries_.clear();
    static const QColor palette[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xff, 0x7f, 0x0e),
                                     QColor(0x2c, 0xa0, 0x2c), QColor(0x94, 0x67, 0xbd),
                                     QColor(0x8c, 0x56, 0x4b), QColor(0xe3, 0x77, 0xc2),
                                     QColor(0x7f, 0x7f, 0x7f), QColor(0xbc, 0xbd, 0x22)};
    const int m = info.actionDimension();
    const int perChannel = m > 0 ? parameterCount / m : 0;
    for (int i = 0; i < parameterCount; ++i) {
        auto* s = new QLineSeries;
        s->setName(
            QStringLiteral("θ%1 %2")
                .arg(i % std::max(1, perChannel))
                .arg(controlName(info.actionNames.value(perChannel > 0 ? i / perChannel : 0))));
        s->setPen(QPen(palette[i % 8], 1.5));
        thetaChart_->addSeries(s);
        attachAxes(thetaChart_, s);
        thetaSeries_.push_back(s);
    }
    for (int l = 0; l < m; ++l) {
        auto* u = new QLineSeries;
        u->setName(QStringLiteral("u %1").arg(controlName(info.actionNames[l])));
        u->setPen(QPen(palette[l % 8], 1.5));
        auto* ref = new QLineSeries;
        ref->setName(QStringLiteral("u* %1").arg(controlName(info.actionNames[l])));
        ref->setPen(QPen(palette[l % 8], 1.0, Qt::DashLine));
        actionChart_->addSeries(u);
        actionChart_->addSeries(ref);
        attachAxes(actionChart_, u);
        attachAxes(actionChart_, ref);
        actionSeries_.push_back(u);
        referenceSeries_.push_back(ref);
    }
    retranslateUi();
    clear();
}

void LiveChartsPanel::clear() {
    error_.clear();
    smooth_.clear();
    trial_.clear();
    trialStarts_.clear();
    theta_ = QVector<QVector<QPointF>>(thetaSeries_.size());
    action_ = QVector<QVector<QPointF>>(actionSeries_.size());
    reference_ = QVector<QVector<QPointF>>(referenceSeries_.size());
    smoothed_ = 0.0;
    zoomed_ = false;
    redraw();
}

void LiveChartsPanel::addSamples(const QVector<LiveSample>& samples) {
    for (const LiveSample& s : samples) {
        const double t = s.runTime;
        const double dt = error_.isEmpty() ? 0.0 : std::max(0.0, t - error_.back().x());
        const double a = error_.isEmpty() ? 1.0 : 1.0 - std::exp(-dt / kSmoothingSeconds);
        smoothed_ += a * (s.trackedError - smoothed_);
        if (!trial_.isEmpty() && s.trial != trial_.back()) {
            trialStarts_.push_back(t);
        }
        trial_.push_back(s.trial);
        error_.push_back({t, s.trackedError});
        smooth_.push_back({t, smoothed_});
        for (int i = 0; i < theta_.size() && i < s.theta.size(); ++i) {
            theta_[i].push_back({t, s.theta[i]});
        }
        for (int l = 0; l < action_.size() && l < s.action.size(); ++l) {
            action_[l].push_back({t, s.action[l]});
            reference_[l].push_back({t, s.referenceAction[l]});
        }
    }
    scheduleRedraw();
}

void LiveChartsPanel::scheduleRedraw() {
    if (!redrawTimer_->isActive()) {
        redrawTimer_->start();
    }
}

int LiveChartsPanel::drawnPoints() const {
    return static_cast<int>(errorSeries_->count());
}

void LiveChartsPanel::redraw() {
    if (freeze_->isChecked()) {
        return;
    }
    // Only the chart on show is redrawn; the others catch up when their tab is chosen (or for
    // export). The decimated series keep every extreme, so the axes are fitted from them.
    fitting_ = true;
    const auto update = [this](QChart* chart, const QVector<QLineSeries*>& series,
                               const QVector<const QVector<QPointF>*>& data) {
        double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
        for (int i = 0; i < series.size(); ++i) {
            const QVector<QPointF> points = plot::decimateMinMax(*data[i], kBuckets);
            for (const QPointF& p : points) {
                x0 = std::min(x0, p.x());
                x1 = std::max(x1, p.x());
                if (std::isfinite(p.y())) {
                    y0 = std::min(y0, p.y());
                    y1 = std::max(y1, p.y());
                }
            }
            series[i]->replace(points);
        }
        if (!zoomed_) {
            if (std::isfinite(x0) && std::isfinite(y0)) {
                setRange(chart, x0, x1, y0, y1);
            } else {
                setRange(chart, 0, 10, 0, 1);
            }
        }
    };
    const int tab = tabs_->currentIndex();
    if (boundarySeries_.size() != 3) {
        boundarySeries_.resize(3);
    }
    if (tab == 0 || forceAll_) {
        update(errorChart_, {errorSeries_, smoothSeries_}, {&error_, &smooth_});
        drawTrialBoundaries(errorChart_, boundarySeries_[0]);
    }
    if (tab == 1 || forceAll_) {
        QVector<const QVector<QPointF>*> data;
        for (const auto& d : theta_) {
            data.push_back(&d);
        }
        update(thetaChart_, thetaSeries_, data);
        drawTrialBoundaries(thetaChart_, boundarySeries_[1]);
    }
    if (tab == 2 || forceAll_) {
        QVector<QLineSeries*> series;
        QVector<const QVector<QPointF>*> data;
        for (int l = 0; l < actionSeries_.size(); ++l) {
            series << actionSeries_[l] << referenceSeries_[l];
            data << &action_[l] << &reference_[l];
        }
        update(actionChart_, series, data);
        drawTrialBoundaries(actionChart_, boundarySeries_[2]);
    }
    fitting_ = false;
}

void LiveChartsPanel::drawTrialBoundaries(QChart* chart, QVector<QLineSeries*>& lines) {
    // A grey dashed line where each later trial began, across the chart's value range; not
    // in the legend, and not counted when the axes are fitted (they span what is shown).
    auto* vertical = qobject_cast<QValueAxis*>(chart->axes(Qt::Vertical).first());
    const double y0 = vertical->min(), y1 = vertical->max();
    while (lines.size() < trialStarts_.size()) {
        auto* line = new QLineSeries;
        line->setPen(QPen(QColor(0x80, 0x80, 0x80), 1, Qt::DashLine));
        chart->addSeries(line);
        attachAxes(chart, line);
        for (QLegendMarker* marker : chart->legend()->markers(line)) {
            marker->setVisible(false);
        }
        lines.push_back(line);
    }
    for (int i = 0; i < lines.size(); ++i) {
        if (i < trialStarts_.size()) {
            lines[i]->replace(QList<QPointF>{{trialStarts_[i], y0}, {trialStarts_[i], y1}});
        } else {
            lines[i]->clear();
        }
    }
}

QString LiveChartsPanel::readoutAt(double t) const {
    if (error_.isEmpty()) {
        return QString();
    }
    // The sample at or just before t.
    auto it = std::upper_bound(error_.begin(), error_.end(), t,
                               [](double value, const QPointF& p) { return value < p.x(); });
    const int k = static_cast<int>(std::max<qsizetype>(0, (it - error_.begin()) - 1));
    const QString unit = info_.pose ? QStringLiteral("m") : QStringLiteral("rad");
    QStringList lines;
    lines << tr("Trial %1, run time %2 s").arg(trial_.value(k) + 1).arg(error_[k].x(), 0, 'f', 2);
    switch (tabs_->currentIndex()) {
        case 0:
            lines << tr("error %1 %2, smoothed %3 %2")
                         .arg(error_[k].y(), 0, 'g', 4)
                         .arg(unit)
                         .arg(smooth_[k].y(), 0, 'g', 4);
            break;
        case 1:
            for (int i = 0; i < theta_.size(); ++i) {
                if (k < theta_[i].size()) {
                    lines << QStringLiteral("θ%1 = %2").arg(i).arg(theta_[i][k].y(), 0, 'g', 4);
                }
            }
            break;
        default:
            for (int l = 0; l < action_.size(); ++l) {
                if (k < action_[l].size()) {
                    lines << tr("%1: u %2, u* %3 %4")
                                 .arg(controlName(info_.actionNames.value(l)))
                                 .arg(action_[l][k].y(), 0, 'g', 4)
                                 .arg(reference_[l][k].y(), 0, 'g', 4)
                                 .arg(info_.actionUnits.value(l));
                }
            }
            break;
    }
    return lines.join(QLatin1Char('\n'));
}

bool LiveChartsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::MouseMove) {
        for (QChartView* view : {errorView_, thetaView_, actionView_}) {
            if (watched != view->viewport()) {
                continue;
            }
            const auto* move = static_cast<QMouseEvent*>(event);
            QChart* chart = view->chart();
            const QPointF scene = view->mapToScene(move->position().toPoint());
            const QPointF inChart = chart->mapFromScene(scene);
            if (chart->plotArea().contains(inChart)) {
                const QString text = readoutAt(chart->mapToValue(inChart).x());
                QToolTip::showText(move->globalPosition().toPoint(), text, view->viewport());
            } else {
                QToolTip::hideText();
            }
        }
    }
    return QWidget::eventFilter(watched, event);
}

void LiveChartsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void LiveChartsPanel::retranslateUi() {
    const bool planar = info_.pose.has_value();
    tabs_->setTabText(0, tr("Tracking error"));
    tabs_->setTabText(1, tr("Policy θ"));
    tabs_->setTabText(2, tr("Action u and u*"));
    errorSeries_->setName(tr("error"));
    smoothSeries_->setName(tr("smoothed (1 s)"));
    errorChart_->axes(Qt::Vertical)
        .first()
        ->setTitleText(planar ? tr("error [m]") : tr("error [rad]"));
    for (QChart* chart : {errorChart_, thetaChart_, actionChart_}) {
        chart->axes(Qt::Horizontal).first()->setTitleText(tr("run time [s]"));
    }
    thetaChart_->axes(Qt::Vertical).first()->setTitleText(tr("θ"));
    actionChart_->axes(Qt::Vertical).first()->setTitleText(tr("action"));
    freeze_->setText(tr("Freeze"));
    freeze_->setToolTip(tr("Stop redrawing to look closely; the data keeps being recorded."));
    fit_->setText(tr("Fit"));
    fit_->setToolTip(tr("Show all the data again after zooming (drag a box to zoom)."));
    exportCsv_->setText(tr("Export CSV..."));
    exportPng_->setText(tr("Export PNG..."));
}

}  // namespace prisca::app
