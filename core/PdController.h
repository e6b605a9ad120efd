#pragma once

#include "Controller.h"
#include "LeastStateDeviationMatcher.h"
#include "PdFeedback.h"

#include <Eigen/Core>

#include <algorithm>

namespace prisca::core {

/// PD around the demonstration, the paper's comparison family (Table I):
///     eps_l = c_l . e_k              (or its H-step nested-expectation smoothing for PD+H)
///     u_l = u*_l - Kp_l eps_l - Kd_l d(eps_l)/dt,
/// saturated. The minus signs make positive gains negative feedback (docs/architecture.md writes
/// the sign into the gains). The reference is time-driven (PD, PD+H) or least-state-deviation
/// (PD+LSD, PD+H+LSD), as set in the problem's matching parameters. d/dt is the backward
/// difference over one control period, zero on the first step.
class PdController : public Controller {
  public:
    PdController(TrackingProblem problem, PdParameters parameters, QString name);

    QString name() const override { return name_; }
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    void setLoopLatencySteps(int steps) override {
        loopLatencySteps_ = std::max(0, steps);
        matcher_.setLoopLatencySteps(loopLatencySteps_);
    }

    const PdParameters& parameters() const { return feedback_.parameters(); }
    /// Per demonstration sample, the share of the feedback acting at that reference
    /// (PdFeedback::setReferenceGate).
    void setFeedbackGate(std::vector<double> gate) { feedback_.setReferenceGate(std::move(gate)); }
    /// Per demonstration sample, a factor on each error component (PdFeedback::setErrorSchedule).
    void setErrorSchedule(Eigen::MatrixXd schedule) {
        feedback_.setErrorSchedule(std::move(schedule));
    }

  private:
    TrackingProblem problem_;
    QString name_;
    LeastStateDeviationMatcher matcher_;
    PdFeedback feedback_;
    ControlStep record_;
    int step_ = 0;
    int loopLatencySteps_ = 0;  // the sensor latency compensated [steps]
};

}  // namespace prisca::core
