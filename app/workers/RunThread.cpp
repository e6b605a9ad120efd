#include "app/workers/RunThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kRunShutdownMs = 3000;
}

RunThread::RunThread(QObject* parent)
    : QObject(parent),
      worker_(new RunWorker),
      host_(worker_, QStringLiteral("prisca-run"), kRunShutdownMs) {
    qRegisterMetaType<RunRequest>();
    qRegisterMetaType<LiveSample>();
    qRegisterMetaType<std::shared_ptr<const core::RunLog>>();
    qRegisterMetaType<QVector<LiveSample>>();
    qRegisterMetaType<RunPhase>();
    qRegisterMetaType<sim::TrialSummary>();
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
    host_.start();
}

RunThread::~RunThread() {
    worker_->requestCancel();
    host_.post([w = worker_] { w->stop(); });
    // host_, destroyed next, ends the thread and deletes the worker.
}

void RunThread::start(const RunRequest& request) {
    host_.post([w = worker_, request] { w->start(request); });
}

void RunThread::pause() {
    host_.post([w = worker_] { w->pause(); });
}

void RunThread::resume() {
    host_.post([w = worker_] { w->resume(); });
}

void RunThread::stop() {
    worker_->requestCancel();  // training polls this; stop() itself waits in the queue
    host_.post([w = worker_] { w->stop(); });
}

void RunThread::emergencyStop() {
    worker_->requestEmergencyStop();
    host_.post([w = worker_] { w->engageEmergencyStop(); });
}

void RunThread::resetEmergencyStop() {
    host_.post([w = worker_] { w->resetEmergencyStop(); });
}

void RunThread::setSpeed(double speed) {
    host_.post([w = worker_, speed] { w->setSpeed(speed); });
}

}  // namespace prisca::app
