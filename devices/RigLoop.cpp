#include "devices/RigLoop.h"

#include "core/DeviationModel.h"
#include "devices/TransmitterLink.h"

#include <QLoggingCategory>

#include <cmath>
#include <exception>
#include <stdexcept>

Q_LOGGING_CATEGORY(lcRig, "prisca.devices.rig")

namespace prisca::devices {

Eigen::VectorXd PoseStateEstimator::update(const PlanarPose& pose, std::int64_t steadyNs) {
    if (last_) {
        const double dt = (steadyNs - lastNs_) * 1e-9;
        if (dt > 1e-4 && dt < 0.5) {
            const double dx = (pose.x - last_->x) / dt;
            const double dy = (pose.y - last_->y) / dt;
            const double r = std::remainder(pose.heading - last_->heading, 2.0 * core::kPi) / dt;
            // Body frame at the mid-heading of the interval.
            const double mid = last_->heading +
                               0.5 * std::remainder(pose.heading - last_->heading, 2.0 * core::kPi);
            const double c = std::cos(mid), s = std::sin(mid);
            const Eigen::Vector3d measured(c * dx + s * dy, -s * dx + c * dy, r);
            rates_ += smoothing_ * (measured - rates_);
        } else if (dt >= 0.5) {
            rates_.setZero();  // a long gap: start the rates afresh
        }
    }
    last_ = pose;
    lastNs_ = steadyNs;
    Eigen::VectorXd state(6);
    state << pose.x, pose.y, pose.heading, rates_[0], rates_[1], rates_[2];
    return state;
}

RigLoop::RigLoop(FloorCalibration calibration, TrackerSettings tracker,
                 std::unique_ptr<core::Controller> controller, ChannelMap channels,
                 TransmitterLink& link)
    : calibration_(std::move(calibration)),
      tracker_(tracker),
      controller_(std::move(controller)),
      channels_(std::move(channels)),
      link_(link) {}

void RigLoop::startTrial(core::ResetMode mode) {
    controller_->reset(mode);
    guard_.reset();
    tripped_.clear();
    fenceTripped_ = false;
    runningOut_ = false;
    lostSinceNs_ = -1;
    estimator_.reset();
    if (filter_) {
        filter_->reset();
    }
    tracker_.reset();
}

void RigLoop::usePoseFilter(std::optional<core::PoseFilterParameters> parameters,
                            double cameraLatencySeconds, bool predict) {
    if (!parameters) {
        filter_.reset();
        return;
    }
    if (!(cameraLatencySeconds >= 0.0)) {
        throw std::invalid_argument("RigLoop: camera latency must be >= 0 s");
    }
    core::PoseFilterParameters p = *parameters;
    p.stateDimension = 6;
    p.pose = core::PlanarPoseIndices{};
    p.velocity = core::BodyVelocityIndices{};
    p.measurePoseOnly();
    if (p.measurementStd.size() != 6) {
        p.measurementStd = core::PoseFilterParameters{}.measurementStd;
    }
    filter_.emplace(p, p.inputGain.size() ? static_cast<int>(p.inputGain.cols()) : 2);
    cameraLatency_ = cameraLatencySeconds;
    predict_ = predict;
}

Eigen::VectorXd RigLoop::estimate(const PlanarPose& pose, std::int64_t frameNs) {
    if (!filter_) {
        return estimator_.update(pose, frameNs);
    }
    const double arrived = static_cast<double>(frameNs) * 1e-9;
    measurement_ << pose.x, pose.y, pose.heading, 0.0, 0.0, 0.0;
    try {
        filter_->update(measurement_, arrived - cameraLatency_);
    } catch (const std::invalid_argument& e) {
        // A frame stamped before the previous one (a clock step): start afresh from it.
        qCWarning(lcRig) << "pose filter restarted:" << e.what();
        filter_->reset();
        filter_->update(measurement_, arrived - cameraLatency_);
    }
    return filter_->predictTo(predict_ ? arrived : arrived - cameraLatency_);
}

RigStep RigLoop::onFrame(const CameraFrame& frame) {
    RigStep step;
    step.frameNs = frame.steadyNs;
    const TrackResult tracked = tracker_.track(frame.image, calibration_);
    step.pose = tracked.pose;
    // Once tripped the trial is over: failsafe whatever comes.
    const auto trip = [&](const QString& reason, bool fence = false) {
        if (tripped_.isEmpty()) {
            qCWarning(lcRig) << "failsafe:" << reason;
            tripped_ = reason;
            fenceTripped_ = fence;
        }
        if (fenceTripped_) {
            link_.reportGeofenceBreach();
        } else {
            link_.reportControllerFault();
        }
        step.fault = true;
        step.stopReason = tripped_;
        return step;
    };
    if (!tripped_.isEmpty()) {
        if (tracked.pose) {
            step.state = estimate(*tracked.pose, frame.steadyNs);
        }
        return trip(tripped_);
    }
    if (!tracked.pose) {
        if (lostSinceNs_ < 0) {
            lostSinceNs_ = frame.steadyNs;
        }
        if (const QString why =
                fence_.breach(std::nullopt, 0.0, (frame.steadyNs - lostSinceNs_) * 1e-9);
            !why.isEmpty()) {
            return trip(why, true);
        }
        link_.setPoseLost(true);  // failsafe from the link's next frame
        estimator_.reset();
        if (filter_ && filter_->status().initialised) {
            // Failsafe: throttle neutral, steering centred, i.e. the zero action.
            filter_->commandedAt(Eigen::VectorXd::Zero(filter_->actionDimension()),
                                 static_cast<double>(frame.steadyNs) * 1e-9);
        }
        return step;
    }
    lostSinceNs_ = -1;
    step.state = estimate(*tracked.pose, frame.steadyNs);
    if (fence_.enabled()) {
        const double speed = std::hypot(step.state[3], step.state[4]);
        if (const QString why = fence_.breach(tracked.pose, speed, 0.0); !why.isEmpty()) {
            return trip(why, true);
        }
    }
    bool offTrack = false;
    if (runningOut_) {
        // Neutral: the zero action, the controller not asked, no lost-track guard.
        step.action = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(channels_.controls.size()));
    } else {
        try {
            const core::ControlStep& control = controller_->step(step.state);
            step.action = control.action;
            if (!step.action.allFinite()) {
                throw std::runtime_error("its action is not finite");
            }
            offTrack = guard_.check(control.deviation);
        } catch (const std::exception& e) {
            return trip(
                QStringLiteral("the controller failed: %1").arg(QString::fromUtf8(e.what())));
        }
    }
    if (offTrack) {
        return trip(QStringLiteral("the car left the demonstration (more than %1 m from it)")
                        .arg(guard_.distance()));
    }
    link_.setCommand(channels_.command(step.action));
    link_.setPoseLost(false);
    if (filter_ && step.action.size() == filter_->actionDimension()) {
        filter_->commandedAt(step.action, static_cast<double>(frame.steadyNs) * 1e-9);
    }
    step.commandNs = steadyNowNs();
    return step;
}

}  // namespace prisca::devices
