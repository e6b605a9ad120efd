#include "StartLaw.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <vector>

namespace prisca::core {

namespace {

// |s| of the fastest mode of x+ = M x, s = log(lambda) / dt.
double fastestRate(const Eigen::MatrixXd& m, double dt) {
    const Eigen::VectorXcd lambda = m.eigenvalues();
    double fastest = 0.0;
    for (Eigen::Index i = 0; i < lambda.size(); ++i) {
        const double magnitude = std::abs(lambda[i]);
        const double rate = magnitude > 0.0 ? std::abs(std::log(lambda[i])) / dt
                                            : std::numeric_limits<double>::infinity();
        fastest = std::max(fastest, rate);
    }
    return fastest;
}

}  // namespace

Eigen::MatrixXd stationaryLqrGain(const Eigen::MatrixXd& ad, const Eigen::MatrixXd& bd,
                                  const Eigen::MatrixXd& q, const Eigen::MatrixXd& r,
                                  int maxIterations, int* iterations) {
    const Eigen::Index n = ad.rows();
    const Eigen::Index m = bd.cols();
    if (ad.cols() != n || bd.rows() != n || q.rows() != n || q.cols() != n || r.rows() != m ||
        r.cols() != m || maxIterations < 1) {
        throw std::invalid_argument("stationaryLqrGain: A n x n, B n x m, Q n x n, R m x m");
    }
    // The recursion of the finite-horizon LQR run until its gain stops changing: the gain
    // settles even where P does not (a weighted component no control reaches grows P
    // linearly, but enters the gain only through the components the controls do reach).
    Eigen::MatrixXd p = q;
    Eigen::MatrixXd gain = Eigen::MatrixXd::Zero(m, n);
    int k = 0;
    for (; k < maxIterations; ++k) {
        const Eigen::MatrixXd s = r + bd.transpose() * p * bd;
        Eigen::MatrixXd next = s.ldlt().solve(bd.transpose() * p * ad);
        p = q + ad.transpose() * p * (ad - bd * next);
        p = 0.5 * (p + p.transpose()).eval();
        if (!next.allFinite() || !p.allFinite()) {
            throw std::invalid_argument(
                "stationaryLqrGain: the Riccati recursion left the numbers");
        }
        const double change = (next - gain).norm();
        gain = std::move(next);
        if (k > 0 && change <= 1e-12 * std::max(gain.norm(), 1e-300)) {
            ++k;
            break;
        }
    }
    if (iterations) {
        *iterations = k;
    }
    return gain;
}

StartLaw deriveStartLaw(const Demonstration& demonstration, const Eigen::MatrixXd& b,
                        const DeviationModel& deviation, const ActionLimits& limits,
                        const StartLawOptions& options) {
    const int n = demonstration.stateDimension();
    const int m = demonstration.actionDimension();
    const int T = demonstration.length();
    if (b.rows() != m || b.cols() != n || limits.lower.size() != m || limits.upper.size() != m) {
        throw std::invalid_argument("deriveStartLaw: B must be m x n and the limits m values");
    }
    if (options.structure.size() != 0 &&
        (options.structure.rows() != m || options.structure.cols() != n)) {
        throw std::invalid_argument("deriveStartLaw: the structure must be m x n");
    }
    if (options.proportional.size() != 0 &&
        (options.proportional.rows() != m || options.proportional.cols() != n)) {
        throw std::invalid_argument("deriveStartLaw: the proportional gains must be m x n");
    }
    if (options.drift.size() != 0 && (options.drift.rows() != n || options.drift.cols() != n)) {
        throw std::invalid_argument("deriveStartLaw: the drift A must be n x n");
    }
    if (options.scaleLag < 1 || T <= options.scaleLag || options.horizon < 0) {
        throw std::invalid_argument(
            "deriveStartLaw: the demonstration must be longer than the scale lag (>= 1), and "
            "the horizon >= 0");
    }
    StartLaw out;
    // A-bar: the drift plus the error's own kinematics, averaged over the demonstration.
    out.meanDynamics = options.drift.size() != 0 ? options.drift : Eigen::MatrixXd::Zero(n, n);
    Eigen::MatrixXd kinematics(n, n);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n, n);
    for (int t = 0; t < T; ++t) {
        deviation.kinematics(demonstration.states.row(t).transpose(), kinematics);
        sum += kinematics;
    }
    out.meanDynamics += sum / static_cast<double>(T);

