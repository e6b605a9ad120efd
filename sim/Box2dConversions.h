#pragma once
// Conversions between Box2D's float vectors and the double Eigen vectors the plants compute in.
// Include only from .cpp files of plants (Box2D stays out of the public headers).

#include <box2d/b2_body.h>
#include <box2d/b2_math.h>

#include <Eigen/Core>

#include <cmath>

namespace prisca::sim {

inline Eigen::Vector2d toEigen(const b2Vec2& v) {
    return {v.x, v.y};
}

inline b2Vec2 toBox2d(const Eigen::Vector2d& v) {
    return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}

/// Puts `to` exactly where `from` is and moving as it moves (pose, velocities), so that a body
/// rebuilt in a fresh world continues as the original would (a plant's clone()).
inline void copyMotion(const b2Body& from, b2Body& to) {
    to.SetTransform(from.GetPosition(), from.GetAngle());
    to.SetLinearVelocity(from.GetLinearVelocity());
    to.SetAngularVelocity(from.GetAngularVelocity());
}

/// A planar vehicle's state from its body: x, y, heading psi, body-frame velocities vx (forward),
/// vy (left) and yaw rate r (the slide-car's and the differential drive's layout).
inline Eigen::VectorXd planarVehicleState(const b2Body& body) {
    const double psi = body.GetAngle();
    const Eigen::Vector2d v = toEigen(body.GetLinearVelocity());
    const Eigen::Vector2d forward(std::cos(psi), std::sin(psi));
    const Eigen::Vector2d left(-std::sin(psi), std::cos(psi));
    Eigen::VectorXd s(6);
    s << body.GetPosition().x, body.GetPosition().y, psi, v.dot(forward), v.dot(left),
        body.GetAngularVelocity();
    return s;
}

/// Whether a planar body is at rest: speed and yaw rate both below their thresholds.
inline bool planarBodyAtRest(const b2Body& body, double restSpeed, double restYawRate) {
    return toEigen(body.GetLinearVelocity()).norm() < restSpeed &&
           std::abs(body.GetAngularVelocity()) < restYawRate;
}

}  // namespace prisca::sim
