#pragma once

#include "sim/plants/AcrobotEquations.h"
#include "sim/plants/Plant.h"

#include <array>
#include <memory>
#include <random>

class b2Body;
class b2Joint;
class b2World;

namespace prisca::sim {

/// The simulated acrobot's parameters. Plain data; SI units.
struct AcrobotParameters {
    AcrobotConstants links;  ///< masses, lengths, inertias and gravity (the book's constants)
    /// Limit on |tau1| and |tau2| [N m]. 10 N m is about half the 19.6 N m the shoulder needs to
    /// hold the straight arm horizontal and twice the 4.9 N m the elbow needs to hold link 2
    /// horizontal: the elbow can place link 2 freely, but the arm as a whole has to be pumped up
    /// by swinging, which is the paper's "limited torque" regime.
    double torqueLimit = 10.0;
    /// The underactuated acrobot: only the elbow is driven. The action stays 2-D (tau1, tau2) so
    /// that controllers and demonstrations keep one shape; tau1's limits become [0, 0], so any
    /// tau1 commanded is clamped to 0 (and gets no actuator noise).
    bool elbowOnly = false;
    double jointDamping = 0.0;  ///< viscous friction in each joint [N m s/rad]; 0 = the book arm
    /// Box2D velocity iterations per physics step. Measured against the analytic equations: with
    /// warm starting the two-pin chain has converged from 4 on (the states then differ by
    /// < 1e-5 rad from 100 iterations'; the remaining error is the first-order time step), so 20
    /// is a wide margin at about 14 us per control step.
    int velocityIterations = 20;
    /// Box2D position iterations per physics step (pin drift). Box2D stops once both pins are
    /// within its 5 mm slop, which one pass achieves here (measured gap ~0.1 mm in a large swing).
    int positionIterations = 8;
    /// atRest() once the energy is within this of the arm hanging still [J] (about 0.01 rad of
    /// swing or 0.02 rad/s of shoulder rate).
    double restEnergy = 1e-3;
};

/// A two-link acrobot swinging in a vertical plane (docs/architecture.md "Plants"), simulated with
/// Box2D: a static ground body, link 1 pinned to it at the origin (the shoulder) and link 2 pinned
/// to the end of link 1 (the elbow), each with b2RevoluteJoints, masses and inertias set exactly,
/// gravity (0, -g), and no collision between the links. Must agree with AcrobotEquations.
///
/// State (n = 4): theta1, theta2 [rad], dtheta1, dtheta2 [rad/s] in AcrobotEquations' convention
/// (theta1 from the downward vertical, theta2 relative to link 1, counter-clockwise positive);
/// the angles are wrapped to (-pi, pi] (the tracking error wraps them too: angleIndices {0, 1}).
/// Actions (m = 2): the joint torques tau1 (shoulder), tau2 (elbow) [N m] in
/// [-torqueLimit, torqueLimit] (tau1 fixed at 0 when elbowOnly). A non-finite torque is taken as 0.
///
/// Perturbation at level 1 (all from the seed): initial angle offsets of 0.05 rad std per joint
/// (the arm starts at rest); link 2's mass and inertia x (1 + 0.05 N(0,1)) (a payload or a
/// denser link), and viscous joint friction of 0.05 |N(0,1)| N m s/rad (one draw, in both joints)
/// on top of jointDamping; actuator noise of 2 % of torqueLimit std per joint, drawn per control
/// step. The noisy torque is clamped again: a motor never exceeds its limit.
class Acrobot : public Plant {
  public:
    explicit Acrobot(AcrobotParameters parameters = {}, SimulationTiming timing = {});
    ~Acrobot() override;
    Acrobot(const Acrobot&) = delete;
    Acrobot& operator=(const Acrobot&) = delete;

    const PlantInfo& info() const override { return info_; }
    const SimulationTiming& timing() const override { return timing_; }
    /// Starts hanging down at rest (plus the seeded offsets of the perturbation).
    Eigen::VectorXd reset(std::uint64_t seed, const Perturbation& perturbation) override;
    Eigen::VectorXd resetTo(const Eigen::VectorXd& state) override;
    Eigen::VectorXd step(const Eigen::VectorXd& action) override;
    std::unique_ptr<Plant> clone(bool actuatorNoise = false) const override;
    Eigen::VectorXd state() const override;
    double time() const override { return steps_ * timing_.controlPeriod; }
    /// True once the arm hangs still (energy within restEnergy of its minimum).
    bool atRest() const override;

    /// The nominal parameters.
    const AcrobotParameters& parameters() const { return parameters_; }
    /// The equations of this trial's arm (link 2's mass and inertia as perturbed) [SI].
    const AcrobotEquations& trialEquations() const { return trialEquations_; }
    /// The viscous friction of each joint in this trial [N m s/rad].
    double trialJointDamping() const { return trialJointDamping_; }
    /// The torques applied in the last control step (clamped, with noise) [N m].
    const Eigen::Vector2d& appliedTorque() const { return appliedTorque_; }
    /// The arm's elbow and tip [m] for display (forward kinematics of state()).
    AcrobotPoints points() const;
    /// The larger of the two pin joints' gaps between their anchor points on either body [m]:
    /// Box2D's remaining constraint error (diagnostics and tests).
    double jointGap() const;

    /// The plant description for these parameters (limits, elbow-only).
    static PlantInfo describe(const AcrobotParameters& parameters = {});

  private:
    void build(const Eigen::Vector4d& state);
    void physicsStep(const Eigen::Vector2d& tau);
    void wrapBodyAngles();

    AcrobotParameters parameters_;
    SimulationTiming timing_;
    PlantInfo info_;
    std::unique_ptr<b2World> world_;
    b2Body* link1_ = nullptr;
    b2Body* link2_ = nullptr;
    std::array<b2Joint*, 2> joints_{{nullptr, nullptr}};  // shoulder, elbow
    long long steps_ = 0;  // control steps since the last reset (time = steps x period)
    Eigen::Vector2d appliedTorque_ = Eigen::Vector2d::Zero();
    // Per-trial perturbation.
    AcrobotEquations trialEquations_;
    double trialJointDamping_ = 0.0;
    double actuatorNoise_ = 0.0;  // torque noise std [N m]
    std::mt19937_64 noise_;
};

}  // namespace prisca::sim
