#pragma once

#include "DeviationModel.h"

#include <Eigen/Core>

#include <optional>

namespace prisca::core {

/// The robot has left the demonstration: its position deviation from the matched reference
/// exceeds a distance. From then on no tracker can bring it back (its reference stalls on a
/// sample the robot has left, the feedback saturates on errors of metres), so the trial ends in
/// failsafe (throttle neutral, steering centred) instead of driving on. Latches until reset().
/// Only for planar vehicles; a guard without a pose or with distance 0 never trips.
class LostTrackGuard {
  public:
    LostTrackGuard() = default;
    /// @param distance  position deviation [m] that trips the guard (0: never)
    LostTrackGuard(double distance, std::optional<PlanarPoseIndices> pose)
        : distance_(distance), pose_(pose) {}

    /// Checks one step's deviation (as the controller formed it); true once tripped.
    bool check(const Eigen::Ref<const Eigen::VectorXd>& deviation) {
        if (!tripped_ && distance_ > 0.0 && pose_) {
            const double dx = deviation[pose_->x];
            const double dy = deviation[pose_->y];
            // A deviation that is not a number is lost too.
            tripped_ = !(dx * dx + dy * dy <= distance_ * distance_);
        }
        return tripped_;
    }
    bool tripped() const { return tripped_; }
    void reset() { tripped_ = false; }
    double distance() const { return distance_; }

  private:
    double distance_ = 0.0;
    std::optional<PlanarPoseIndices> pose_;
    bool tripped_ = false;
};

}  // namespace prisca::core
