#include "rig/RigSession.h"

#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"
#include "devices/LedTracker.h"
#include "devices/ProcessFailsafe.h"
#include "devices/RigLoop.h"
#include "devices/ThreadHandOff.h"
#include "rigsim/VirtualCar.h"
#include "sim/DemonstrationRecorder.h"
#include "sim/EpisodeRunner.h"

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

namespace {
constexpr int kShutdownWaitMs = 3000;
}

/// What the camera thread and the commands share (under mutex_).
struct RigSession::Loop {
    devices::FloorCalibration calibration;       ///< the tracker's, outside trials
    devices::Geofence fence;                     ///< every trial's (RigLoop::setGeofence)
    std::optional<devices::LatencyProbe> probe;  ///< a latency measurement under way
    std::optional<double> loopLatency;           ///< measured [s], for the compensation
    LatencySource latencySource = LatencySource::Assumed;
    QString bundleParent;            ///< where trial bundles go (empty: none)
    double bundleFps = 10.0;         ///< their video's frame rate
    double lastBundleFrameT = -1.0;  ///< the trial's newest frame stored [s]
    devices::LedTracker tracker;
    // The closed loop, kept from trial to trial for one method.
    std::unique_ptr<devices::RigLoop> loop;
    QString method;
    bool poseFilter = false;  ///< the loop estimates with the pose filter
    bool stale = false;  ///< the calibration or channels changed: rebuild before the next trial
    int trials = 0;
    // The trial under way.
    bool running = false;
    double trialSeconds = 0.0;
    std::int64_t trialStartNs = -1;  ///< its first frame; -1 before it
    /// When the trial was started: a frame taken before it (the virtual car not yet back at its
    /// start, or a real car's stale pose still in the pipeline) does not drive the loop.
    std::int64_t startedNs = 0;
    std::int64_t lastFrameNs = -1;
    long long frames = 0;
    long long framesWithPose = 0;
    std::vector<double> latencyMs;
    std::optional<devices::PlanarPose> lastTrackedPose;
    sim::PlantInfo plant;
    std::shared_ptr<const core::Demonstration> demonstration;
    // Recording by driving.
    bool recording = false;
    Eigen::VectorXd driveAction;
    devices::PoseStateEstimator estimator;
    std::int64_t firstFrameNs = -1;  ///< the recording's first frame with a pose
    double lastTime = -1.0;          ///< its newest sample's time [s]
};

/// The take being recorded, on the worker thread only: the one streaming recorder (the
/// window's too), fed with the frames' own times.
struct RigSession::Recorder {
    core::DemonstrationStream stream;
};

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

template <typename F>
void RigSession::onWorker(F&& f) {
    devices::postTo(worker_, std::forward<F>(f));
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

PreTrialCheck RigSession::preTrialCheck(const sim::Task& task,
                                        const sim::MethodSpec& method) const {
    PreTrialInputs in;
    in.cameraRunning = camera_.isRunning();
    in.virtualCamera = cameraSource_ == CameraRequest::Source::Virtual;
    in.carSeen = in.cameraRunning && (lastPose().has_value() || car_ != nullptr);
    in.frameSize = cv::Size(frameWidth_.load(), frameHeight_.load());
    in.calibration = calibration_;
    in.calibrationIsVirtualRigs =
        calibration_.toJson() == devices::syntheticCeilingCamera().toJson();
    in.link = linkStatus_;
    in.injectedCameraDelay = injectedCameraDelay_;
    in.emergencyLatched = link_.emergencyLatched();
    in.failsafeHeld = devices::processfailsafe::held();
    {
        std::lock_guard<std::mutex> lock(mutex_);
        in.loopLatency = loop_->loopLatency;
        in.latencySource = loop_->latencySource;
        in.fence = loop_->fence;
    }
    in.demonstration = task.demonstration;
    in.plant = task.profile.info;
    in.methodLabel = method.label;
    in.methodSimulationOnly = method.simulationOnly;
    in.methodTrainsOffline = method.trainsOffline();
    in.methodPlansThroughModel = method.plansThroughModel;
    in.modelIdentified = task.profile.mpcModel != nullptr;
    return evaluatePreTrialCheck(in);
}

bool RigSession::putVirtualCarBack(QString* error) {
    if (!car_) {
        if (error) {
            *error = tr("Only the virtual rig's car can be put back; carry a real one.");
        }
        return false;
    }
    if (trialRunning()) {
        if (error) {
            *error = tr("A trial is running: stop it first.");
        }
        return false;
    }
    std::uint64_t seed = 1;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        seed = static_cast<std::uint64_t>(loop_->trials + 1);
    }
    car_->requestReset(seed);
    return true;
}

