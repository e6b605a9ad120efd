#pragma once

#include "devices/CameraSource.h"
#include "devices/ChannelMap.h"
#include "devices/Geofence.h"
#include "devices/LedTracker.h"

#include "core/Controller.h"
#include "core/LostTrackGuard.h"
#include "core/PoseFilter.h"

#include <Eigen/Core>

#include <memory>
#include <optional>

namespace prisca::devices {

class TransmitterLink;

/// The car's state (x, y, psi, vx, vy, r as the slide-car's) from successive camera poses:
/// velocities by finite differences over the frames' own timestamps, in the body frame, lightly
/// smoothed. Reset when the pose is lost.
class PoseStateEstimator {
  public:
    /// @param smoothing  weight of the newest difference, in (0, 1]
    explicit PoseStateEstimator(double smoothing = 0.6) : smoothing_(smoothing) {}
    Eigen::VectorXd update(const PlanarPose& pose, std::int64_t steadyNs);
    void reset() { last_.reset(); }

  private:
    double smoothing_;
    std::optional<PlanarPose> last_;
    std::int64_t lastNs_ = 0;
    Eigen::Vector3d rates_ = Eigen::Vector3d::Zero();  ///< vx, vy, r
};

/// What one camera frame led to.
struct RigStep {
    std::optional<PlanarPose> pose;  ///< empty: no pose, failsafe sent
    Eigen::VectorXd state;           ///< the observation given to the controller (if a pose)
    Eigen::VectorXd action;          ///< the controller's action (if a pose)
    bool fault = false;              ///< the controller failed (failsafe latched)
    /// Why the trial must end in failsafe now (the fence breached, the car off the
    /// demonstration, the controller failed); empty while it may go on.
    QString stopReason;
    std::int64_t frameNs = 0;    ///< when the frame arrived
    std::int64_t commandNs = 0;  ///< when the command was handed to the link
};

/// The closed loop on the rig, one camera frame at a time: track the LEDs, estimate the state,
/// step the controller, map the action to channel pulses and hand them to the link. A lost pose
/// or a controller fault puts the link in failsafe at once. Runs on the camera's thread; the
/// link's methods are thread-safe.
class RigLoop {
  public:
    RigLoop(FloorCalibration calibration, TrackerSettings tracker,
            std::unique_ptr<core::Controller> controller, ChannelMap channels,
            TransmitterLink& link);
    RigStep onFrame(const CameraFrame& frame);
    /// A new trial: the controller resets (warm start keeps what it learnt), the estimator too.
    void startTrial(core::ResetMode mode);
    /// The trial's time is up but the car still moves: from the next frame until the next
    /// startTrial, the car is tracked and fenced as before but the controller is no longer
    /// asked; the link is sent the zero action (throttle neutral, steering centred), and the
    /// lost-track guard no longer applies (a coasting car may leave the demonstration's end).
    void runOut() { runningOut_ = true; }
    /// A car further than this [m] from its matched reference has left the demonstration: the
    /// link goes to failsafe as on a controller fault (core::LostTrackGuard); 0: never.
    void setLostTrackDistance(double metres) {
        guard_ = core::LostTrackGuard(metres, core::PlanarPoseIndices{});
    }
    /// The trial's fence: a pose outside it, a speed over its limit or a track lost longer
    /// than it allows latches failsafe in that frame and ends the trial (RigStep::fault with
    /// the reason). Takes effect at once.
    void setGeofence(Geofence fence) { fence_ = std::move(fence); }
    const Geofence& geofence() const { return fence_; }
    /// Estimate the state with a pose filter (core::PoseFilter, time-stamped, pose only) in
    /// place of the finite-difference estimator: each frame's pose is a measurement taken
    /// `cameraLatencySeconds` before the frame arrived, a frame with no pose is bridged by
    /// prediction (the link is in failsafe meanwhile, which the filter takes as the zero action
    /// commanded), and the controller sees the estimate predicted to the frame's arrival. The
    /// car's state layout is forced (n = 6, x y psi vx vy r, pose measured); the noise, densities,
    /// input gain and gate are the caller's. Tell the controller latency 0 then: the filter has
    /// predicted to now. With `predict` false the controller sees the estimate of the frame's
    /// exposure instead (and compensates the latency itself). Off (std::nullopt) by default.
    /// Takes effect from the next trial.
    void usePoseFilter(std::optional<core::PoseFilterParameters> parameters,
                       double cameraLatencySeconds = 0.0, bool predict = true);
    /// The pose filter, if in use (for its counters).
    const core::PoseFilter* poseFilter() const { return filter_ ? &*filter_ : nullptr; }
    core::Controller& controller() { return *controller_; }

  private:
    /// The state for this frame's pose: the filter's estimate or the finite differences.
    Eigen::VectorXd estimate(const PlanarPose& pose, std::int64_t frameNs);

    FloorCalibration calibration_;
    LedTracker tracker_;
    PoseStateEstimator estimator_;
    std::optional<core::PoseFilter> filter_;
    double cameraLatency_ = 0.0;  ///< [s]
    bool predict_ = true;         ///< hand out the estimate of the frame's arrival
    Eigen::VectorXd measurement_ = Eigen::VectorXd::Zero(6);
    std::unique_ptr<core::Controller> controller_;
    core::LostTrackGuard guard_;
    Geofence fence_;
    QString tripped_;                ///< why the trial ended in failsafe (latched until startTrial)
    bool fenceTripped_ = false;      ///< ... and whether that was the fence
    bool runningOut_ = false;        ///< runOut(): neutral, the controller no longer asked
    std::int64_t lostSinceNs_ = -1;  ///< when the pose was lost (-1: tracked)
    ChannelMap channels_;
    TransmitterLink& link_;
};

}  // namespace prisca::devices
