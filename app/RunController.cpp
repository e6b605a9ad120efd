#include "app/RunController.h"

#include <QMetaObject>

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
    thread_.start();
}

RunController::~RunController() {
    worker_->requestCancel();
    QMetaObject::invokeMethod(worker_, &RunWorker::stop, Qt::QueuedConnection);
    thread_.quit();
    thread_.wait(kShutdownWaitMs);
    // Deleted here, after its thread has ended (so every write it made is ordered before this,
    // visibly to ThreadSanitizer too); left alone if the thread has not ended in time.
    if (thread_.isFinished()) {
        delete worker_;
    }
}

void RunController::start(const RunRequest& request) {
    QMetaObject::invokeMethod(
        worker_, [w = worker_, request] { w->start(request); }, Qt::QueuedConnection);
}

void RunController::pause() {
    QMetaObject::invokeMethod(worker_, &RunWorker::pause, Qt::QueuedConnection);
}

void RunController::resume() {
    QMetaObject::invokeMethod(worker_, &RunWorker::resume, Qt::QueuedConnection);
}

void RunController::stop() {
    worker_->requestCancel();  // training polls this; stop() itself waits in the queue
    QMetaObject::invokeMethod(worker_, &RunWorker::stop, Qt::QueuedConnection);
}

void RunController::emergencyStop() {
    worker_->requestEmergencyStop();
    QMetaObject::invokeMethod(worker_, &RunWorker::engageEmergencyStop, Qt::QueuedConnection);
}

void RunController::resetEmergencyStop() {
    QMetaObject::invokeMethod(worker_, &RunWorker::resetEmergencyStop, Qt::QueuedConnection);
}

void RunController::setSpeed(double speed) {
    QMetaObject::invokeMethod(
        worker_, [w = worker_, speed] { w->setSpeed(speed); }, Qt::QueuedConnection);
}

}  // namespace prisca::app
