#include "app/panels/RunPanel.h"

#include "app/MessageLog.h"

#include "app/EmergencyStop.h"
#include "app/LabSession.h"
#include "app/OperatorText.h"
#include "app/widgets/ModalDialog.h"
#include "app/workers/RunThread.h"
#include "core/RunLogCsv.h"
#include "sim/MethodCatalog.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonDocument>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTime>
#include <QTimer>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>

namespace prisca::app {

namespace {
const char* const kSettingsGroup = "run";
}

RunPanel::RunPanel(LabSession& session, RunThread& run, EmergencyStop& emergency, QWidget* parent)
    : QWidget(parent),
      session_(session),
      run_(run),
      emergency_(emergency),
      trialsLabel_(new QLabel(this)),
      trials_(new QSpinBox(this)),
      seedLabel_(new QLabel(this)),
      seed_(new QSpinBox(this)),
      perturbationLabel_(new QLabel(this)),
      perturbation_(new QDoubleSpinBox(this)),
      sensorLabel_(new QLabel(this)),
      sensor_(new QDoubleSpinBox(this)),
      speedLabel_(new QLabel(this)),
      speed_(new QComboBox(this)),
      runAction_(new QAction(this)),
      pauseAction_(new QAction(this)),
      stopAction_(new QAction(this)),
      resetAction_(new QAction(this)),
      emergencyAction_(new QAction(this)),
      resetEmergencyAction_(new QAction(this)),
      exportLog_(new QPushButton(this)),
      status_(new QLabel(this)),
      results_(new QTableWidget(0, 4, this)),
      divergence_(new QWidget(this)),
      divergenceText_(new QLabel(divergence_)),
      divergenceStop_(new QPushButton(divergence_)),
      divergenceRestart_(new QPushButton(divergence_)) {
    setObjectName(QStringLiteral("runPanel"));
    trials_->setObjectName(QStringLiteral("trials"));
    trials_->setRange(1, 1000);
    seed_->setObjectName(QStringLiteral("seed"));
    seed_->setRange(0, 1000000);
    perturbation_->setObjectName(QStringLiteral("perturbation"));
    perturbation_->setRange(0.0, 5.0);
    perturbation_->setSingleStep(0.25);
    sensor_->setObjectName(QStringLiteral("sensor"));
    sensor_->setRange(0.0, 5.0);
    sensor_->setSingleStep(0.25);
    speed_->setObjectName(QStringLiteral("speed"));
    for (int i = 0; i < speeds().size(); ++i) {
        speed_->addItem(QString(), speeds()[i]);
    }
    // The shortcuts live on actions, not on the buttons: a button's setText() replaces its
    // shortcut with the text's mnemonic (none), which is how F5 once did nothing.
    runAction_->setObjectName(QStringLiteral("runAction"));
    runAction_->setShortcut(QKeySequence(Qt::Key_F5));
    pauseAction_->setObjectName(QStringLiteral("pauseAction"));
    pauseAction_->setShortcut(QKeySequence(Qt::Key_F6));
    stopAction_->setObjectName(QStringLiteral("stopAction"));
    stopAction_->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F5));
    resetAction_->setObjectName(QStringLiteral("resetAction"));
    resetAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_R));
    for (QAction* action : {runAction_, pauseAction_, stopAction_, resetAction_}) {
        action->setShortcutContext(Qt::WindowShortcut);
    }
    emergencyAction_->setObjectName(QStringLiteral("emergencyStopAction"));
    resetEmergencyAction_->setObjectName(QStringLiteral("resetEmergencyAction"));
    exportLog_->setObjectName(QStringLiteral("exportRunLog"));
    exportLog_->setEnabled(false);
    status_->setObjectName(QStringLiteral("runStatus"));
    // One line, its whole text in the tool tip: the results below keep the height.
    status_->setWordWrap(false);
    status_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    status_->installEventFilter(this);
    results_->setObjectName(QStringLiteral("trialResults"));
    results_->verticalHeader()->setVisible(false);
    results_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    results_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    results_->setTabKeyNavigation(false);  // Tab moves on to the next control, not cell by cell
    results_->setMinimumHeight(results_->fontMetrics().height() * 3);  // the header, a row
    // Rows as tall as their text: five trials and the header in about 140 px.
    results_->verticalHeader()->setDefaultSectionSize(results_->fontMetrics().height() + 6);
    results_->viewport()->installEventFilter(this);

    // Two settings a row: at 1280 x 800 the results below keep the height for a whole run.
    auto* form = new QGridLayout;
    form->addWidget(trialsLabel_, 0, 0);
    form->addWidget(trials_, 0, 1);
    form->addWidget(seedLabel_, 0, 2);
    form->addWidget(seed_, 0, 3);
    form->addWidget(perturbationLabel_, 1, 0);
    form->addWidget(perturbation_, 1, 1);
    form->addWidget(sensorLabel_, 1, 2);
    form->addWidget(sensor_, 1, 3);
    form->addWidget(speedLabel_, 2, 0);
    form->addWidget(speed_, 2, 1, 1, 3);
    form->setColumnStretch(1, 1);
    form->setColumnStretch(3, 1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(status_);
    divergence_->setObjectName(QStringLiteral("divergenceWarning"));
    divergence_->setStyleSheet(QStringLiteral(
        "#divergenceWarning { background: #fdecea; border: 1px solid #b00020; border-radius: 4px; }"
        "QLabel { color: #b00020; }"));
    divergence_->setAttribute(Qt::WA_StyledBackground);
    divergenceText_->setWordWrap(true);
    divergenceStop_->setObjectName(QStringLiteral("divergenceStop"));
    divergenceRestart_->setObjectName(QStringLiteral("divergenceRestart"));
    auto* warning = new QVBoxLayout(divergence_);
    warning->addWidget(divergenceText_);
    auto* choices = new QHBoxLayout;
    choices->addWidget(divergenceStop_);
    choices->addWidget(divergenceRestart_);
    warning->addLayout(choices);
    divergence_->hide();
    layout->addWidget(divergence_);
    layout->addWidget(results_, 1);
    layout->addWidget(exportLog_);

    QSettings settings;
    settings.beginGroup(QLatin1String(kSettingsGroup));
    trials_->setValue(settings.value("trials", 5).toInt());
    seed_->setValue(settings.value("seed", 1).toInt());
    perturbation_->setValue(settings.value("perturbation", 1.0).toDouble());
    sensor_->setValue(settings.value("sensor", 1.0).toDouble());
    speed_->setCurrentIndex(std::clamp(settings.value("speedIndex", 0).toInt(), 0,
                                       static_cast<int>(speeds().size()) - 1));
    settings.endGroup();
    run_.setSpeed(speed_->currentData().toDouble());

    connect(runAction_, &QAction::triggered, this, &RunPanel::startRun);
    connect(pauseAction_, &QAction::triggered, this, [this] {
        if (phase_ == RunPhase::Paused) {
            run_.resume();
        } else if (phase_ == RunPhase::Running) {
            run_.pause();
        }
    });
    connect(stopAction_, &QAction::triggered, &run_, &RunThread::stop);

    connect(&run_, &RunThread::runLogReady, this, [this](std::shared_ptr<const core::RunLog> log) {
        exportLog_->setEnabled(log && log->rows.rows() > 0);
    });
    connect(exportLog_, &QPushButton::clicked, this, [this] {
        const QString path = ModalDialog::saveFileName(
            this, tr("Export run log"), QSettings().value("run/logDirectory").toString(),
            tr("Run logs (*.csv)"));
        if (path.isEmpty()) {
            return;
        }
        const QString file = path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)
                                 ? path
                                 : path + QStringLiteral(".csv");
        QString error;
        if (!exportRunLog(file, &error)) {
            warningBox(this, tr("Export run log"), error);
            return;
        }
        QSettings().setValue("run/logDirectory", QFileInfo(file).absolutePath());
        showStatus(status_, tr("Run"), [this, file] {
            return tr("Run log written to %1").arg(QDir::toNativeSeparators(file));
        });
    });
    // Reset: stop whatever runs and start the views afresh (the next run starts cold anyway).
    connect(resetAction_, &QAction::triggered, this, [this] {
        run_.stop();
        results_->setRowCount(0);
        if (!emergency_.isLatched()) {
            status_->clear();  // under E-STOP its explanation stays until it is reset
        }
        emit runStarting();
    });
    connect(emergencyAction_, &QAction::triggered, this,
            [this] { emergency_.engage(tr("the Run menu")); });
    connect(resetEmergencyAction_, &QAction::triggered, &emergency_, &EmergencyStop::reset);
    connect(&emergency_, &EmergencyStop::engaged, this, &RunPanel::emergencyStop);
    connect(&emergency_, &EmergencyStop::released, this, [this] { run_.resetEmergencyStop(); });
    connect(&emergency_, &EmergencyStop::latchChanged, this, &RunPanel::showLatch);
    connect(speed_, &QComboBox::currentIndexChanged, this, [this] {
        run_.setSpeed(speed_->currentData().toDouble());
        QSettings().setValue(QStringLiteral("run/speedIndex"), speed_->currentIndex());
    });
    connect(&run_, &RunThread::phaseChanged, this, &RunPanel::updateButtons);
    // Results of another plant or demonstration are not this task's: cleared on a switch.
    connect(&session_, &LabSession::plantChanged, this, &RunPanel::clearResultsForNewTask);
    connect(&session_, &LabSession::demonstrationChanged, this, &RunPanel::clearResultsForNewTask);
    // The panel's own words, in the language of the moment (the worker's lines go to the status
    // bar, where they pass).
    connect(&run_, &RunThread::trialStarted, this, [this](int trial, int trials) {
        if (trial == 0) {
            runClock_.start();  // from the first trial: training is before it
        }
        const qint64 elapsed = runClock_.isValid() ? runClock_.elapsed() : 0;
        // Not logged: a line a trial would drown the log.
        setTranslatedText(status_, [this, trial, trials, elapsed] {
            return trial == 0 ? tr("Trial 1 of %1 running...").arg(trials)
                              : tr("Trial %1 of %2 running · %3")
                                    .arg(trial + 1)
                                    .arg(trials)
                                    .arg(progressTime(elapsed, trial, trials));
        });
    });
    connect(&run_, &RunThread::trainingProgress, this, [this](int done, int total) {
        setTranslatedText(status_, [this, done, total] {
            return total > 0 ? tr("Training before the run: %1 of %2...").arg(done).arg(total)
                             : tr("Training before the run...");
        });
    });
    connect(&run_, &RunThread::runFinished, this, [this] {
        finishedSeen_ = true;
        const int trials = results_->rowCount();
        showStatus(status_, tr("Run"), [this, trials] {
            return trials == 1 ? tr("Run finished: 1 trial.")
                               : tr("Run finished: %1 trials.").arg(trials);
        });
    });
    connect(&run_, &RunThread::failed, status_, &QLabel::setText);
    connect(&run_, &RunThread::trialFinished, this, &RunPanel::addTrialRow);
    connect(divergenceStop_, &QPushButton::clicked, this, [this] {
        run_.stop();
        divergence_->hide();
    });
    // Learning starts again from the method's start (a new run is cold), the views afresh.
    connect(divergenceRestart_, &QPushButton::clicked, this, [this] {
        divergence_->hide();
        if (phase_ == RunPhase::Idle) {
            startRun();
        } else if (phase_ != RunPhase::EmergencyStopped) {
            restartPending_ = true;  // once the stopped run is idle
            run_.stop();
        }
    });
    retranslateUi();
    updateButtons(run_.phase());
    resetEmergencyAction_->setEnabled(emergency_.isLatched());
}

