#include "app/workers/IdentificationThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kShutdownWaitMs = 5000;
}

IdentificationThread::IdentificationThread(QObject* parent)
    : QObject(parent), worker_(new IdentificationWorker) {
    thread_.setObjectName(QStringLiteral("prisca-identify"));
    worker_->moveToThread(&thread_);
    connect(worker_, &IdentificationWorker::progress, this, &IdentificationThread::progress);
    connect(worker_, &IdentificationWorker::finished, this, &IdentificationThread::finished);
    connect(worker_, &IdentificationWorker::failed, this, &IdentificationThread::failed);
    devices::markThreadEnd(thread_);
    thread_.start();
}

IdentificationThread::~IdentificationThread() {
    worker_->cancel();
    devices::endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void IdentificationThread::start(const IdentificationRequest& request) {
    worker_->prepare();
    devices::postTo(worker_, [w = worker_, request] { w->run(request); });
}

void IdentificationThread::cancel() {
    worker_->cancel();
}

bool IdentificationThread::isCancelled() const {
    return worker_->isCancelled();
}

}  // namespace prisca::app
