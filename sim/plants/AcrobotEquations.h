#pragma once

#include <Eigen/Core>

namespace prisca::sim {

/// The constants of the common reinforcement-learning acrobot (its "book" dynamics).
/// Plain data; SI units. The defaults are the standard values (docs/architecture.md "Plants").
struct AcrobotConstants {
    double m1 = 1.0;   ///< mass of link 1 [kg]
    double m2 = 1.0;   ///< mass of link 2 [kg]
    double l1 = 1.0;   ///< length of link 1, shoulder to elbow [m]
    double l2 = 1.0;   ///< length of link 2, elbow to tip [m] (kinematics only)
    double lc1 = 0.5;  ///< shoulder to the centre of mass of link 1 [m]
    double lc2 = 0.5;  ///< elbow to the centre of mass of link 2 [m]
    double I1 = 1.0;   ///< moment of inertia of link 1 about its centre of mass [kg m^2]
    double I2 = 1.0;   ///< moment of inertia of link 2 about its centre of mass [kg m^2]
    double g = 9.8;    ///< gravitational acceleration [m/s^2]
};

/// Points of the arm in the vertical plane [m]: x to the right, y up, the shoulder at the origin.
struct AcrobotPoints {
    Eigen::Vector2d elbow;    ///< end of link 1 [m]
    Eigen::Vector2d tip;      ///< end of link 2 [m]
    Eigen::Vector2d centre1;  ///< centre of mass of link 1 [m]
    Eigen::Vector2d centre2;  ///< centre of mass of link 2 [m]
};

/// The analytic "book" equations of motion of the acrobot, generalised to a torque at both joints:
///
///     d1 ddth1 + d2 ddth2 + phi1 = tau1
///     d2 ddth1 + d3 ddth2 + m2 l1 lc2 dth1^2 sin th2 + phi2 = tau2
///
/// State s = (theta1, theta2, dtheta1, dtheta2) [rad, rad, rad/s, rad/s]: theta1 is link 1's angle
/// from the downward vertical (0 = hanging down), theta2 link 2's angle relative to link 1; both
/// counter-clockwise positive seen with x to the right and y up. tau = (tau1, tau2) [N m] are the
/// joint torques: tau1 acts between the ground and link 1, tau2 between link 1 and link 2. With
/// tau1 = 0 this is the underactuated acrobot of the book. Plain functions; any thread.
struct AcrobotEquations {
    AcrobotConstants constants;  ///< the arm

    /// The mass matrix [[d1, d2], [d2, d3]] at elbow angle theta2 [rad] ([kg m^2]).
    Eigen::Matrix2d massMatrix(double theta2) const;
    /// ds/dt at state s under joint torques tau [N m]: (dth1, dth2, ddth1, ddth2).
    Eigen::Vector4d derivative(const Eigen::Vector4d& state, const Eigen::Vector2d& tau) const;
    /// One classical Runge-Kutta 4 step of h [s] with tau held constant.
    Eigen::Vector4d rk4Step(const Eigen::Vector4d& state, const Eigen::Vector2d& tau,
                            double h) const;
    /// RK4 over duration [s] with tau held constant, in ceil(duration / maxStep) equal steps.
    Eigen::Vector4d integrate(const Eigen::Vector4d& state, const Eigen::Vector2d& tau,
                              double duration, double maxStep) const;

    /// Kinetic energy [J].
    double kineticEnergy(const Eigen::Vector4d& state) const;
    /// Potential energy [J], zero with both centres of mass at the shoulder's height (so the arm
    /// hanging at rest has -((m1 lc1 + m2 l1) + m2 lc2) g).
    double potentialEnergy(const Eigen::Vector4d& state) const;
    /// Total mechanical energy, kinetic + potential [J].
    double energy(const Eigen::Vector4d& state) const;

    /// Forward kinematics of the link end points and centres of mass [m].
    AcrobotPoints points(const Eigen::Vector4d& state) const;
};

}  // namespace prisca::sim
