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
    if (!tracked.pose) {
        link_.setPoseLost(true);  // failsafe from the link's next frame
        estimator_.reset();
        if (filter_ && filter_->status().initialised) {
            // Failsafe: throttle neutral, steering centred, i.e. the zero action.
            filter_->commandedAt(Eigen::VectorXd::Zero(filter_->actionDimension()),
                                 static_cast<double>(frame.steadyNs) * 1e-9);
        }
        return step;
    }
    step.state = estimate(*tracked.pose, frame.steadyNs);
    if (guard_.tripped()) {  // left the demonstration earlier in this trial: failsafe stays
        link_.reportControllerFault();
        step.fault = true;
        return step;
    }
    try {
        const core::ControlStep& control = controller_->step(step.state);
        step.action = control.action;
        if (!step.action.allFinite()) {
            throw std::runtime_error("the controller's action is not finite");
        }
        if (guard_.check(control.deviation)) {
            throw std::runtime_error("the car left the demonstration (position deviation over " +
                                     std::to_string(guard_.distance()) + " m)");
        }
    } catch (const std::exception& e) {
        qCWarning(lcRig) << "controller fault:" << e.what();
        link_.reportControllerFault();
        step.fault = true;
        return step;
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
