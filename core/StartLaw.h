#pragma once

#include "Controller.h"
#include "Demonstration.h"
#include "DeviationModel.h"
#include "PdFeedback.h"

#include <Eigen/Core>

namespace prisca::core {

/// How the start law is derived from a demonstration (deriveStartLaw). Plain data.
struct StartLawOptions {
    /// Samples between the two demonstration states whose deviation sets each error
    /// component's scale sigma_i (the RMS over the demonstration); >= 1. The product uses one
    /// second of samples, the window PRISCA's automatic feature scales use.
    int scaleLag = 40;
    /// H of the law's nested-expectation smoothing [steps], >= 0 (0: the raw error).
    int horizon = 0;
    /// The fitted drift A (n x n) of eq. 5, added to the error's own kinematics; empty: none.
    Eigen::MatrixXd drift;
    /// The loop's dead time tau [s] (the sensor's age, the actuators' dead time, the hold),
    /// >= 0; 0: none known, no limit on the loop's speed. Every closed-loop mode is then kept
    /// no faster than kDelayPhase / tau (see deriveStartLaw).
    double delay = 0.0;
    /// Which error components each control's law may use (m x n, non-zero: used; empty: all):
    /// B~, so that control l feeds back the components its row of B~ names, as the PD
    /// family's error combination c_l does. The LQR gain is computed in full, then restricted.
    Eigen::MatrixXd structure;
    /// Components the action sets rather than drives (m x n; empty: none): a non-zero column i
    /// says that error component i follows the controls' level, e_i = G[:, i]^T (u - u*), within
    /// a step (a car's yaw rate follows its steering), instead of integrating them as eq. 5's
    /// model has it. Such a component is not a state of the loop: what it drives through A-bar
    /// moves into B (B[:, j] += A-bar(j, i) G[:, i]), and the law gets no gain on it. A
    /// component given here that integrates another one given here (A-bar(j, i) != 0: the
    /// heading integrates the yaw rate) is driven through it and stays a state.
    Eigen::MatrixXd proportional;
};

/// The phase a dead time may take from the loop at its fastest mode [rad]: pi/6, half of the
/// 60 degrees of phase margin an LQR loop has in every channel, so that at least 30 degrees
/// remain with the delay.
inline constexpr double kDelayPhase = 3.14159265358979323846 / 6.0;

/// The start law and what it was derived from (for the operator to read and for tests).
struct StartLaw {
    /// The law as the PD family forms it: errorCombination = K (m x n), Kp = 1, Kd = 0, so that
    /// u = u* - K e (smoothed over horizon steps).
    PdParameters law;
    Eigen::MatrixXd gain;           ///< K (m x n)
    Eigen::VectorXd errorScale;     ///< sigma_i (n) [state units]
    Eigen::VectorXd actionScale;    ///< half the actuator range per control (m) [action units]
    Eigen::MatrixXd meanDynamics;   ///< A-bar (n x n) [1/s]: drift + mean kinematics
    Eigen::MatrixXd reducedModel;   ///< A-bar without the components the action sets (n x n)
    Eigen::MatrixXd reducedEffect;  ///< B with their effect moved in (m x n)
    Eigen::VectorXd effort;         ///< R per control, after the delay's limit
    double fastestMode = 0.0;       ///< |s| of the closed loop's fastest mode [1/s]
    int riccatiIterations = 0;      ///< iterations the stationary Riccati equation took
};

/// The stationary discrete-time LQR gain K = (R + Bd^T P Bd)^-1 Bd^T P Ad, P the solution of
/// P = Q + Ad^T P Ad - Ad^T P Bd (R + Bd^T P Bd)^-1 Bd^T P Ad, found by iterating the Riccati
/// recursion from P = Q until it settles (relative change < 1e-12, at most `maxIterations`).
/// Ad n x n, Bd n x m, Q n x n, R m x m (positive definite). iterations (optional) receives how
/// many it took. Throws std::invalid_argument on shapes that do not match or numbers that leave
/// the finite range.
Eigen::MatrixXd stationaryLqrGain(const Eigen::MatrixXd& ad, const Eigen::MatrixXd& bd,
                                  const Eigen::MatrixXd& q, const Eigen::MatrixXd& r,
                                  int maxIterations = 200000, int* iterations = nullptr);

/// A feedback law around the demonstration derived from the demonstration, the fitted model and
/// the actuator limits alone, no number tuned on the plant being run:
///   1. the model: e_{k+1} = (I + dt A-bar) e_k + dt B^T (u_k - u*_k), A-bar the drift (if any)
///      plus the error's own kinematics (DeviationModel::kinematics) averaged over the
///      demonstration's samples, B the fit (m x n);
///   2. the weights by Bryson's rule, from the demonstration's own scales: Q_ii = 1 / sigma_i^2,
///      sigma_i the RMS of error component i between demonstration states scaleLag samples
///      apart (how far that component moves over that time in the manoeuvre), and
///      R_ll = 1 / ubar_l^2, ubar_l half the actuator's range: an error of one sigma in a
///      component costs as much as a half-range correction;
///   3. K the stationary LQR gain of that model and those weights (stationaryLqrGain);
///   4. the loop's dead time: while a control's own loop (the others open) or the whole loop
///      has a mode faster than kDelayPhase / delay, that control's R (or every R) is doubled
///      and K found again (the delay takes at most 30 of the LQR's 60 degrees of phase margin);
///   5. the law u = u* - K e with K restricted to `structure` (B~), smoothed over `horizon`.
/// With `proportional` set, the model of step 1 is first reduced by the components the action
/// sets (see StartLawOptions::proportional).
/// A component that never moves in the demonstration (sigma ~ 0) or that no control and no
/// kinematics reaches gets no weight. Throws std::invalid_argument on shapes that do not match
/// or a demonstration too short for the scale lag.
StartLaw deriveStartLaw(const Demonstration& demonstration, const Eigen::MatrixXd& b,
                        const DeviationModel& deviation, const ActionLimits& limits,
                        const StartLawOptions& options = {});

}  // namespace prisca::core
