#include "sim/plants/SlideCar.h"

#include "sim/plants/Box2dConversions.h"

#include <box2d/box2d.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::sim {

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

int delaySteps(double delay, const SimulationTiming& timing) {
    return std::max(0, static_cast<int>(std::lround(delay / timing.physicsStep())));
}

}  // namespace

PlantInfo SlideCar::describe() {
    PlantInfo info;
    info.name = QStringLiteral("slidecar");
    info.description = QStringLiteral("Brakeless 4x4 1:10 RC car sliding on a flat floor");
    info.stateNames = {"x", "y", "psi", "vx", "vy", "r"};
    info.stateUnits = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
    info.actionNames = {"throttle", "steering"};
    info.actionUnits = {"1", "1"};
    info.actionLower = Eigen::Vector2d(-1.0, -1.0);
    info.actionUpper = Eigen::Vector2d(1.0, 1.0);
    info.angleIndices = {2};
    info.pose = core::PlanarPoseIndices{0, 1, 2};
    info.bodyVelocity = core::BodyVelocityIndices{3, 4, 5};
    info.steersThroughTravel = true;
    return info;
}

SlideCar::SlideCar(SlideCarParameters parameters, SimulationTiming timing)
    : parameters_(parameters), timing_(timing), info_(describe()) {
    if (timing_.controlPeriod <= 0.0 || timing_.physicsSubsteps < 1) {
        throw std::invalid_argument("SlideCar: control period > 0 and >= 1 physics substep needed");
    }
    build(0, 0, 0, 0, 0, 0);
}

SlideCar::~SlideCar() = default;

void SlideCar::build(double x, double y, double psi, double vx, double vy, double r) {
    const double inertia = parameters_.yawInertia > 0.0
                               ? parameters_.yawInertia
                               : parameters_.mass *
                                     (parameters_.length * parameters_.length +
                                      parameters_.width * parameters_.width) /
                                     12.0;
    world_ = makePlanarBox({parameters_.length, parameters_.width, parameters_.mass, inertia}, x, y,
                           psi, vx, vy, r, &body_);
    time_ = 0.0;
    steeringAngle_ = 0.0;
    servoAngle_ = 0.0;
    longitudinalAcceleration_ = 0.0;
    sliding_ = {false, false};
    throttleQueue_.assign(delaySteps(parameters_.throttleDelay, timing_), 0.0);
    steeringQueue_.assign(delaySteps(parameters_.servoDelay, timing_), 0.0);
}

Eigen::VectorXd SlideCar::reset(std::uint64_t seed, const Perturbation& perturbation) {
    std::mt19937_64 draw(mixSeed(seed, 0));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double s0 = perturbation.initialState;
    const double x = 0.03 * s0 * normal(draw);
    const double y = 0.03 * s0 * normal(draw);
    const double psi = 0.0349 * s0 * normal(draw);
    const double sp = perturbation.parameters;
    if (perturbation.session()) {
        // The day's car: its mismatch drawn once for the day, the battery sagging trial by
        // trial, a little variation per trial (magnitudes in the class comment).
        SessionDay day(perturbation);
        const double friction = 0.10 * sp * day.normal();
        const double gain = 0.08 * sp * day.normal();
        const double trim = 0.03 * sp * day.normal();
        const double sag = day.drift(0.002 * sp * std::max(0.0, 1.0 + 0.25 * day.normal()));
        std::mt19937_64 trialDraw(mixSeed(seed, 3));
        const double trialFriction = 0.03 * sp * normal(trialDraw);
        const double trialTrim = 0.005 * sp * normal(trialDraw);
        frictionScale_ = std::clamp((1.0 + friction) * (1.0 + trialFriction), 0.5, 1.5);
        throttleGain_ = std::clamp((1.0 + gain) * (1.0 - sag), 0.5, 1.5);
        steeringTrim_ = std::clamp(trim + trialTrim, -0.3, 0.3);
    } else {
        // Clamped so that a wild draw at a large level still leaves a drivable car.
        frictionScale_ = std::clamp(1.0 + 0.10 * sp * normal(draw), 0.5, 1.5);
        throttleGain_ = std::clamp(1.0 + 0.08 * sp * normal(draw), 0.5, 1.5);
        steeringTrim_ = std::clamp(0.03 * sp * normal(draw), -0.3, 0.3);
    }
    actuatorNoise_ = 0.02 * perturbation.actuatorNoise;
    noise_.seed(mixSeed(seed, 1));
    build(x, y, psi, 0, 0, 0);
    return state();
}

