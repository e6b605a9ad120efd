#include "app/panels/ExperimentsPanel.h"

#include "app/widgets/ModalDialog.h"

#include "app/MessageLog.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/OperatorText.h"
#include "app/figures/PaperFigures.h"
#include "app/plot/FigureFile.h"
#include "core/FileIo.h"
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

namespace {

// The slide-car's body for the end postures of Fig. 7 [m].
constexpr double kCarLength = 0.40;
constexpr double kCarWidth = 0.20;

QString plusMinus(const core::ErrorSummary& s) {
    if (s.count == 0) {
        return QStringLiteral("—");
    }
    if (s.count == 1) {  // no spread from one trial
        return QString::number(s.meanAbsoluteError, 'f', 2);
    }
    return QStringLiteral("%1 ± %2")
        .arg(s.meanAbsoluteError, 0, 'f', 2)
        .arg(s.standardDeviation, 0, 'f', 2);
}

// A variance only where there were trials to take it from (a cancelled row may have one or none).
QString variance(const core::ErrorSummary& s) {
    return s.count < 2 || !std::isfinite(s.variance) ? QStringLiteral("—")
                                                     : QString::number(s.variance, 'f', 2);
}

}  // namespace

ExperimentsPanel::ExperimentsPanel(LabSession& session, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      emergency_(emergency),
      experiment_(new ExperimentThread(this)),
      kind_(new QComboBox(this)),
      countLabel_(new QLabel(this)),
      count_(new QSpinBox(this)),
      seedLabel_(new QLabel(this)),
      seed_(new QSpinBox(this)),
      budgetLabel_(new QLabel(this)),
      budget_(new QSpinBox(this)),
      start_(new QPushButton(this)),
      cancel_(new QPushButton(this)),
      progress_(new QProgressBar(this)),
      status_(new QLabel(this)),
      table_(new QTableWidget(this)),
      figureView_(new QLabel(this)),
      exportTable_(new QPushButton(this)),
      exportFigure_(new QPushButton(this)) {
    setObjectName(QStringLiteral("experimentsPanel"));
    qRegisterMetaType<ExperimentRequest>();
    qRegisterMetaType<std::shared_ptr<const sim::Table1Result>>();
    qRegisterMetaType<std::shared_ptr<const std::vector<sim::CurveSummary>>>();
    kind_->setObjectName(QStringLiteral("experimentKind"));
    kind_->addItem(QString(), static_cast<int>(ExperimentRequest::Kind::Table1));
    kind_->addItem(QString(), static_cast<int>(ExperimentRequest::Kind::LearningCurves));
    count_->setObjectName(QStringLiteral("experimentCount"));
    count_->setRange(1, 1000);
    seed_->setObjectName(QStringLiteral("experimentSeed"));
    seed_->setRange(0, 1000000);
    budget_->setObjectName(QStringLiteral("experimentBudget"));
    budget_->setRange(320, 10000000);
    budget_->setSingleStep(3200);
    start_->setObjectName(QStringLiteral("startExperiment"));
    cancel_->setObjectName(QStringLiteral("cancelExperiment"));
    progress_->setObjectName(QStringLiteral("experimentProgress"));
    status_->setObjectName(QStringLiteral("experimentStatus"));
    exportTable_->setObjectName(QStringLiteral("exportTable"));
    exportFigure_->setObjectName(QStringLiteral("exportFigure"));
    table_->setObjectName(QStringLiteral("experimentTable"));
    table_->setMinimumHeight(60);
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->setTabKeyNavigation(false);  // Tab moves on to the next control, not cell by cell
    table_->verticalHeader()->setVisible(false);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Rows as tall as their text: Table I's rows fit the short bottom dock at 1280 x 800.
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 6);
    figureView_->setObjectName(QStringLiteral("experimentFigure"));
    figureView_->setAlignment(Qt::AlignCenter);
    figureView_->setMinimumSize(200, 100);
    figureView_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    figureView_->installEventFilter(this);
    figureView_->setCursor(Qt::PointingHandCursor);
    // One line (the whole text in its tool tip): the table below keeps the height.
    status_->setWordWrap(false);
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    status_->installEventFilter(this);

    QSettings settings;
    kind_->setCurrentIndex(settings.value("experiments/kind", 0).toInt() == 1 ? 1 : 0);
    count_->setValue(settings.value("experiments/count", 20).toInt());
    seed_->setValue(settings.value("experiments/seed", 1).toInt());
    budget_->setValue(settings.value("experiments/budget", 64000).toInt());

    // Two rows of controls across the top, then the table beside the figure with all the height
    // that is left: at 1280x800 the dock is short, and Table I's rows are what an operator reads.
    auto* what = new QHBoxLayout;
    what->addWidget(kind_, 2);
    what->addWidget(start_);
    what->addWidget(cancel_);
    what->addWidget(progress_, 1);
    auto* how = new QHBoxLayout;
    how->addWidget(countLabel_);
    how->addWidget(count_);
    how->addSpacing(8);
    how->addWidget(seedLabel_);
    how->addWidget(seed_);
    how->addSpacing(8);
    how->addWidget(budgetLabel_);
    how->addWidget(budget_);
    how->addStretch(1);
    how->addWidget(exportTable_);
    how->addWidget(exportFigure_);
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    splitter->addWidget(table_);
    splitter->addWidget(figureView_);
    // The table gets the larger share: its columns must show; the figure keeps its aspect.
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    splitter->setChildrenCollapsible(false);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addLayout(what);
    layout->addLayout(how);
    layout->addWidget(status_);
    layout->addWidget(splitter, 1);

    // The experiments report "k/N" in words of their own; the panel says it in the operator's.
    connect(experiment_, &ExperimentThread::progress, this,
            [this](int done, int total, const QString&) {
                if (!running_) {
                    return;  // a report that crossed the end
                }
                if (total > 0) {
                    done_ = done;
                    total_ = total;
                    progress_->setRange(0, total);
                    progress_->setValue(done);
                }
                showProgress();
            });
    ticker_ = new QTimer(this);
    ticker_->setInterval(1000);
    connect(ticker_, &QTimer::timeout, this, &ExperimentsPanel::showProgress);
    connect(experiment_, &ExperimentThread::table1Finished, this, &ExperimentsPanel::showTable1);
    connect(experiment_, &ExperimentThread::curvesFinished, this, &ExperimentsPanel::showCurves);
    connect(experiment_, &ExperimentThread::failed, this, [this](const QString& message) {
        setRunning(false);
        progress_->setRange(0, 1);
        progress_->setValue(0);
        status_->setText(message);
        warningBox(this, tr("Experiment"), message);
        emit finished();
    });
    connect(start_, &QPushButton::clicked, this, &ExperimentsPanel::start);
    connect(cancel_, &QPushButton::clicked, this, &ExperimentsPanel::cancel);
    connect(&emergency_, &EmergencyStop::latchChanged, this, [this] { setRunning(running_); });
    connect(&emergency_, &EmergencyStop::engaged, this, [this] {
        if (running_ && !stoppedByEmergency_) {
            stoppedByEmergency_ = true;
            experiment_->cancel();
            showStatus(status_, tr("Experiments"),
                       tr("E-STOP: the experiment stops once the trials under way end; what "
                          "finished is kept and marked partial."));
        }
    });
    connect(exportTable_, &QPushButton::clicked, this, &ExperimentsPanel::askExportTable);
    connect(exportFigure_, &QPushButton::clicked, this, &ExperimentsPanel::askExportFigure);
    connect(kind_, &QComboBox::currentIndexChanged, this, &ExperimentsPanel::retranslateUi);
    retranslateUi();
    setRunning(false);
}

