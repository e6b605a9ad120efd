#pragma once

#include "devices/LedTracker.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <vector>

namespace prisca::devices {

struct LatencyProbeSettings {
    int steps = 5;               ///< throttle steps to time
    double throttle = 0.35;      ///< the step's size [-1, 1]; alternating forward and back
    double stillFor = 0.4;       ///< the car must be still this long before a step [s]
    double stillWithin = 0.004;  ///< "still": no pose further than this from the newest [m]
    double onsetFrom = 0.006;    ///< a step answered: at least two frames this far [m]
    double fitUpTo = 0.05;       ///< the response is fitted up to this displacement [m]
    double giveUpAfter = 1.0;    ///< a step with no response by then is a failure [s]
    double settleTimeout = 8.0;  ///< the car not still within this long: the probe fails [s]
    int throttleIndex = 0;       ///< which action component is the throttle
    int actions = 2;             ///< the action's size
};

/// One timed step.
struct LatencyStep {
    double latency = 0.0;  ///< from the step command to the response's onset [s]
    int samples = 0;       ///< frames the onset was fitted on
};

/// The loop's latency from the camera: with the car at rest the probe steps the throttle and
/// watches the tracked poses for the response. A brakeless car's displacement after a step is
/// d(t) = q (t - t0)^2 once the motor pulls (0 before t0), so the onset t0 is fitted, with q
/// and an offset, to every frame up to fitUpTo, to a fraction of a frame; taking the first
/// frame past a threshold instead would add the time the car needs to cover it. The latency
/// is t0 minus the arrival of the frame on which the step was commanded: everything from the
/// command to the response appearing in a frame's pose (link, receiver, servo or motor dead
/// time, the camera's exposure to arrival). Steps alternate forward and back so the car stays
/// where it was. Pure logic: feed it every frame.
class LatencyProbe {
  public:
    explicit LatencyProbe(LatencyProbeSettings settings = {});
    /// The frame's arrival time [ns] and its pose (empty: none); returns the action to command
    /// for this frame.
    Eigen::VectorXd onFrame(std::int64_t frameNs, const std::optional<PlanarPose>& pose);
    bool finished() const { return phase_ == Phase::Done || !failure_.empty(); }
    /// Why it failed (no pose, the car never still, no response); empty otherwise.
    const std::string& failure() const { return failure_; }
    const std::vector<LatencyStep>& steps() const { return steps_; }
    double medianSeconds() const;
    double minSeconds() const;
    double maxSeconds() const;
    /// The steps' standard deviation [s].
    double spreadSeconds() const;

  private:
    enum class Phase { Settle, Step, Done };
    Eigen::VectorXd neutral() const { return Eigen::VectorXd::Zero(s_.actions); }

    LatencyProbeSettings s_;
    Phase phase_ = Phase::Settle;
    std::string failure_;
    std::vector<LatencyStep> steps_;
    // Settling: recent poses with their times.
    std::vector<std::pair<double, PlanarPose>> recent_;
    double phaseStart_ = -1.0;
    // The step under way.
    double stepAt_ = 0.0;
    PlanarPose from_;
    double sign_ = 1.0;
    std::vector<std::pair<double, double>> response_;  ///< time, displacement
};

}  // namespace prisca::devices
