#pragma once

#include "sim/plants/Plant.h"

#include <array>
#include <memory>
#include <random>

class b2Body;
class b2World;

namespace prisca::sim {

/// Physical constants of a small differential-drive ground robot (two driven wheels and a
/// caster, the kind most labs have). Plain data; SI units.
struct DiffDriveParameters {
    double mass = 2.0;                ///< [kg]
    double length = 0.30;             ///< body length [m]
    double width = 0.25;              ///< body width [m]
    double track = 0.24;              ///< distance between the two wheels [m]
    double yawInertia = 0.02;         ///< about the centre [kg m^2]
    double maxWheelSpeed = 0.6;       ///< wheel rim speed at a command of 1 [m/s]
    double motorTimeConstant = 0.12;  ///< first-order lag of each wheel's speed [s]
    double friction = 0.5;            ///< tyre-floor coefficient mu (wheels slip past mu N)
    double tractionStiffness = 0.3;   ///< share of the slip a wheel removes per physics step [1]
    double casterDrag = 0.4;          ///< viscous drag of the caster [N s/m]
    double gravity = 9.81;            ///< [m/s^2]
    double restSpeed = 0.01;          ///< below this speed ... [m/s]
    double restYawRate = 0.05;        ///< ... and this yaw rate the robot is at rest [rad/s]
};

/// A differential-drive robot on a flat floor seen from above, one Box2D body with gravity off
/// and a traction force at each wheel each physics step.
///
/// State (n = 6, as the slide-car's): x, y [m], heading psi [rad], body-frame velocities vx
/// (forward), vy (left) [m/s], yaw rate r [rad/s]. Actions (m = 2): left and right wheel speed
/// commands in [-1, 1] (1 is maxWheelSpeed forward). Each wheel's speed follows its command with
/// a first-order motor lag; a wheel's traction removes part of its slip against the floor each
/// step, within the friction circle mu N (so hard accelerations and turns slip).
///
/// Perturbation at level 1 (all from the seed): initial offset 2 cm per axis and 2 deg heading;
/// each wheel's gain x (1 + 0.05 N(0,1)) (unequal wheels make it drift), friction
/// x (1 + 0.1 N(0,1)); actuator noise 0.02 N(0,1) per step on both wheels.
class DiffDrive : public Plant {
  public:
    explicit DiffDrive(DiffDriveParameters parameters = {}, SimulationTiming timing = {});
    ~DiffDrive() override;
    DiffDrive(const DiffDrive&) = delete;
    DiffDrive& operator=(const DiffDrive&) = delete;

    const PlantInfo& info() const override { return info_; }
    const SimulationTiming& timing() const override { return timing_; }
    Eigen::VectorXd reset(std::uint64_t seed, const Perturbation& perturbation) override;
    Eigen::VectorXd resetTo(const Eigen::VectorXd& state) override;
    Eigen::VectorXd step(const Eigen::VectorXd& action) override;
    std::unique_ptr<Plant> clone(bool actuatorNoise = false) const override;
    Eigen::VectorXd state() const override;
    double time() const override { return time_; }
    bool atRest() const override;

    const DiffDriveParameters& parameters() const { return parameters_; }

    /// The plant description shared by every differential-drive robot.
    static PlantInfo describe();

  private:
    void build(double x, double y, double psi, double vx, double vy, double r);
    void physicsStep(const std::array<double, 2>& command);

    DiffDriveParameters parameters_;
    SimulationTiming timing_;
    PlantInfo info_;
    std::unique_ptr<b2World> world_;
    b2Body* body_ = nullptr;
    double time_ = 0.0;
    std::array<double, 2> wheelSpeed_{{0.0, 0.0}};
    // Per-trial perturbation.
    std::array<double, 2> wheelGain_{{1.0, 1.0}};
    double frictionScale_ = 1.0;
    double actuatorNoise_ = 0.0;
    std::mt19937_64 noise_;
};

}  // namespace prisca::sim
