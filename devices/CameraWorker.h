#pragma once

#include "devices/CameraSource.h"

#include <QMetaType>
#include <QObject>
#include <QThread>

#include <atomic>
#include <functional>
#include <memory>

namespace prisca::devices {

/// Runs a camera source on its own thread: every frame goes to the consumer on that thread
/// (the rig loop, with no queue in between), and a copy at most `displayHz` times a second to
/// frameReady() for the screen. Stops on request, at the end of a file, or on a device error
/// (failed() says which).
class Camera : public QObject {
    Q_OBJECT
  public:
    explicit Camera(QObject* parent = nullptr);
    /// Stops and joins the thread (bounded wait).
    ~Camera() override;

    /// Called on the camera thread for every frame. Set before start().
    void setConsumer(std::function<void(const CameraFrame&)> consumer);
    /// Opens and runs the source (ownership shared with the thread).
    void start(std::shared_ptr<CameraSource> source, double displayHz = 30.0);
    /// Asks the thread to stop after the frame under way. Any thread.
    void stop();
    bool isRunning() const { return running_.load(); }
    long long framesDelivered() const { return frames_.load(); }
    /// The open source's frame rate [1/s] (the device's or file's own, else the one asked
    /// for); 0 until a source is open.
    double framesPerSecond() const { return fps_.load(); }

  signals:
    void frameReady(const prisca::devices::CameraFrame& frame);
    void failed(const QString& message);
    /// The source came to its end (a video file played through): no fault; finished() follows.
    void ended(const QString& message);
    void finished();

  private:
    void run(std::shared_ptr<CameraSource> source, double displayHz);

    QThread thread_;
    QObject* context_;  ///< lives on thread_; run() is queued to it
    std::function<void(const CameraFrame&)> consumer_;
    std::atomic<bool> stopRequested_{false};
    std::atomic<bool> running_{false};
    std::atomic<long long> frames_{0};
    std::atomic<double> fps_{0.0};
};

}  // namespace prisca::devices

Q_DECLARE_METATYPE(prisca::devices::CameraFrame)
