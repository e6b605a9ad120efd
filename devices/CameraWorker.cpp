#include "devices/CameraWorker.h"

#include "devices/ThreadHandOff.h"
#include "devices/ThreadPriority.h"

namespace prisca::devices {

namespace {
constexpr unsigned long kShutdownWaitMs = 3000;
}

Camera::Camera(QObject* parent) : QObject(parent), context_(new QObject) {
    qRegisterMetaType<CameraFrame>();
    thread_.setObjectName(QStringLiteral("prisca-camera"));
    context_->moveToThread(&thread_);
    markThreadEnd(thread_);
    thread_.start();
    // Frames are tracked and the loop stepped on this thread: ahead of other programs' work.
    postTo(context_, [] { raiseCurrentThreadPriority(); });
}

Camera::~Camera() {
    stop();
    endWorkerThread(thread_, context_, kShutdownWaitMs);
}

void Camera::setConsumer(std::function<void(const CameraFrame&)> consumer) {
    consumer_ = std::move(consumer);
}

void Camera::start(std::shared_ptr<CameraSource> source, double displayHz) {
    stopRequested_.store(false);
    running_.store(true);
    postTo(context_, [this, source, displayHz] { run(source, displayHz); });
}

void Camera::stop() {
    stopRequested_.store(true);
}

void Camera::run(std::shared_ptr<CameraSource> source, double displayHz) {
    QString error;
    if (!source->open(&error)) {
        running_.store(false);
        emit failed(error);
        emit finished();
        return;
    }
    fps_.store(source->framesPerSecond());
    const std::int64_t displayPeriodNs =
        displayHz > 0 ? static_cast<std::int64_t>(1e9 / displayHz) : 0;
    std::int64_t lastDisplayNs = 0;
    CameraFrame frame;
    while (!stopRequested_.load()) {
        if (!source->grab(&frame, &error)) {
            if (source->ended()) {
                emit ended(error);
            } else {
                emit failed(error);
            }
            break;
        }
        frames_.fetch_add(1);
        if (consumer_) {
            consumer_(frame);
        }
        if (displayPeriodNs > 0 && frame.steadyNs - lastDisplayNs >= displayPeriodNs) {
            lastDisplayNs = frame.steadyNs;
            CameraFrame copy = frame;
            copy.image = frame.image.clone();  // the source may reuse its buffer
            emit frameReady(copy);
        }
    }
    running_.store(false);
    emit finished();
}

}  // namespace prisca::devices
