#pragma once

#include "sim/plants/Plant.h"

#include <array>
#include <deque>
#include <memory>
#include <random>
#include <utility>
#include <vector>

class b2Body;
class b2World;

namespace prisca::sim {

/// Physical constants of the brakeless 4x4 1:10 RC car. Plain data; SI units.
struct SlideCarParameters {
    double mass = 1.5;        ///< [kg]
    double length = 0.40;     ///< body length [m]
    double width = 0.20;      ///< body width [m]
    double wheelbase = 0.26;  ///< front to rear axle, centred on the origin [m]
    /// About the centre [kg m^2]; battery and motor sit mid-car, so well below a uniform box's
    /// m (L^2 + W^2) / 12 = 0.025. 0 means the uniform box.
    double yawInertia = 0.015;
    double cgHeight = 0.06;            ///< centre of mass above the floor, for load transfer [m]
    double maxSteeringAngle = 0.5236;  ///< front-wheel angle at full steering, 30 deg [rad]
    double servoRate = 6.0;            ///< slew rate of the front-wheel angle [rad/s]
    double servoDelay = 0.02;          ///< dead time of steering commands [s]
    double throttleDelay = 0.01;       ///< dead time of the speed controller [s]
    double maxDriveForce = 9.0;  ///< traction of all four wheels at standstill, full throttle [N]
    double topSpeed = 6.0;       ///< speed at which full throttle gives no more force [m/s]
    /// Centre of mass ahead of the wheelbase's midpoint [m] (negative: behind it). It sets the
    /// static load on each axle and each axle's lever arm about the centre of mass; the state's
    /// x, y are the centre of mass.
    double cgForward = 0.0;
    double staticFriction = 0.65;   ///< front tyres' static coefficient mu_s
    double kineticFriction = 0.45;  ///< front tyres' sliding coefficient mu_k (< mu_s: the "snap")
    /// The rear tyres' static and sliding coefficients as shares of the front's (harder or
    /// narrower rear tyres). Below about mu_k / mu_s the rear lets go once the front slides,
    /// which is what makes the car yaw into a slide when steered hard at speed rather than
    /// plough straight on.
    double rearGripRatio = 0.75;
    double rearKineticGripRatio = 0.75;
    double rollingResistance = 0.03;  ///< coefficient of rolling resistance
    double drivelineDrag = 0.5;       ///< viscous drag of motor and gears when coasting [N s/m]
    double gravity = 9.81;            ///< [m/s^2]
    double restSpeed = 0.02;          ///< below this speed ... [m/s]
    double restYawRate = 0.05;        ///< ... and this yaw rate the car is at rest [rad/s]

    // Effects a real car has that the identification model (the parameters above) leaves out:
    // the reality gap. Each is off at its default, so the catalog car is the model itself;
    // plant files switch them on (`unmodelled` in a plant file, docs/architecture.md "Plants").
    /// Tyres on a saturating force curve (the Magic Formula) instead of Coulomb stick-slip:
    /// cornering stiffness per unit load [1/rad]; 0 is off. The curve peaks at mu_s N, falls
    /// towards mu_k N at large slip angles, and shares the friction ellipse with the drive
    /// force (longitudinal and lateral slip coupled).
    double tyreStiffness = 0.0;
    /// Play in the steering linkage: the wheels follow the servo only once it has taken up
    /// this much angle [rad]; 0 is off.
    double servoBacklash = 0.0;
    /// A brushed motor's stall force as a multiple of the ESC's current limit (maxDriveForce):
    /// full force up to a speed, then falling more steeply than the linear law; 1 is off.
    double motorStallRatio = 1.0;
    /// The ESC's neutral band: commands below this share of full throttle do nothing, the rest
    /// is stretched over the range [1]; 0 is off.
    double escDeadband = 0.0;
    /// Floor patches: a checkerboard of squares patchSize on a side whose every other square
    /// has its grip scaled by patchFriction (felt per axle, at the axle); 1 is off.
    double patchFriction = 1.0;
    double patchSize = 0.5;  ///< [m]
};

/// A brakeless 4x4 RC car on a flat floor, seen from above (docs/architecture.md "Plants"),
/// simulated as one Box2D body with gravity off and tyre forces applied at the two axles each
/// physics step.
///
/// State (n = 6): x, y [m] of the car-frame origin (the body centre), heading psi [rad] of the
/// body x axis counter-clockwise from world x, body-frame velocities vx (forward), vy (left)
/// [m/s], yaw rate r [rad/s]. Actions (m = 2): throttle in [-1, 1] (negative is motor reverse;
/// there is no brake, 0 coasts) and steering in [-1, 1] (positive steers left).
///
/// Tyres: each step the lateral impulses that would stop both axles slipping sideways are solved
/// together; an axle whose demand (with its drive force) exceeds mu_s N snaps into a slide and
/// then transmits mu_k N until the demand falls below mu_k N (Coulomb stick-slip with a
/// static-to-kinetic drop). Normal loads shift between the axles with longitudinal acceleration.
///
/// Perturbation at level 1 (all from the seed): initial offset 3 cm per axis and 2 deg heading;
/// friction x (1 + 0.1 N(0,1)), throttle gain x (1 + 0.08 N(0,1)), steering trim 0.03 N(0,1);
/// actuator noise 0.02 N(0,1) per step on both channels.
///
/// Session model (Perturbation::Session, level 1): the same three mismatches drawn once for the
/// day (a floor's grip 10 %, an ESC and battery 8 %, a trim of 0.03 of full lock, about 1 deg
/// of wheel angle: what an operator who trimmed by eye leaves); the battery sags, the throttle
/// gain falling 0.2 % x (1 + 0.25 N(0,1)) per trial (a 2S pack loses about 7 % of its voltage
/// over the first half of its charge, some 35 trials of a few seconds' driving and the drive
/// back); and each trial its own friction x (1 + 0.03 N(0,1)) (dust, tyre temperature) and
/// trim 0.005 N(0,1) (the servo's centring repeatability). Offsets and noise as above.
class SlideCar : public Plant {
  public:
    explicit SlideCar(SlideCarParameters parameters = {}, SimulationTiming timing = {});
    ~SlideCar() override;
    SlideCar(const SlideCar&) = delete;
    SlideCar& operator=(const SlideCar&) = delete;

