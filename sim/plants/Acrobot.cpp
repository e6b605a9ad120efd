#include "sim/plants/Acrobot.h"

#include "core/DeviationModel.h"

#include "sim/plants/Box2dConversions.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace prisca::sim {

namespace {

using core::kPi;

// Realistic-lab perturbation levels (documented in Acrobot.h).
constexpr double kInitialAngleStd = 0.05;        // [rad] per joint
constexpr double kLink2MassStd = 0.05;           // relative
constexpr double kJointFrictionScale = 0.05;     // [N m s/rad], half-normal
constexpr double kActuatorNoiseFraction = 0.02;  // of the torque limit

using core::wrapAngle;

// Velocity of a point at offset r from a pivot moving at v, turning at rate w (2-D cross product).
Eigen::Vector2d pointVelocity(const Eigen::Vector2d& v, double w, const Eigen::Vector2d& r) {
    return v + w * Eigen::Vector2d(-r.y(), r.x());
}

// One link: a dynamic body whose origin is its centre of mass, the link pointing along local -y
// (so the body angle is the link's absolute angle from the downward vertical).
b2Body* createLink(b2World& world, const Eigen::Vector2d& centre, double angle,
                   const Eigen::Vector2d& velocity, double rate, double mass, double inertia,
                   double length, double toCentre) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = toBox2d(centre);
    def.angle = static_cast<float>(angle);
    def.linearVelocity = toBox2d(velocity);
    def.angularVelocity = static_cast<float>(rate);
    def.allowSleep = false;  // a pendulum passing a turning point must never be put to sleep
    b2Body* body = world.CreateBody(&def);

    // A thin box for debug drawing only: zero density so it adds no mass, and a shared negative
    // group so the links never collide with each other (or with anything).
    b2PolygonShape box;
    const float halfLength = static_cast<float>(length / 2.0);
    box.SetAsBox(0.025f, halfLength, b2Vec2(0.0f, static_cast<float>(toCentre - length / 2.0)),
                 0.0f);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = 0.0f;
    fixture.filter.groupIndex = -1;
    body->CreateFixture(&fixture);

    // Exact mass properties: I about the body origin, which is the centre of mass.
    b2MassData data;
    data.mass = static_cast<float>(mass);
    data.center.SetZero();
    data.I = static_cast<float>(inertia);
    body->SetMassData(&data);
    return body;
}

b2Joint* pin(b2World& world, b2Body* a, b2Body* b, const b2Vec2& anchorOnA,
             const b2Vec2& anchorOnB) {
    b2RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.localAnchorA = anchorOnA;
    def.localAnchorB = anchorOnB;
    // Reference angle 0 (not Initialize()'s current difference): the joint angle is then the
    // book's relative angle whatever state the arm is built in.
    def.referenceAngle = 0.0f;
    def.collideConnected = false;
    return world.CreateJoint(&def);
}

}  // namespace

PlantInfo Acrobot::describe(const AcrobotParameters& parameters) {
    PlantInfo info;
    info.name = QStringLiteral("acrobot");
    info.description =
        parameters.elbowOnly
            ? QStringLiteral("Two-link acrobot in a vertical plane, torque at the elbow only")
            : QStringLiteral("Two-link acrobot in a vertical plane, torque at both joints");
    info.stateNames = {"theta1", "theta2", "dtheta1", "dtheta2"};
    info.stateUnits = {"rad", "rad", "rad/s", "rad/s"};
    info.actionNames = {"tau1", "tau2"};
    info.actionUnits = {"N m", "N m"};
    const double limit = parameters.torqueLimit;
    const double shoulder = parameters.elbowOnly ? 0.0 : limit;
    info.actionLower = Eigen::Vector2d(-shoulder, -limit);
    info.actionUpper = Eigen::Vector2d(shoulder, limit);
    info.angleIndices = {0, 1};
    return info;
}

Acrobot::Acrobot(AcrobotParameters parameters, SimulationTiming timing)
    : parameters_(parameters), timing_(timing), info_(describe(parameters)) {
    if (timing_.controlPeriod <= 0.0 || timing_.physicsSubsteps < 1) {
        throw std::invalid_argument("Acrobot: control period > 0 and >= 1 physics substep needed");
    }
    if (!(parameters_.torqueLimit >= 0.0) || parameters_.velocityIterations < 1 ||
        parameters_.positionIterations < 1) {
        throw std::invalid_argument("Acrobot: torque limit >= 0 and solver iterations >= 1 needed");
    }
    trialEquations_.constants = parameters_.links;
    trialJointDamping_ = parameters_.jointDamping;
    build(Eigen::Vector4d::Zero());
}

