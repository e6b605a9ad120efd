#include "sim/plants/PlanarAircraft.h"

#include "core/DeviationModel.h"

#include "sim/plants/Box2dConversions.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::sim {

namespace {

using core::kPi;

// Level-1 perturbation (documented on the class).
constexpr double kInitialPositionSigma = 2.0;               // [m]
constexpr double kInitialHeadingSigma = 5.0 * kPi / 180.0;  // [rad]
constexpr double kInitialSpeedSigma = 1.0;                  // [m/s]
constexpr double kMeanWindSpeed = 2.0;                      // [m/s]
constexpr double kGustRms = 1.0;                            // [m/s] per axis
constexpr double kGustTimeConstant = 2.0;                   // [s]
constexpr double kThrustDragSpan = 0.05;                    // +-5 %
constexpr double kActuatorNoise = 0.02;                     // fraction of each action range

// Random streams of a trial seed.
constexpr std::uint64_t kDrawStream = 0;
constexpr std::uint64_t kNoiseStream = 1;
constexpr std::uint64_t kWindStream = 2;

Eigen::Vector2d forwardOf(double psi) {
    return {std::cos(psi), std::sin(psi)};
}

Eigen::Vector2d leftOf(double psi) {
    return {-std::sin(psi), std::cos(psi)};
}

double aspectRatio(const PlanarAircraftParameters& p) {
    return p.wingSpan * p.wingSpan / p.wingArea;
}

// Drag coefficient at dynamic pressure q [Pa] and sideslip beta [rad]: the lift that holds the
// weight sets the induced drag, so slow flight costs more (the parabolic polar).
double dragCoefficient(const PlanarAircraftParameters& p, double q, double beta) {
    const double lift = q > 0.0
                            ? std::min(p.maxLiftCoefficient, p.mass * p.gravity / (q * p.wingArea))
                            : p.maxLiftCoefficient;
    return p.zeroLiftDrag + lift * lift / (kPi * p.oswaldEfficiency * aspectRatio(p)) +
           p.sideslipDrag * beta * beta;
}

double propellerFactor(const PlanarAircraftParameters& p, double forwardAirspeed) {
    // No negative thrust above the pitch speed: a windmilling propeller's drag is left out.
    return std::max(0.0, 1.0 - forwardAirspeed / p.propellerPitchSpeed);
}

}  // namespace

PlantInfo PlanarAircraft::describe() {
    PlantInfo info;
    info.name = QStringLiteral("aircraft");
    info.description = QStringLiteral("Small fixed-wing UAV flying flat turns in gusty wind");
    info.stateNames = {"x", "y", "psi", "u", "v", "r"};
    info.stateUnits = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
    info.actionNames = {"throttle", "rudder"};
    info.actionUnits = {"1", "1"};
    info.actionLower = Eigen::Vector2d(0.0, -1.0);
    info.actionUpper = Eigen::Vector2d(1.0, 1.0);
    info.angleIndices = {2};
    info.pose = core::PlanarPoseIndices{0, 1, 2};
    info.bodyVelocity = core::BodyVelocityIndices{3, 4, 5};
    return info;
}

double PlanarAircraft::trimThrottle(const PlanarAircraftParameters& p, double airspeed) {
    const double q = 0.5 * p.airDensity * airspeed * airspeed;
    const double drag = q * p.wingArea * dragCoefficient(p, q, 0.0);
    const double thrustPerThrottle = p.staticThrust * propellerFactor(p, airspeed);
    return thrustPerThrottle > 0.0 ? drag / thrustPerThrottle
                                   : std::numeric_limits<double>::infinity();
}

PlanarAircraft::PlanarAircraft(PlanarAircraftParameters parameters, SimulationTiming timing)
    : parameters_(parameters), timing_(timing), info_(describe()) {
    if (!(timing_.controlPeriod > 0.0) || timing_.physicsSubsteps < 1) {
        throw std::invalid_argument(
            "PlanarAircraft: control period > 0 and >= 1 physics substep needed");
    }
    if (!(parameters_.mass > 0.0) || !(parameters_.yawInertia > 0.0) ||
        !(parameters_.wingArea > 0.0) || !(parameters_.wingSpan > 0.0) ||
        !(parameters_.propellerPitchSpeed > 0.0) || !(parameters_.oswaldEfficiency > 0.0)) {
        throw std::invalid_argument(
            "PlanarAircraft: mass, inertia, wing area, span, pitch speed and e must be > 0");
    }
    build(0.0, 0.0, 0.0, Eigen::Vector2d(nominalSpeed, 0.0), 0.0);
}

PlanarAircraft::~PlanarAircraft() = default;

