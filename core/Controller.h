#pragma once

#include "Demonstration.h"
#include "DeviationModel.h"
#include "LeastStateDeviationMatcher.h"

#include <Eigen/Core>

#include <QString>

#include <memory>
#include <stdexcept>

namespace prisca::core {

/// Actuator limits; every controller saturates its action to them.
struct ActionLimits {
    Eigen::VectorXd lower;  ///< m lower bounds [action units]
    Eigen::VectorXd upper;  ///< m upper bounds [action units]

    /// Symmetric limits [-bound, bound] on each of m channels.
    static ActionLimits symmetric(int channels, double bound);
    /// Clamps u in place.
    void saturate(Eigen::Ref<Eigen::VectorXd> u) const;
};

/// What every controller shares: the demonstration to repeat, how errors are formed, how the
/// reference index is matched, how errors are weighed in the cost, and the actuator limits.
struct TrackingProblem {
    std::shared_ptr<const Demonstration> demonstration;  ///< S*, U*
    DeviationModel deviation;                            ///< e = s (-) s*
    MatchingParameters matching;  ///< least-state-deviation or time-driven reference
    Eigen::VectorXd costWeights;  ///< W in C = e^T W e (size n; empty = identity)
    ActionLimits limits;          ///< saturation

    /// Empty when consistent; else a one-line description of the first problem.
    QString validate() const;
    /// The problem ready for a controller: throws std::invalid_argument with validate()'s
    /// message when inconsistent, and fills empty cost weights with ones.
    static TrackingProblem validated(TrackingProblem problem);
    /// C = e^T W e for a problem returned by validated().
    double cost(const Eigen::Ref<const Eigen::VectorXd>& deviation) const {
        return deviation.dot(costWeights.cwiseProduct(deviation));
    }
};

/// The record of one control step. Valid until the next call to step() or reset().
struct ControlStep {
    int step = 0;                     ///< k, counted from the last reset
    int referenceIndex = 0;           ///< j_k, the matched demonstration sample
    Eigen::VectorXd action;           ///< u_k after saturation (size m)
    Eigen::VectorXd referenceAction;  ///< u*_{j_k} (size m)
    Eigen::VectorXd deviation;        ///< e_k (size n)
    double cost = 0.0;                ///< C_k = e_k^T W e_k
};

/// How reset() treats what was learned.
enum class ResetMode {
    Cold,      ///< forget what was learned: theta back to its initial value (0 unless set), step
               ///< counter 0
    WarmStart  ///< new trial, keep theta and the step-size schedule (learning continues)
};

/// A feedback policy run at the control rate: observation in, saturated action out.
/// Implementations are single-threaded objects; clone() one per parallel trial.
class Controller {
  public:
    virtual ~Controller() = default;

    /// Short method name as used by the command line, e.g. "prisca", "pd-h".
    virtual QString name() const = 0;
    /// Prepares a new trial.
    virtual void reset(ResetMode mode = ResetMode::Cold) = 0;
    /// One control step with the current observation s_k (size n).
    virtual const ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& observation) = 0;
    /// An independent copy in the same state.
    virtual std::unique_ptr<Controller> clone() const = 0;
    /// Latency compensation: how old each observation is when it reaches the controller
    /// [control steps] (a camera's latency; 0 by default). A controller that compensates compares
    /// the observation with the reference of the time it was taken and applies the
    /// demonstration's action of now (that index + the latency). Takes effect from the next
    /// reset(); controllers that track no reference ignore it. The simulation and the rig both
    /// set it from EpisodeSettings::compensatedLoopLatencySteps().
    virtual void setLoopLatencySteps(int steps) { (void)steps; }
    /// The learned policy parameters theta (p x m) for logging and plotting, or nullptr for a
    /// controller that learns nothing.
    virtual const Eigen::MatrixXd* learnedParameters() const { return nullptr; }
    /// What the operator should know about the trial running or just run, in a sentence (which
    /// law drove it, and why that changed); empty: nothing beyond the method's name.
    virtual QString trialNote() const { return {}; }
};

}  // namespace prisca::core