QList<QAction*> RunPanel::runActions() const {
    return {runAction_, pauseAction_, stopAction_, resetAction_};
}

void RunPanel::emergencyStop() {
    run_.emergencyStop();
    divergence_->hide();
    restartPending_ = false;
}

void RunPanel::showLatch(bool latched) {
    resetEmergencyAction_->setEnabled(latched);
    runAction_->setEnabled(phase_ == RunPhase::Idle && !latched);
    const QTime at = emergency_.engagedAt();
    const QString by = emergency_.pressedBy();
    if (latched) {
        showStatus(status_, tr("Run"), [this, at, by] {
            return tr("E-STOP pressed at %1 (%2): nothing runs until Reset E-STOP.")
                .arg(at.toString(QStringLiteral("HH:mm:ss")), by);
        });
    } else {
        // The explanation stays until the operator runs again: what stopped, and when.
        showStatus(status_, tr("Run"), [this, at] {
            return tr("E-STOP was pressed at %1; it is reset now: ready to run.")
                .arg(at.toString(QStringLiteral("HH:mm:ss")));
        });
    }
}

void RunPanel::clearResultsForNewTask() {
    if (phase_ != RunPhase::Idle && phase_ != RunPhase::EmergencyStopped) {
        return;  // a run in progress keeps its own task (it copied it)
    }
    if (results_->rowCount() > 0) {
        results_->setRowCount(0);
        showStatus(status_, tr("Run"),
                   [this] { return tr("The task changed: the previous results were cleared."); });
    }
    retranslateUi();  // the RMS column's unit follows the plant
}

