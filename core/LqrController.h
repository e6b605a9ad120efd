#pragma once

#include "Controller.h"
#include "LeastStateDeviationMatcher.h"

#include <Eigen/Core>

#include <vector>

namespace prisca::core {

/// Tuning of the time-varying LQR. Plain data.
struct LqrParameters {
    /// The fitted model of the deviation dynamics (eq. 5 with drift, fitted on the
    /// demonstration): e_{k+1} = (I + dt A) e_k + dt B^T (u_k - u*_k).
    Eigen::MatrixXd a;  ///< A, n x n [1/s]
    Eigen::MatrixXd b;  ///< B = B_v (.) B~, m x n [state unit / (action unit s)]
    /// Q = diag(the problem's cost weights): the state cost per step (the same W as every
    /// method's C = e^T W e). R = diag(effort) per control [1 / action unit^2]: > 0.
    Eigen::VectorXd effort;
    /// The deviation at the trial's end costs terminalWeight x Q (a parking manoeuvre is judged
    /// where it ends), > 0.
    double terminalWeight = 10.0;
    /// Control steps the trial goes on past the demonstration's end (its settle time), the
    /// reference held at the last sample: the recursion plans over them too, so the loop keeps
    /// its feedback while the vehicle comes to rest. >= 0.
    int holdSteps = 0;
};

/// A finite-horizon, time-varying LQR around the demonstration: the control engineer's first
/// model-based try. On the model fitted from the demonstration plus the error's own kinematics
/// at each reference sample (DeviationModel::kinematics, as PRISCA's closed-loop gradient has
/// it), the Riccati recursion is run backwards once over the trial (the demonstration and
/// holdSteps more at its last sample, from P_N = terminalWeight Q), giving one gain per step:
///     K_k = (R + Bd^T P_{k+1} Bd)^-1 Bd^T P_{k+1} Ad_k,
///     Ad_k = I + dt (A + kinematics(s*_k)),  Bd = dt B^T,
///     u_k = u*_k - K_k e_k          (time-driven reference, saturated).
/// Learns nothing: a warm start is a cold one. Single-threaded; clone() for parallel trials.
class LqrController : public Controller {
  public:
    /// Throws std::invalid_argument for shapes that do not match the problem, a non-positive
    /// effort weight or a model whose Riccati recursion does not stay finite.
    LqrController(TrackingProblem problem, LqrParameters parameters);

    QString name() const override { return QStringLiteral("lqr"); }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    void setLoopLatencySteps(int steps) override;

    /// K_k (m x n) of step k (the last one past the trial's planned end).
    const Eigen::MatrixXd& gain(int k) const;
    int gainCount() const { return static_cast<int>(gains_.size()); }

  private:
    TrackingProblem problem_;
    LqrParameters parameters_;
    LeastStateDeviationMatcher matcher_;
    std::vector<Eigen::MatrixXd> gains_;  // K_0 .. K_{T-1}
    ControlStep record_;
    int step_ = 0;
    int loopLatencySteps_ = 0;  // the sensor latency compensated [steps]
};

}  // namespace prisca::core
