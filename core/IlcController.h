#pragma once

#include "Controller.h"
#include "PdController.h"

#include <Eigen/Core>

#include <vector>

namespace prisca::core {

/// Tuning of iterative learning control. Plain data.
struct IlcParameters {
    /// The feedback in the loop: PD on the time-aligned error, formed as PdFeedback does (the
    /// profile's horizon is 0: the raw combined error); gains of zero give pure feedforward
    /// learning. Its error combination C (m x n) also forms the error
    /// each channel learns from.
    PdParameters feedback;
    /// Learning gain per control (m), >= 0: how much of the combined error eps = C e at k + lead
    /// goes into the feedforward at k after a trial [action unit / error unit].
    Eigen::VectorXd learningGain;
    int lead = 2;  ///< the error this many steps later corrects the action at k [steps], >= 0
    /// Q filter: zero-phase (forward and backward) first-order low-pass of the feedforward after
    /// each update, so the learning cannot build up what the loop cannot follow [Hz]; 0: none.
    double cutoff = 2.0;
    /// The feedforward shrinks by this share before each update (Q's robustness), in [0, 1).
    double forgetting = 0.0;
};

/// Iterative learning control, the engineering standard for a repeated trajectory:
///     u_k = u*_k + f_k - Kp eps_k - Kd d(eps_k)/dt,       eps_k = C e_k  (time-driven reference)
/// and after each trial (the next warm reset), with the trial's recorded eps:
///     f_k <- Q[ (1 - forgetting) f_k - Gamma eps_{k + lead} ],
/// a P-type update with a phase lead and a zero-phase low-pass Q filter. f is indexed by time
/// from the trial's start; a cold reset forgets it. Saturated like every controller.
/// Single-threaded; clone() for parallel trials.
class IlcController : public Controller {
  public:
    IlcController(TrackingProblem problem, IlcParameters parameters);

    QString name() const override { return QStringLiteral("ilc"); }
    /// Cold: f = 0. Warm start: learn from the trial just run (if any), then start a new one.
    void reset(ResetMode mode = ResetMode::Cold) override;
    const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) override;
    std::unique_ptr<Controller> clone() const override;
    void setLoopLatencySteps(int steps) override { loopLatencySteps_ = steps > 0 ? steps : 0; }

    /// The learned feedforward f (m x steps it covers), column k for step k.
    const Eigen::MatrixXd& feedforward() const { return feedforward_; }
    /// Trials learned from since the last cold reset.
    int iterations() const { return iterations_; }
    const IlcParameters& parameters() const { return parameters_; }

  private:
    void learn();

    TrackingProblem problem_;
    IlcParameters parameters_;
    Eigen::MatrixXd feedforward_;           // m x K
    std::vector<Eigen::VectorXd> signals_;  // eps_k of the trial under way
    PdFeedback feedback_;                   // the PD around the demonstration
    ControlStep record_;
    int step_ = 0;
    int iterations_ = 0;
    int loopLatencySteps_ = 0;  // the sensor latency compensated [steps]
};

}  // namespace prisca::core