    // Bryson's rule from the demonstration's own scales.
    const int lag = options.scaleLag;
    Eigen::VectorXd meanSquare = Eigen::VectorXd::Zero(n);
    for (int t = 0; t + lag < T; ++t) {
        meanSquare += deviation
                          .deviation(demonstration.states.row(t + lag).transpose(),
                                     demonstration.states.row(t).transpose())
                          .cwiseAbs2();
    }
    out.errorScale = (meanSquare / static_cast<double>(T - lag)).cwiseSqrt();
    out.actionScale = 0.5 * (limits.upper - limits.lower);
    Eigen::VectorXd qDiagonal = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i) {
        const double sigma = out.errorScale[i];
        if (std::isfinite(sigma) && sigma > 1e-9) {
            qDiagonal[i] = 1.0 / (sigma * sigma);
        }
    }
    Eigen::VectorXd rDiagonal(m);
    for (int l = 0; l < m; ++l) {
        const double half = out.actionScale[l];
        if (!(std::isfinite(half) && half > 0.0)) {
            throw std::invalid_argument("deriveStartLaw: every control needs a finite range");
        }
        rDiagonal[l] = 1.0 / (half * half);
    }

    // Components the action sets: their effect through A-bar moves into B, and they leave the
    // loop's state (no weight, no dynamics, no gain).
    Eigen::MatrixXd model = out.meanDynamics;
    Eigen::MatrixXd effect = b;
    std::vector<bool> set(static_cast<size_t>(n), false);
    if (options.proportional.size() != 0) {
        std::vector<bool> candidate(static_cast<size_t>(n), false);
        for (int i = 0; i < n; ++i) {
            candidate[static_cast<size_t>(i)] =
                options.proportional.col(i).cwiseAbs().maxCoeff() > 0.0;
        }
        // A candidate that integrates another (A-bar links them: the heading integrates the
        // yaw rate) is driven through it, not set: it stays a state.
        for (int j = 0; j < n; ++j) {
            bool integrates = false;
            for (int i = 0; i < n; ++i) {
                integrates = integrates ||
                             (i != j && candidate[static_cast<size_t>(i)] && model(j, i) != 0.0);
            }
            set[static_cast<size_t>(j)] = candidate[static_cast<size_t>(j)] && !integrates;
        }
        for (int i = 0; i < n; ++i) {
            if (!set[static_cast<size_t>(i)]) {
                continue;
            }
            for (int j = 0; j < n; ++j) {
                if (!set[static_cast<size_t>(j)]) {
                    effect.col(j) += model(j, i) * options.proportional.col(i);
                }
            }
        }
        for (int i = 0; i < n; ++i) {
            if (set[static_cast<size_t>(i)]) {
                model.row(i).setZero();
                model.col(i).setZero();
                effect.col(i).setZero();
                qDiagonal[i] = 0.0;
            }
        }
    }
    out.reducedModel = model;
    out.reducedEffect = effect;

    const double dt = demonstration.dt;
    const Eigen::MatrixXd ad = Eigen::MatrixXd::Identity(n, n) + dt * model;
    const Eigen::MatrixXd bd = dt * effect.transpose();
    out.gain = stationaryLqrGain(ad, bd, qDiagonal.asDiagonal(), rDiagonal.asDiagonal(), 200000,
                                 &out.riccatiIterations);
    // The delay's limit: a channel whose own loop (the others open) has a mode faster than
    // kDelayPhase / tau has its effort weight doubled until none has; then the whole loop.
    if (options.delay > 0.0) {
        const double fastestAllowed = kDelayPhase / options.delay;
        for (int round = 0; round < 200; ++round) {
            bool slower = false;
            for (int l = 0; l < m; ++l) {
                const Eigen::MatrixXd own = ad - bd.col(l) * out.gain.row(l);
                if (fastestRate(own, dt) > fastestAllowed) {
                    rDiagonal[l] *= 2.0;
                    slower = true;
                }
            }
            if (!slower && fastestRate(ad - bd * out.gain, dt) > fastestAllowed) {
                rDiagonal *= 2.0;
                slower = true;
            }
            if (!slower) {
                break;
            }
            out.gain = stationaryLqrGain(ad, bd, qDiagonal.asDiagonal(), rDiagonal.asDiagonal(),
                                         200000, &out.riccatiIterations);
        }
    }
    for (int i = 0; i < n; ++i) {
        if (set[static_cast<size_t>(i)]) {
            out.gain.col(i).setZero();
        }
    }
    out.effort = rDiagonal;
    out.fastestMode = fastestRate(ad - bd * out.gain, dt);
    out.law.errorCombination = out.gain;
    if (options.structure.size() != 0) {
        out.law.errorCombination =
            out.gain.cwiseProduct((options.structure.array() != 0.0).cast<double>().matrix());
    }
    out.law.kp = Eigen::VectorXd::Ones(m);
    out.law.kd = Eigen::VectorXd::Zero(m);
    out.law.horizon = options.horizon;
    return out;
}

}  // namespace prisca::core
