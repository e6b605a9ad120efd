#include "app/workers/ExperimentThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kShutdownWaitMs = 5000;
}

ExperimentThread::ExperimentThread(QObject* parent)
    : QObject(parent), worker_(new ExperimentWorker) {
    thread_.setObjectName(QStringLiteral("prisca-experiments"));
    worker_->moveToThread(&thread_);
    connect(worker_, &ExperimentWorker::progress, this, &ExperimentThread::progress);
    connect(worker_, &ExperimentWorker::table1Finished, this, &ExperimentThread::table1Finished);
    connect(worker_, &ExperimentWorker::curvesFinished, this, &ExperimentThread::curvesFinished);
    connect(worker_, &ExperimentWorker::failed, this, &ExperimentThread::failed);
    devices::markThreadEnd(thread_);
    thread_.start();
}

ExperimentThread::~ExperimentThread() {
    worker_->cancel();
    devices::endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void ExperimentThread::start(const ExperimentRequest& request) {
    worker_->prepare();
    devices::postTo(worker_, [w = worker_, request] { w->run(request); });
}

void ExperimentThread::cancel() {
    worker_->cancel();
}

bool ExperimentThread::isCancelled() const {
    return worker_->isCancelled();
}

}  // namespace prisca::app
