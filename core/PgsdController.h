#pragma once

#include "ActionMapping.h"
#include "Controller.h"
#include "FeatureMap.h"

#include <Eigen/Core>

#include <deque>

namespace prisca::core {

/// Tuning of PGSD (policy gradient with the signed derivative).
struct PgsdParameters {
    int horizon = 10;        ///< H, the smoothing horizon [steps] (>= 1)
    double stepSize = 1e-3;  ///< fixed alpha (no decay)
    /// If > 0, theta is kept in the box |theta_i| <= thetaBound (the same safeguard PRISCA may
    /// use, so that the comparison is of the methods and not of this guard).
    double thetaBound = 0.0;
};

/// Policy search via the signed derivative, as the paper's special case of PRISCA (Section II):
/// no baseline (b = 0), no inverse depreciation (D = 1), a fixed step size, the time-driven
/// reference j_k = k, and the signs of B~ as the model (no fitted B_v):
///     g_l = sum_j w_j phi_l(s_j) (e_j^T W dt B~[l, :]),   theta_l -= alpha g_l,
///     u_l = theta_l^T phi_l(s_k) + u*_k.
/// Written out on its own (not through PriscaController) so that the equivalence of the two
/// is a real check of both.
class PgsdController : public Controller {
  public:
    /// The problem's matching mode is ignored: PGSD is always time-driven.
    PgsdController(TrackingProblem problem, FeatureMap features, IntuitiveMapping signs,
                   PgsdParameters parameters);

    QString name() const override { return QStringLiteral("pgsd"); }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    void setLoopLatencySteps(int steps) override { loopLatencySteps_ = steps > 0 ? steps : 0; }
    const Eigen::MatrixXd* learnedParameters() const override { return &theta_; }

    const Eigen::MatrixXd& theta() const { return theta_; }
    const Eigen::MatrixXd& gradient() const { return gradient_; }

  private:
    struct Sample {
        Eigen::MatrixXd phi;        // p x m
        Eigen::VectorXd deviation;  // n
    };
    TrackingProblem problem_;
    FeatureMap features_;
    IntuitiveMapping signs_;
    PgsdParameters parameters_;
    std::deque<Sample> window_;  // the last H + 1 samples, oldest first
    Eigen::MatrixXd theta_;
    Eigen::MatrixXd gradient_;
    ControlStep record_;
    int step_ = 0;
    int loopLatencySteps_ = 0;  // the sensor latency compensated [steps]
};

}  // namespace prisca::core
