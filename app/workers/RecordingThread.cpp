#include "app/workers/RecordingThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kShutdownWaitMs = 3000;
}

RecordingThread::RecordingThread(QObject* parent) : QObject(parent), worker_(new RecordingWorker) {
    thread_.setObjectName(QStringLiteral("prisca-record"));
    worker_->moveToThread(&thread_);
    connect(worker_, &RecordingWorker::samplesReady, this, &RecordingThread::samplesReady);
    connect(worker_, &RecordingWorker::finished, this, &RecordingThread::finished);
    connect(worker_, &RecordingWorker::failed, this, &RecordingThread::failed);
    devices::markThreadEnd(thread_);
    thread_.start();
}

RecordingThread::~RecordingThread() {
    worker_->requestStop();
    devices::endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void RecordingThread::start(const QString& plant, const QString& streamPath,
                            std::shared_ptr<const sim::PlantParameters> parameters) {
    devices::postTo(worker_, [w = worker_, plant, streamPath, parameters = std::move(parameters)] {
        w->start(plant, streamPath, parameters);
    });
}

void RecordingThread::setInput(const Eigen::VectorXd& input) {
    devices::postTo(worker_, [w = worker_, input] { w->setInput(input); });
}

void RecordingThread::stop() {
    devices::postTo(worker_, [w = worker_] { w->stop(); });
}

void RecordingThread::requestStop() {
    worker_->requestStop();
}

}  // namespace prisca::app
