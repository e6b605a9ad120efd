#include "app/workers/RunWorker.h"

#include "rig/TrialBundle.h"

#include <QDateTime>
#include <QDir>

#include "core/Controller.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/RunLogBuilder.h"

#include <QLoggingCategory>
#include <QRegularExpression>
#include <QTimer>

#include <exception>

Q_LOGGING_CATEGORY(lcRun, "prisca.app.run")

namespace prisca::app {

namespace {

constexpr int kPaceTickMs = 5;         // how often the pace is checked [ms]
constexpr int kFlushMs = 40;           // samples are sent at most this often [ms]
constexpr qint64 kFastSliceMs = 12;    // "as fast as possible": wall time per slice [ms]
constexpr int kMaxCatchUpSteps = 400;  // a stalled pace never runs more than this per tick

}  // namespace

RunWorker::RunWorker(QObject* parent) : QObject(parent), timer_(new QTimer(this)) {
    timer_->setTimerType(Qt::PreciseTimer);
    timer_->setInterval(kPaceTickMs);
    connect(timer_, &QTimer::timeout, this, &RunWorker::tick);
}

RunWorker::~RunWorker() = default;

void RunWorker::start(const RunRequest& request) {
    timer_->stop();
    stepper_.reset();
    pending_.clear();
    if (emergency_.load()) {
        emit failed(tr("E-STOP is engaged: reset it before starting a run."));
        setPhase(RunPhase::EmergencyStopped);
        return;
    }
    cancelTraining_.store(false);
    request_ = request;
    try {
        // The same set-up as `prisca-cli run`: the plant at the demonstration's period, the
        // trials' seeds, the training, the run log.
        setup_.emplace(request_.task, request_.method, request_.settings);
        plant_ = setup_->makePlant();
        // Offline methods train first, on seeds the run never uses; a method that plans through
        // a model identifies it first (seconds). Either is work under way for E-STOP.
        if (setup_->method().trainsOffline() || setup_->method().plansThroughModel) {
            setPhase(RunPhase::Training);
        }
        controller_ = setup_->makeController(
            [this] { return cancelTraining_.load() || emergency_.load(); },
            [this](const QString& text) {
                emit progress(text);
                static const QRegularExpression fraction(QStringLiteral("(\\d+)/(\\d+)"));
                const QRegularExpressionMatch m = fraction.match(text);
                emit trainingProgress(m.hasMatch() ? m.captured(1).toInt() : 0,
                                      m.hasMatch() ? m.captured(2).toInt() : 0);
            });
        if (!controller_) {  // training cancelled
            if (emergency_.load()) {
                enterEmergencyStop();
            } else {
                setPhase(RunPhase::Idle);
            }
            return;
        }
    } catch (const std::exception& e) {
        setPhase(RunPhase::Idle);
        emit failed(tr("Cannot start the run: %1").arg(QString::fromStdString(e.what())));
        return;
    }
    runLog_ = setup_->startRunLog(*controller_, request_.trials, request_.demonstrationSource);
    trial_ = 0;
    runTimeOffset_ = 0.0;
    stepsTaken_.store(0);
    beginTrial();
    setPhase(RunPhase::Running);
    timer_->start();
}

void RunWorker::beginTrial() {
    stepper_ = std::make_unique<sim::EpisodeStepper>(*plant_, *controller_, setup_->trial(trial_));
    emit progress(tr("Trial %1 of %2").arg(trial_ + 1).arg(request_.trials));
    emit trialStarted(trial_, request_.trials);
    repace();
    flushClock_.start();
}

void RunWorker::repace() {
    paceClock_.start();
    paceOriginStep_ = stepper_ ? stepper_->stepCount() : 0;
}

void RunWorker::tick() {
    if (phase_ != RunPhase::Running || !stepper_) {
        return;
    }
    const double dt = plant_->timing().controlPeriod;
    int due = 0;
    if (speed_ > 0.0) {
        const double simulated = paceClock_.nsecsElapsed() * 1e-9 * speed_;
        due = static_cast<int>(simulated / dt) - (stepper_->stepCount() - paceOriginStep_);
        if (due > kMaxCatchUpSteps) {
            // Behind (a slow machine, a debugger): drop the backlog rather than race to catch up.
            due = kMaxCatchUpSteps;
            repace();
        }
    }
    QElapsedTimer slice;
    slice.start();
    for (int i = 0; speed_ <= 0.0 || i < due; ++i) {
        if (speed_ <= 0.0 && slice.elapsed() >= kFastSliceMs) {
            break;
        }
        // Checked before every step: E-STOP takes effect within one control period.
        if (emergency_.load()) {
            enterEmergencyStop();
            return;
        }
        if (stepper_->finished()) {
            endTrial();
            return;
        }
        const sim::StepRecord& record = stepper_->step();
        stepsTaken_.fetch_add(1);
        LiveSample sample;
        sample.trial = trial_;
        sample.step = stepper_->stepCount() - 1;
        sample.time = record.time;
        sample.runTime = runTimeOffset_ + record.time;
        sample.state = record.state;
        sample.action = record.action;
        sample.referenceAction = record.referenceAction;
        sample.theta = record.parameters;
        sample.referenceIndex = record.referenceIndex;
        sample.cost = record.cost;
        sample.trackedError = sim::trackedError(
            request_.task.profile.info, *request_.task.demonstration, record.state, sample.step);
        sample.wind = plant_->windVelocity();
        pending_.push_back(std::move(sample));
    }
    if (flushClock_.elapsed() >= kFlushMs) {
        flushSamples();
    }
}

void RunWorker::endTrial() {
    flushSamples();
    const sim::EpisodeResult result = stepper_->takeResult();
    const sim::TrialSummary summary =
        sim::summarizeTrial(request_.task.profile.info, *request_.task.demonstration, result);
    sim::appendRunLogTrial(runLog_, trial_, result, request_.task.demonstration->dt);
    saveBundle(result, summary);
    emit trialFinished(trial_, summary);
    runTimeOffset_ += result.duration;
    ++trial_;
    if (trial_ >= request_.trials) {
        timer_->stop();
        stepper_.reset();
        // The log and the end are told before the phase: whoever waits for Idle (a quit that
        // keeps the run's log) finds this run's log there, not the last one's.
        emit progress(tr("Run finished: %1 trials").arg(request_.trials));
        emitRunLog();
        emit runFinished();
        setPhase(RunPhase::Idle);
        return;
    }
    beginTrial();
}

void RunWorker::flushSamples() {
    if (!pending_.isEmpty()) {
        emit samplesReady(pending_);
        pending_.clear();
    }
    flushClock_.restart();
}

void RunWorker::pause() {
    if (phase_ == RunPhase::Running) {
        flushSamples();
        setPhase(RunPhase::Paused);
    }
}

void RunWorker::resume() {
    if (phase_ == RunPhase::Paused) {
        repace();
        setPhase(RunPhase::Running);
    }
}

void RunWorker::saveBundle(const sim::EpisodeResult& result, const sim::TrialSummary& summary) {
    if (request_.bundleParent.isEmpty()) {
        return;
    }
    const QString folder =
        QDir(request_.bundleParent)
            .filePath(
                QStringLiteral("sim-%1-%2-trial-%3")
                    .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss")),
                         request_.method)
                    .arg(trial_ + 1));
    QJsonObject header{{"method", request_.method},
                       {"trial", trial_ + 1},
                       {"seed", static_cast<double>(request_.settings.seed)},
                       {"session", request_.session}};
    QString error;
    if (!rig::writeSimulationBundle(folder, header, request_.task.profile.info,
                                    *request_.task.demonstration, result, summary, &error)) {
        emit progress(tr("The trial's bundle could not be written: %1").arg(error));
        return;
    }
    emit bundleSaved(folder);
}