void PlanarAircraft::build(double x, double y, double psi, const Eigen::Vector2d& groundVelocity,
                           double r) {
    // A fresh world per trial: nothing of the previous trial survives.
    world_ = std::make_unique<b2World>(b2Vec2(0.0f, 0.0f));
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.SetZero();
    def.angle = 0.0f;
    def.allowSleep = false;
    def.linearDamping = 0.0f;
    def.angularDamping = 0.0f;
    body_ = world_->CreateBody(&def);
    // No fixture: nothing to collide with, and the mass comes from the parameters directly.
    b2MassData mass;
    mass.mass = static_cast<float>(parameters_.mass);
    mass.center.SetZero();
    mass.I = static_cast<float>(parameters_.yawInertia);
    body_->SetMassData(&mass);
    body_->SetLinearVelocity(toBox2d(groundVelocity));
    body_->SetAngularVelocity(static_cast<float>(r));
    origin_ = Eigen::Vector2d(x, y);
    headingOrigin_ = psi;
    time_ = 0.0;
}

Eigen::VectorXd PlanarAircraft::reset(std::uint64_t seed, const Perturbation& perturbation) {
    std::mt19937_64 draw(mixSeed(seed, kDrawStream));
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    // Every draw is made whatever the levels, so a level never shifts another quantity's draw.
    const double s0 = perturbation.initialState;
    const double x = kInitialPositionSigma * s0 * normal(draw);
    const double y = kInitialPositionSigma * s0 * normal(draw);
    const double psi = kInitialHeadingSigma * s0 * normal(draw);
    const double speed = std::max(0.0, nominalSpeed + kInitialSpeedSigma * s0 * normal(draw));
    const double sp = perturbation.parameters;
    const double windDirection = kPi * uniform(draw);
    // Clamped so that a large level still leaves an aircraft that can fly.
    thrustScale_ = std::clamp(1.0 + kThrustDragSpan * sp * uniform(draw), 0.5, 1.5);
    dragScale_ = std::clamp(1.0 + kThrustDragSpan * sp * uniform(draw), 0.5, 1.5);
    if (perturbation.session()) {
        // The day's aircraft: its propeller and airframe drawn once for the day (the same span
        // as a trial's, from the day's normals clamped to it), the battery sagging 0.2 % of
        // thrust per trial; the wind stays the trial's weather.
        SessionDay day(perturbation);
        const double thrust = std::clamp(day.normal() / 1.7320508, -1.0, 1.0);
        const double drag = std::clamp(day.normal() / 1.7320508, -1.0, 1.0);
        thrustScale_ = std::clamp(
            (1.0 + kThrustDragSpan * sp * thrust) * (1.0 - day.drift(0.002 * sp)), 0.5, 1.5);
        dragScale_ = std::clamp(1.0 + kThrustDragSpan * sp * drag, 0.5, 1.5);
    }
    throttleNoise_ = kActuatorNoise * (info_.actionUpper[0] - info_.actionLower[0]) *
                     std::max(0.0, perturbation.actuatorNoise);
    rudderNoise_ = kActuatorNoise * (info_.actionUpper[1] - info_.actionLower[1]) *
                   std::max(0.0, perturbation.actuatorNoise);
    noise_.seed(mixSeed(seed, kNoiseStream));

    GustyWindParameters wind;
    wind.meanSpeed = kMeanWindSpeed * std::max(0.0, sp);
    wind.meanDirection = windDirection;
    wind.gustRms = kGustRms * std::max(0.0, sp);
    wind.gustTimeConstant = kGustTimeConstant;
    wind_ = GustyWind(wind, mixSeed(seed, kWindStream));

    // Trimmed in the air mass: flying along the nose at the start speed, so the trial does not
    // open with a weathercock jerk when there is wind.
    build(x, y, psi, speed * forwardOf(psi) + wind_.velocity(), 0.0);
    return state();
}

Eigen::VectorXd PlanarAircraft::resetTo(const Eigen::VectorXd& s) {
    // Checked before it reaches the physics engine, which asserts on what it cannot hold.
    if (const QString problem = info().stateProblem(s); !problem.isEmpty()) {
        throw std::invalid_argument(problem.toStdString());
    }
    thrustScale_ = 1.0;
    dragScale_ = 1.0;
    throttleNoise_ = 0.0;
    rudderNoise_ = 0.0;
    wind_ = GustyWind();
    build(s[0], s[1], s[2], s[3] * forwardOf(s[2]) + s[4] * leftOf(s[2]), s[5]);
    return state();
}

std::unique_ptr<Plant> PlanarAircraft::clone(bool actuatorNoise) const {
    auto copy = std::make_unique<PlanarAircraft>(parameters_, timing_);
    copyMotion(*body_, *copy->body_);
    copy->origin_ = origin_;
    copy->headingOrigin_ = headingOrigin_;
    copy->time_ = time_;
    copy->wind_ = wind_;  // the trial's own wind, gusts to come included
    copy->thrustScale_ = thrustScale_;
    copy->dragScale_ = dragScale_;
    copy->throttleNoise_ = actuatorNoise ? throttleNoise_ : 0.0;
    copy->rudderNoise_ = actuatorNoise ? rudderNoise_ : 0.0;
    copy->noise_ = noise_;
    return copy;
}

