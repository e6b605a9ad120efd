#include "ActionMapping.h"

#include "NestedExpectation.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::core {

std::optional<IntuitiveMapping> IntuitiveMapping::parse(const QString& text, QString* error) {
    const QStringList rows = text.split(QLatin1Char(';'));
    std::vector<std::vector<int>> values;
    for (int r = 0; r < rows.size(); ++r) {
        const QStringList entries = rows[r].split(QLatin1Char(','));
        std::vector<int> row;
        for (int c = 0; c < entries.size(); ++c) {
            const QString e = entries[c].trimmed();
            int v = 0;
            if (e == QLatin1String("1") || e == QLatin1String("+1")) {
                v = 1;
            } else if (e == QLatin1String("-1")) {
                v = -1;
            } else if (e == QLatin1String("0") || e == QLatin1String("-0") ||
                       e == QLatin1String("+0")) {
                v = 0;
            } else {
                if (error) {
                    *error = QStringLiteral("mapping row %1, column %2: '%3' is not -1, 0 or +1")
                                 .arg(r + 1)
                                 .arg(c + 1)
                                 .arg(e);
                }
                return std::nullopt;
            }
            row.push_back(v);
        }
        if (!values.empty() && row.size() != values.front().size()) {
            if (error) {
                *error = QStringLiteral("mapping row %1 has %2 entries, row 1 has %3")
                             .arg(r + 1)
                             .arg(row.size())
                             .arg(values.front().size());
            }
            return std::nullopt;
        }
        values.push_back(std::move(row));
    }
    IntuitiveMapping mapping;
    mapping.signs.resize(static_cast<int>(values.size()), static_cast<int>(values.front().size()));
    for (int r = 0; r < mapping.signs.rows(); ++r) {
        for (int c = 0; c < mapping.signs.cols(); ++c) {
            mapping.signs(r, c) = values[r][c];
        }
    }
    return mapping;
}

QString IntuitiveMapping::toString() const {
    QStringList rows;
    for (int r = 0; r < signs.rows(); ++r) {
        QStringList entries;
        for (int c = 0; c < signs.cols(); ++c) {
            entries << QString::number(signs(r, c));
        }
        rows << entries.join(QLatin1Char(','));
    }
    return rows.join(QLatin1Char(';'));
}