ExperimentsPanel::~ExperimentsPanel() {
    delete experiment_;  // its thread ends (cancelled, bounded wait) before the widgets go
}

void ExperimentsPanel::start() {
    if (running_) {
        return;
    }
    if (emergency_.isLatched()) {
        showStatus(status_, tr("Experiments"), emergency_.refusal());
        return;
    }
    ExperimentRequest request;
    request.kind = static_cast<ExperimentRequest::Kind>(kind_->currentData().toInt());
    if (request.kind == ExperimentRequest::Kind::Table1 && !session_.profile().info.pose) {
        ModalDialog::information(
            this, tr("Experiment"),
            tr("Table I compares final positions and headings, so it needs a vehicle: choose the "
               "slide-car or the aircraft as the target."));
        return;
    }
    request.task = session_.task();
    request.trials = request.runs = count_->value();
    request.settings.seed = static_cast<std::uint64_t>(seed_->value());
    request.budgetSteps = budget_->value();
    request.settings.threads = std::max(1, QThread::idealThreadCount());
    // What the result will be about (its caption and every export say so), whatever the spin
    // boxes show later.
    pending_ = ExperimentRecord();
    pending_.curves = request.kind == ExperimentRequest::Kind::LearningCurves;
    pending_.plant = session_.plant();
    pending_.poseTarget = session_.profile().info.pose.has_value();
    pending_.count = count_->value();
    pending_.seed = seed_->value();
    pending_.budget = budget_->value();
    pending_.demonstration = session_.demonstrationDescription();
    QSettings settings;
    settings.setValue("experiments/kind", kind_->currentIndex());
    settings.setValue("experiments/count", count_->value());
    settings.setValue("experiments/seed", seed_->value());
    settings.setValue("experiments/budget", budget_->value());
    progress_->setRange(0, 0);  // busy until the first count arrives
    progress_->resetFormat();
    showStatus(status_, tr("Experiments"), tr("Starting..."));
    stoppedByEmergency_ = false;
    done_ = total_ = 0;
    clock_.start();
    setRunning(true);
    ticker_->start();
    experiment_->start(request);
}

