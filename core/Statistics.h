#pragma once

#include <vector>

namespace prisca::core {

// Statistics for the evaluation metrics (docs/architecture.md "Metrics"): Table I error summaries
// and the learning-curve confidence bands. Pure functions, no state; any thread may call them.
//
// Non-finite values (NaN, +-inf) are never averaged in: every function here skips them, and
// summarizeErrors() reports how many it skipped, so a failed trial cannot silently turn a whole
// table row into NaN nor silently vanish.

/// Table I statistics of a set of errors, computed on their absolute values |e|.
///
/// Units are those of the input (cm, deg); variance is in units squared (cm^2, deg^2).
struct ErrorSummary {
    /// Number of finite errors used (non-finite ones are not counted here).
    int count = 0;
    /// Number of non-finite inputs (NaN, +-inf) that were skipped.
    int nonFinite = 0;
    /// Mean of |e|; NaN when count == 0.
    double meanAbsoluteError = 0.0;
    /// Sample (N-1) standard deviation of |e|; 0 when count == 1, NaN when count == 0.
    double standardDeviation = 0.0;
    /// Sample (N-1) variance of |e|, always standardDeviation^2 (as in the paper's Table I).
    double variance = 0.0;
    /// Smallest |e|; NaN when count == 0.
    double minimum = 0.0;
    /// Largest |e|; NaN when count == 0.
    double maximum = 0.0;
};

/// Table I summary ("mean absolute error +- std" and "error variance") of signed or absolute
/// errors. Uses |e|; skips non-finite values and counts them in ErrorSummary::nonFinite.
/// With no finite value every statistic is NaN and count is 0.
ErrorSummary summarizeErrors(const std::vector<double>& errors);

/// Mean of the finite values; non-finite ones are skipped. NaN when there is no finite value.
double mean(const std::vector<double>& values);

/// Sample (N-1) variance of the finite values; non-finite ones are skipped.
/// 0 for a single finite value (no spread can be estimated), NaN when there is none.
double sampleVariance(const std::vector<double>& values);

/// Cumulative distribution function of Student's t distribution, P(T <= t).
/// @param t                 any value; +-inf give 1 and 0, NaN gives NaN
/// @param degreesOfFreedom  >= 1; throws std::invalid_argument otherwise
/// Closed forms for 1 and 2 degrees of freedom; otherwise Eigen's regularized incomplete beta
/// (unsupported/Eigen/SpecialFunctions) on the tail, so small tail probabilities keep their
/// relative precision. Accuracy: ~1e-15 absolute; relative in the tails about dof * 1e-16 (the
/// argument x = k / (k + t^2) is a double), ~1e-10 at dof 1e6.
double studentTCdf(double t, int degreesOfFreedom);

/// Quantile (inverse CDF) of Student's t distribution: the t with P(T <= t) = probability.
/// @param probability       in [0, 1]; 0 gives -inf, 1 gives +inf, 0.5 gives exactly 0;
///                          outside [0, 1] or NaN throws std::invalid_argument
/// @param degreesOfFreedom  >= 1; throws std::invalid_argument otherwise
/// Inverts studentTCdf() by bracketed Newton iteration: ~1e-13 relative for dof up to ~1000,
/// ~1e-10 at dof 1e6 (see studentTCdf()); probabilities down to 1e-300 work (1 dof). Symmetric:
/// studentTQuantile(1 - p, k) == -studentTQuantile(p, k) up to the rounding of 1 - p.
double studentTQuantile(double probability, int degreesOfFreedom);

/// Point-wise mean and two-sided confidence band of a set of runs (a learning curve).
/// All vectors have the length of the longest run; element i describes point i.
struct ConfidenceBand {
    /// Mean over the runs that have a finite value at point i; NaN where count[i] == 0.
    std::vector<double> mean;
    /// mean - t * s / sqrt(N); equal to mean where N == 1, NaN where N == 0.
    std::vector<double> lower;
    /// mean + t * s / sqrt(N); equal to mean where N == 1, NaN where N == 0.
    std::vector<double> upper;
    /// Sample (N-1) standard deviation s over the runs (not the standard error);
    /// 0 where N == 1, NaN where N == 0.
    std::vector<double> standardDeviation;
    /// N: how many runs contributed a finite value at point i.
    std::vector<int> count;
};

/// Learning-curve band: runs[r][i] is the value of run r at point i. Runs may differ in length;
/// point i uses the runs that reach it, skipping non-finite values. The band is
/// mean +- t_{(1+level)/2, N-1} * s / sqrt(N) (Student t, as for the paper's Fig. 3 95% band).
/// @param level  confidence level in (0, 1), default 0.95; throws std::invalid_argument otherwise
ConfidenceBand confidenceBand(const std::vector<std::vector<double>>& runs, double level = 0.95);

}  // namespace prisca::core
