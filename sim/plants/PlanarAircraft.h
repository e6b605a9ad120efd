#pragma once

#include "sim/plants/GustyWind.h"
#include "sim/plants/Plant.h"

#include <memory>
#include <random>

class b2Body;
class b2World;

namespace prisca::sim {

/// Physical constants of the small fixed-wing UAV (about 2 kg, 2 m span, cruising 15-20 m/s).
/// Plain data; SI units. Aerodynamic derivatives are per radian and in the plant's frame (body x
/// forward, y left, yaw counter-clockwise, rudder positive = nose left); their magnitudes are the
/// usual published ones: a light general-aviation aircraft has about CY_beta -0.56,
/// Cn_beta 0.071, Cn_r -0.125, |Cn_delta_r| 0.072, and a small survey UAV about CY_beta -0.98,
/// Cn_beta 0.25, Cn_r -0.35. Against NED body axes with the usual rudder sign (trailing edge left
/// positive) the rudder derivatives flip sign; the beta and r ones do not.
struct PlanarAircraftParameters {
    double mass = 2.0;              ///< [kg]
    double yawInertia = 0.15;       ///< about the vertical axis through the centre of mass [kg m^2]
    double wingArea = 0.5;          ///< reference area S [m^2]
    double wingSpan = 2.0;          ///< reference span b [m] (aspect ratio b^2 / S = 8)
    double airDensity = 1.225;      ///< rho, sea-level standard atmosphere [kg/m^3]
    double gravity = 9.81;          ///< sets the lift, and with it the induced drag [m/s^2]
    double zeroLiftDrag = 0.04;     ///< CD0 of a small UAV with exposed payload (0.02..0.05) [1]
    double oswaldEfficiency = 0.8;  ///< e in the induced drag CL^2 / (pi e AR) [1]
    double maxLiftCoefficient = 1.2;  ///< CL cap below the stall speed (about 8 m/s) [1]
    double sideslipDrag = 0.15;       ///< CD_beta2: extra drag coefficient per rad^2 sideslip [1]
    /// CY_beta [1/rad], < 0: side force from sideslip. In this top-down model it is also what
    /// turns the aircraft (flat turn), standing in for the horizontal lift of a banked turn, so it
    /// sits at the large end of the textbook range.
    double sideForceSideslip = -1.0;
    double sideForceRudder = -0.1;    ///< CY_delta_r [1/rad]: the fin pushed right by left rudder
    double yawMomentSideslip = 0.08;  ///< Cn_beta [1/rad], > 0: weathercock stability
    double yawMomentRudder = 0.05;    ///< Cn_delta_r [1/rad], > 0: positive rudder yaws left
    double yawDamping = -0.15;        ///< Cn_r per non-dimensional yaw rate r b / (2 V) [1], < 0
    double maxRudderDeflection = 0.436;  ///< rudder angle at full deflection, 25 deg [rad]
    double staticThrust = 13.0;  ///< thrust at full throttle and zero airspeed [N] (T/W 0.66)
    /// Forward airspeed at which the propeller's thrust has fallen to zero [m/s]: thrust is
    /// throttle * staticThrust * (1 - u_air / pitchSpeed), the usual fixed-pitch propeller line.
    double propellerPitchSpeed = 40.0;
    double restSpeed = 0.1;     ///< below this ground speed ... [m/s]
    double restYawRate = 0.05;  ///< ... and this yaw rate the aircraft is at rest [rad/s]
};

/// A small fixed-wing UAV flying in the horizontal plane, seen from above (docs/architecture.md
/// "Plants"; the paper's aerial robot, section V.B), simulated as one Box2D body with gravity off
/// and aerodynamic and propeller forces and a yaw moment applied at every physics step.
///
/// State (n = 6): x, y [m] world position of the centre of mass; heading psi [rad] of the body x
/// axis (the nose), counter-clockwise from world x, continuous (not wrapped: two left circles
/// give 4 pi; the deviation model wraps it); u, v [m/s] the ground velocity in the body frame
/// (forward, left); r [rad/s] yaw rate, positive counter-clockwise.
/// Actions (m = 2): throttle in [0, 1] and rudder in [-1, 1], positive = yaw left
/// (counter-clockwise), scaled to +-maxRudderDeflection. A non-finite action component is
/// replaced by 0 (engine off, rudder centred).
///
/// Forces, all with the airspeed vector V_a = ground velocity - wind, V = |V_a|, sideslip
/// beta = atan2(v_air, u_air) (positive when the air-relative motion is to the left of the nose),
/// q = rho V^2 / 2, delta = rudder * maxRudderDeflection:
///   thrust  throttle * staticThrust * max(0, 1 - u_air / pitchSpeed) along the nose;
///   drag    q S (CD0 + CL^2 / (pi e AR) + CD_beta2 beta^2) against V_a, CL = m g / (q S) capped;
///   side    q S (CY_beta beta + CY_delta_r delta) along body y;
///   yaw     q S b (Cn_beta beta + Cn_delta_r delta + Cn_r r b / (2 V)).
/// Flat turns only (no bank, no altitude); valid for airspeeds of about 9..30 m/s and small
/// sideslip (|beta| < 30 deg); outside it stays finite but is not aerodynamics.
///
/// Measured with the default parameters (tests/sim/test_aircraft.cpp): straight flight at
/// 17 m/s trims at throttle 0.503 (analytic and simulated agree to 1e-4) and holds speed and
/// heading exactly; full throttle tops out at 21.7 m/s, throttle 0 decelerates at about 1.9 m/s^2.
/// Full rudder settles into a flat turn of 34 m radius (21 deg/s, sideslip 12.5 deg) whatever
/// the speed; the turn costs drag, so at trim throttle the speed falls to 12.5 m/s (16.7 m/s at
/// full throttle); half rudder gives about 70 m. The yaw-sideslip (weathercock) mode is well
/// damped: a 0.5 rad/s yaw-rate kick is below 1% after 0.7 s, a 10 deg sideslip is gone in 3 s.
/// Below about 8 m/s a real aircraft would stall; this model just keeps decelerating.
///
/// Precision: Box2D integrates in float, so at the start of every control period the body is
/// put back at Box2D's origin with angle 0 and the pose is carried in double offsets; position
/// and heading therefore keep full precision at any distance, velocities keep float precision
/// (about 1e-6 relative). Box2D's b2_maxTranslation (2 m per physics step) limits the ground
/// speed to 2 / physicsStep (800 m/s at 400 Hz, 80 m/s at 40 Hz).
///
/// Perturbation at level 1 (all from the seed): initial offsets N(0, 2 m) on x and y,
/// N(0, 5 deg) on heading, N(0, 1 m/s) on the airspeed; a steady wind of 2 m/s towards a
/// uniformly random direction plus gusts of 1 m/s rms per axis with a 2 s correlation time
/// (GustyWind); thrust and drag each scaled by a uniform factor in [0.95, 1.05] (the span scales
/// with the level); actuator noise N(0, 0.02) on throttle and N(0, 0.04) on rudder (2% of each
/// range) per control step. The nominal start is the origin, heading 0, flying at 17 m/s
/// airspeed along the nose (trimmed, zero sideslip, in whatever wind the trial draws).
class PlanarAircraft : public Plant {
  public:
    /// Cruise airspeed of the nominal start [m/s].
    static constexpr double nominalSpeed = 17.0;