void ExperimentsPanel::cancel() {
    if (running_) {
        experiment_->cancel();
        showStatus(status_, tr("Experiments"),
                   tr("Cancelling: the trials under way finish first..."));
        showProgress();
    }
}

void ExperimentsPanel::setRunning(bool running) {
    running_ = running;
    if (!running && ticker_) {
        ticker_->stop();
    }
    start_->setEnabled(!running && !emergency_.isLatched());
    cancel_->setEnabled(running);
    kind_->setEnabled(!running);
    exportTable_->setEnabled(!running && !caption_.isEmpty());
    exportFigure_->setEnabled(!running && hasFigure_);
}

void ExperimentsPanel::showTable1(std::shared_ptr<const sim::Table1Result> result) {
    lastTable1_ = result;
    lastCurves_.reset();
    adoptFinishedRecord();
    displayTable1(*result);
    keepResult();
    setRunning(false);
    int done = 0;
    sim::table1Rows(*result, &done);
    showEnd(done, total_ > 0 ? total_ : done, result->cancelled);
    emit finished();
}

void ExperimentsPanel::displayTable1(const sim::Table1Result& table1) {
    const sim::Table1Result* result = &table1;
    int done = 0;
    rows_ = sim::table1Rows(*result, &done);
    caption_ = tr("Slide parking in simulation (%1): %2 trials per method, seed %3; "
                  "demonstration: %4")
                   .arg(record_.plant)
                   .arg(record_.count)
                   .arg(record_.seed)
                   .arg(record_.demonstration);
    if (result->cancelled) {
        caption_ += tr(" (cancelled: %1 trials finished)").arg(done);
    }
    table_->clear();
    table_->setColumnCount(6);
    table_->setRowCount(static_cast<int>(rows_.size()));
    table_->setHorizontalHeaderLabels({tr("Method"), tr("N"), tr("Position [cm]"), tr("Var. [cm²]"),
                                       tr("Orientation [deg]"), tr("Var. [deg²]")});
    for (int r = 0; r < static_cast<int>(rows_.size()); ++r) {
        const core::Table1Row& row = rows_[r];
        // A row with fewer trials than asked (a cancelled batch) says so.
        const bool partial = row.partial();
        const QStringList cells = {partial ? row.shownLabel() + tr(" (partial)") : row.shownLabel(),
                                   QString::number(row.position.count),
                                   plusMinus(row.position),
                                   variance(row.position),
                                   plusMinus(row.orientation),
                                   variance(row.orientation)};
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            item->setTextAlignment(c == 0 ? Qt::AlignLeft | Qt::AlignVCenter
                                          : Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(r, c, item);
        }
    }
    figure_ = figures::parkingFigure(*result, kCarLength, kCarWidth);
    hasFigure_ = true;
    showFigure();
}

void ExperimentsPanel::showCurves(std::shared_ptr<const std::vector<sim::CurveSummary>> curves,
                                  bool cancelled) {
    lastCurves_ = curves;
    lastCurvesCancelled_ = cancelled;
    lastTable1_.reset();
    adoptFinishedRecord();
    displayCurves(curves, cancelled);
    keepResult();
    setRunning(false);
    showEnd(done_, total_, cancelled);
    emit finished();
}

