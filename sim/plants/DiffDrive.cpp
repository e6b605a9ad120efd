#include "sim/plants/DiffDrive.h"

#include "sim/plants/Box2dConversions.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::sim {

PlantInfo DiffDrive::describe() {
    PlantInfo info;
    info.name = QStringLiteral("diffdrive");
    info.description = QStringLiteral("Differential-drive ground robot (two wheels and a caster)");
    info.stateNames = {"x", "y", "psi", "vx", "vy", "r"};
    info.stateUnits = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
    info.actionNames = {"left wheel", "right wheel"};
    info.actionUnits = {"1", "1"};
    info.actionLower = Eigen::Vector2d(-1.0, -1.0);
    info.actionUpper = Eigen::Vector2d(1.0, 1.0);
    info.angleIndices = {2};
    info.pose = core::PlanarPoseIndices{0, 1, 2};
    info.bodyVelocity = core::BodyVelocityIndices{3, 4, 5};
    return info;
}

DiffDrive::DiffDrive(DiffDriveParameters parameters, SimulationTiming timing)
    : parameters_(parameters), timing_(timing), info_(describe()) {
    if (timing_.controlPeriod <= 0.0 || timing_.physicsSubsteps < 1) {
        throw std::invalid_argument(
            "DiffDrive: control period > 0 and >= 1 physics substep needed");
    }
    build(0, 0, 0, 0, 0, 0);
}

DiffDrive::~DiffDrive() = default;

void DiffDrive::build(double x, double y, double psi, double vx, double vy, double r) {
    world_ = makePlanarBox(
        {parameters_.length, parameters_.width, parameters_.mass, parameters_.yawInertia}, x, y,
        psi, vx, vy, r, &body_);
    time_ = 0.0;
    // Wheels turning as the body moves (no slip at the start).
    const double half = parameters_.track / 2;
    wheelSpeed_ = {vx - half * r, vx + half * r};
}

Eigen::VectorXd DiffDrive::reset(std::uint64_t seed, const Perturbation& perturbation) {
    std::mt19937_64 draw(mixSeed(seed, 0));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double s0 = perturbation.initialState;
    const double x = 0.02 * s0 * normal(draw);
    const double y = 0.02 * s0 * normal(draw);
    const double psi = 0.0349 * s0 * normal(draw);
    const double sp = perturbation.parameters;
    if (perturbation.session()) {
        // The day's robot: unequal wheels and the floor's grip drawn once, the battery sagging
        // (both wheels' gain falling 0.2 % per trial), the grip varying 3 % per trial.
        SessionDay day(perturbation);
        const double left = 0.05 * sp * day.normal();
        const double right = 0.05 * sp * day.normal();
        const double friction = 0.10 * sp * day.normal();
        const double sag = day.drift(0.002 * sp);
        std::mt19937_64 trialDraw(mixSeed(seed, 3));
        wheelGain_[0] = std::clamp((1.0 + left) * (1.0 - sag), 0.5, 1.5);
        wheelGain_[1] = std::clamp((1.0 + right) * (1.0 - sag), 0.5, 1.5);
        frictionScale_ =
            std::clamp((1.0 + friction) * (1.0 + 0.03 * sp * normal(trialDraw)), 0.5, 1.5);
    } else {
        wheelGain_[0] = std::clamp(1.0 + 0.05 * sp * normal(draw), 0.5, 1.5);
        wheelGain_[1] = std::clamp(1.0 + 0.05 * sp * normal(draw), 0.5, 1.5);
        frictionScale_ = std::clamp(1.0 + 0.10 * sp * normal(draw), 0.5, 1.5);
    }
    actuatorNoise_ = 0.02 * perturbation.actuatorNoise;
    noise_.seed(mixSeed(seed, 1));
    build(x, y, psi, 0, 0, 0);
    return state();
}

Eigen::VectorXd DiffDrive::resetTo(const Eigen::VectorXd& s) {
    // Checked before it reaches the physics engine, which asserts on what it cannot hold.
    if (const QString problem = info().stateProblem(s); !problem.isEmpty()) {
        throw std::invalid_argument(problem.toStdString());
    }
    wheelGain_ = {1.0, 1.0};
    frictionScale_ = 1.0;
    actuatorNoise_ = 0.0;
    build(s[0], s[1], s[2], s[3], s[4], s[5]);
    return state();
}