    explicit PlanarAircraft(PlanarAircraftParameters parameters = {}, SimulationTiming timing = {});
    ~PlanarAircraft() override;
    PlanarAircraft(const PlanarAircraft&) = delete;
    PlanarAircraft& operator=(const PlanarAircraft&) = delete;

    const PlantInfo& info() const override { return info_; }
    const SimulationTiming& timing() const override { return timing_; }
    Eigen::VectorXd reset(std::uint64_t seed, const Perturbation& perturbation) override;
    Eigen::VectorXd resetTo(const Eigen::VectorXd& state) override;
    Eigen::VectorXd step(const Eigen::VectorXd& action) override;
    std::unique_ptr<Plant> clone(bool actuatorNoise = false) const override;
    Eigen::VectorXd state() const override;
    double time() const override { return time_; }
    bool atRest() const override;

    /// The air's velocity over the ground now [m/s], world frame (zero without wind).
    Eigen::Vector2d wind() const { return wind_.velocity(); }
    std::optional<Eigen::Vector2d> windVelocity() const override { return wind(); }
    /// The wind field of the trial (steady part, gusts, statistics).
    const GustyWind& windField() const { return wind_; }
    /// Replaces the wind for the rest of the trial (tests, scenario set-ups); the state is kept.
    void setWind(const GustyWindParameters& wind, std::uint64_t seed);
    /// Airspeed |ground velocity - wind| now [m/s].
    double airspeed() const;
    /// Sideslip now [rad], positive when the air-relative motion is to the left of the nose.
    double sideslip() const;
    /// The thrust and drag factors of this trial (1 when nominal).
    double thrustScale() const { return thrustScale_; }
    double dragScale() const { return dragScale_; }
    const PlanarAircraftParameters& parameters() const { return parameters_; }

    /// The plant description shared by every planar aircraft.
    static PlantInfo describe();
    /// The throttle that holds straight flight at this airspeed [m/s] in still air with nominal
    /// thrust and drag (0.503 at 17 m/s). Above 1 when full throttle cannot hold that speed,
    /// infinite at or above the propeller's pitch speed.
    static double trimThrottle(const PlanarAircraftParameters& parameters, double airspeed);

  private:
    void build(double x, double y, double psi, const Eigen::Vector2d& groundVelocity, double r);
    void physicsStep(double throttle, double rudder);
    double heading() const;

    PlanarAircraftParameters parameters_;
    SimulationTiming timing_;
    PlantInfo info_;
    std::unique_ptr<b2World> world_;
    b2Body* body_ = nullptr;
    // The pose in double; the Box2D body only carries the motion since the last control period.
    Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
    double headingOrigin_ = 0.0;
    double time_ = 0.0;
    GustyWind wind_;
    // Per-trial perturbation.
    double thrustScale_ = 1.0;
    double dragScale_ = 1.0;
    double throttleNoise_ = 0.0;
    double rudderNoise_ = 0.0;
    std::mt19937_64 noise_;
};

}  // namespace prisca::sim
