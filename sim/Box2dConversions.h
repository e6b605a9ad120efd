#pragma once
// Conversions between Box2D's float vectors and the double Eigen vectors the plants compute in.
// Include only from .cpp files of plants (Box2D stays out of the public headers).

#include <box2d/b2_body.h>
#include <box2d/b2_math.h>

#include <Eigen/Core>

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

}  // namespace prisca::sim
