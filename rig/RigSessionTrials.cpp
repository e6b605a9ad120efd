// RigSession's trials: the pre-trial check, starting, finishing and stopping a trial, and the
// camera's frames driving the loop and the recording (the rest: RigSession.cpp).
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
#include "sim/planning/MpcController.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMetaObject>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <utility>

namespace prisca::rig {

namespace {

/// Whether the car rests: tracked over the whole of the last kRestWindowSeconds, within
/// kRestDistance and kRestTurn of its newest pose all along.
bool resting(const std::deque<std::pair<std::int64_t, devices::PlanarPose>>& poses) {
    if (poses.empty() ||
        (poses.back().first - poses.front().first) * 1e-9 < 0.9 * kRestWindowSeconds) {
        return false;
    }
    const devices::PlanarPose& now = poses.back().second;
    return std::all_of(poses.begin(), poses.end(), [&](const auto& p) {
        return std::hypot(p.second.x - now.x, p.second.y - now.y) < kRestDistance &&
               std::abs(std::remainder(p.second.heading - now.heading, 2.0 * core::kPi)) <
                   kRestTurn;
    });
}

}  // namespace

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
        in.loopLatencySource = loop_->loopLatencySource;
        in.fence = loop_->fence;
    }
    in.demonstration = task.demonstration;
    in.plant = task.profile.info;
    in.methodLabel = method.label;
    in.methodSimulationOnly = method.simulationOnly;
    in.methodTrainsOffline = method.trainsOffline();
    // mpc needs the car's model only for a demonstration it plans through: one sliding less
    // than mpc.plan-slide is the feedback law's from the start (MpcController).
    in.methodPlansThroughModel =
        method.plansThroughModel &&
        (!task.demonstration ||
         sim::slideWorthPlanning(*task.demonstration, task.profile.info.bodyVelocity,
                                 task.profile.mpc));
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
            sim::withLoopLatency(setup.episode(), l.loopLatency, dt);
        controller->setLoopLatencySteps(episode.compensatedLoopLatencySteps());
        l.loop = std::make_unique<devices::RigLoop>(l.calibration, devices::TrackerSettings{},
                                                    std::move(controller), channels_, link_);
        l.loop->setLostTrackDistance(setup.profile().lostTrackDistance);
        if (poseFilter) {
            // Pose-only frames, as old as the loop's latency (above); with the filter
            // predicting, the controller was told latency 0 (compensatedLoopLatencySteps).
            try {
                l.loop->usePoseFilter(episode.poseFilterParameters,
                                      episode.measurement.loopLatencySteps * dt,
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
    l.loopLatencyMs.clear();
    l.lastTrackedPose.reset();
    l.recentPoses.clear();
    l.runOutLimit = setup.profile().runOutLimit;
    l.runOutStartNs = -1;
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
    result.runOutSeconds =
        l.runOutStartNs >= 0 ? std::max(0.0, (l.lastFrameNs - l.runOutStartNs) * 1e-9) : 0.0;
    result.frames = l.frames;
    result.framesWithPose = l.framesWithPose;
    result.loopLatencyMs = std::move(l.loopLatencyMs);
    l.loopLatencyMs.clear();
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
                      {"runOutSeconds", result.runOutSeconds},
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
                    l.loopLatencySource = LoopLatencySource::Measured;
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
                if (l.runOutStartNs < 0) {  // a run-out's command is no controller's
                    l.loopLatencyMs.push_back((step.commandNs - step.frameNs) * 1e-6);
                }
                l.recentPoses.emplace_back(frame.steadyNs, *pose);
                while (l.recentPoses.front().first <
                       frame.steadyNs - static_cast<std::int64_t>(kRestWindowSeconds * 1e9)) {
                    l.recentPoses.pop_front();
                }
            } else {
                l.recentPoses.clear();  // a gap: rest is seen afresh
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
            if (step.fault) {
                finished = finishTrialLocked(false, true, step.stopReason);
            } else if (elapsed >= l.trialSeconds && l.runOutStartNs < 0 && l.runOutLimit > 0.0 &&
                       !resting(l.recentPoses)) {
                // Still moving: the car runs out in neutral and is scored where it rests, as
                // in simulation (sim::EpisodeSettings::runOutLimit).
                l.runOutStartNs = frame.steadyNs;
                l.loop->runOut();
            } else if (elapsed >= l.trialSeconds &&
                       (l.runOutStartNs < 0 || resting(l.recentPoses) ||
                        (frame.steadyNs - l.runOutStartNs) * 1e-9 >= l.runOutLimit)) {
                finished = finishTrialLocked(false, false, QString());
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
    if (result.runOutSeconds > 0.0) {
        //: The car still moved when the trial's time was up and rolled on in neutral.
        sentence += RigSession::tr(" after running out %1 s in neutral")
                        .arg(result.runOutSeconds, 0, 'f', 1);
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