bool RigSession::startTrial(const TrialRequest& request, QString* error) {
    auto fail = [error](const QString& why) {
        if (error) {
            *error = why;
        }
        return false;
    };
    // The pre-trial check first: a trial that cannot end well does not start.
    if (!request.setup) {
        return fail(tr("The rig needs a demonstration of a planar vehicle."));
    }
    if (const PreTrialCheck check = preTrialCheck(request.setup->task(), request.setup->method());
        !check.ready()) {
        return fail(check.missingDetails());
    }
    std::lock_guard<std::mutex> lock(mutex_);
    Loop& l = *loop_;
    if (l.running) {
        return fail(tr("A trial is already running."));
    }
    if (l.probe) {
        return fail(tr("The latency is being measured."));
    }
    if (link_.emergencyLatched()) {
        return fail(emergencyProblem(devices::processfailsafe::held()));
    }
    if (l.recording) {
        return fail(tr("Stop driving first."));
    }
    // One loop per method: learners keep what they learnt from trial to trial (warm start).
    const sim::RunSetup& setup = *request.setup;
    const QString& method = setup.method().id;
    const bool poseFilter = setup.settings().poseFilter;  // (its mode is fixed per method loop)
    if (!l.loop || l.stale || l.method != method || l.poseFilter != poseFilter) {
        std::unique_ptr<core::Controller> controller;
        try {
            controller = setup.makeUntrainedController();
        } catch (const std::exception& e) {
            return fail(tr("%1 could not be set up: %2").arg(method, QString::fromUtf8(e.what())));
        }
        // Latency as in simulation (EpisodeStepper follows the same rule): the loop's measured
        // latency where there is one, else the sensor latency the profile assumes for the
        // camera; compensated by the controller only where the tuning says so and the pose
        // filter does not predict across it already (never twice).
        const double dt = setup.task().demonstration->dt;
        const sim::EpisodeSettings episode =
            sim::withMeasuredLatency(setup.episode(), l.loopLatency, dt);
        controller->setLatencyCompensation(episode.compensatedLatencySteps());
        l.loop = std::make_unique<devices::RigLoop>(l.calibration, devices::TrackerSettings{},
                                                    std::move(controller), channels_, link_);
        l.loop->setLostTrackDistance(setup.profile().lostTrackDistance);
        if (poseFilter) {
            // Pose-only frames, as old as the loop's latency (above); with the filter
            // predicting, the controller was told latency 0 (compensatedLatencySteps).
            try {
                l.loop->usePoseFilter(episode.poseFilterParameters,
                                      episode.measurement.latencySteps * dt,
                                      episode.poseFilterPredicts);
            } catch (const std::exception& e) {
                l.loop.reset();
                return fail(
                    tr("%1 could not be set up: %2").arg(method, QString::fromUtf8(e.what())));
            }
        }
        l.poseFilter = poseFilter;
        l.method = method;
        l.stale = false;
        l.trials = 0;
    }
    l.loop->setGeofence(l.fence);
    l.loop->startTrial(sim::resetForTrial(l.trials));
    link_.clearFault();  // the last trial's fault or fence breach ended that trial, not this one
    l.lastBundleFrameT = -1.0;
    if (!l.bundleParent.isEmpty()) {
        QJsonObject header{
            {"kind", QStringLiteral("rig")},
            {"method", method},
            {"plant", setup.profile().info.name},
            {"trial", l.trials + 1},
            {"seed", static_cast<double>(request.virtualSeed)},
            {"started", QDateTime::currentDateTime().toString(Qt::ISODate)},
            {"calibration", QJsonDocument::fromJson(l.calibration.toJson()).object()},
            {"fence", l.fence.toJson()},
            {"videoFps", l.bundleFps}};
        if (!request.session.isEmpty()) {
            header.insert("session", request.session);
        }
        if (l.loopLatency) {
            header.insert("loopLatencyMs", *l.loopLatency * 1000.0);
        }
        const QString folder =
            QDir(l.bundleParent)
                .filePath(QStringLiteral("trial-%1-%2-%3")
                              .arg(QDateTime::currentDateTime().toString(
                                  QStringLiteral("yyyyMMdd-hhmmss")))
                              .arg(l.trials + 1)
                              .arg(QCoreApplication::applicationPid()));  // two rigs on one folder
                                                                          // never collide
        onWorker([this, folder, header, demo = setup.task().demonstration] {
            bundle_ = std::make_unique<TrialBundleWriter>();
            QString error;
            if (!bundle_->open(folder, header, *demo, &error)) {
                bundle_.reset();
                emit bundleSaved(folder, error);
            }
        });
    }
    if (car_) {  // back at the start
        car_->requestReset(request.virtualSeed != 0 ? request.virtualSeed
                                                    : static_cast<std::uint64_t>(l.trials + 1));
    }
    const core::Demonstration& demo = *setup.task().demonstration;
    l.trialSeconds = demo.length() * demo.dt + setup.profile().settleTime;
    l.trialStartNs = -1;
    l.startedNs = devices::steadyNowNs();  // after the virtual car's reset was asked for
    l.lastFrameNs = -1;
    l.frames = 0;
    l.framesWithPose = 0;
    l.latencyMs.clear();
    l.lastTrackedPose.reset();
    l.plant = setup.profile().info;
    l.demonstration = setup.task().demonstration;
    l.running = true;
    ++l.trials;
    return true;
}