Acrobot::~Acrobot() = default;

void Acrobot::build(const Eigen::Vector4d& s) {
    const AcrobotConstants& c = trialEquations_.constants;
    // A fresh world per trial: no warm-start impulses of the previous trial survive.
    world_ = std::make_unique<b2World>(b2Vec2(0.0f, static_cast<float>(-c.g)));
    b2BodyDef groundDef;
    b2Body* ground = world_->CreateBody(&groundDef);

    // Bodies placed and moving consistently with the joint angles and rates (forward kinematics).
    const AcrobotPoints p = trialEquations_.points(s);
    const double w1 = s[2];
    const double w2 = s[2] + s[3];
    const Eigen::Vector2d v1 = pointVelocity(Eigen::Vector2d::Zero(), w1, p.centre1);
    const Eigen::Vector2d vElbow = pointVelocity(Eigen::Vector2d::Zero(), w1, p.elbow);
    const Eigen::Vector2d v2 = pointVelocity(vElbow, w2, p.centre2 - p.elbow);
    link1_ = createLink(*world_, p.centre1, s[0], v1, w1, c.m1, c.I1, c.l1, c.lc1);
    link2_ = createLink(*world_, p.centre2, s[0] + s[1], v2, w2, c.m2, c.I2, c.l2, c.lc2);

    joints_[0] =
        pin(*world_, ground, link1_, b2Vec2(0.0f, 0.0f), b2Vec2(0.0f, static_cast<float>(c.lc1)));
    joints_[1] = pin(*world_, link1_, link2_, b2Vec2(0.0f, static_cast<float>(-(c.l1 - c.lc1))),
                     b2Vec2(0.0f, static_cast<float>(c.lc2)));
    steps_ = 0;
    appliedTorque_.setZero();
}

Eigen::VectorXd Acrobot::reset(std::uint64_t seed, const Perturbation& perturbation) {
    std::mt19937_64 draw(mixSeed(seed, 0));
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::Vector4d s = Eigen::Vector4d::Zero();
    s[0] = kInitialAngleStd * perturbation.initialState * normal(draw);
    s[1] = kInitialAngleStd * perturbation.initialState * normal(draw);

    AcrobotConstants c = parameters_.links;
    // Clamped so that a wild draw at a large level still leaves a physical arm.
    // Session model: the day's payload and joint friction, the same every trial of the day.
    std::optional<SessionDay> day;
    if (perturbation.session()) {
        day.emplace(perturbation);
    }
    auto draw1 = [&] { return day ? day->normal() : normal(draw); };
    const double massScale =
        std::clamp(1.0 + kLink2MassStd * perturbation.parameters * draw1(), 0.5, 1.5);
    c.m2 *= massScale;
    c.I2 *= massScale;
    trialEquations_.constants = c;
    trialJointDamping_ = parameters_.jointDamping +
                         kJointFrictionScale * std::abs(perturbation.parameters * draw1());
    actuatorNoise_ = kActuatorNoiseFraction * parameters_.torqueLimit *
                     std::max(0.0, perturbation.actuatorNoise);
    noise_.seed(mixSeed(seed, 1));
    build(s);
    return state();
}

Eigen::VectorXd Acrobot::resetTo(const Eigen::VectorXd& s) {
    // Checked before it reaches the physics engine, which asserts on what it cannot hold.
    if (const QString problem = info().stateProblem(s); !problem.isEmpty()) {
        throw std::invalid_argument(problem.toStdString());
    }
    trialEquations_.constants = parameters_.links;
    trialJointDamping_ = parameters_.jointDamping;
    actuatorNoise_ = 0.0;
    build(Eigen::Vector4d(wrapAngle(s[0]), wrapAngle(s[1]), s[2], s[3]));
    return state();
}

