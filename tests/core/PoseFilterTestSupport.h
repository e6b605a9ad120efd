#pragma once

// What the pose filter tests share: the truth a filter is run against.

#include "core/PoseFilter.h"

#include <QtTest>

#include <cmath>
#include <deque>
#include <random>

using namespace prisca;
using core::PoseFilter;
using core::PoseFilterParameters;

namespace {

using Vector6 = PoseFilter::Vector6;
using Matrix6 = PoseFilter::Matrix6;

/// The two-sided 95% bounds of the mean of `runs` chi-square variables of `dof` each: the sum is
/// chi-square with runs x dof degrees of freedom.
inline std::pair<double, double> meanBounds(int runs, int dof) {
    const int total = runs * dof;
    return {core::chiSquareQuantile(0.025, total) / runs,
            core::chiSquareQuantile(0.975, total) / runs};
}

inline Vector6 error(const Vector6& truth, const Vector6& estimate) {
    Vector6 e = truth - estimate;
    e[2] = core::wrapAngle(e[2]);
    return e;
}

/// z = truth's measured components plus noise, the rest of the 6-vector as the truth.
inline Eigen::VectorXd measure(const Vector6& truth, const PoseFilterParameters& parameters,
                               std::mt19937_64& random) {
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::VectorXd z = truth;
    for (int index : parameters.measured) {
        z[index] += parameters.measurementStd[index] * normal(random);
    }
    z[2] = core::wrapAngle(z[2]);
    return z;
}

/// Per-step averages of NEES and NIS over runs.
struct Consistency {
    std::vector<double> nees;
    std::vector<double> nis;
    int runs = 0;
};

/// A truth drawn from the filter's own discrete process model (arc + exact constant-velocity
/// noise), measured, filtered; no gate, no latency.
inline Consistency ownModelRuns(const PoseFilterParameters& parameters, int runs, int steps,
                                std::uint64_t seed) {
    Consistency out;
    out.runs = runs;
    out.nees.assign(steps, 0.0);
    out.nis.assign(steps, 0.0);
    std::mt19937_64 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const double dt = parameters.controlPeriod;
    for (int run = 0; run < runs; ++run) {
        PoseFilter filter(parameters);
        Vector6 truth;
        truth << 0.3, -0.2, 0.5, 0.0, 0.0, 0.0;
        // Unmeasured components start as the filter's prior (0, initialStd) says.
        for (int i = 0; i < 6; ++i) {
            if (std::find(parameters.measured.begin(), parameters.measured.end(), i) ==
                parameters.measured.end()) {
                truth[i] += parameters.initialStd[i] * normal(random);
            }
        }
        for (int k = 0; k < steps; ++k) {
            if (k > 0) {
                const Matrix6 q =
                    PoseFilter::processNoise(truth, dt, parameters.accelerationDensity);
                Vector6 w;
                for (int i = 0; i < 6; ++i) {
                    w[i] = normal(random);
                }
                // Q is positive semi-definite of rank 6 for positive densities.
                const Eigen::LLT<Matrix6> llt(q);
                truth = PoseFilter::propagate(truth, dt);
                truth += llt.matrixL() * w;
                truth[2] = core::wrapAngle(truth[2]);
            }
            filter.step(measure(truth, parameters, random));
            filter.commanded(Eigen::Vector2d::Zero());
            const Vector6 e = error(truth, filter.nowEstimate());
            out.nees[k] += e.dot(filter.nowCovariance().ldlt().solve(e)) / runs;
            out.nis[k] += filter.status().nis / runs;
        }
    }
    return out;
}

/// How many per-step averages lie inside the two-sided 95% bounds, from step `from` on.
inline double shareInside(const std::vector<double>& averages, int runs, int dof, int from) {
    const auto [low, high] = meanBounds(runs, dof);
    int inside = 0;
    for (std::size_t k = from; k < averages.size(); ++k) {
        inside += averages[k] >= low && averages[k] <= high;
    }
    return static_cast<double>(inside) / static_cast<double>(averages.size() - from);
}

inline double mean(const std::vector<double>& values, int from) {
    double sum = 0.0;
    for (std::size_t k = from; k < values.size(); ++k) {
        sum += values[k];
    }
    return sum / static_cast<double>(values.size() - from);
}

/// A constant turn integrated finely (substeps of dt / 20) with white accelerations of the given
/// densities on the body velocities: what the filter's discretisation approximates.
class FineTruth {
  public:
    FineTruth(Vector6 start, Eigen::Vector3d density, double dt, std::uint64_t seed)
        : x_(start), density_(density), dt_(dt), random_(seed) {}
    const Vector6& state() const { return x_; }
    void advance() {
        std::normal_distribution<double> normal(0.0, 1.0);
        const int substeps = 20;
        const double h = dt_ / substeps;
        for (int s = 0; s < substeps; ++s) {
            const double mid = x_[2] + 0.5 * x_[5] * h;
            const double c = std::cos(mid), sn = std::sin(mid);
            x_[0] += (c * x_[3] - sn * x_[4]) * h;
            x_[1] += (sn * x_[3] + c * x_[4]) * h;
            x_[2] = core::wrapAngle(x_[2] + x_[5] * h);
            for (int i = 0; i < 3; ++i) {
                x_[3 + i] += std::sqrt(density_[i] * h) * normal(random_);
            }
        }
    }

  private:
    Vector6 x_;
    Eigen::Vector3d density_;
    double dt_;
    std::mt19937_64 random_;
};

inline Vector6 turnStart() {
    Vector6 start;
    start << 0.0, 0.0, 2.8, 1.5, 0.2, 1.2;  // heading crosses +-pi within the first second
    return start;
}

}  // namespace