ActionMappingFit fitActionMapping(const Demonstration& demonstration,
                                  const IntuitiveMapping& mapping, const DeviationModel& deviation,
                                  const ActionMappingFitOptions& options) {
    const int n = demonstration.stateDimension();
    const int m = demonstration.actionDimension();
    const int T = demonstration.length();
    const int d = options.latency;
    if (mapping.controls() != m || mapping.states() != n) {
        throw std::invalid_argument(
            QStringLiteral(
                "the mapping is %1 x %2 but the demonstration has %3 controls and %4 states")
                .arg(mapping.controls())
                .arg(mapping.states())
                .arg(m)
                .arg(n)
                .toStdString());
    }
    if (deviation.dimension != n) {
        throw std::invalid_argument("fitActionMapping: the deviation model's dimension is not n");
    }
    if (d < 0) {
        throw std::invalid_argument("fitActionMapping: the latency shift must be >= 0");
    }
    // Pairs k = first .. T-2-d: du_k needs u_{k-1}, ds_{k+1+d} needs s_{k+1+d}, and the rate
    // change also needs ds_{k+d} = s_{k+d} - s_{k+d-1}.
    const bool rateChange = options.target == ActionMappingFitOptions::Target::RateChange;
    const int first = 1;
    const int last = T - 2 - d;
    const int K = last - first + 1;
    if (K < 1) {
        throw std::invalid_argument(
            QStringLiteral("the demonstration has %1 samples, too few to fit with latency %2")
                .arg(T)
                .arg(d)
                .toStdString());
    }
    const double dt = demonstration.dt;
    Eigen::MatrixXd ds(K, n);  // row t: change of state, in the frame of the earlier sample
    Eigen::MatrixXd du(K, m);  // row t: change of action
    Eigen::VectorXd change(n);
    Eigen::VectorXd previousChange(n);
    for (int t = 0; t < K; ++t) {
        const int k = first + t;
        deviation.deviation(demonstration.states.row(k + 1 + d).transpose(),
                            demonstration.states.row(k + d).transpose(), change);
        if (rateChange) {
            // Both changes in the frame of s_{k+d}, so a turning vehicle's frame cancels.
            deviation.deviation(demonstration.states.row(k + d - 1).transpose(),
                                demonstration.states.row(k + d).transpose(), previousChange);
            change += previousChange;  // (s_{k+1} - s_k) - (s_k - s_{k-1})
        }
        ds.row(t) = change.transpose();
        du.row(t) = demonstration.actions.row(k) - demonstration.actions.row(k - 1);
    }
    const Eigen::VectorXd w = nestedExpectationWeights(K);
    const Eigen::VectorXd sqrtW = w.array().sqrt();

    ActionMappingFit fit;
    fit.samples = K;
    fit.bv.setZero(m, n);
    fit.residualRms.setZero(n);
    fit.rSquared.setConstant(n, std::numeric_limits<double>::quiet_NaN());

    std::vector<bool> excited(m, true);
    for (int l = 0; l < m; ++l) {
        const double meanSquare = (w.array() * du.col(l).array().square()).sum();
        if (!(meanSquare > options.excitationThreshold)) {
            excited[l] = false;
            fit.unexcitedChannels.push_back(l);
            fit.warnings << QStringLiteral(
                                "control '%1' never changed in the demonstration: its B_v entries "
                                "stay 0 and it will not adapt; record a demonstration that uses it")
                                .arg(demonstration.actionNames.value(l, QString::number(l)));
        }
    }

    for (int c = 0; c < n; ++c) {
        std::vector<int> controls;
        for (int l = 0; l < m; ++l) {
            if (mapping.signs(l, c) != 0 && excited[l]) {
                controls.push_back(l);
            }
        }
        const Eigen::VectorXd y = ds.col(c);
        Eigen::VectorXd prediction = Eigen::VectorXd::Zero(K);
        if (!controls.empty()) {
            // Column j of X is B~[l, c] dt du_l, so the unknowns are the B_v entries themselves.
            Eigen::MatrixXd X(K, static_cast<int>(controls.size()));
            for (int j = 0; j < static_cast<int>(controls.size()); ++j) {
                X.col(j) = mapping.signs(controls[j], c) * dt * du.col(controls[j]);
            }
            // Complete orthogonal decomposition: the minimum-norm answer if two controls move
            // together in the demonstration, instead of an arbitrary split.
            const Eigen::MatrixXd WX = sqrtW.asDiagonal() * X;
            const Eigen::VectorXd Wy = sqrtW.asDiagonal() * y;
            const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(WX);
            Eigen::VectorXd beta = solver.solve(Wy);
            if (solver.rank() < X.cols()) {
                fit.warnings
                    << QStringLiteral(
                           "state '%1': the controls acting on it moved together, so their "
                           "shares cannot be told apart (minimum-norm fit)")
                           .arg(demonstration.stateNames.value(c, QString::number(c)));
            }
            for (int j = 0; j < static_cast<int>(controls.size()); ++j) {
                if (beta[j] < 0.0) {
                    fit.signConflicts.emplace_back(controls[j], c);
                    fit.warnings
                        << QStringLiteral(
                               "'%1' moved '%2' the opposite way to the intuitive mapping "
                               "(unconstrained B_v = %3)%4")
                               .arg(demonstration.actionNames.value(controls[j]),
                                    demonstration.stateNames.value(c))
                               .arg(beta[j], 0, 'g', 4)
                               .arg(options.nonNegative
                                        ? QStringLiteral("; set to 0, check the sign or the "
                                                         "demonstration")
                                        : QStringLiteral("; check the sign or the demonstration"));
                }
            }
            if (options.nonNegative && (beta.array() < 0.0).any()) {
                // Few unknowns per column (one per control): try every subset of entries left
                // free, the rest at 0, and keep the best feasible one. Exact, and cheap for m <= 4.
                const int q = static_cast<int>(beta.size());
                double best = std::numeric_limits<double>::infinity();
                Eigen::VectorXd bestBeta = Eigen::VectorXd::Zero(q);
                for (int mask = 0; mask < (1 << q); ++mask) {
                    std::vector<int> free;
                    for (int j = 0; j < q; ++j) {
                        if (mask & (1 << j)) {
                            free.push_back(j);
                        }
                    }
                    Eigen::VectorXd candidate = Eigen::VectorXd::Zero(q);
                    if (!free.empty()) {
                        Eigen::MatrixXd sub(K, static_cast<int>(free.size()));
                        for (int f = 0; f < static_cast<int>(free.size()); ++f) {
                            sub.col(f) = WX.col(free[f]);
                        }
                        const Eigen::VectorXd part =
                            sub.completeOrthogonalDecomposition().solve(Wy);
                        if ((part.array() < 0.0).any()) {
                            continue;
                        }
                        for (int f = 0; f < static_cast<int>(free.size()); ++f) {
                            candidate[free[f]] = part[f];
                        }
                    }
                    const double residual = (Wy - WX * candidate).squaredNorm();
                    if (residual < best) {
                        best = residual;
                        bestBeta = candidate;
                    }
                }
                beta = bestBeta;
            }
            for (int j = 0; j < static_cast<int>(controls.size()); ++j) {
                fit.bv(controls[j], c) = beta[j];
            }
            prediction = X * beta;
            const double meanY = w.dot(y);
            const double total = (w.array() * (y.array() - meanY).square()).sum();
            const double residual = (w.array() * (y - prediction).array().square()).sum();
            fit.rSquared[c] =
                total > 0.0 ? 1.0 - residual / total : std::numeric_limits<double>::quiet_NaN();
        }
        fit.residualRms[c] = std::sqrt((w.array() * (y - prediction).array().square()).sum());
    }

    fit.b = fit.bv.cwiseProduct(mapping.asDouble());
    return fit;
}

}  // namespace prisca::core
