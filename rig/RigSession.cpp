#include "rig/RigSession.h"
#include "rig/RigSession_p.h"

#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"
#include "devices/LedTracker.h"
#include "devices/ProcessFailsafe.h"
#include "devices/RigLoop.h"
#include "devices/ThreadHandOff.h"
#include "rigsim/VirtualCar.h"
#include "sim/demonstrations/DemonstrationRecorder.h"
#include "sim/episodes/EpisodeRunner.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMetaObject>

#include <chrono>
#include <thread>
#include <utility>

namespace prisca::rig {

RigSession::RigSession(QObject* parent)
    : QObject(parent), worker_(new QObject), loop_(std::make_unique<Loop>()) {
    qRegisterMetaType<RigTrialResult>();
    qRegisterMetaType<RigRecording>();
    qRegisterMetaType<LatencyMeasurement>();
    qRegisterMetaType<std::optional<devices::PlanarPose>>();
    workerThread_.setObjectName(QStringLiteral("prisca-rig"));
    worker_->moveToThread(&workerThread_);
    devices::markThreadEnd(workerThread_);
    workerThread_.start();

    // Until the operator calibrates, the synthetic camera's own calibration.
    setCalibration(devices::syntheticCeilingCamera());
    camera_.setConsumer([this](const devices::CameraFrame& frame) { onFrame(frame); });
    connect(&camera_, &devices::Camera::frameReady, this,
            [this](const devices::CameraFrame& frame) { emit frameReady(frame, lastPose()); });
    connect(&camera_, &devices::Camera::failed, this, &RigSession::cameraFailed);
    connect(&camera_, &devices::Camera::ended, this, &RigSession::cameraEnded);
    connect(&camera_, &devices::Camera::finished, this, [this] {
        {
            std::lock_guard<std::mutex> lock(poseMutex_);
            pose_.reset();  // no camera, no pose
        }
        emit cameraRunningChanged(false);
    });
    connect(&link_, &devices::TransmitterLink::statusChanged, this,
            [this](const devices::LinkStatus& status) {
                linkStatus_ = status;
                emit linkStatusChanged(status);
            });
}

RigSession::~RigSession() {
    camera_.stop();
    // The camera thread calls onFrame(): it must be done before anything here goes.
    const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::milliseconds(kShutdownWaitMs);
    while (camera_.isRunning() && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    {
        std::lock_guard<std::mutex> lock(mutex_);
        loop_->running = false;
        loop_->recording = false;
    }
    // The samples already handed over are written, then the stream is flushed and closed: a
    // recording in progress stays on disk (its crash copy), nobody is told.
    QMetaObject::invokeMethod(
        worker_,
        [this] {
            recorder_.reset();  // flushed and closed; its ".part" file stays
        },
        Qt::BlockingQueuedConnection);
    devices::endWorkerThread(workerThread_, worker_, kShutdownWaitMs);
    link_.stop();
}

bool RigSession::startCamera(const CameraRequest& request, QString* error) {
    if (camera_.isRunning()) {
        return true;
    }
    std::unique_ptr<devices::CameraSource> source;
    switch (request.source) {
        case CameraRequest::Source::Virtual: {
            if (!(request.virtualFps > 0.0)) {
                if (error) {
                    *error = tr("The virtual camera needs a frame rate above zero.");
                }
                return false;
            }
            if (!car_) {
                auto car = std::make_shared<rigsim::VirtualCar>(devices::RcProtocol::Crsf,
                                                                devices::ChannelMap::car(), 1,
                                                                request.virtualPerturbation);
                if (!car->open(error)) {
                    return false;
                }
                car_ = car;
            }
            if (car_->plant() != request.virtualPlant) {
                try {
                    car_->usePlant(request.virtualPlant);
                } catch (const std::exception& e) {
                    if (error) {
                        *error = QString::fromUtf8(e.what());
                    }
                    return false;
                }
            }
            car_->reset(1);
            try {
                car_->setCameraDelay(request.virtualCameraDelay);
            } catch (const std::exception& e) {
                if (error) {
                    *error = QString::fromUtf8(e.what());
                }
                return false;
            }
            source = devices::makeSyntheticSource(
                [car = car_](double t) {
                    return std::optional<devices::PlanarPose>(car->poseAt(t));
                },
                devices::syntheticCeilingCamera(), {}, request.virtualFps);
            break;
        }
        case CameraRequest::Source::Device:
            source = devices::makeV4l2Source(request.device);
            break;
        case CameraRequest::Source::Video:
            source = devices::makeVideoFileSource(request.videoPath, true);
            break;
    }
    cameraSource_ = request.source;
    injectedCameraDelay_ =
        request.source == CameraRequest::Source::Virtual ? request.virtualCameraDelay : 0.0;
    frameWidth_.store(0);
    frameHeight_.store(0);
    camera_.start(std::shared_ptr<devices::CameraSource>(std::move(source)));
    emit cameraRunningChanged(true);
    return true;
}

void RigSession::stopCamera() {
    camera_.stop();
}

QString RigSession::virtualPort() const {
    return car_ ? car_->portPath() : QString();
}

long long RigSession::virtualFramesDecoded() const {
    return car_ ? car_->framesDecoded() : -1;
}

std::optional<Eigen::VectorXd> RigSession::virtualReceivedCommand() const {
    if (!car_) {
        return std::nullopt;
    }
    return car_->receivedCommand();
}

std::optional<devices::PlanarPose> RigSession::lastPose() const {
    std::lock_guard<std::mutex> lock(poseMutex_);
    return pose_;
}

void RigSession::setCalibration(const devices::FloorCalibration& calibration) {
    calibration_ = calibration;
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->calibration = calibration;
    loop_->stale = true;  // the loop tracks with its own copy: rebuilt for the next trial
}

void RigSession::setGeofence(const devices::Geofence& fence) {
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->fence = fence;
    if (loop_->loop) {
        loop_->loop->setGeofence(fence);  // at once, in a trial under way too
    }
}

devices::Geofence RigSession::geofence() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->fence;
}

bool RigSession::loadCalibration(const QString& path, QString* error) {
    const auto loaded = devices::FloorCalibration::load(path, error);
    if (!loaded) {
        return false;
    }
    setCalibration(*loaded);
    return true;
}

bool RigSession::saveCalibration(const QString& path, QString* error) const {
    return calibration_.save(path, error);
}

void RigSession::connectLink(const devices::LinkSettings& settings) {
    link_.start(settings);
}

void RigSession::disconnectLink() {
    link_.stop();
}

void RigSession::setChannels(const devices::ChannelMap& channels) {
    channels_ = channels;
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->stale = true;
}

QString RigSession::notReady() const {
    if (!camera_.isRunning()) {
        return tr("Start the camera first.");
    }
    if (!linkStatus_.connected) {
        return tr("Connect the transmitter link first.");
    }
    return {};
}

bool RigSession::startRecording(const sim::PlantInfo& plant, const QString& path, QString* error) {
    auto fail = [error](const QString& why) {
        if (error) {
            *error = why;
        }
        return false;
    };
    if (const QString missing = notReady(); !missing.isEmpty()) {
        return fail(missing);
    }
    const double fps = camera_.framesPerSecond();
    if (!(fps > 0.0)) {
        return fail(tr("The camera has not opened yet; try again in a moment."));
    }
    if (trialRunning() || recording()) {
        return fail(tr("A trial or a recording is already running."));
    }
    // The header of the demonstration format, on disk at once; rows follow as frames come,
    // interpolated from the frames' own times onto the camera's frame period.
    auto recorder = std::make_unique<Recorder>();
    core::Demonstration header = sim::DemonstrationRecorder(plant, 1.0 / fps).demonstration();
    header.metadata.insert(QStringLiteral("source"), QStringLiteral("recorded on the rig"));
    QString openError;
    if (!recorder->stream.open(path, header, plant.angleIndices, &openError)) {
        return fail(tr("Cannot record to %1").arg(openError));
    }
    writtenSeconds_.store(-1.0);
    onWorker([this, r = recorder.release()] {
        recorder_.reset(r);
        writtenSeconds_.store(-1.0);  // after any sample of an earlier take still queued
    });
    {
        std::lock_guard<std::mutex> lock(mutex_);
        Loop& l = *loop_;
        l.firstFrameNs = -1;
        l.lastTime = -1.0;
        l.estimator.reset();
        l.driveAction = Eigen::VectorXd::Zero(plant.actionDimension());
        l.recording = true;
    }
    if (car_) {
        car_->requestReset(1);
    }
    return true;
}

void RigSession::setDriveCommand(const Eigen::VectorXd& action) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!loop_->recording) {
            return;
        }
        loop_->driveAction = action;
    }
    link_.setCommand(channels_.command(action));
}