Eigen::VectorXd SlideCar::resetTo(const Eigen::VectorXd& s) {
    // Checked before it reaches the physics engine, which asserts on what it cannot hold.
    if (const QString problem = info().stateProblem(s); !problem.isEmpty()) {
        throw std::invalid_argument(problem.toStdString());
    }
    frictionScale_ = 1.0;
    throttleGain_ = 1.0;
    steeringTrim_ = 0.0;
    actuatorNoise_ = 0.0;
    build(s[0], s[1], s[2], s[3], s[4], s[5]);
    return state();
}

std::unique_ptr<Plant> SlideCar::clone(bool actuatorNoise) const {
    auto copy = std::make_unique<SlideCar>(parameters_, timing_);
    // One body and no contacts: its pose and velocities are all Box2D keeps between steps.
    copyMotion(*body_, *copy->body_);
    copy->time_ = time_;
    copy->steeringAngle_ = steeringAngle_;
    copy->servoAngle_ = servoAngle_;
    copy->longitudinalAcceleration_ = longitudinalAcceleration_;
    copy->sliding_ = sliding_;
    copy->throttleQueue_ = throttleQueue_;
    copy->steeringQueue_ = steeringQueue_;
    copy->frictionScale_ = frictionScale_;
    copy->throttleGain_ = throttleGain_;
    copy->steeringTrim_ = steeringTrim_;
    copy->steeringOffset_ = steeringOffset_;
    copy->actuatorNoise_ = actuatorNoise ? actuatorNoise_ : 0.0;
    copy->noise_ = noise_;
    return copy;
}

Eigen::VectorXd SlideCar::state() const {
    return planarVehicleState(*body_);
}

bool SlideCar::atRest() const {
    return planarBodyAtRest(*body_, parameters_.restSpeed, parameters_.restYawRate);
}

Eigen::VectorXd SlideCar::step(const Eigen::VectorXd& action) {
    if (action.size() != 2) {
        throw std::invalid_argument(
            "SlideCar::step: the action needs 2 values (throttle, steering)");
    }
    double throttle = std::clamp(action[0], -1.0, 1.0);
    double steering = std::clamp(action[1], -1.0, 1.0);
    if (!std::isfinite(throttle) || !std::isfinite(steering)) {
        // A broken command must never move the car: neutral throttle, centred steering.
        throttle = 0.0;
        steering = 0.0;
    }
    if (actuatorNoise_ > 0.0) {
        std::normal_distribution<double> normal(0.0, actuatorNoise_);
        throttle = std::clamp(throttle + normal(noise_), -1.0, 1.0);
        steering = std::clamp(steering + normal(noise_), -1.0, 1.0);
    }
    for (int i = 0; i < timing_.physicsSubsteps; ++i) {
        physicsStep(throttle, steering);
    }
    return state();
}

void SlideCar::primeActuators(const std::vector<Eigen::VectorXd>& recentActions) {
    for (const Eigen::VectorXd& action : recentActions) {
        if (action.size() != 2) {
            throw std::invalid_argument("SlideCar::primeActuators: actions of 2 values needed");
        }
        const double throttle = std::isfinite(action[0]) ? std::clamp(action[0], -1.0, 1.0) : 0.0;
        const double steering = std::isfinite(action[1]) ? std::clamp(action[1], -1.0, 1.0) : 0.0;
        for (int i = 0; i < timing_.physicsSubsteps; ++i) {
            actuatorStep(throttle, steering);
        }
    }
}

std::vector<double> SlideCar::hiddenState() const {
    return {sliding_[0] ? 1.0 : 0.0, sliding_[1] ? 1.0 : 0.0, longitudinalAcceleration_};
}

void SlideCar::setHiddenState(const std::vector<double>& hidden) {
    if (hidden.size() != 3 || !std::isfinite(hidden[2])) {
        return;
    }
    sliding_ = {hidden[0] != 0.0, hidden[1] != 0.0};
    longitudinalAcceleration_ = hidden[2];
}

bool SlideCar::setSteeringOffset(double offset) {
    steeringOffset_ = offset;
    return true;
}

std::pair<double, double> SlideCar::actuatorStep(double throttleCommand, double steeringCommand) {
    const SlideCarParameters& p = parameters_;
    const double h = timing_.physicsStep();
    // Dead times: the command applied now is the one queued delay steps ago.
    throttleQueue_.push_back(throttleCommand);
    steeringQueue_.push_back(steeringCommand);
    double throttle = std::clamp(throttleQueue_.front() * throttleGain_, -1.0, 1.0);
    if (p.escDeadband > 0.0) {
        // The ESC's neutral band; what is left is stretched over the whole range.
        const double magnitude = std::max(0.0, std::abs(throttle) - p.escDeadband);
        throttle = std::copysign(magnitude / (1.0 - p.escDeadband), throttle);
    }
    const double steering =
        std::clamp(steeringQueue_.front() + steeringTrim_ + steeringOffset_, -1.0, 1.0);
    throttleQueue_.pop_front();
    steeringQueue_.pop_front();

    // Servo: its output slews towards its target; the wheels follow through the linkage's play.
    const double target = steering * p.maxSteeringAngle;
    const double maxChange = p.servoRate * h;
    servoAngle_ += std::clamp(target - servoAngle_, -maxChange, maxChange);
    const double play = 0.5 * p.servoBacklash;
    steeringAngle_ = std::clamp(steeringAngle_, servoAngle_ - play, servoAngle_ + play);
    return {throttle, steering};
}