int RigSession::trialNumber() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->trials;
}

bool RigSession::trialRunning() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->running;
}

RigTrialResult RigSession::finishTrialLocked(bool stopped, bool fault, const QString& reason) {
    Loop& l = *loop_;
    l.running = false;
    // Outside a trial the pose drives nothing: the link's failsafe is the stale command's now,
    // not "pose lost" from the trial's last frames.
    link_.setPoseLost(false);
    RigTrialResult result;
    result.trial = l.trials;
    result.stopped = stopped;
    result.fault = fault;
    result.reason = reason;
    result.seconds = l.trialStartNs >= 0 ? (l.lastFrameNs - l.trialStartNs) * 1e-9 : 0.0;
    result.frames = l.frames;
    result.framesWithPose = l.framesWithPose;
    result.latencyMs = std::move(l.latencyMs);
    l.latencyMs.clear();
    if (l.loop) {
        result.controllerNote = l.loop->controller().trialNote();
    }
    if (l.lastTrackedPose && l.demonstration && l.plant.pose) {
        result.parked = sim::parkingError(l.plant, *l.demonstration, l.lastTrackedPose->x,
                                          l.lastTrackedPose->y, l.lastTrackedPose->heading);
    }
    if (!l.bundleParent.isEmpty()) {
        QJsonObject r{{"stopped", stopped},
                      {"failsafe", fault},
                      {"reason", reason},
                      {"seconds", result.seconds},
                      {"frames", static_cast<double>(result.frames)},
                      {"framesWithPose", static_cast<double>(result.framesWithPose)}};
        if (!result.controllerNote.isEmpty()) {
            r.insert("controllerNote", result.controllerNote);
        }
        if (result.parked) {
            r.insert("finalPositionErrorCm", result.parked->position * 100.0);
            r.insert("finalHeadingErrorDeg", result.parked->heading * 180.0 / M_PI);
        }
        onWorker([this, r] {
            if (bundle_) {
                QString error;
                bundle_->finish(r, &error);
                const QString folder = bundle_->folder();
                bundle_.reset();
                emit bundleSaved(folder, error);
            }
        });
    }
    return result;
}

