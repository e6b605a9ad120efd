#pragma once

#include "Controller.h"
#include "LeastStateDeviationMatcher.h"

#include <Eigen/Core>

#include <algorithm>
#include <deque>

namespace prisca::core {

/// Gains and variant of the PD baselines (DESIGN.md "Baselines").
struct PdParameters {
    /// Error combination c_l (m x n): row l weighs the tracking error components for control l;
    /// normally B~ (or B), so that "left of the path" becomes "steer right".
    Eigen::MatrixXd errorCombination;
    Eigen::VectorXd kp;  ///< proportional gain per control (m), >= 0 [action unit / error unit]
    Eigen::VectorXd kd;  ///< derivative gain per control (m), >= 0 [action unit * s / error unit]
    /// Smoothing horizon H [steps] for PD+H; 0 means the raw error (plain PD).
    int horizon = 0;
};

/// PD around the demonstration, the paper's comparison family (Table I):
///     eps_l = c_l . e_k              (or its H-step nested-expectation smoothing for PD+H)
///     u_l = u*_l - Kp_l eps_l - Kd_l d(eps_l)/dt,
/// saturated. The minus signs make positive gains negative feedback (DESIGN.md writes the sign
/// into the gains). The reference is time-driven (PD, PD+H) or least-state-deviation
/// (PD+LSD, PD+H+LSD), as set in the problem's matching parameters. d/dt is the backward
/// difference over one control period, zero on the first step.
class PdController : public Controller {
  public:
    PdController(TrackingProblem problem, PdParameters parameters, QString name);

    /// The method name for a variant: "pd", "pd-h", "pd-lsd" or "pd-h-lsd".
    static QString variantName(bool smoothed, bool leastStateDeviation);

    QString name() const override { return name_; }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    void setObservationAge(int steps) override {
        age_ = std::max(0, steps);
        matcher_.setAge(age_);
    }

    const PdParameters& parameters() const { return parameters_; }
    /// The error signal eps (m) of the last step, after smoothing.
    const Eigen::VectorXd& errorSignal() const { return signal_; }

  private:
    TrackingProblem problem_;
    PdParameters parameters_;
    QString name_;
    LeastStateDeviationMatcher matcher_;
    std::deque<Eigen::VectorXd> rawSignals_;  // the last H + 1 values of c . e, oldest first
    Eigen::VectorXd signal_;
    Eigen::VectorXd previousSignal_;
    ControlStep record_;
    int step_ = 0;
    int age_ = 0;  // observations' age compensated [steps]
};

}  // namespace prisca::core