void SlideCar::physicsStep(double throttleCommand, double steeringCommand) {
    const SlideCarParameters& p = parameters_;
    const double h = timing_.physicsStep();
    const double throttle = actuatorStep(throttleCommand, steeringCommand).first;

    const double psi = body_->GetAngle();
    const Eigen::Vector2d v = toEigen(body_->GetLinearVelocity());
    const double omega = body_->GetAngularVelocity();
    const double mass = p.mass;
    const double inertia = body_->GetInertia();
    const Eigen::Vector2d carForward(std::cos(psi), std::sin(psi));
    const Eigen::Vector2d carLeft(-std::sin(psi), std::cos(psi));

    // Axle geometry: 0 front (steered), 1 rear.
    // Axle geometry about the centre of mass: front a = L/2 - cg ahead, rear b = L/2 + cg behind.
    const double toFront = p.wheelbase / 2 - p.cgForward;
    const double toRear = p.wheelbase / 2 + p.cgForward;
    std::array<Eigen::Vector2d, 2> arm = {carForward * toFront, -carForward * toRear};
    std::array<Eigen::Vector2d, 2> forward;
    std::array<Eigen::Vector2d, 2> lateral;
    forward[0] = Eigen::Vector2d(std::cos(psi + steeringAngle_), std::sin(psi + steeringAngle_));
    lateral[0] = Eigen::Vector2d(-forward[0].y(), forward[0].x());
    forward[1] = carForward;
    lateral[1] = carLeft;

    // Normal loads with longitudinal load transfer (accelerating unloads the front).
    const double transfer = mass * longitudinalAcceleration_ * p.cgHeight / p.wheelbase;
    std::array<double, 2> load;
    load[0] = std::max(0.0, mass * p.gravity * (toRear / p.wheelbase) - transfer);
    load[1] = std::max(0.0, mass * p.gravity * (toFront / p.wheelbase) + transfer);

    // Longitudinal forces per axle: the motor (half the traction each) and rolling losses.
    std::array<double, 2> longitudinal{};
    std::array<Eigen::Vector2d, 2> contactVelocity;
    for (int a = 0; a < 2; ++a) {
        contactVelocity[a] = v + omega * Eigen::Vector2d(-arm[a].y(), arm[a].x());
        const double rolling = contactVelocity[a].dot(forward[a]);
        // An ESC without brake: the motor pushes towards throttle * top speed and freewheels
        // rather than ever braking.
        // With a stall force above the current limit (motorStallRatio > 1) the force stays at
        // the limit up to a speed and then falls along the motor's steeper line.
        const double drive = p.motorStallRatio * (throttle - rolling / p.topSpeed);
        const double motor =
            throttle >= 0.0 ? std::clamp(drive, 0.0, throttle) : std::clamp(drive, throttle, 0.0);
        longitudinal[a] = 0.5 * p.maxDriveForce * motor -
                          p.rollingResistance * load[a] * std::tanh(rolling / 0.05) -
                          0.5 * p.drivelineDrag * rolling;
    }

    // Lateral impulses that would stop both axles slipping sideways this step (2 x 2 solve).
    auto response =
        [&](int a, int b) {  // velocity change along lateral[a] per unit impulse along lateral[b]
            return lateral[a].dot(lateral[b]) / mass +
                   cross(arm[a], lateral[a]) * cross(arm[b], lateral[b]) / inertia;
        };
    Eigen::Matrix2d K;
    K << response(0, 0), response(0, 1), response(1, 0), response(1, 1);
    const Eigen::Vector2d slip(contactVelocity[0].dot(lateral[0]),
                               contactVelocity[1].dot(lateral[1]));
    Eigen::Vector2d impulse = K.fullPivLu().solve(-slip);

    // Friction circle per axle with stick-slip. Returns whether the axle is at its limit.
    std::array<double, 2> lateralForce{};
    const Eigen::Vector2d centre = toEigen(body_->GetPosition());
    auto limit = [&](int a, double wanted) {
        const double grip = frictionScale_ * patchScale(centre + arm[a]) * load[a];
        const double muS = p.staticFriction * (a == 1 ? grip * p.rearGripRatio : grip);
        const double muK = p.kineticFriction * (a == 1 ? grip * p.rearKineticGripRatio : grip);
        if (p.tyreStiffness > 0.0) {
            return magicFormula(a, wanted, muS, muK, contactVelocity[a].dot(forward[a]), slip[a],
                                longitudinal, lateralForce);
        }
        const double demand = std::hypot(longitudinal[a], wanted);
        if (!sliding_[a] && demand > muS) {
            sliding_[a] = true;
        } else if (sliding_[a] && demand <= muK) {
            sliding_[a] = false;
        }
        if (sliding_[a]) {
            // A sliding tyre: the motor or rolling force takes its share of mu_k N first (a
            // spinning or dragged wheel loses its side grip), and the rest opposes the axle's
            // own sideways slip.
            longitudinal[a] = std::clamp(longitudinal[a], -muK, muK);
            const double side =
                std::sqrt(std::max(0.0, muK * muK - longitudinal[a] * longitudinal[a]));
            lateralForce[a] = slip[a] > 0.0 ? -side : (slip[a] < 0.0 ? side : 0.0);
            return true;
        }
        lateralForce[a] = wanted;
        return false;
    };
    const bool frontLimited = limit(0, impulse[0] / h);
    const bool rearLimited = limit(1, impulse[1] / h);
    if (frontLimited != rearLimited) {
        // One axle slides: hold it at its limit and re-solve the other, so the pair stays
        // consistent (the gripping axle must also stop what the sliding one no longer does).
        const int fixed = frontLimited ? 0 : 1;
        const int free = 1 - fixed;
        const double fixedImpulse = lateralForce[fixed] * h;
        limit(free, (-slip[free] - K(free, fixed) * fixedImpulse) / K(free, free) / h);
    }

    Eigen::Vector2d total = Eigen::Vector2d::Zero();
    for (int a = 0; a < 2; ++a) {
        const Eigen::Vector2d force = longitudinal[a] * forward[a] + lateralForce[a] * lateral[a];
        total += force;
        const Eigen::Vector2d point = centre + arm[a];
        body_->ApplyForce(toBox2d(force), toBox2d(point), true);
    }
    longitudinalAcceleration_ = total.dot(carForward) / mass;
    world_->Step(static_cast<float>(h), 8, 3);
    time_ += h;
}