void RigSession::stopTrial() {
    std::optional<RigTrialResult> result;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (loop_->running) {
            result = finishTrialLocked(true, false);
        }
    }
    if (result) {
        emit trialFinished(*result);
    }
}

void RigSession::onFrame(const devices::CameraFrame& frame) {
    std::optional<devices::PlanarPose> pose;
    std::optional<RigTrialResult> finished;
    std::optional<LatencyMeasurement> measured;
    frameWidth_.store(frame.image.cols);
    frameHeight_.store(frame.image.rows);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        Loop& l = *loop_;
        if (l.probe) {
            pose = l.tracker.track(frame.image, l.calibration).pose;
            const Eigen::VectorXd action = l.probe->onFrame(frame.steadyNs, pose);
            link_.setPoseLost(false);
            link_.setCommand(channels_.command(action));
            if (l.probe->finished()) {
                LatencyMeasurement m;
                m.error = QString::fromStdString(l.probe->failure());
                if (m.error.isEmpty()) {
                    for (const devices::LatencyStep& step : l.probe->steps()) {
                        m.stepsSeconds.push_back(step.latency);
                    }
                    m.median = l.probe->medianSeconds();
                    m.min = l.probe->minSeconds();
                    m.max = l.probe->maxSeconds();
                    m.spread = l.probe->spreadSeconds();
                    // The trials compensate what was measured, whoever shows it.
                    l.loopLatency = m.median;
                    l.latencySource = LatencySource::Measured;
                    l.stale = true;
                }
                l.probe.reset();
                measured = m;
            }
        } else if (l.running && l.loop && frame.steadyNs >= l.startedNs) {
            // The closed loop: pose -> controller -> link, on this thread, no queue between.
            const devices::RigStep step = l.loop->onFrame(frame);
            pose = step.pose;
            ++l.frames;
            if (pose) {
                ++l.framesWithPose;
                l.lastTrackedPose = pose;
                l.latencyMs.push_back((step.commandNs - step.frameNs) * 1e-6);
            }
            if (l.trialStartNs < 0) {
                l.trialStartNs = frame.steadyNs;
            }
            l.lastFrameNs = frame.steadyNs;
            if (!l.bundleParent.isEmpty()) {
                BundleSample sample;
                sample.t = (frame.steadyNs - l.trialStartNs) * 1e-9;
                sample.frame = frame.index;
                sample.found = pose.has_value();
                if (pose) {
                    sample.x = pose->x;
                    sample.y = pose->y;
                    sample.psi = pose->heading;
                    sample.state.assign(step.state.data(), step.state.data() + step.state.size());
                }
                if (!step.fault && step.action.size() > 0) {
                    sample.action.assign(step.action.data(),
                                         step.action.data() + step.action.size());
                }
                sample.failsafe = step.fault || !pose;
                cv::Mat image;
                if (l.bundleFps > 0.0 &&
                    (l.lastBundleFrameT < 0.0 ||
                     sample.t - l.lastBundleFrameT >= 1.0 / l.bundleFps - 1e-6)) {
                    l.lastBundleFrameT = sample.t;
                    image = frame.image.clone();
                }
                onWorker([this, sample = std::move(sample), image] {
                    if (bundle_) {
                        bundle_->append(sample);
                        if (!image.empty()) {
                            bundle_->addFrame(sample.frame, image);
                        }
                    }
                });
            }
            // A trial lasts its length by the camera's own frame clock, whatever the frame rate.
            const double elapsed = (frame.steadyNs - l.trialStartNs) * 1e-9;
            if (elapsed >= l.trialSeconds || step.fault) {
                finished = finishTrialLocked(false, step.fault, step.stopReason);
            } else if (devices::processfailsafe::held()) {
                // The process was stopped and continued: the link holds failsafe, and a trial
                // that lost its time cannot go on (the next one needs E-STOP reset first).
                finished = finishTrialLocked(
                    true, true, tr("the process was stopped and continued: failsafe held"));
            }
        } else {
            pose = l.tracker.track(frame.image, l.calibration).pose;
            if (l.recording) {
                if (!pose) {
                    // No pose, no command: the car must not drive blind.
                    link_.setPoseLost(true);
                    l.estimator.reset();
                } else {
                    link_.setPoseLost(false);
                    const Eigen::VectorXd state = l.estimator.update(*pose, frame.steadyNs);
                    if (l.firstFrameNs < 0) {
                        l.firstFrameNs = frame.steadyNs;
                    }
                    // The frame's own time: frames come at the camera's rate, some are dropped.
                    const double t = (frame.steadyNs - l.firstFrameNs) * 1e-9;
                    if (l.lastTime < 0.0 || t > l.lastTime) {  // else out of order: no sample
                        l.lastTime = t;
                        onWorker([this, t, state, action = l.driveAction] {
                            if (recorder_) {
                                QString ignored;  // retried at the next flush; told at the end
                                recorder_->stream.append(t, state, action, &ignored);
                                writtenSeconds_.store(t);
                            }
                        });
                    }
                }
            }
        }
    }
    {
        std::lock_guard<std::mutex> lock(poseMutex_);
        pose_ = pose;
    }
    if (finished) {
        emit trialFinished(*finished);
    }
    if (measured) {
        emit latencyMeasured(*measured);
    }
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