void RunPanel::startRun() {
    if (phase_ == RunPhase::Running || phase_ == RunPhase::Training) {
        return;
    }
    if (emergency_.isLatched()) {
        showStatus(status_, tr("Run"), emergency_.refusal());
        return;
    }
    QSettings settings;
    settings.beginGroup(QLatin1String(kSettingsGroup));
    settings.setValue("trials", trials_->value());
    settings.setValue("seed", seed_->value());
    settings.setValue("perturbation", perturbation_->value());
    settings.setValue("sensor", sensor_->value());
    settings.endGroup();

    RunRequest request;
    request.task = session_.task();
    request.method = session_.method();
    request.trials = trials_->value();
    request.settings.seed = static_cast<std::uint64_t>(seed_->value());
    request.settings.perturbation = perturbation_->value();
    request.settings.sensor = sensor_->value();
    request.demonstrationSource = session_.demonstrationSource().isEmpty()
                                      ? QStringLiteral("scripted %1, seed %2")
                                            .arg(session_.scriptedStyle())
                                            .arg(session_.scriptedSeed())
                                      : session_.demonstrationSource();
    // Trials kept as bundles, as the Rig tab's "Save every trial as a bundle" says.
    if (QSettings().value(QStringLiteral("rig/saveBundles"), true).toBool()) {
        request.bundleParent =
            QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                .filePath(QStringLiteral("trials"));
        request.session = QJsonDocument::fromJson(session_.toJson()).object();
    }
    results_->setRowCount(0);
    finishedSeen_ = false;
    firstTrialRms_ = 0.0;
    divergence_->hide();
    exportLog_->setEnabled(false);
    emit runStarting();
    logMessage(this, tr("Run"), MessageLevel::Info,
               tr("Run started: %1, %2 trial(s), seed %3, perturbation %4, sensor noise %5")
                   .arg(sim::MethodCatalog::get(request.method).label)
                   .arg(request.trials)
                   .arg(seed_->value())
                   .arg(perturbation_->value(), 0, 'f', 2)
                   .arg(sensor_->value(), 0, 'f', 2));
    run_.start(request);
}

