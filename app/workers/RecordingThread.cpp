#include "app/workers/RecordingThread.h"

#include "devices/ThreadHandOff.h"

namespace prisca::app {

namespace {
constexpr unsigned long kRecordingShutdownMs = 3000;
}

RecordingThread::RecordingThread(QObject* parent)
    : QObject(parent),
      worker_(new RecordingWorker),
      host_(worker_, QStringLiteral("prisca-record"), kRecordingShutdownMs) {
    connect(worker_, &RecordingWorker::samplesReady, this, &RecordingThread::samplesReady);
    connect(worker_, &RecordingWorker::finished, this, &RecordingThread::finished);
    connect(worker_, &RecordingWorker::failed, this, &RecordingThread::failed);
    host_.start();
}

RecordingThread::~RecordingThread() {
    worker_->requestStop();
    // host_, destroyed next, ends the thread and deletes the worker.
}

void RecordingThread::start(const QString& plant, const QString& streamPath,
                            std::shared_ptr<const sim::PlantParameters> parameters) {
    host_.post([w = worker_, plant, streamPath, parameters = std::move(parameters)] {
        w->start(plant, streamPath, parameters);
    });
}

void RecordingThread::setInput(const Eigen::VectorXd& input) {
    host_.post([w = worker_, input] { w->setInput(input); });
}

void RecordingThread::stop() {
    host_.post([w = worker_] { w->stop(); });
}

void RecordingThread::requestStop() {
    worker_->requestStop();
}

}  // namespace prisca::app