void RigSession::setLoopLatency(std::optional<double> seconds, LatencySource source) {
    std::lock_guard<std::mutex> lock(mutex_);
    loop_->loopLatency = seconds;
    loop_->latencySource = seconds ? source : LatencySource::Assumed;
    loop_->stale = true;  // the compensation is set when the loop is built
}

LatencySource RigSession::loopLatencySource() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->latencySource;
}

std::optional<double> RigSession::loopLatency() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return loop_->loopLatency;
}

void RigSession::resetEmergencyStop() {
    link_.resetEmergencyStop();
}

QString trialSentence(const RigTrialResult& result) {
    QString sentence;
    if (result.parked) {
        sentence = RigSession::tr("Trial %1: parked %2 cm from the lot, heading off by %3°")
                       .arg(result.trial)
                       .arg(result.parked->position * 100.0, 0, 'f', 1)
                       .arg(result.parked->heading * 180.0 / core::kPi, 0, 'f', 1);
    } else {
        sentence = RigSession::tr("Trial %1 ended without a pose").arg(result.trial);
    }
    if (result.stopped) {
        sentence += RigSession::tr(" (stopped after %1 s)").arg(result.seconds, 0, 'f', 1);
    } else if (result.fault) {
        sentence += result.reason.isEmpty()
                        ? RigSession::tr(" (failsafe after %1 s)").arg(result.seconds, 0, 'f', 1)
                        : RigSession::tr(" (failsafe after %1 s: %2)")
                              .arg(result.seconds, 0, 'f', 1)
                              .arg(result.reason);
    }
    if (!result.controllerNote.isEmpty()) {
        //: A rig trial's result, then what the method says of it (which law drove, and why).
        sentence = RigSession::tr("%1; %2").arg(sentence, result.controllerNote);
    }
    return sentence;
}

}  // namespace prisca::rig