std::unique_ptr<Plant> DiffDrive::clone(bool actuatorNoise) const {
    auto copy = std::make_unique<DiffDrive>(parameters_, timing_);
    copyMotion(*body_, *copy->body_);
    copy->time_ = time_;
    copy->wheelSpeed_ = wheelSpeed_;
    copy->wheelGain_ = wheelGain_;
    copy->frictionScale_ = frictionScale_;
    copy->actuatorNoise_ = actuatorNoise ? actuatorNoise_ : 0.0;
    copy->noise_ = noise_;
    return copy;
}

Eigen::VectorXd DiffDrive::state() const {
    return planarVehicleState(*body_);
}

bool DiffDrive::atRest() const {
    return planarBodyAtRest(*body_, parameters_.restSpeed, parameters_.restYawRate);
}

Eigen::VectorXd DiffDrive::step(const Eigen::VectorXd& action) {
    if (action.size() != 2) {
        throw std::invalid_argument(
            "DiffDrive::step: the action needs 2 values (left wheel, right wheel)");
    }
    std::array<double, 2> command = {std::clamp(action[0], -1.0, 1.0),
                                     std::clamp(action[1], -1.0, 1.0)};
    if (!std::isfinite(command[0]) || !std::isfinite(command[1])) {
        command = {0.0, 0.0};  // a broken command must never move the robot
    }
    if (actuatorNoise_ > 0.0) {
        std::normal_distribution<double> normal(0.0, actuatorNoise_);
        for (double& c : command) {
            c = std::clamp(c + normal(noise_), -1.0, 1.0);
        }
    }
    for (int i = 0; i < timing_.physicsSubsteps; ++i) {
        physicsStep(command);
    }
    return state();
}

void DiffDrive::physicsStep(const std::array<double, 2>& command) {
    const DiffDriveParameters& p = parameters_;
    const double h = timing_.physicsStep();
    const double psi = body_->GetAngle();
    const Eigen::Vector2d v = toEigen(body_->GetLinearVelocity());
    const double omega = body_->GetAngularVelocity();
    const Eigen::Vector2d forward(std::cos(psi), std::sin(psi));
    const Eigen::Vector2d left(-std::sin(psi), std::cos(psi));
    const double load = p.mass * p.gravity / 2;  // the caster carries little; two wheels share
    const double grip = p.friction * frictionScale_ * load;
    // Each wheel removes this share of its slip per step at most (a stiff but stable traction):
    // the force that would do it is share * (mass per wheel) * slip / h.
    const double perWheelMass = p.mass / 2;
    const Eigen::Vector2d centre = toEigen(body_->GetPosition());
    for (int w = 0; w < 2; ++w) {
        // Motor lag: the wheel's rim speed follows its command.
        const double target = command[w] * wheelGain_[w] * p.maxWheelSpeed;
        wheelSpeed_[w] += (target - wheelSpeed_[w]) * std::min(1.0, h / p.motorTimeConstant);
        const double side = w == 0 ? 1.0 : -1.0;  // the left wheel sits at +track/2 along left
        const Eigen::Vector2d arm = side * (p.track / 2) * left;
        const Eigen::Vector2d contact = v + omega * Eigen::Vector2d(-arm.y(), arm.x());
        const double longitudinalSlip = wheelSpeed_[w] - contact.dot(forward);
        const double lateralSlip = -contact.dot(left);
        const double k = p.tractionStiffness * perWheelMass / h;
        double fx = k * longitudinalSlip;
        double fy = k * lateralSlip;
        const double demand = std::hypot(fx, fy);
        if (demand > grip) {  // past the friction circle: the wheel slides
            fx *= grip / demand;
            fy *= grip / demand;
        }
        const Eigen::Vector2d force = fx * forward + fy * left;
        body_->ApplyForce(toBox2d(force), toBox2d(centre + arm), true);
    }
    body_->ApplyForceToCenter(toBox2d(-p.casterDrag * v), true);
    world_->Step(static_cast<float>(h), 8, 3);
    time_ += h;
}

}  // namespace prisca::sim
