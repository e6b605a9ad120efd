#include "LeastStateDeviationMatcher.h"

#include "DeviationModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::core {

LeastStateDeviationMatcher::LeastStateDeviationMatcher(const Eigen::MatrixXd& demonstrationStates,
                                                       MatchingParameters parameters)
    : states_(demonstrationStates.transpose()), parameters_(std::move(parameters)) {
    const int n = static_cast<int>(states_.rows());
    if (states_.cols() < 1 || n < 1) {
        throw std::invalid_argument("LeastStateDeviationMatcher: empty demonstration");
    }
    if (parameters_.window < 0) {
        throw std::invalid_argument("LeastStateDeviationMatcher: window must be >= 0");
    }
    weights_ = parameters_.weights.size() == 0 ? Eigen::VectorXd::Ones(n) : parameters_.weights;
    if (weights_.size() != n) {
        throw std::invalid_argument("LeastStateDeviationMatcher: weights must have size n");
    }
    angleMask_.setZero(n);
    for (int i : parameters_.angleIndices) {
        if (i < 0 || i >= n) {
            throw std::invalid_argument("LeastStateDeviationMatcher: angle index out of range");
        }
        angleMask_[i] = 1.0;
        hasAngles_ = true;
    }
}

void LeastStateDeviationMatcher::reset() {
    last_ = -1;
    step_ = 0;
}

double LeastStateDeviationMatcher::distance(const Eigen::Ref<const Eigen::VectorXd>& state,
                                            int j) const {
    if (!hasAngles_) {
        return (weights_.array() * (state - states_.col(j)).array().abs()).sum();
    }
    double sum = 0.0;
    for (int c = 0; c < states_.rows(); ++c) {
        double d = state[c] - states_(c, j);
        if (angleMask_[c] != 0.0) {
            d = wrapAngle(d);
        }
        sum += weights_[c] * std::abs(d);
    }
    return sum;
}

int LeastStateDeviationMatcher::match(const Eigen::Ref<const Eigen::VectorXd>& state) {
    const int T = length();
    if (parameters_.mode == MatchingParameters::Mode::TimeDriven) {
        last_ = std::min(step_, T - 1);
        ++step_;
        return last_;
    }
    const int first = std::max(last_, 0);
    const int end = std::min(T - 1, first + parameters_.window);
    int best = first;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int j = first; j <= end; ++j) {
        const double d = distance(state, j);
        if (d < bestDistance) {  // strict: ties keep the earlier sample
            bestDistance = d;
            best = j;
        }
    }
    last_ = best;
    ++step_;
    return last_;
}

}  // namespace prisca::core
