#include "LeastStateDeviationMatcher.h"

#include "DeviationModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::core {

namespace {
// Candidates are scored in blocks of this many samples: large enough to vectorise, small
// enough that the scratch stays in L1 cache.
constexpr int kChunk = 256;
// Distances this close (relative) are a tie: equal samples up to rounding.
constexpr double kTieTolerance = 1e-12;
}  // namespace

LeastStateDeviationMatcher::LeastStateDeviationMatcher(const Eigen::MatrixXd& demonstrationStates,
                                                       MatchingParameters parameters)
    : states_(demonstrationStates), parameters_(std::move(parameters)) {
    const int n = static_cast<int>(states_.cols());
    if (states_.rows() < 1 || n < 1) {
        throw std::invalid_argument("LeastStateDeviationMatcher: empty demonstration");
    }
    if (parameters_.window < 0 || parameters_.maxLag < 0) {
        throw std::invalid_argument("LeastStateDeviationMatcher: window and maxLag must be >= 0");
    }
    weights_ = parameters_.weights.size() == 0 ? Eigen::VectorXd::Ones(n) : parameters_.weights;
    if (weights_.size() != n) {
        throw std::invalid_argument("LeastStateDeviationMatcher: weights must have size n");
    }
    for (int i : parameters_.angleIndices) {
        if (i < 0 || i >= n) {
            throw std::invalid_argument("LeastStateDeviationMatcher: angle index out of range");
        }
        angleRows_.push_back(i);
        // Stored wrapped, so a difference of two angles lies in (-2 pi, 2 pi) and its wrapped
        // magnitude is min(|d|, 2 pi - |d|): branch-free and vectorisable.
        for (Eigen::Index j = 0; j < states_.rows(); ++j) {
            states_(j, i) = wrapAngle(states_(j, i));
        }
    }
    wrappedState_.resize(n);
    difference_.resize(kChunk);
    distances_.resize(kChunk);
}

void LeastStateDeviationMatcher::reset() {
    last_ = -1;
    step_ = 0;
}

double LeastStateDeviationMatcher::distance(const Eigen::Ref<const Eigen::VectorXd>& state,
                                            int j) const {
    Eigen::ArrayXd d = (state - states_.row(j).transpose()).array();
    for (int c : angleRows_) {
        d[c] = wrapAngle(d[c]);
    }
    return (weights_.array() * d.abs()).sum();
}

int LeastStateDeviationMatcher::match(const Eigen::Ref<const Eigen::VectorXd>& state) {
    const int T = length();
    if (parameters_.mode == MatchingParameters::Mode::TimeDriven) {
        last_ = std::clamp(step_ - loopLatencySteps_, 0, T - 1);
        ++step_;
        return last_;
    }
    int first = std::max(last_, 0);
    if (parameters_.maxLag > 0) {
        first = std::max(first, std::min(step_ - loopLatencySteps_ - parameters_.maxLag, T - 1));
    }
    const int end = std::min(T - 1, first + parameters_.window);
    constexpr double kTwoPi = 2.0 * M_PI;
    wrappedState_ = state;
    for (int c : angleRows_) {
        wrappedState_[c] = wrapAngle(state[c]);
    }
    // Where the demonstration's own clock would be: ties go to the sample nearest it, so a
    // robot standing exactly where the demonstration stood still (identical samples) moves on
    // with the demonstration's time instead of staying on the first of them forever.
    const int expected = std::clamp(last_ + 1, first, end);
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int start = first; start <= end; start += kChunk) {
        const int count = std::min(kChunk, end - start + 1);
        // One contiguous pass per component: sum_c w_c |s*_j,c - s_c| for the whole block.
        auto dist = distances_.head(count);
        auto diff = difference_.head(count);
        dist.setZero();
        for (int c = 0; c < states_.cols(); ++c) {
            diff = (states_.col(c).segment(start, count).array() - wrappedState_[c]).abs();
            if (std::find(angleRows_.begin(), angleRows_.end(), c) != angleRows_.end()) {
                diff = diff.min(kTwoPi - diff);
            }
            dist += weights_[c] * diff;
        }
        for (int t = 0; t < count; ++t) {
            const int j = start + t;
            const double tolerance = kTieTolerance * std::max(1.0, bestDistance);
            if (best < 0 || dist[t] < bestDistance - tolerance) {
                bestDistance = dist[t];
                best = j;
            } else if (dist[t] <= bestDistance + tolerance &&
                       std::abs(j - expected) < std::abs(best - expected)) {
                bestDistance = std::min(bestDistance, static_cast<double>(dist[t]));
                best = j;
            }
        }
    }
    last_ = best >= 0 ? best : first;  // a non-finite observation keeps the reference
    ++step_;
    return last_;
}

}  // namespace prisca::core
