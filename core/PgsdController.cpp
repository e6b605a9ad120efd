#include "PgsdController.h"

#include "NestedExpectation.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

PgsdController::PgsdController(TrackingProblem problem, FeatureMap features, IntuitiveMapping signs,
                               PgsdParameters parameters)
    : problem_(TrackingProblem::validated(std::move(problem))),
      features_(std::move(features)),
      signs_(std::move(signs)),
      parameters_(parameters) {
    problem_.matching.mode = MatchingParameters::Mode::TimeDriven;
    const int n = problem_.demonstration->stateDimension();
    const int m = problem_.demonstration->actionDimension();
    if (signs_.controls() != m || signs_.states() != n || features_.channelCount() != m ||
        parameters_.horizon < 1) {
        throw std::invalid_argument(
            "PgsdController: B~ must be m x n, features per control, H >= 1");
    }
    theta_.setZero(features_.featureCount(), m);
    gradient_.setZero(features_.featureCount(), m);
}

void PgsdController::reset(ResetMode mode) {
    window_.clear();
    step_ = 0;
    gradient_.setZero();
    if (mode == ResetMode::Cold) {
        theta_.setZero();
    }
}

std::unique_ptr<Controller> PgsdController::clone() const {
    return std::make_unique<PgsdController>(*this);
}

const ControlStep& PgsdController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    const int n = demo.stateDimension();
    const int m = demo.actionDimension();
    const int p = features_.featureCount();
    // The reference of the time the observation was taken; the action of now.
    const int j = std::clamp(step_ - loopLatencySteps_, 0, demo.length() - 1);

    Sample sample;
    sample.deviation = problem_.deviation.deviation(observation, demo.states.row(j).transpose());
    sample.phi.resize(p, m);
    features_.evaluate(sample.deviation, observation, sample.phi);
    window_.push_back(sample);
    if (static_cast<int>(window_.size()) > parameters_.horizon + 1) {
        window_.pop_front();
    }

    const Eigen::VectorXd& W = problem_.costWeights;
    const Eigen::VectorXd w = nestedExpectationWeights(static_cast<int>(window_.size()));
    gradient_.setZero();
    for (int t = 0; t < static_cast<int>(window_.size()); ++t) {
        for (int l = 0; l < m; ++l) {
            double projection = 0.0;  // e_j^T W dS_l with the sign-only model
            for (int c = 0; c < n; ++c) {
                projection += window_[t].deviation[c] * W[c] * demo.dt * signs_.signs(l, c);
            }
            for (int i = 0; i < p; ++i) {
                gradient_(i, l) += w[t] * window_[t].phi(i, l) * projection;
            }
        }
    }
    theta_ -= parameters_.stepSize * gradient_;
    if (parameters_.thetaBound > 0.0) {
        theta_ = theta_.cwiseMax(-parameters_.thetaBound).cwiseMin(parameters_.thetaBound);
    }

    record_.step = step_;
    record_.referenceIndex = j;
    record_.referenceAction =
        demo.actions.row(std::min(j + std::min(loopLatencySteps_, step_), demo.length() - 1))
            .transpose();
    record_.deviation = sample.deviation;
    record_.cost = problem_.cost(sample.deviation);
    record_.action.resize(m);
    for (int l = 0; l < m; ++l) {
        record_.action[l] = theta_.col(l).dot(sample.phi.col(l)) + record_.referenceAction[l];
    }
    problem_.limits.saturate(record_.action);
    ++step_;
    return record_;
}

}  // namespace prisca::core