void ExperimentsPanel::displayCurves(
    const std::shared_ptr<const std::vector<sim::CurveSummary>>& curves, bool cancelled) {
    rows_.clear();
    caption_ = tr("Learning curves (%1): %2 runs per method, %3 steps each, seed %4; "
                  "demonstration: %5")
                   .arg(record_.plant)
                   .arg(record_.count)
                   .arg(record_.budget)
                   .arg(record_.seed)
                   .arg(record_.demonstration);
    if (cancelled) {
        caption_ += tr(" (cancelled)");
    }
    table_->clear();
    table_->setColumnCount(4);
    table_->setRowCount(static_cast<int>(curves->size()));
    table_->setHorizontalHeaderLabels(
        {tr("Method"), tr("First point"), tr("Half way"), tr("Last point reached")});
    std::vector<QString> methods;
    std::vector<std::vector<double>> seconds;
    std::vector<core::ConfidenceBand> bands;
    for (int r = 0; r < static_cast<int>(curves->size()); ++r) {
        const sim::CurveSummary& c = (*curves)[r];
        methods.push_back(c.method);
        seconds.push_back(c.seconds);
        bands.push_back(c.band);
        const auto at = [&](size_t i) {
            if (i >= c.band.mean.size() || c.band.count[i] == 0) {
                return QStringLiteral("—");
            }
            return QStringLiteral("%1 [%2, %3]")
                .arg(c.band.mean[i], 0, 'g', 3)
                .arg(c.band.lower[i], 0, 'g', 3)
                .arg(c.band.upper[i], 0, 'g', 3);
        };
        size_t last = c.band.count.size();
        while (last > 0 && c.band.count[last - 1] == 0) {
            --last;
        }
        const QStringList cells = {sim::MethodCatalog::get(c.method).label, at(0),
                                   at(c.band.mean.size() / 2),
                                   last > 0 ? at(last - 1) : QStringLiteral("—")};
        for (int col = 0; col < cells.size(); ++col) {
            table_->setItem(r, col, new QTableWidgetItem(cells[col]));
        }
    }
    const QString yLabel = record_.poseTarget ? tr("mean squared position error [m²]")
                                              : tr("mean squared joint-angle error [rad²]");
    figure_ = figures::learningCurveFigure(methods, seconds, bands, yLabel);
    hasFigure_ = true;
    showFigure();
}

void ExperimentsPanel::adoptFinishedRecord() {
    record_ = pending_;
    record_.finished = QDateTime::currentDateTime();
    showsKept_ = false;
}

void ExperimentsPanel::keepResult() {
    KeptExperiment kept;
    kept.record = record_;
    kept.table1 = lastTable1_;
    kept.curves = lastCurves_;
    kept.curvesCancelled = lastCurvesCancelled_;
    QString error;
    if (!saveKeptExperiment(keptExperimentPath(), kept, &error)) {
        logMessage(this, tr("Experiments"), MessageLevel::Warning,
                   tr("The result could not be kept for the next session: %1").arg(error));
    }
}

void ExperimentsPanel::restoreKeptResult() {
    const QString path = keptExperimentPath();
    if (!QFileInfo::exists(path)) {
        return;
    }
    QString error;
    const auto kept = loadKeptExperiment(path, &error);
    if (!kept) {
        logMessage(this, tr("Experiments"), MessageLevel::Warning,
                   tr("The last session's experiment could not be shown again: %1").arg(error));
        return;
    }
    record_ = kept->record;
    lastTable1_ = kept->table1;
    lastCurves_ = kept->curves;
    lastCurvesCancelled_ = kept->curvesCancelled;
    showsKept_ = true;
    const QDateTime finished = record_.finished;
    if (lastTable1_) {
        displayTable1(*lastTable1_);
    } else {
        displayCurves(lastCurves_, lastCurvesCancelled_);
    }
    setRunning(running_);  // the exports of what is shown
    const bool cancelled = lastTable1_ ? lastTable1_->cancelled : lastCurvesCancelled_;
    showStatus(status_, tr("Experiments"), [finished, cancelled] {
        const QString when = finished.toString(QStringLiteral("yyyy-MM-dd HH:mm"));  // any language
        return cancelled ? tr("The last experiment, cancelled %1 (its rows are partial), is shown "
                              "again; Start runs a new one.")
                               .arg(when)
                         : tr("The last experiment, finished %1, is shown again; Start runs a new "
                              "one.")
                               .arg(when);
    });
}

