#include "Pegasus.h"

#include <stdexcept>

namespace prisca::core {

Pegasus::Pegasus(RolloutFunction rollout, Eigen::MatrixXd initialTheta,
                 PegasusParameters parameters)
    : rollout_(std::move(rollout)), theta_(std::move(initialTheta)), parameters_(parameters) {
    if (!rollout_ || parameters_.scenarios < 1 || !(parameters_.perturbation > 0.0) ||
        !(parameters_.stepSize >= 0.0) || theta_.size() == 0) {
        throw std::invalid_argument(
            "Pegasus: needs a rollout, >= 1 scenario, h > 0, alpha >= 0 and a non-empty theta");
    }
}

std::optional<double> Pegasus::evaluateCancellable(const Eigen::MatrixXd& theta,
                                                   const std::function<bool()>& cancelled) {
    double sum = 0.0;
    for (int s = 0; s < parameters_.scenarios; ++s) {
        if (cancelled && cancelled()) {
            return std::nullopt;
        }
        const EpisodeOutcome outcome = rollout_(theta, s);
        sum += outcome.cost;
        steps_ += outcome.steps;
    }
    return sum / parameters_.scenarios;
}

double Pegasus::evaluate(const Eigen::MatrixXd& theta) {
    return *evaluateCancellable(theta, {});
}

std::optional<Pegasus::Iteration> Pegasus::iterate(const std::function<bool()>& cancelled) {
    Iteration iteration;
    const auto cost = evaluateCancellable(theta_, cancelled);
    if (!cost) {
        return std::nullopt;
    }
    iteration.cost = *cost;
    iteration.gradient.setZero(theta_.rows(), theta_.cols());
    const double h = parameters_.perturbation;
    for (Eigen::Index i = 0; i < theta_.size(); ++i) {
        Eigen::MatrixXd probe = theta_;
        probe.data()[i] += h;
        const auto plus = evaluateCancellable(probe, cancelled);
        probe.data()[i] -= 2.0 * h;
        const auto minus = plus ? evaluateCancellable(probe, cancelled) : std::nullopt;
        if (!minus) {
            return std::nullopt;
        }
        iteration.gradient.data()[i] = (*plus - *minus) / (2.0 * h);
    }
    Eigen::MatrixXd change = parameters_.stepSize * iteration.gradient;
    const double norm = change.norm();
    if (parameters_.maxStepNorm > 0.0 && norm > parameters_.maxStepNorm) {
        change *= parameters_.maxStepNorm / norm;
    }
    theta_ -= change;
    iteration.stepsConsumed = steps_;
    return iteration;
}

}  // namespace prisca::core
