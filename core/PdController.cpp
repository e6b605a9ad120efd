#include "PdController.h"

#include "NestedExpectation.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

PdController::PdController(TrackingProblem problem, PdParameters parameters, QString name)
    : problem_(TrackingProblem::validated(std::move(problem))),
      parameters_(std::move(parameters)),
      name_(std::move(name)),
      matcher_(problem_.demonstration->states, problem_.matching) {
    const int n = problem_.demonstration->stateDimension();
    const int m = problem_.demonstration->actionDimension();
    if (parameters_.errorCombination.rows() != m || parameters_.errorCombination.cols() != n ||
        parameters_.kp.size() != m || parameters_.kd.size() != m || parameters_.horizon < 0) {
        throw std::invalid_argument(
            "PdController: error combination must be m x n, gains of size m, horizon >= 0");
    }
    signal_.setZero(m);
    previousSignal_.setZero(m);
}

QString PdController::variantName(bool smoothed, bool leastStateDeviation) {
    QString name = QStringLiteral("pd");
    if (smoothed) {
        name += QStringLiteral("-h");
    }
    if (leastStateDeviation) {
        name += QStringLiteral("-lsd");
    }
    return name;
}

void PdController::reset(ResetMode) {
    // PD learns nothing, so a warm start is the same as a cold one.
    matcher_.reset();
    rawSignals_.clear();
    signal_.setZero();
    previousSignal_.setZero();
    step_ = 0;
}

std::unique_ptr<Controller> PdController::clone() const {
    return std::make_unique<PdController>(*this);
}

const ControlStep& PdController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    const int j = matcher_.match(observation);
    record_.deviation = problem_.deviation.deviation(observation, demo.states.row(j).transpose());
    const Eigen::VectorXd& e = record_.deviation;
    const Eigen::VectorXd raw = parameters_.errorCombination * e;

    rawSignals_.push_back(raw);
    if (static_cast<int>(rawSignals_.size()) > parameters_.horizon + 1) {
        rawSignals_.pop_front();
    }
    if (parameters_.horizon == 0) {
        signal_ = raw;
    } else {
        const Eigen::VectorXd w = nestedExpectationWeights(static_cast<int>(rawSignals_.size()));
        signal_.setZero();
        for (int t = 0; t < static_cast<int>(rawSignals_.size()); ++t) {
            signal_ += w[t] * rawSignals_[t];
        }
    }
    const Eigen::VectorXd rate = step_ == 0
                                     ? Eigen::VectorXd::Zero(signal_.size())
                                     : Eigen::VectorXd((signal_ - previousSignal_) / demo.dt);
    previousSignal_ = signal_;

    record_.step = step_;
    record_.referenceIndex = j;
    record_.referenceAction =
        demo.actions.row(std::min(j + std::min(age_, step_), demo.length() - 1)).transpose();
    record_.action = record_.referenceAction - parameters_.kp.cwiseProduct(signal_) -
                     parameters_.kd.cwiseProduct(rate);
    problem_.limits.saturate(record_.action);
    record_.cost = problem_.cost(e);
    ++step_;
    return record_;
}

}  // namespace prisca::core