void ExperimentsPanel::showFigure() {
    if (auto* window = findChild<QDialog*>(QStringLiteral("figureWindow"));
        window && window->isVisible()) {
        window->setWindowTitle(caption_);  // a new result, or another language
        renderLargeFigure();
    }
    if (!hasFigure_) {
        figureView_->clear();
        return;
    }
    // Drawn at the size it is shown (text at its normal size, not a 1200 x 800 picture shrunk
    // to a third), never smaller than a readable minimum.
    plot::Figure onScreen = figure_;
    onScreen.size = figureView_->size().expandedTo(QSize(480, 320));
    const QImage image = plot::renderFigure(onScreen);
    figureView_->setPixmap(QPixmap::fromImage(image).scaled(
        figureView_->size(), Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

bool ExperimentsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == figureView_ && event->type() == QEvent::Resize && hasFigure_) {
        showFigure();
    }
    if (watched->objectName() == QLatin1String("figureLarge") && event->type() == QEvent::Resize) {
        renderLargeFigure();
    }
    if (watched == figureView_ && event->type() == QEvent::MouseButtonRelease && hasFigure_) {
        openFigure();
        return true;
    }
    if (watched == status_ && event->type() == QEvent::ToolTip) {
        status_->setToolTip(status_->text());  // the whole line, however narrow the dock
    }
    return QWidget::eventFilter(watched, event);
}

void ExperimentsPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void ExperimentsPanel::retranslateUi() {
    kind_->setItemText(0, tr("Table I: slide parking, every method"));
    kind_->setItemText(1, tr("Learning curves: PRISCA, PGSD, PEGASUS"));
    const bool curves = kind_->currentIndex() == 1;
    countLabel_->setText(curves ? tr("Runs per method:") : tr("Trials per method:"));
    seedLabel_->setText(tr("Seed:"));
    budgetLabel_->setText(tr("Budget:"));
    budget_->setSuffix(tr(" steps"));
    budget_->setToolTip(tr("Simulated control steps each run may use (the same for every method)"));
    budget_->setEnabled(curves);
    start_->setText(tr("Start"));
    cancel_->setText(tr("Cancel"));
    exportTable_->setText(tr("Export table..."));
    exportFigure_->setText(tr("Export figure..."));
    figureView_->setToolTip(tr("Click to open the figure large"));
    // The result shown, its headers, caption and figure, in the new language too.
    const QString shownCaption = caption_;
    if (lastTable1_) {
        displayTable1(*lastTable1_);
    } else if (lastCurves_) {
        displayCurves(lastCurves_, lastCurvesCancelled_);
    }
    if (!shownCaption.isEmpty() && status_->text() == shownCaption) {
        status_->setText(caption_);
    }
}

int ExperimentsPanel::progressDone() const {
    return progress_->maximum() > 0 ? progress_->value() : 0;
}

int ExperimentsPanel::progressTotal() const {
    return progress_->maximum();
}

void ExperimentsPanel::showProgress() {
    if (!running_) {
        return;
    }
    const bool curves = pending_.curves;
    const qint64 elapsed = clock_.elapsed();
    QString text;
    if (total_ <= 0) {
        text = tr("Starting... %1 so far").arg(duration(elapsed));
    } else {
        const QString done = curves ? tr("Run %1 of %2 done").arg(done_).arg(total_)
                                    : tr("Trial %1 of %2 done").arg(done_).arg(total_);
        text = QStringLiteral("%1 · %2").arg(done, progressTime(elapsed, done_, total_));
    }
    if (stoppedByEmergency_) {
        text = tr("E-STOP: stopping once the trials under way end. %1").arg(text);
    } else if (experiment_->isCancelled()) {
        text = tr("Cancelling: the trials under way finish first. %1").arg(text);
    }
    status_->setText(text);
}

void ExperimentsPanel::showEnd(int done, int asked, bool cancelled) {
    // The bar shows what came back, not the last count reported before the end.
    progress_->setRange(0, std::max(1, asked));
    progress_->setValue(std::clamp(done, 0, std::max(1, asked)));
    const bool curves = record_.curves;
    if (cancelled) {
        progress_->setFormat(curves ? tr("Cancelled: %v of %m runs")
                                    : tr("Cancelled: %v of %m trials"));
    } else {
        progress_->resetFormat();
    }
    const qint64 took = clock_.isValid() ? clock_.elapsed() : 0;
    const bool byEmergency = stoppedByEmergency_;
    showStatus(status_, tr("Experiments"), [this, took, cancelled, byEmergency] {
        const QString how =
            !cancelled ? tr("Finished in %1.").arg(duration(took))
            : byEmergency
                ? tr("Stopped by E-STOP after %1: the rows are partial.").arg(duration(took))
                : tr("Cancelled after %1: the rows are partial.").arg(duration(took));
        return QStringLiteral("%1 %2").arg(how, caption_);
    });
}

}  // namespace prisca::app
