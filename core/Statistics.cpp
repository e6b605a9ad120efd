#include "Statistics.h"

#include "core/DeviationModel.h"

#include <unsupported/Eigen/SpecialFunctions>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>

namespace prisca::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Moments {
    int count = 0;
    double mean = kNaN;
    double variance = kNaN;  // sample (N-1); 0 for N == 1
};

// Two passes with the compensating term (Chan, Golub & LeVeque): accurate even when the mean
// is large compared with the spread, which a one-pass sum of squares is not.
Moments moments(const std::vector<double>& finiteValues) {
    Moments m;
    m.count = static_cast<int>(finiteValues.size());
    if (m.count == 0) {
        return m;
    }
    double sum = 0.0;
    for (double v : finiteValues) {
        sum += v;
    }
    const double firstMean = sum / m.count;
    double squares = 0.0;
    double residual = 0.0;
    for (double v : finiteValues) {
        const double d = v - firstMean;
        squares += d * d;
        residual += d;
    }
    // The residual is the rounding error of the first pass's sum; adding it back refines the mean.
    m.mean = firstMean + residual / m.count;
    m.variance = m.count == 1
                     ? 0.0
                     : std::max(0.0, (squares - residual * residual / m.count) / (m.count - 1));
    return m;
}

std::vector<double> finiteOnly(const std::vector<double>& values) {
    std::vector<double> out;
    out.reserve(values.size());
    for (double v : values) {
        if (std::isfinite(v)) {
            out.push_back(v);
        }
    }
    return out;
}

// x = k / (k + t^2) and y = t^2 / (k + t^2) = 1 - x for t >= 0, without forming t^2 (it
// overflows for huge t) and without computing one from the other (y would cancel near x = 1).
struct BetaArgument {
    double x = 1.0;
    double y = 0.0;
};

BetaArgument studentTBetaArgument(double t, double dof) {
    const double root = std::sqrt(dof);
    if (t > root) {
        const double r = root / t;  // < 1, may underflow for t near the double range
        return {r * r / (1.0 + r * r), 1.0 / (1.0 + r * r)};
    }
    const double s = t / root;  // <= 1
    return {1.0 / (1.0 + s * s), s * s / (1.0 + s * s)};
}

// P(T > |t|), kept at full relative precision in the far tail instead of rounding it
// against 1. One and two degrees of freedom have closed forms (and the Cauchy tail reaches far
// beyond what x = k / (k + t^2) can hold); otherwise 0.5 I_x(k/2, 1/2) from Eigen's regularized
// incomplete beta.
double upperTail(double t, double dof) {
    t = std::abs(t);  // symmetric
    if (dof == 1.0) {
        return t > 1.0 ? std::atan(1.0 / t) / kPi : 0.5 - std::atan(t) / kPi;
    }
    if (dof == 2.0) {
        // 1/2 - t / (2 sqrt(2 + t^2)) = 1 / ((2 + t^2) (1 + t / sqrt(2 + t^2))), without the
        // cancellation.
        if (t > 1e150) {
            return 0.5 / t / t;
        }
        const double s = t / std::sqrt(2.0 + t * t);
        return 1.0 / ((2.0 + t * t) * (1.0 + s));
    }
    const BetaArgument arg = studentTBetaArgument(t, dof);
    const double a = 0.5 * dof;
    const double direct = Eigen::numext::betainc(a, 0.5, arg.x);
    // I_x(a, b) sees y only as 1 - x, a relative error of about eps / y; its complement
    // 1 - I_y(b, a) sees y exactly and loses about eps / I_x. Take the smaller error.
    if (arg.y < direct) {
        return 0.5 * (1.0 - Eigen::numext::betainc(0.5, a, arg.y));
    }
    return 0.5 * direct;
}

// ln B(k/2, 1/2) for the density; only Newton's step uses it, never the returned quantile.
double logBetaHalf(double dof) {
    return std::lgamma(0.5 * dof) + std::lgamma(0.5) - std::lgamma(0.5 * dof + 0.5);
}

double studentTDensity(double t, double dof) {
    const double s = std::abs(t) / std::sqrt(dof);
    const double logKernel = s > 1e150 ? 2.0 * std::log(s) : std::log1p(s * s);
    return std::exp(-0.5 * std::log(dof) - logBetaHalf(dof) - 0.5 * (dof + 1.0) * logKernel);
}

void requireDegreesOfFreedom(int degreesOfFreedom) {
    if (degreesOfFreedom < 1) {
        throw std::invalid_argument("Student t: degrees of freedom must be >= 1");
    }
}

