#include "app/workers/RunThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kShutdownWaitMs = 3000;
}

RunThread::RunThread(QObject* parent) : QObject(parent), worker_(new RunWorker) {
    qRegisterMetaType<RunRequest>();
    qRegisterMetaType<LiveSample>();
    qRegisterMetaType<std::shared_ptr<const core::RunLog>>();
    qRegisterMetaType<QVector<LiveSample>>();
    qRegisterMetaType<RunPhase>();
    qRegisterMetaType<sim::TrialSummary>();
    thread_.setObjectName(QStringLiteral("prisca-run"));
    worker_->moveToThread(&thread_);
    connect(worker_, &RunWorker::samplesReady, this, &RunThread::samplesReady);
    connect(worker_, &RunWorker::phaseChanged, this, [this](RunPhase phase) {
        phase_ = phase;
        emit phaseChanged(phase);
    });
    connect(worker_, &RunWorker::progress, this, &RunThread::progress);
    connect(worker_, &RunWorker::trialStarted, this, &RunThread::trialStarted);
    connect(worker_, &RunWorker::trainingProgress, this, &RunThread::trainingProgress);
    connect(worker_, &RunWorker::trialFinished, this, &RunThread::trialFinished);
    connect(worker_, &RunWorker::runFinished, this, &RunThread::runFinished);
    connect(worker_, &RunWorker::runLogReady, this,
            [this](std::shared_ptr<const core::RunLog> log) {
                lastRunLog_ = std::move(log);
                emit runLogReady(lastRunLog_);
            });
    connect(worker_, &RunWorker::failed, this, &RunThread::failed);
    devices::markThreadEnd(thread_);
    thread_.start();
}

RunThread::~RunThread() {
    worker_->requestCancel();
    devices::postTo(worker_, [w = worker_] { w->stop(); });
    devices::endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void RunThread::start(const RunRequest& request) {
    devices::postTo(worker_, [w = worker_, request] { w->start(request); });
}

void RunThread::pause() {
    devices::postTo(worker_, [w = worker_] { w->pause(); });
}

void RunThread::resume() {
    devices::postTo(worker_, [w = worker_] { w->resume(); });
}

void RunThread::stop() {
    worker_->requestCancel();  // training polls this; stop() itself waits in the queue
    devices::postTo(worker_, [w = worker_] { w->stop(); });
}

void RunThread::emergencyStop() {
    worker_->requestEmergencyStop();
    devices::postTo(worker_, [w = worker_] { w->engageEmergencyStop(); });
}

void RunThread::resetEmergencyStop() {
    devices::postTo(worker_, [w = worker_] { w->resetEmergencyStop(); });
}

void RunThread::setSpeed(double speed) {
    devices::postTo(worker_, [w = worker_, speed] { w->setSpeed(speed); });
}

}  // namespace prisca::app
