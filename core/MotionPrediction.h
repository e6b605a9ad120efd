#pragma once

#include "DeviationModel.h"

#include <Eigen/Core>

#include <cmath>

namespace prisca::core {

/// Moves a planar vehicle's observed pose forward by `seconds` at its observed body velocities
/// (turning at its yaw rate, the mid-point heading for the displacement); the velocities stay.
/// What an observation `seconds` old says about now, so a controller acts on the pose of now
/// instead of one its commands have already left behind (a Smith predictor's kinematic part).
/// A state without a pose or body velocities is returned as it is.
inline void predictPlanarMotion(const DeviationModel& model, double seconds,
                                Eigen::Ref<Eigen::VectorXd> state) {
    if (!model.pose || !model.bodyVelocity || seconds <= 0.0) {
        return;
    }
    const PlanarPoseIndices& p = *model.pose;
    const BodyVelocityIndices& v = *model.bodyVelocity;
    const double turn = state[v.yawRate] * seconds;
    const double heading = state[p.heading] + 0.5 * turn;
    const double c = std::cos(heading), s = std::sin(heading);
    state[p.x] += (c * state[v.forward] - s * state[v.lateral]) * seconds;
    state[p.y] += (s * state[v.forward] + c * state[v.lateral]) * seconds;
    state[p.heading] += turn;
}

}  // namespace prisca::core