void RunWorker::reportCutTrial() {
    if (stepper_ && stepper_->stepCount() > 0) {
        const sim::EpisodeResult result = stepper_->takeResult();
        sim::TrialSummary summary =
            sim::summarizeTrial(request_.task.profile.info, *request_.task.demonstration, result);
        summary.complete = false;  // stopped part-way: reported, and marked as such
        saveBundle(result, summary);
        emit trialFinished(trial_, summary);
    }
}

void RunWorker::stop() {
    cancelTraining_.store(true);
    if (phase_ == RunPhase::Running || phase_ == RunPhase::Paused) {
        flushSamples();
        timer_->stop();
        reportCutTrial();
        stepper_.reset();
        emitRunLog();
        emit progress(tr("Run stopped"));
        setPhase(RunPhase::Idle);
    }
}

void RunWorker::emitRunLog() {
    emit runLogReady(std::make_shared<const core::RunLog>(runLog_));
}

void RunWorker::enterEmergencyStop() {
    timer_->stop();
    flushSamples();
    if (stepper_) {
        reportCutTrial();  // shown as far as it went (not in the run log: it did not finish)
        emitRunLog();      // the finished trials
    }
    stepper_.reset();
    qCWarning(lcRun) << "E-STOP after" << stepsTaken_.load() << "steps";
    emit progress(tr("E-STOP: run stopped"));
    setPhase(RunPhase::EmergencyStopped);
}

void RunWorker::engageEmergencyStop() {
    emergency_.store(true);
    if (phase_ != RunPhase::EmergencyStopped) {
        enterEmergencyStop();
    }
}

void RunWorker::resetEmergencyStop() {
    emergency_.store(false);
    if (phase_ == RunPhase::EmergencyStopped) {
        setPhase(RunPhase::Idle);
    }
}

void RunWorker::setSpeed(double speed) {
    speed_ = speed;
    if (stepper_) {
        repace();
    }
}

void RunWorker::setPhase(RunPhase phase) {
    if (phase != phase_) {
        phase_ = phase;
        emit phaseChanged(phase);
    }
}

}  // namespace prisca::app