double SlideCar::patchScale(const Eigen::Vector2d& point) const {
    const SlideCarParameters& p = parameters_;
    if (p.patchFriction == 1.0 || p.patchSize <= 0.0) {
        return 1.0;
    }
    const auto cell = [&](double v) { return static_cast<long long>(std::floor(v / p.patchSize)); };
    return (cell(point.x()) + cell(point.y())) % 2 == 0 ? 1.0 : p.patchFriction;
}

bool SlideCar::magicFormula(int axle, double wanted, double peak, double sliding,
                            double rollingSpeed, double slipSpeed,
                            std::array<double, 2>& longitudinal,
                            std::array<double, 2>& lateralForce) {
    // The drive or rolling force takes its share of the friction ellipse first; the side force
    // follows the Magic Formula in the slip angle, scaled to what the ellipse leaves.
    longitudinal[axle] = std::clamp(longitudinal[axle], -peak, peak);
    const double share = peak > 0.0 ? longitudinal[axle] / peak : 1.0;
    const double available = std::sqrt(std::max(0.0, 1.0 - share * share));
    // Shape C from the frictions: the curve falls from mu_s N at its peak to mu_k N at large
    // slip (D sin(C pi / 2) = mu_k N).
    const double ratio = peak > 0.0 ? std::clamp(sliding / peak, 0.05, 1.0) : 1.0;
    const double shape = 2.0 / M_PI * (M_PI - std::asin(ratio));
    // B from the cornering stiffness per unit load: B C D = stiffness N with D = mu_s N.
    const double axleFriction = axle == 1 ? parameters_.staticFriction * parameters_.rearGripRatio
                                          : parameters_.staticFriction;
    const double b = parameters_.tyreStiffness / (shape * axleFriction);
    // Slip angle, with a floor on the speed so that it stays defined near standstill.
    const double alpha = std::atan2(slipSpeed, std::max(std::abs(rollingSpeed), 0.3));
    const double force = peak * available * std::sin(shape * std::atan(b * std::abs(alpha)));
    // Never more than stops the slip this step (what the contact would do at low speed).
    const double side = std::min(force, std::abs(wanted));
    lateralForce[axle] = slipSpeed > 0.0 ? -side : (slipSpeed < 0.0 ? side : 0.0);
    const bool pastPeak = b * std::abs(alpha) > std::tan(M_PI / (2.0 * shape));
    sliding_[axle] = pastPeak;
    return pastPeak;
}

}  // namespace prisca::sim
