#pragma once
// Conversions between Box2D's float vectors and the double Eigen vectors the plants compute in,
// and the planar body the slide-car and the differential drive share. Include only from .cpp
// files of plants (Box2D stays out of the public headers).

#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_math.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_world.h>

#include <Eigen/Core>

#include <cmath>
#include <memory>

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

/// A rigid box on the floor: its size [m], mass [kg] and yaw inertia about its centre [kg m^2].
struct PlanarBox {
    double length = 0.0;
    double width = 0.0;
    double mass = 0.0;
    double yawInertia = 0.0;
};

/// A fresh world (no gravity: the floor is the plane) holding one such box, awake for good, at
/// (x, y) heading psi, moving at vx forward and vy left in its own frame and turning at r: the
/// body of the slide-car and of the differential drive, rebuilt for every trial so nothing of the
/// previous one (contacts, sleep state) survives. *body is the box, owned by the world.
inline std::unique_ptr<b2World> makePlanarBox(const PlanarBox& box, double x, double y, double psi,
                                              double vx, double vy, double r, b2Body** body) {
    auto world = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set(static_cast<float>(x), static_cast<float>(y));
    def.angle = static_cast<float>(psi);
    def.allowSleep = false;
    b2Body* made = world->CreateBody(&def);
    b2PolygonShape shape;
    shape.SetAsBox(static_cast<float>(box.length / 2), static_cast<float>(box.width / 2));
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = 1.0f;
    made->CreateFixture(&fixture);
    b2MassData mass;
    mass.mass = static_cast<float>(box.mass);
    mass.center.SetZero();
    mass.I = static_cast<float>(box.yawInertia);
    made->SetMassData(&mass);
    const Eigen::Vector2d forward(std::cos(psi), std::sin(psi));
    const Eigen::Vector2d left(-std::sin(psi), std::cos(psi));
    made->SetLinearVelocity(toBox2d(vx * forward + vy * left));
    made->SetAngularVelocity(static_cast<float>(r));
    *body = made;
    return world;
}

/// Whether a planar body is at rest: speed and yaw rate both below their thresholds.
inline bool planarBodyAtRest(const b2Body& body, double restSpeed, double restYawRate) {
    return toEigen(body.GetLinearVelocity()).norm() < restSpeed &&
           std::abs(body.GetAngularVelocity()) < restYawRate;
}

}  // namespace prisca::sim