bool RigSession::recording() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->recording;
}

double RigSession::recordedSeconds() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->recording ? writtenSeconds_.load() : -1.0;
}

void RigSession::stopRecording() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!loop_->recording) {
            return;
        }
        loop_->recording = false;
    }
    link_.setCommand(channels_.failsafe());  // neutral now; stale (failsafe) after that
    link_.setPoseLost(false);
    onWorker([this] {
        if (!recorder_) {
            return;
        }
        std::unique_ptr<Recorder> r = std::move(recorder_);
        RigRecording done;
        done.path = r->stream.fileName();
        if (r->stream.rows() < 2) {
            r->stream.abandon();
            done.error = tr("Nothing recorded (no pose seen).");
            emit recordingFinished(done);
            return;
        }
        // Rows at the camera's frame period, interpolated from the frames' own times.
        core::Demonstration demo = r->stream.demonstration();
        QString writeError;
        if (!r->stream.finish(&writeError)) {
            done.error = tr("The rig recording could not be saved: %1 (the take so far is in %2)")
                             .arg(writeError, core::DemonstrationStream::partPath(done.path));
        } else {
            done.demonstration = std::make_shared<core::Demonstration>(std::move(demo));
        }
        emit recordingFinished(done);
    });
}

void RigSession::emergencyStop() {
    link_.emergencyStop();  // failsafe from the link's next frame, latched
    stopRecording();
    stopTrial();
    cancelLatencyMeasurement();
}

