#include "app/RunController.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kShutdownWaitMs = 3000;
}

RunController::RunController(QObject* parent) : QObject(parent), worker_(new RunWorker) {
    qRegisterMetaType<RunRequest>();
    qRegisterMetaType<LiveSample>();
    qRegisterMetaType<std::shared_ptr<const core::RunLog>>();
    qRegisterMetaType<QVector<LiveSample>>();
    qRegisterMetaType<RunPhase>();
    qRegisterMetaType<sim::TrialSummary>();
    thread_.setObjectName(QStringLiteral("prisca-run"));
    worker_->moveToThread(&thread_);
    connect(worker_, &RunWorker::samplesReady, this, &RunController::samplesReady);
    connect(worker_, &RunWorker::phaseChanged, this, [this](RunPhase phase) {
        phase_ = phase;
        emit phaseChanged(phase);
    });
    connect(worker_, &RunWorker::progress, this, &RunController::progress);
    connect(worker_, &RunWorker::trialFinished, this, &RunController::trialFinished);
    connect(worker_, &RunWorker::runFinished, this, &RunController::runFinished);
    connect(worker_, &RunWorker::runLogReady, this,
            [this](std::shared_ptr<const core::RunLog> log) {
                lastRunLog_ = std::move(log);
                emit runLogReady(lastRunLog_);
            });
    connect(worker_, &RunWorker::failed, this, &RunController::failed);
    devices::markThreadEnd(thread_);
    thread_.start();
}

RunController::~RunController() {
    worker_->requestCancel();
    devices::postTo(worker_, [w = worker_] { w->stop(); });
    devices::endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void RunController::start(const RunRequest& request) {
    devices::postTo(worker_, [w = worker_, request] { w->start(request); });
}

void RunController::pause() {
    devices::postTo(worker_, [w = worker_] { w->pause(); });
}

void RunController::resume() {
    devices::postTo(worker_, [w = worker_] { w->resume(); });
}

void RunController::stop() {
    worker_->requestCancel();  // training polls this; stop() itself waits in the queue
    devices::postTo(worker_, [w = worker_] { w->stop(); });
}

void RunController::emergencyStop() {
    worker_->requestEmergencyStop();
    devices::postTo(worker_, [w = worker_] { w->engageEmergencyStop(); });
}

void RunController::resetEmergencyStop() {
    devices::postTo(worker_, [w = worker_] { w->resetEmergencyStop(); });
}

void RunController::setSpeed(double speed) {
    devices::postTo(worker_, [w = worker_, speed] { w->setSpeed(speed); });
}

}  // namespace prisca::app
