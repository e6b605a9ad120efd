#include "PdFeedback.h"

#include "NestedExpectation.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

PdFeedback::PdFeedback(PdParameters parameters, int n, int m, double dt)
    : parameters_(std::move(parameters)), dt_(dt) {
    if (parameters_.errorCombination.rows() != m || parameters_.errorCombination.cols() != n ||
        parameters_.kp.size() != m || parameters_.kd.size() != m || parameters_.horizon < 0) {
        throw std::invalid_argument(
            "PD gains: the error combination must be m x n, the gains of size m, the horizon "
            ">= 0");
    }
    for (int c = 1; c <= parameters_.horizon + 1; ++c) {
        weights_.push_back(nestedExpectationWeights(c));
    }
    raw_.setZero(m, parameters_.horizon + 1);
    signal_.setZero(m);
    previous_.setZero(m);
    rate_.setZero(m);
}

void PdFeedback::reset() {
    raw_.setZero();
    signal_.setZero();
    previous_.setZero();
    rate_.setZero();
    step_ = 0;
}

void PdFeedback::setErrorSchedule(Eigen::MatrixXd schedule) {
    if (schedule.size() != 0 && schedule.rows() != parameters_.errorCombination.cols()) {
        throw std::invalid_argument("PdFeedback::setErrorSchedule: one row per error component");
    }
    schedule_ = std::move(schedule);
    scheduled_.setZero(schedule_.rows());  // the step's scratch, sized once
}

void PdFeedback::update(const Eigen::Ref<const Eigen::VectorXd>& error, int referenceIndex) {
    const int ring = static_cast<int>(raw_.cols());
    const int k = step_;
    if (referenceIndex >= 0 && referenceIndex < schedule_.cols()) {
        scheduled_ = error.cwiseProduct(schedule_.col(referenceIndex));
        raw_.col(k % ring).noalias() = parameters_.errorCombination * scheduled_;
    } else {
        raw_.col(k % ring).noalias() = parameters_.errorCombination * error;
    }
    const int samples = std::min(k, ring - 1) + 1;
    const Eigen::VectorXd& w = weights_[samples - 1];
    signal_.setZero();
    for (int t = 0; t < samples; ++t) {  // oldest first
        signal_ += w[t] * raw_.col((k - samples + 1 + t) % ring);
    }
    if (k == 0) {
        rate_.setZero();
    } else {
        rate_ = (signal_ - previous_) / dt_;
    }
    previous_ = signal_;
    ++step_;
}

void PdFeedback::apply(Eigen::Ref<Eigen::VectorXd> action, int referenceIndex) const {
    const double g = referenceIndex >= 0 && referenceIndex < static_cast<int>(gate_.size())
                         ? gate_[static_cast<std::size_t>(referenceIndex)]
                         : 1.0;
    action -= g * parameters_.kp.cwiseProduct(signal_);
    action -= g * parameters_.kd.cwiseProduct(rate_);
}

}  // namespace prisca::core