bool RigSession::measureLatency(const devices::LatencyProbeSettings& settings, QString* error) {
    const auto fail = [error](const QString& message) {
        if (error) {
            *error = message;
        }
        return false;
    };
    if (const QString missing = notReady(); !missing.isEmpty()) {
        return fail(missing);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    Loop& l = *loop_;
    if (l.running) {
        return fail(tr("A trial is running."));
    }
    if (l.recording) {
        return fail(tr("Stop driving first."));
    }
    if (l.probe) {
        return fail(tr("The latency is being measured already."));
    }
    l.probe.emplace(settings);
    return true;
}

void RigSession::cancelLatencyMeasurement() {
    std::optional<LatencyMeasurement> cancelled;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (loop_->probe) {
            loop_->probe.reset();
            cancelled = LatencyMeasurement{};
            cancelled->error = tr("cancelled");
        }
    }
    if (cancelled) {
        link_.setCommand(channels_.command(Eigen::VectorXd::Zero(2)));  // the step ends
        emit latencyMeasured(*cancelled);
    }
}

bool RigSession::measuringLatency() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->probe.has_value();
}

void RigSession::setBundles(const QString& parent, double videoFps) {
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->bundleParent = parent;
    loop_->bundleFps = std::max(0.0, videoFps);
}

QString RigSession::bundleParent() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->bundleParent;
}

void RigSession::setLoopLatency(std::optional<double> seconds, LoopLatencySource source) {
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->loopLatency = seconds;
    loop_->loopLatencySource = seconds ? source : LoopLatencySource::Assumed;
    loop_->stale = true;  // the compensation is set when the loop is built
}

LoopLatencySource RigSession::loopLatencySource() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->loopLatencySource;
}

std::optional<double> RigSession::loopLatency() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->loopLatency;
}

void RigSession::resetEmergencyStop() {
    link_.resetEmergencyStop();
}

}  // namespace prisca::rig
