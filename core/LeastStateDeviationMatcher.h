#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <vector>

namespace prisca::core {

/// How the reference index j_k of step k is chosen.
struct MatchingParameters {
    enum class Mode {
        LeastStateDeviation,  ///< eq. 12: the demonstration state nearest to s_k
        TimeDriven            ///< j_k = k (PGSD, plain PD, action playback)
    };
    Mode mode = Mode::LeastStateDeviation;
    /// Forward search window [samples]: candidates are j_{k-1} .. j_{k-1} + window, so progress
    /// along the demonstration is monotone. The first step searches 0 .. window.
    int window = 40;
    /// The reference never falls more than this many samples behind the demonstration's own
    /// clock (j_k >= k - maxLag); 0 means it may lag without bound. A robot standing just ahead
    /// of where the demonstration stood still is nearer to the last resting sample than to any
    /// moving one, so an unbounded reference waits there for a robot that waits for it.
    int maxLag = 0;
    /// Per-component weights of the L1 distance (size n); empty means all ones.
    Eigen::VectorXd weights;
    /// State components that are angles: their differences wrap to (-pi, pi].
    std::vector<int> angleIndices;
};

/// Least-state-deviation reference matching (eq. 12): j_k minimises the weighted L1 distance
/// sum_c w_c |s_k,c - s*_j,c| over a forward window after the previous match (and no further
/// than maxLag behind the clock k); ties (equal
/// samples, e.g. a demonstration standing still) go to the sample nearest j_{k-1} + 1, the
/// demonstration's own clock. In TimeDriven mode j_k = min(k, T - 1).
/// One instance per controller; not thread-safe. match() does not allocate.
class LeastStateDeviationMatcher {
  public:
    /// @param demonstrationStates T x n, row j is s*_j
    LeastStateDeviationMatcher(const Eigen::MatrixXd& demonstrationStates,
                               MatchingParameters parameters);

    /// Back to the start of the demonstration.
    void reset();
    /// The sensor latency compensated [steps] >= 0: time-driven matching returns
    /// j_k = k - latency (the sample of the time the observation was taken) and maxLag counts
    /// from there.
    void setLoopLatencySteps(int steps) { loopLatencySteps_ = std::max(0, steps); }
    int loopLatencySteps() const { return loopLatencySteps_; }
    /// The reference index for the next observation (call once per control step).
    int match(const Eigen::Ref<const Eigen::VectorXd>& state);
    /// Weighted L1 distance between a state and demonstration sample j.
    double distance(const Eigen::Ref<const Eigen::VectorXd>& state, int j) const;

    const MatchingParameters& parameters() const { return parameters_; }
    int length() const { return static_cast<int>(states_.rows()); }

  private:
    Eigen::MatrixXd states_;  // T x n: each component contiguous over time, angles in (-pi, pi]
    Eigen::VectorXd weights_;
    std::vector<int> angleRows_;    // components that are angles
    Eigen::ArrayXd difference_;     // kChunk scratch, so match() never allocates
    Eigen::ArrayXd distances_;      // kChunk scratch
    Eigen::VectorXd wrappedState_;  // n scratch
    MatchingParameters parameters_;
    int last_ = -1;
    int step_ = 0;
    int loopLatencySteps_ = 0;
};

}  // namespace prisca::core