// The t > 0 with P(T > t) = tail, for tail in (0, 0.5).
double upperTailQuantile(double tail, double dof) {
    // Bracket: upperTail is decreasing, so double hi until it drops to the target.
    double lo = 0.0;
    double hi = 1.0;
    for (int i = 0; i < 2100 && upperTail(hi, dof) > tail; ++i) {
        lo = hi;
        hi *= 2.0;
    }
    // Newton on upperTail(t) - tail, falling back to bisection whenever a step leaves the bracket.
    double t = 0.5 * (lo + hi);
    for (int i = 0; i < 400; ++i) {
        const double g = upperTail(t, dof) - tail;
        if (g == 0.0) {
            return t;
        }
        if (g > 0.0) {
            lo = t;  // tail still too heavy: the quantile lies further out
        } else {
            hi = t;
        }
        const double density = studentTDensity(t, dof);
        double next = density > 0.0 ? t + g / density : kNaN;
        if (!(next > lo && next < hi)) {
            next = 0.5 * (lo + hi);
        }
        const double step = std::abs(next - t);
        t = next;
        if (step <= 4.0 * kEps * t || hi - lo <= 4.0 * kEps * hi) {
            break;
        }
    }
    return t;
}

}  // namespace

ErrorSummary summarizeErrors(const std::vector<double>& errors) {
    ErrorSummary summary;
    std::vector<double> magnitudes;
    magnitudes.reserve(errors.size());
    for (double e : errors) {
        if (std::isfinite(e)) {
            magnitudes.push_back(std::abs(e));
        } else {
            ++summary.nonFinite;
        }
    }
    const Moments m = moments(magnitudes);
    summary.count = m.count;
    summary.meanAbsoluteError = m.mean;
    summary.standardDeviation = std::sqrt(m.variance);
    if (magnitudes.empty()) {
        summary.minimum = kNaN;
        summary.maximum = kNaN;
    } else {
        const auto [lowest, highest] = std::minmax_element(magnitudes.begin(), magnitudes.end());
        summary.minimum = *lowest;
        summary.maximum = *highest;
    }
    // Table I reports the variance as the square of the std shown beside it; keep them identical.
    summary.variance = summary.standardDeviation * summary.standardDeviation;
    return summary;
}

double mean(const std::vector<double>& values) {
    return moments(finiteOnly(values)).mean;
}

double sampleVariance(const std::vector<double>& values) {
    return moments(finiteOnly(values)).variance;
}

double studentTCdf(double t, int degreesOfFreedom) {
    requireDegreesOfFreedom(degreesOfFreedom);
    if (std::isnan(t)) {
        return kNaN;
    }
    const double tail = upperTail(t, degreesOfFreedom);
    return t >= 0.0 ? 1.0 - tail : tail;
}

double studentTQuantile(double probability, int degreesOfFreedom) {
    requireDegreesOfFreedom(degreesOfFreedom);
    if (!(probability >= 0.0 && probability <= 1.0)) {
        throw std::invalid_argument("Student t quantile: probability must lie in [0, 1]");
    }
    if (probability == 0.0) {
        return -kInf;
    }
    if (probability == 1.0) {
        return kInf;
    }
    if (probability == 0.5) {
        return 0.0;
    }
    // Solve on the smaller tail and mirror, so that both halves share one code path (symmetry).
    const double tail = probability < 0.5 ? probability : 1.0 - probability;
    const double t = upperTailQuantile(tail, degreesOfFreedom);
    return probability < 0.5 ? -t : t;
}

ConfidenceBand confidenceBand(const std::vector<std::vector<double>>& runs, double level) {
    if (!(level > 0.0 && level < 1.0)) {
        throw std::invalid_argument("confidenceBand: level must lie in (0, 1)");
    }
    std::size_t length = 0;
    for (const auto& run : runs) {
        length = std::max(length, run.size());
    }
    ConfidenceBand band;
    band.mean.resize(length);
    band.lower.resize(length);
    band.upper.resize(length);
    band.standardDeviation.resize(length);
    band.count.resize(length);

    // Few distinct N occur along a curve; cache the quantile instead of inverting per point.
    std::map<int, double> quantileByCount;
    const double probability = 0.5 * (1.0 + level);
    std::vector<double> column;
    column.reserve(runs.size());
    for (std::size_t i = 0; i < length; ++i) {
        column.clear();
        for (const auto& run : runs) {
            if (i < run.size() && std::isfinite(run[i])) {
                column.push_back(run[i]);
            }
        }
        const Moments m = moments(column);
        band.count[i] = m.count;
        band.mean[i] = m.mean;
        band.standardDeviation[i] = std::sqrt(m.variance);
        if (m.count < 2) {
            // N == 1: no spread to estimate, the band collapses to the mean; N == 0: all NaN.
            band.lower[i] = m.mean;
            band.upper[i] = m.mean;
            continue;
        }
        auto found = quantileByCount.find(m.count);
        if (found == quantileByCount.end()) {
            found =
                quantileByCount.emplace(m.count, studentTQuantile(probability, m.count - 1)).first;
        }
        const double halfWidth = found->second * band.standardDeviation[i] / std::sqrt(m.count);
        band.lower[i] = m.mean - halfWidth;
        band.upper[i] = m.mean + halfWidth;
    }
    return band;
}

}  // namespace prisca::core