std::unique_ptr<Plant> Acrobot::clone(bool actuatorNoise) const {
    auto copy = std::make_unique<Acrobot>(parameters_, timing_);
    copy->trialEquations_ = trialEquations_;
    copy->trialJointDamping_ = trialJointDamping_;
    copy->build(Eigen::Vector4d(state()));
    // The links exactly where they are (joint gaps included); only the joints' warm-start
    // impulses start afresh, a difference of the solver's tolerance.
    copyMotion(*link1_, *copy->link1_);
    copyMotion(*link2_, *copy->link2_);
    copy->steps_ = steps_;
    copy->appliedTorque_ = appliedTorque_;
    copy->actuatorNoise_ = actuatorNoise ? actuatorNoise_ : 0.0;
    copy->noise_ = noise_;
    return copy;
}

Eigen::VectorXd Acrobot::state() const {
    const double a1 = link1_->GetAngle();
    const double a2 = link2_->GetAngle();
    const double w1 = link1_->GetAngularVelocity();
    const double w2 = link2_->GetAngularVelocity();
    Eigen::VectorXd s(4);
    s << wrapAngle(a1), wrapAngle(a2 - a1), w1, w2 - w1;
    return s;
}

AcrobotPoints Acrobot::points() const {
    return trialEquations_.points(state());
}

double Acrobot::jointGap() const {
    double gap = 0.0;
    for (const b2Joint* joint : joints_) {
        const b2Vec2 d = joint->GetAnchorB() - joint->GetAnchorA();
        gap = std::max(gap, static_cast<double>(d.Length()));
    }
    return gap;
}

bool Acrobot::atRest() const {
    const AcrobotConstants& c = trialEquations_.constants;
    const double hanging = -((c.m1 * c.lc1 + c.m2 * c.l1) + c.m2 * c.lc2) * c.g;
    return trialEquations_.energy(state()) - hanging < parameters_.restEnergy;
}

Eigen::VectorXd Acrobot::step(const Eigen::VectorXd& action) {
    if (action.size() != 2) {
        throw std::invalid_argument("Acrobot::step: the action needs 2 values (tau1, tau2)");
    }
    Eigen::Vector2d tau;
    for (int j = 0; j < 2; ++j) {
        // A broken command must never drive a joint: a non-finite torque is taken as 0.
        const double wanted = std::isfinite(action[j]) ? action[j] : 0.0;
        const double lo = info_.actionLower[j];
        const double hi = info_.actionUpper[j];
        tau[j] = std::clamp(wanted, lo, hi);
        if (actuatorNoise_ > 0.0 && hi > lo) {
            std::normal_distribution<double> normal(0.0, actuatorNoise_);
            tau[j] = std::clamp(tau[j] + normal(noise_), lo, hi);
        }
    }
    appliedTorque_ = tau;
    for (int i = 0; i < timing_.physicsSubsteps; ++i) {
        physicsStep(tau);
    }
    ++steps_;
    wrapBodyAngles();
    return state();
}

void Acrobot::physicsStep(const Eigen::Vector2d& tau) {
    // Joint friction from the rates at the start of the step (explicit, like the applied torque).
    const double w1 = link1_->GetAngularVelocity();
    const double w2 = link2_->GetAngularVelocity();
    const double shoulder = tau[0] - trialJointDamping_ * w1;
    const double elbow = tau[1] - trialJointDamping_ * (w2 - w1);
    // A joint torque acts on both bodies it joins: +shoulder on link 1 (and -shoulder on the
    // ground), +elbow on link 2 and its reaction -elbow on link 1. Forces are cleared by Step.
    link1_->ApplyTorque(static_cast<float>(shoulder - elbow), true);
    link2_->ApplyTorque(static_cast<float>(elbow), true);
    world_->Step(static_cast<float>(timing_.physicsStep()), parameters_.velocityIterations,
                 parameters_.positionIterations);
}

void Acrobot::wrapBodyAngles() {
    // Box2D keeps body angles unwrapped; a spinning arm would lose float resolution, so bring a
    // body back to (-pi, pi] once it has gone a full turn (the joints have no limits, so the jump
    // of 2 pi is invisible to the solver).
    for (b2Body* body : {link1_, link2_}) {
        const double a = body->GetAngle();
        if (std::abs(a) > 2.0 * kPi) {
            body->SetTransform(body->GetPosition(), static_cast<float>(wrapAngle(a)));
        }
    }
}

}  // namespace prisca::sim
