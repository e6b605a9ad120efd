// PoseFilter's parameters: checked, and derived from the fit (the input gain) and from a
// demonstration (the process noise densities); the quantiles the gate uses.
#include "PoseFilter.h"
#include "PoseFilter_p.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace prisca::core {

using namespace posefilter;

double normalQuantile(double p) {
    if (!(p > 0.0 && p < 1.0)) {
        throw std::invalid_argument("normalQuantile: p = " + std::to_string(p) +
                                    " is outside (0, 1)");
    }
    // A rational approximation on three ranges (relative error about 1e-9) ...
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                               -2.759285104469687e+02, 1.383577518672690e+02,
                               -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                               -1.556989798598866e+02, 6.680131188771972e+01,
                               -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                               -2.400758277161838e+00, -2.549732539343734e+00,
                               4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};
    constexpr double low = 0.02425;
    double x = 0.0;
    if (p < low || p > 1.0 - low) {
        const double q = std::sqrt(-2.0 * std::log(p < low ? p : 1.0 - p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
        if (p > 1.0 - low) {
            x = -x;
        }
    } else {
        const double q = p - 0.5;
        const double r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    // ... refined by one step of Halley's iteration on the exact distribution function.
    const double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
    const double u = e * std::sqrt(2.0 * kPi) * std::exp(0.5 * x * x);
    return x - u / (1.0 + 0.5 * x * u);
}

double chiSquareQuantile(double p, int dof) {
    if (dof < 1) {
        throw std::invalid_argument("chiSquareQuantile: degrees of freedom " + std::to_string(dof) +
                                    " < 1");
    }
    const double z = normalQuantile(p);
    const double k = dof;
    const double h = 2.0 / (9.0 * k);
    const double cube = 1.0 - h + z * std::sqrt(h);
    return cube > 0.0 ? k * cube * cube * cube : 0.0;
}

std::array<int, 6> PoseFilterParameters::componentIndices() const {
    return {pose.x, pose.y, pose.heading, velocity.forward, velocity.lateral, velocity.yawRate};
}

void PoseFilterParameters::validate() const {
    if (stateDimension < 6) {
        fail("state dimension " + std::to_string(stateDimension) + " < 6 (pose and velocities)");
    }
    const std::array<int, 6> indices = componentIndices();
    for (int i = 0; i < 6; ++i) {
        if (indices[i] < 0 || indices[i] >= stateDimension) {
            fail(std::string(kComponentNames[i]) + " index " + std::to_string(indices[i]) +
                 " is outside the state (n = " + std::to_string(stateDimension) + ")");
        }
        for (int j = 0; j < i; ++j) {
            if (indices[j] == indices[i]) {
                fail(std::string(kComponentNames[i]) + " and " + kComponentNames[j] +
                     " share index " + std::to_string(indices[i]));
            }
        }
    }
    if (measured.empty() || measured.size() > 6) {
        fail("the measured set has " + std::to_string(measured.size()) +
             " components (1 to 6 needed)");
    }
    for (std::size_t i = 0; i < measured.size(); ++i) {
        if (std::find(indices.begin(), indices.end(), measured[i]) == indices.end()) {
            fail("measured index " + std::to_string(measured[i]) +
                 " is none of the pose and velocity indices");
        }
        if (std::find(measured.begin(), measured.begin() + static_cast<long>(i), measured[i]) !=
            measured.begin() + static_cast<long>(i)) {
            fail("measured index " + std::to_string(measured[i]) + " is listed twice");
        }
    }
    if (measurementStd.size() != stateDimension) {
        fail("measurement std has " + std::to_string(measurementStd.size()) +
             " components, the state " + std::to_string(stateDimension));
    }
    for (int index : measured) {
        if (!(measurementStd[index] > 0.0) || !std::isfinite(measurementStd[index])) {
            fail("measurement std of component " + std::to_string(index) + " = " +
                 std::to_string(measurementStd[index]) + " (finite and > 0 needed)");
        }
    }
    for (int i = 0; i < 3; ++i) {
        if (!(accelerationDensity[i] >= 0.0) || !std::isfinite(accelerationDensity[i])) {
            fail("acceleration density of the " + std::string(kComponentNames[3 + i]) + " = " +
                 std::to_string(accelerationDensity[i]) + " (finite and >= 0 needed)");
        }
    }
    for (int i = 0; i < 3; ++i) {
        if (!(jerkDensity[i] >= 0.0) || !std::isfinite(jerkDensity[i])) {
            fail("jerk density of the " + std::string(kComponentNames[3 + i]) + " = " +
                 std::to_string(jerkDensity[i]) + " (finite and >= 0 needed)");
        }
    }
    if (!(initialAccelerationStd.array() > 0.0).all() || !initialAccelerationStd.allFinite()) {
        fail("initial acceleration std must be finite and > 0");
    }
    if (!(controlPeriod > 0.0) || !std::isfinite(controlPeriod)) {
        fail("control period " + std::to_string(controlPeriod) + " s (> 0 needed)");
    }
    if (loopLatencySteps < 0) {
        fail("latency " + std::to_string(loopLatencySteps) + " steps (>= 0 needed)");
    }
    if (inputGain.size() && (inputGain.rows() != 3 || !inputGain.allFinite())) {
        fail("input gain is " + std::to_string(inputGain.rows()) + " x " +
             std::to_string(inputGain.cols()) + " or not finite (3 x m, finite needed)");
    }
    if (!(gateProbability > 0.0)) {
        fail("gate probability " + std::to_string(gateProbability) + " (in (0, 1], 1 = no gate)");
    }
    if (reinitialiseAfter < 1) {
        fail("re-initialisation count " + std::to_string(reinitialiseAfter) + " (>= 1 needed)");
    }
    if (!(initialStd.array() > 0.0).all() || !initialStd.allFinite()) {
        fail("initial std must be finite and > 0 for all six components");
    }
    if (!(maxPredictionSpan > 0.0) || !std::isfinite(maxPredictionSpan)) {
        fail("largest prediction span " + std::to_string(maxPredictionSpan) + " s (> 0 needed)");
    }
}

Eigen::MatrixXd inputGainFromFit(const Eigen::MatrixXd& b, const BodyVelocityIndices& velocity) {
    const int columns[3] = {velocity.forward, velocity.lateral, velocity.yawRate};
    Eigen::MatrixXd g(3, b.rows());
    for (int i = 0; i < 3; ++i) {
        if (columns[i] < 0 || columns[i] >= b.cols()) {
            throw std::invalid_argument("inputGainFromFit: velocity index " +
                                        std::to_string(columns[i]) + " is outside B's " +
                                        std::to_string(b.cols()) + " columns");
        }
        g.row(i) = b.col(columns[i]).transpose();
    }
    return g;
}

namespace {

// The random-walk density of each body velocity's `order`-th difference per step (1: the
// velocity's change, an acceleration density; 2: the change of that change per step, a jerk
// density): the nearest-rank 99th percentile of the differences' size over the demonstration,
// squared, per dt, and at least `floor`. `name` names the caller in messages.
Eigen::Vector3d differenceDensity(const Eigen::MatrixXd& states,
                                  const BodyVelocityIndices& velocity, double dt, double floor,
                                  int order, const char* name) {
    if (states.rows() < order + 2) {
        throw std::invalid_argument(std::string(name) + ": " + std::to_string(states.rows()) +
                                    " samples (" + std::to_string(order + 2) + " or more needed)");
    }
    if (!(dt > 0.0)) {
        throw std::invalid_argument(std::string(name) + ": dt = " + std::to_string(dt) +
                                    " (> 0 needed)");
    }
    const int columns[3] = {velocity.forward, velocity.lateral, velocity.yawRate};
    Eigen::Vector3d density;
    std::vector<double> changes(static_cast<std::size_t>(states.rows() - order));
    for (int i = 0; i < 3; ++i) {
        if (columns[i] < 0 || columns[i] >= states.cols()) {
            throw std::invalid_argument(std::string(name) + ": velocity index " +
                                        std::to_string(columns[i]) + " is outside the state");
        }
        const int c = columns[i];
        for (Eigen::Index k = 0; k + order < states.rows(); ++k) {
            changes[static_cast<std::size_t>(k)] =
                order == 1
                    ? std::abs(states(k + 1, c) - states(k, c))
                    // the change of a per-step change, per step
                    : std::abs(states(k + 2, c) - 2.0 * states(k + 1, c) + states(k, c)) / dt;
        }
        // Nearest-rank 99th percentile.
        const std::size_t rank =
            static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(changes.size()))) - 1;
        std::nth_element(changes.begin(), changes.begin() + static_cast<long>(rank), changes.end());
        const double change = changes[rank];
        density[i] = std::max(change * change / dt, floor);
    }
    return density;
}

}  // namespace

Eigen::Vector3d accelerationDensityFromStates(const Eigen::MatrixXd& states,
                                              const BodyVelocityIndices& velocity, double dt,
                                              double floor) {
    return differenceDensity(states, velocity, dt, floor, 1, "accelerationDensityFromStates");
}

Eigen::Vector3d jerkDensityFromStates(const Eigen::MatrixXd& states,
                                      const BodyVelocityIndices& velocity, double dt,
                                      double floor) {
    return differenceDensity(states, velocity, dt, floor, 2, "jerkDensityFromStates");
}

}  // namespace prisca::core
