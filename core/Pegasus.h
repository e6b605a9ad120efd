#pragma once

#include <Eigen/Core>

#include <functional>
#include <optional>

namespace prisca::core {

/// What one episode of a fixed policy cost and consumed.
struct EpisodeOutcome {
    double cost = 0.0;    ///< total (or mean) tracking cost of the episode
    long long steps = 0;  ///< simulated control steps consumed
};

/// Runs one episode with policy parameters theta (p x m) on fixed scenario s (0..scenarios-1).
/// A scenario fixes the start state and every noise stream, so the same (theta, s) always gives
/// the same outcome (the PEGASUS idea). Called from the optimiser's thread only.
using RolloutFunction = std::function<EpisodeOutcome(const Eigen::MatrixXd& theta, int scenario)>;

/// Tuning of PEGASUS.
struct PegasusParameters {
    int scenarios = 4;           ///< fixed scenarios averaged per evaluation (>= 1)
    double stepSize = 1e-2;      ///< gradient-descent step alpha
    double perturbation = 1e-2;  ///< central finite-difference half-width h per parameter
    /// If > 0, a step longer than this (Euclidean norm over theta) is scaled down to it.
    double maxStepNorm = 0.0;
};

/// PEGASUS-style episodic policy search: the mean episode cost over fixed scenarios,
/// J(theta) = 1/S sum_s cost(theta, s), is minimised by gradient descent with the gradient from
/// central finite differences per parameter, (J(theta + h e_i) - J(theta - h e_i)) / 2h.
/// Each iteration costs (2 p m + 1) S episodes; stepsConsumed() counts their simulated steps so
/// learning curves compare methods by experience used.
class Pegasus {
  public:
    Pegasus(RolloutFunction rollout, Eigen::MatrixXd initialTheta, PegasusParameters parameters);

    /// What one iteration did.
    struct Iteration {
        double cost = 0.0;            ///< J(theta) before the step
        Eigen::MatrixXd gradient;     ///< finite-difference gradient at that theta
        long long stepsConsumed = 0;  ///< cumulative simulated steps after the iteration
    };

    /// One gradient step. Returns nullopt (theta unchanged) if cancelled() turned true; it is
    /// polled between episodes.
    std::optional<Iteration> iterate(const std::function<bool()>& cancelled = {});
    /// J(theta), counted in stepsConsumed().
    double evaluate(const Eigen::MatrixXd& theta);

    const Eigen::MatrixXd& theta() const { return theta_; }
    long long stepsConsumed() const { return steps_; }
    const PegasusParameters& parameters() const { return parameters_; }

  private:
    std::optional<double> evaluateCancellable(const Eigen::MatrixXd& theta,
                                              const std::function<bool()>& cancelled);
    RolloutFunction rollout_;
    Eigen::MatrixXd theta_;
    PegasusParameters parameters_;
    long long steps_ = 0;
};

}  // namespace prisca::core
