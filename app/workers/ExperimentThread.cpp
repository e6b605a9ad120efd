#include "app/workers/ExperimentThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kExperimentShutdownMs = 5000;
}

ExperimentThread::ExperimentThread(QObject* parent)
    : QObject(parent),
      worker_(new ExperimentWorker),
      host_(worker_, QStringLiteral("prisca-experiments"), kExperimentShutdownMs) {
    connect(worker_, &ExperimentWorker::progress, this, &ExperimentThread::progress);
    connect(worker_, &ExperimentWorker::table1Finished, this, &ExperimentThread::table1Finished);
    connect(worker_, &ExperimentWorker::curvesFinished, this, &ExperimentThread::curvesFinished);
    connect(worker_, &ExperimentWorker::failed, this, &ExperimentThread::failed);
    host_.start();
}

ExperimentThread::~ExperimentThread() {
    worker_->cancel();
    // host_, destroyed next, ends the thread and deletes the worker.
}

void ExperimentThread::start(const ExperimentRequest& request) {
    worker_->prepare();
    host_.post([w = worker_, request] { w->run(request); });
}

void ExperimentThread::cancel() {
    worker_->cancel();
}

bool ExperimentThread::isCancelled() const {
    return worker_->isCancelled();
}

}  // namespace prisca::app