    const PlantInfo& info() const override { return info_; }
    const SimulationTiming& timing() const override { return timing_; }
    Eigen::VectorXd reset(std::uint64_t seed, const Perturbation& perturbation) override;
    Eigen::VectorXd resetTo(const Eigen::VectorXd& state) override;
    Eigen::VectorXd step(const Eigen::VectorXd& action) override;
    void primeActuators(const std::vector<Eigen::VectorXd>& recentActions) override;
    /// {front sliding, rear sliding, longitudinal acceleration [m/s^2]}.
    std::vector<double> hiddenState() const override;
    void setHiddenState(const std::vector<double>& hidden) override;
    bool setSteeringOffset(double offset) override;
    std::unique_ptr<Plant> clone(bool actuatorNoise = false) const override;
    Eigen::VectorXd state() const override;
    double time() const override { return time_; }
    bool atRest() const override;

    /// The current front-wheel angle [rad] (after servo delay and slew).
    double steeringAngle() const { return steeringAngle_; }
    /// Whether the front (0) or rear (1) axle is sliding.
    bool sliding(int axle) const { return sliding_[axle]; }
    const SlideCarParameters& parameters() const { return parameters_; }
    /// This trial's perturbed throttle gain, steering trim and friction scale (as reset drew
    /// them; 1, 0, 1 for the nominal car).
    double throttleGain() const { return throttleGain_; }
    double steeringTrim() const { return steeringTrim_; }
    double frictionScale() const { return frictionScale_; }

    /// The plant description shared by every slide-car.
    static PlantInfo describe();

  private:
    void build(double x, double y, double psi, double vx, double vy, double r);
    void physicsStep(double throttle, double steering);
    /// One physics step of the actuators: the commands through the dead times, the servo's
    /// slew and the linkage's play (steeringAngle_). Returns the throttle that reaches the
    /// motor (after the gain and the ESC's band) and the steering target.
    std::pair<double, double> actuatorStep(double throttleCommand, double steeringCommand);
    /// The floor's grip factor at a point (the patches; 1 where there are none).
    double patchScale(const Eigen::Vector2d& point) const;
    /// The Magic Formula tyre of one axle (tyreStiffness > 0): sets its longitudinal and side
    /// force from the force that would stop its slip (`wanted`), its peak and sliding friction
    /// forces and its contact's rolling and slip speeds. Returns whether it is past its peak.
    bool magicFormula(int axle, double wanted, double peak, double sliding, double rollingSpeed,
                      double slipSpeed, std::array<double, 2>& longitudinal,
                      std::array<double, 2>& lateralForce);

    SlideCarParameters parameters_;
    SimulationTiming timing_;
    PlantInfo info_;
    std::unique_ptr<b2World> world_;
    b2Body* body_ = nullptr;
    double time_ = 0.0;
    double steeringAngle_ = 0.0;
    double servoAngle_ = 0.0;  // the servo's output; the wheels follow it with the backlash
    double longitudinalAcceleration_ = 0.0;
    std::array<bool, 2> sliding_{{false, false}};
    std::deque<double> throttleQueue_;  // commands waiting out the dead times, one per physics step
    std::deque<double> steeringQueue_;
    // Per-trial perturbation.
    double frictionScale_ = 1.0;
    double throttleGain_ = 1.0;
    double steeringTrim_ = 0.0;
    double steeringOffset_ = 0.0;  // a model's estimate of its car's trim (setSteeringOffset)
    double actuatorNoise_ = 0.0;
    std::mt19937_64 noise_;
};

}  // namespace prisca::sim