bool RunPanel::exportRunLog(const QString& path, QString* error) const {
    const std::shared_ptr<const core::RunLog> log = run_.lastRunLog();
    if (!log || log->rows.rows() == 0) {
        *error = tr("No finished trial to write yet: run first.");
        return false;
    }
    core::FileError fileError;
    if (!core::writeRunLogCsv(*log, path, &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

bool RunPanel::diverged(const sim::TrialSummary& summary, double firstTrialRms) {
    // Three times the first trial's tracking error, and clearly off the path (the first trial
    // is the method's untrained start: learning that works brings the error down from there).
    return summary.complete && firstTrialRms > 0.0 && std::isfinite(firstTrialRms) &&
           !(summary.trackingRms <= 3.0 * firstTrialRms);
}

void RunPanel::updateButtons(RunPhase phase) {
    const bool active =
        phase == RunPhase::Running || phase == RunPhase::Paused || phase == RunPhase::Training;
    const RunPhase previous = phase_;
    phase_ = phase;
    runAction_->setEnabled(phase == RunPhase::Idle && !emergency_.isLatched());
    pauseAction_->setEnabled(phase == RunPhase::Running || phase == RunPhase::Paused);
    stopAction_->setEnabled(active);
    retranslateRunActions();
    if (phase == RunPhase::Idle && restartPending_) {
        restartPending_ = false;
        startRun();
        return;
    }
    if (phase == RunPhase::Training) {
        const sim::MethodSpec* method = sim::MethodCatalog::find(session_.method());
        if (method && method->plansThroughModel && !method->trainsOffline()) {
            showStatus(status_, tr("Run"),
                       [this] { return tr("Identifying the car's model before the run..."); });
        } else {
            showStatus(status_, tr("Run"), [this] { return tr("Training before the run..."); });
        }
    } else if (phase == RunPhase::Idle && previous != RunPhase::Idle &&
               previous != RunPhase::EmergencyStopped && !finishedSeen_) {
        // Ended without finishing and without E-STOP (which says so itself): stopped.
        showStatus(status_, tr("Run"), [this] { return tr("Run stopped."); });
    }
}

void RunPanel::retranslateRunActions() {
    runAction_->setText(tr("Run (F5)"));
    pauseAction_->setText(phase_ == RunPhase::Paused ? tr("Resume (F6)") : tr("Pause (F6)"));
    stopAction_->setText(tr("Stop (Shift+F5)"));
    resetAction_->setText(tr("Reset (Ctrl+R)"));
}

void RunPanel::addTrialRow(int trial, const sim::TrialSummary& summary) {
    const int row = results_->rowCount();
    results_->insertRow(row);
    const bool planar = session_.profile().info.pose.has_value();
    const auto cell = [&](int column, const QString& text) {
        auto* item = new QTableWidgetItem(text);
        item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (!summary.complete) {
            // Stopped part-way: its numbers cover only what was run.
            QFont font = item->font();
            font.setItalic(true);
            item->setFont(font);
            item->setForeground(palette().color(QPalette::Disabled, QPalette::Text));
            item->setToolTip(
                tr("Stopped after %1 s: not a finished trial").arg(summary.duration, 0, 'f', 1));
        }
        results_->setItem(row, column, item);
    };
    // Cut short while E-STOP is latched: E-STOP cut it (the worker reports it right after).
    const bool byEmergency = !summary.complete && emergency_.isLatched();
    cell(0, summary.complete ? QString::number(trial + 1)
            : byEmergency    ? tr("%1 (E-STOP)").arg(trial + 1)
                             : tr("%1 (stopped)").arg(trial + 1));
    cell(1, planar ? QString::number(summary.finalPositionError * 100.0, 'f', 1)
                   : QStringLiteral("—"));
    cell(2, planar ? QString::number(summary.finalHeadingError * 180.0 / M_PI, 'f', 1)
                   : QStringLiteral("—"));
    cell(3, QString::number(summary.trackingRms, 'f', 3));
    const QString tracking = tr("tracking RMS %1 m").arg(summary.trackingRms, 0, 'f', 3);
    logMessage(
        this, tr("Run"), MessageLevel::Info,
        (planar ? tr("Trial %1: parked %2 cm and %3 deg off; %4")
                      .arg(trial + 1)
                      .arg(summary.finalPositionError * 100.0, 0, 'f', 1)
                      .arg(summary.finalHeadingError * 180.0 / M_PI, 0, 'f', 1)
                      .arg(tracking)
                : tr("Trial %1: %2").arg(trial + 1).arg(tracking)) +
            (summary.runOutSeconds > 0.0
                 //: The car still moved when the trial's time was up.
                 ? tr("; ran out %1 s in neutral, scored where it rests")
                       .arg(summary.runOutSeconds, 0, 'f', 1)
                 : QString()) +
            (summary.controllerNote.isEmpty() ? QString()
                                              : QStringLiteral("; ") + summary.controllerNote) +
            (summary.complete ? QString()
             : byEmergency    ? tr(" (cut short by E-STOP)")
                              : tr(" (stopped part-way)")));
    if (row == 0 && summary.complete) {
        firstTrialRms_ = summary.trackingRms;
    } else if (diverged(summary, firstTrialRms_)) {
        for (int c = 0; c < results_->columnCount(); ++c) {
            results_->item(row, c)->setBackground(QColor(0xfd, 0xd8, 0xd8));
        }
        divergenceText_->setText(
            tr("Trial %1 diverged: its tracking error is %2 times the first trial's. The learner "
               "may have gone unstable; stop the run, or start learning again from the start.")
                .arg(trial + 1)
                .arg(summary.trackingRms / firstTrialRms_, 0, 'f', 1));
        divergence_->show();
    }
    results_->scrollToBottom();
}

bool RunPanel::eventFilter(QObject* watched, QEvent* event) {
    if (watched == status_ && event->type() == QEvent::ToolTip) {
        status_->setToolTip(status_->text());
    }
    if (watched == results_->viewport() && event->type() == QEvent::Resize) {
        // The panel given less room (another tab above it needed more): the newest stays.
        QTimer::singleShot(0, results_, [table = results_] { table->scrollToBottom(); });
    }
    if (watched == results_->viewport() && event->type() == QEvent::Wheel) {
        const auto* wheel = static_cast<QWheelEvent*>(event);
        QScrollBar* bar = results_->verticalScrollBar();
        bar->setValue(bar->value() - wheel->angleDelta().y() * QApplication::wheelScrollLines() *
                                         bar->singleStep() / 120);
        return true;  // handled here even at the table's end: the dock does not scroll
    }
    return QWidget::eventFilter(watched, event);
}

void RunPanel::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QWidget::changeEvent(event);
}

void RunPanel::retranslateUi() {
    trialsLabel_->setText(tr("Trials in a row:"));
    trials_->setToolTip(tr("Learners keep what they learnt from one trial to the next."));
    seedLabel_->setText(tr("Seed:"));
    seed_->setToolTip(
        tr("Draws the perturbation and sensor noise of each trial; the same seed "
           "gives the same trials."));
    perturbationLabel_->setText(tr("Perturbation:"));
    perturbation_->setToolTip(
        tr("Start offsets, friction and gain variation, trim and actuator noise: 0 nominal, 1 "
           "a realistic lab."));
    sensorLabel_->setText(tr("Sensor noise:"));
    sensor_->setToolTip(
        tr("Measurement noise, latency and dropped samples: 0 perfect, 1 "
           "realistic."));
    speedLabel_->setText(tr("Speed:"));
    speed_->setItemText(0, tr("Real time (1x)"));
    speed_->setItemText(1, tr("10x"));
    speed_->setItemText(2, tr("As fast as possible"));
    retranslateRunActions();
    exportLog_->setText(tr("Export run log..."));
    exportLog_->setToolTip(
        tr("Every control step of the last run's finished trials, in the format "
           "of prisca-cli run --out (state, observation, reference, error, u, "
           "u*, cost, θ)"));
    resetAction_->setToolTip(tr("Stop the run and clear the trails, charts and results (Ctrl+R)"));
    emergencyAction_->setText(tr("E-STOP (Space / Esc)"));
    emergencyAction_->setToolTip(
        tr("Stops the run, a recording and the rig at once (within one control period) and stays "
           "engaged until reset. Space outside text fields, or Esc."));
    resetEmergencyAction_->setText(tr("Reset E-STOP"));
    divergenceStop_->setText(tr("Stop the run"));
    divergenceRestart_->setText(tr("Start learning again"));
    divergenceRestart_->setToolTip(
        tr("Stop this run and start a new one: the method starts again from its initial policy"));
    resetEmergencyAction_->setToolTip(tr("Release the E-STOP latch so a run can start again"));
    // Short headings (the table is narrow); the tooltips say them in full.
    results_->setHorizontalHeaderLabels(
        {tr("Trial"), tr("Δp [cm]"), tr("Δψ [deg]"),
         session_.profile().info.pose ? tr("RMS [m]") : tr("RMS [rad]")});
    const QStringList tips = {
        tr("Trial in the run"), tr("Final position error: distance from the lot [cm]"),
        tr("Final heading error [deg]"), tr("Time-aligned RMS tracking error over the trial")};
    for (int i = 0; i < tips.size(); ++i) {
        if (QTableWidgetItem* header = results_->horizontalHeaderItem(i)) {
            header->setToolTip(tips[i]);
        }
    }
}

}  // namespace prisca::app
