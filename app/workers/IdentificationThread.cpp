#include "app/workers/IdentificationThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kIdentificationShutdownMs = 5000;
}

IdentificationThread::IdentificationThread(QObject* parent)
    : QObject(parent),
      worker_(new IdentificationWorker),
      host_(worker_, QStringLiteral("prisca-identify"), kIdentificationShutdownMs) {
    connect(worker_, &IdentificationWorker::progress, this, &IdentificationThread::progress);
    connect(worker_, &IdentificationWorker::finished, this, &IdentificationThread::finished);
    connect(worker_, &IdentificationWorker::failed, this, &IdentificationThread::failed);
    host_.start();
}

IdentificationThread::~IdentificationThread() {
    worker_->cancel();
    // host_, destroyed next, ends the thread and deletes the worker.
}

void IdentificationThread::start(const IdentificationRequest& request) {
    worker_->prepare();
    host_.post([w = worker_, request] { w->run(request); });
}

void IdentificationThread::cancel() {
    worker_->cancel();
}

bool IdentificationThread::isCancelled() const {
    return worker_->isCancelled();
}

}  // namespace prisca::app