void PlanarAircraft::setWind(const GustyWindParameters& wind, std::uint64_t seed) {
    wind_ = GustyWind(wind, seed);
}

double PlanarAircraft::heading() const {
    return headingOrigin_ + body_->GetAngle();
}

Eigen::VectorXd PlanarAircraft::state() const {
    const double psi = heading();
    const Eigen::Vector2d position = origin_ + toEigen(body_->GetPosition());
    const Eigen::Vector2d v = toEigen(body_->GetLinearVelocity());
    Eigen::VectorXd s(6);
    s << position.x(), position.y(), psi, v.dot(forwardOf(psi)), v.dot(leftOf(psi)),
        body_->GetAngularVelocity();
    return s;
}

double PlanarAircraft::airspeed() const {
    return (toEigen(body_->GetLinearVelocity()) - wind_.velocity()).norm();
}

double PlanarAircraft::sideslip() const {
    const double psi = heading();
    const Eigen::Vector2d air = toEigen(body_->GetLinearVelocity()) - wind_.velocity();
    const double forward = air.dot(forwardOf(psi));
    const double left = air.dot(leftOf(psi));
    return forward == 0.0 && left == 0.0 ? 0.0 : std::atan2(left, forward);
}

bool PlanarAircraft::atRest() const {
    return toEigen(body_->GetLinearVelocity()).norm() < parameters_.restSpeed &&
           std::abs(body_->GetAngularVelocity()) < parameters_.restYawRate;
}

Eigen::VectorXd PlanarAircraft::step(const Eigen::VectorXd& action) {
    if (action.size() != 2) {
        throw std::invalid_argument(
            "PlanarAircraft::step: the action needs 2 values (throttle, rudder)");
    }
    // A broken command cuts the engine and centres the rudder rather than poisoning the state.
    double throttle = std::isfinite(action[0]) ? std::clamp(action[0], 0.0, 1.0) : 0.0;
    double rudder = std::isfinite(action[1]) ? std::clamp(action[1], -1.0, 1.0) : 0.0;
    if (throttleNoise_ > 0.0 || rudderNoise_ > 0.0) {
        std::normal_distribution<double> normal(0.0, 1.0);
        // Both deviates are always drawn so the two channels' streams stay aligned.
        const double wThrottle = normal(noise_);
        const double wRudder = normal(noise_);
        throttle = std::clamp(throttle + throttleNoise_ * wThrottle, 0.0, 1.0);
        rudder = std::clamp(rudder + rudderNoise_ * wRudder, -1.0, 1.0);
    }
    // Move the body back to Box2D's origin so its float pose only ever holds one period's motion.
    origin_ += toEigen(body_->GetPosition());
    headingOrigin_ += body_->GetAngle();
    body_->SetTransform(b2Vec2(0.0f, 0.0f), 0.0f);
    for (int i = 0; i < timing_.physicsSubsteps; ++i) {
        physicsStep(throttle, rudder);
    }
    return state();
}

void PlanarAircraft::physicsStep(double throttle, double rudder) {
    const PlanarAircraftParameters& p = parameters_;
    const double h = timing_.physicsStep();

    const double psi = heading();
    const Eigen::Vector2d forward = forwardOf(psi);
    const Eigen::Vector2d left = leftOf(psi);
    const Eigen::Vector2d air = toEigen(body_->GetLinearVelocity()) - wind_.velocity();
    const double r = body_->GetAngularVelocity();
    const double forwardAir = air.dot(forward);
    const double leftAir = air.dot(left);
    const double speed = air.norm();
    const double beta = speed > 0.0 ? std::atan2(leftAir, forwardAir) : 0.0;
    const double q = 0.5 * p.airDensity * speed * speed;
    const double qS = q * p.wingArea;
    const double delta = rudder * p.maxRudderDeflection;

    const double thrust = throttle * p.staticThrust * thrustScale_ * propellerFactor(p, forwardAir);
    const double drag = qS * dragCoefficient(p, q, beta) * dragScale_;
    const double side = qS * (p.sideForceSideslip * beta + p.sideForceRudder * delta);
    Eigen::Vector2d force = thrust * forward + side * left;
    if (speed > 0.0) {
        force -= drag * air / speed;
    }
    // The damping term q S b Cn_r r b / (2 V) written without the division, so it is finite at V =
    // 0.
    const double moment =
        qS * p.wingSpan * (p.yawMomentSideslip * beta + p.yawMomentRudder * delta) +
        0.25 * p.airDensity * speed * p.wingArea * p.wingSpan * p.wingSpan * p.yawDamping * r;

    body_->ApplyForceToCenter(toBox2d(force), true);
    body_->ApplyTorque(static_cast<float>(moment), true);
    // No contacts: the solver iterations do nothing, so the fewest allowed.
    world_->Step(static_cast<float>(h), 1, 1);
    wind_.advance(h);
    time_ += h;
}

}  // namespace prisca::sim
