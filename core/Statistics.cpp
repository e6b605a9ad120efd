#include "Statistics.h"

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

// ln Gamma(a + b) - ln Gamma(a) for a >= 20 from the Stirling series, written so that the two
// huge lgamma values never get subtracted (they would lose ~1e-9 at a = 5e5, i.e. dof = 1e6).
double logGammaRatio(double a, double b) {
    auto correction = [](double z) {
        // Stirling series tail 1/(12z) - 1/(360z^3) + ...; the next term is < 2e-15 at z = 20.
        const double r = 1.0 / z;
        const double r2 = r * r;
        return r * (1.0 / 12.0 - r2 * (1.0 / 360.0 - r2 * (1.0 / 1260.0 - r2 / 1680.0)));
    };
    const double c = a + b;
    return (a - 0.5) * std::log1p(b / a) + b * std::log(c) - b + correction(c) - correction(a);
}

double logBeta(double a, double b) {
    const double big = std::max(a, b);
    const double small = std::min(a, b);
    if (big >= 20.0) {
        return std::lgamma(small) - logGammaRatio(big, small);
    }
    return std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b);
}

// Continued fraction of the incomplete beta function (modified Lentz method);
// converges fast for x < (a + 1) / (a + b + 2), in O(sqrt(max(a, b))) iterations.
double betaContinuedFraction(double a, double b, double x, double y) {
    constexpr double tiny = 1e-300;
    const int maxIterations = 1000 + static_cast<int>(20.0 * std::sqrt(std::max(a, b)));
    const double qab = a + b;
    const double qap = a + 1.0;
    const double qam = a - 1.0;
    double c = 1.0;
    // 1 - (a + b) x / (a + 1) written with y = 1 - x: it cancels badly for x near 1 and large a.
    double d = ((1.0 - b) + qab * y) / qap;
    if (std::abs(d) < tiny) {
        d = tiny;
    }
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m <= maxIterations; ++m) {
        const double m2 = 2.0 * m;
        // Even step of the fraction.
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny) {
            d = tiny;
        }
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny) {
            c = tiny;
        }
        d = 1.0 / d;
        h *= d * c;
        // Odd step.
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny) {
            d = tiny;
        }
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny) {
            c = tiny;
        }
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) <= kEps) {
            break;
        }
    }
    return h;
}

// Arguments of the incomplete beta, each with its logarithm: x and ln x may differ in range
// (x underflows to 0 for |t| > 1e154 while ln x is still finite and needed).
struct BetaArgument {
    double x = 0.0;
    double y = 1.0;  // 1 - x, computed without cancelling against 1
    double lnX = -kInf;
    double lnY = 0.0;
};

// Regularized incomplete beta I_x(a, b) for a, b > 0.
double regularizedIncompleteBeta(double a, double b, const BetaArgument& arg) {
    if (arg.lnX == -kInf) {
        return 0.0;
    }
    if (arg.lnY == -kInf) {
        return 1.0;
    }
    const double front = std::exp(a * arg.lnX + b * arg.lnY - logBeta(a, b));
    if (arg.x < (a + 1.0) / (a + b + 2.0)) {
        return front * betaContinuedFraction(a, b, arg.x, arg.y) / a;
    }
    return 1.0 - front * betaContinuedFraction(b, a, arg.y, arg.x) / b;
}

// x = k / (k + t^2) and y = t^2 / (k + t^2) without forming t^2 (it overflows for huge t), and
// their logarithms via log1p so that k/2 * ln x stays accurate when x is near 1 and k is large.
BetaArgument studentTBetaArgument(double t, double dof) {
    BetaArgument arg;
    const double root = std::sqrt(dof);
    const double at = std::abs(t);
    if (at == 0.0) {
        arg.x = 1.0;
        arg.y = 0.0;
        arg.lnX = 0.0;
        arg.lnY = -kInf;
    } else if (at > root) {
        const double r = root / at;  // < 1, may underflow for t near the double range
        const double r2 = r * r;
        arg.x = r2 / (1.0 + r2);
        arg.y = 1.0 / (1.0 + r2);
        arg.lnX = 2.0 * (std::log(root) - std::log(at)) - std::log1p(r2);
        arg.lnY = -std::log1p(r2);
    } else {
        const double s = at / root;  // <= 1
        const double s2 = s * s;
        arg.x = 1.0 / (1.0 + s2);
        arg.y = s2 / (1.0 + s2);
        arg.lnX = -std::log1p(s2);
        arg.lnY = 2.0 * std::log(s) - std::log1p(s2);
    }
    return arg;
}

// P(T > t) for t >= 0: 0.5 * I_x(k/2, 1/2). Working on the tail keeps small tail probabilities
// at full relative precision instead of rounding them against 1.
double upperTail(double t, double dof) {
    return 0.5 * regularizedIncompleteBeta(0.5 * dof, 0.5, studentTBetaArgument(t, dof));
}

double studentTDensity(double t, double dof) {
    const double s = std::abs(t) / std::sqrt(dof);
    const double logKernel = s > 1e150 ? 2.0 * std::log(s) : std::log1p(s * s);
    return std::exp(-0.5 * std::log(dof) - logBeta(0.5 * dof, 0.5) - 0.5 * (dof + 1.0) * logKernel);
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
