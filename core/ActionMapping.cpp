#include "ActionMapping.h"

#include "NestedExpectation.h"

#include <Eigen/QR>

#include <QCoreApplication>

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
    const int R = rateChange ? options.responseSteps : 1;
    if (R < 1) {
        throw std::invalid_argument("fitActionMapping: the response horizon must be >= 1");
    }
    if (options.drift && (!rateChange || R != 1)) {
        throw std::invalid_argument(
            "fitActionMapping: the drift regressors (eq. 5 in full) need the rate-change target "
            "with response horizon 1");
    }
    const int first = 1;
    const int last = T - 1 - R - d;
    const int K = last - first + 1;
    // As few pairs as the reader accepts samples (4), and more than the unknowns of one state's
    // regression (its m gains, and its drift with eq. 5 in full): fewer are no fit.
    const int needed = std::max(4, m + (options.drift ? n : 0) + 1);
    if (K < needed) {
        throw std::invalid_argument(
            QStringLiteral("the demonstration has %1 samples: with latency %2 and response %3 "
                           "that leaves %4 pairs to fit on, at least %5 are needed")
                .arg(T)
                .arg(d)
                .arg(R)
                .arg(std::max(K, 0))
                .arg(needed)
                .toStdString());
    }
    const double dt = demonstration.dt;
    Eigen::MatrixXd ds(K, n);     // row t: change of state, in the frame of the earlier sample
    Eigen::MatrixXd du(K, m);     // row t: change of action
    Eigen::MatrixXd drift(K, n);  // row t: the previous one-step change ds_k (eq. 5's A term)
    Eigen::VectorXd change(n);
    Eigen::VectorXd previousChange(n);
    for (int t = 0; t < K; ++t) {
        const int k = first + t;
        if (rateChange) {
            // (s_{k+R} - s_k) - R (s_k - s_{k-1}) (with the latency shift d), both parts in the
            // frame of s_{k+d} so a turning vehicle's own rotation cancels.
            deviation.deviation(demonstration.states.row(k + R + d).transpose(),
                                demonstration.states.row(k + d).transpose(), change);
            deviation.deviation(demonstration.states.row(k + d - 1).transpose(),
                                demonstration.states.row(k + d).transpose(), previousChange);
            change += R * previousChange;
            drift.row(t) = -previousChange.transpose();  // s_{k+d} - s_{k+d-1} in its frame
        } else {
            deviation.deviation(demonstration.states.row(k + 1 + d).transpose(),
                                demonstration.states.row(k + d).transpose(), change);
        }
        ds.row(t) = change.transpose();
        du.row(t) = demonstration.actions.row(k) - demonstration.actions.row(k - 1);
    }
    const Eigen::VectorXd w = nestedExpectationWeights(K);

    ActionMappingFit fit;
    fit.samples = K;
    fit.bv.setZero(m, n);
    fit.explained.assign(T, true);
    fit.a.setZero(n, n);
    fit.unconstrainedBv.setZero(m, n);
    fit.residualRms.setZero(n);
    fit.rSquared.setConstant(n, std::numeric_limits<double>::quiet_NaN());
    fit.outlierShare.setZero(n);

    std::vector<bool> excited(m, true);
    for (int l = 0; l < m; ++l) {
        const double meanSquare = (w.array() * du.col(l).array().square()).sum();
        if (!(meanSquare > options.excitationThreshold)) {
            excited[l] = false;
            fit.unexcitedChannels.push_back(l);
            fit.warnings << QCoreApplication::translate(
                                "ActionMappingFit",
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
        double residualRms = 0.0;
        if (!controls.empty() || options.drift) {
            // Column j of X is B~[l, c] dt du_l, so the unknowns are the B_v entries themselves;
            // with the drift, n more columns dt ds_k whose unknowns are row c of A (no sign).
            const int q = static_cast<int>(controls.size());
            const int driftColumns = options.drift ? n : 0;
            Eigen::MatrixXd X(K, q + driftColumns);
            for (int j = 0; j < q; ++j) {
                X.col(j) = mapping.signs(controls[j], c) * dt * du.col(controls[j]);
            }
            for (int i = 0; i < driftColumns; ++i) {
                X.col(q + i) = dt * drift.col(i);
            }
            // One weighted fit (with the sign constraint) for given per-sample weights.
            const auto solve = [&](const Eigen::VectorXd& weights, bool report) {
                const Eigen::VectorXd root = weights.array().sqrt();
                // Complete orthogonal decomposition: the minimum-norm answer if two controls move
                // together in the demonstration, instead of an arbitrary split.
                const Eigen::MatrixXd WX = root.asDiagonal() * X;
                const Eigen::VectorXd Wy = root.asDiagonal() * y;
                const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(WX);
                Eigen::VectorXd beta = solver.solve(Wy);
                if (report && solver.rank() < X.cols()) {
                    fit.warnings
                        << QCoreApplication::translate(
                               "ActionMappingFit",
                               "state '%1': the controls acting on it moved together, so their "
                               "shares cannot be told apart (minimum-norm fit)")
                               .arg(demonstration.stateNames.value(c, QString::number(c)));
                }
                if (report) {
                    for (int j = 0; j < q; ++j) {
                        fit.unconstrainedBv(controls[j], c) = beta[j];
                    }
                }
                for (int j = 0; j < q; ++j) {
                    if (report && beta[j] < 0.0) {
                        fit.signConflicts.emplace_back(controls[j], c);
                        fit.warnings
                            << QCoreApplication::translate(
                                   "ActionMappingFit",
                                   "'%1' moved '%2' the opposite way to the intuitive mapping "
                                   "(unconstrained B_v = %3)%4")
                                   .arg(demonstration.actionNames.value(controls[j]),
                                        demonstration.stateNames.value(c))
                                   .arg(beta[j], 0, 'g', 4)
                                   .arg(options.nonNegative
                                            ? QCoreApplication::translate(
                                                  "ActionMappingFit",
                                                  "; set to 0, check the sign or the demonstration")
                                            : QCoreApplication::translate(
                                                  "ActionMappingFit",
                                                  "; check the sign or the demonstration"));
                    }
                }
                if (options.nonNegative && (beta.head(q).array() < 0.0).any()) {
                    // Few constrained unknowns per column (one per control): try every subset of
                    // B_v entries left free, the rest at 0 (A's entries always free), and keep
                    // the best feasible one. Exact, and cheap for m <= 4.
                    const int all = static_cast<int>(beta.size());
                    double best = std::numeric_limits<double>::infinity();
                    Eigen::VectorXd bestBeta = Eigen::VectorXd::Zero(all);
                    for (int mask = 0; mask < (1 << q); ++mask) {
                        std::vector<int> free;
                        for (int j = 0; j < q; ++j) {
                            if (mask & (1 << j)) {
                                free.push_back(j);
                            }
                        }
                        for (int j = q; j < all; ++j) {
                            free.push_back(j);
                        }
                        Eigen::VectorXd candidate = Eigen::VectorXd::Zero(all);
                        if (!free.empty()) {
                            Eigen::MatrixXd sub(K, static_cast<int>(free.size()));
                            for (int f = 0; f < static_cast<int>(free.size()); ++f) {
                                sub.col(f) = WX.col(free[f]);
                            }
                            const Eigen::VectorXd part =
                                sub.completeOrthogonalDecomposition().solve(Wy);
                            bool feasible = true;
                            for (int f = 0; f < static_cast<int>(free.size()); ++f) {
                                feasible = feasible && (free[f] >= q || part[f] >= 0.0);
                            }
                            if (!feasible) {
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
                return beta;
            };
            Eigen::VectorXd weights = w;
            Eigen::VectorXd beta = solve(weights, !options.robust);
            if (options.robust) {
                // IRLS with Tukey's bisquare: residuals beyond 4.685 robust sigmas get no weight.
                for (int iteration = 0; iteration < 50; ++iteration) {
                    const Eigen::VectorXd residual = y - X * beta;
                    // The scale comes from the samples that carry information (du != 0): with
                    // held sticks most samples have du = 0 and a residual of exactly 0.
                    std::vector<double> magnitudes;
                    for (int t = 0; t < K; ++t) {
                        if (X.row(t).squaredNorm() > 0.0) {
                            magnitudes.push_back(std::abs(residual[t]));
                        }
                    }
                    if (magnitudes.empty()) {
                        break;
                    }
                    const size_t middle = magnitudes.size() / 2;
                    std::nth_element(magnitudes.begin(), magnitudes.begin() + middle,
                                     magnitudes.end());
                    const double scale = 1.4826 * magnitudes[middle];
                    if (!(scale > 0.0)) {
                        break;
                    }
                    Eigen::VectorXd next = w;
                    for (int t = 0; t < K; ++t) {
                        const double u = residual[t] / (4.685 * scale);
                        next[t] *= std::abs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
                    }
                    const Eigen::VectorXd updated = solve(next, false);
                    const bool settled = (updated - beta).norm() <= 1e-10 * (1.0 + beta.norm());
                    beta = updated;
                    weights = next;
                    if (settled) {
                        break;
                    }
                }
                beta = solve(weights, true);  // once more, to report conflicts on the final weights
                int setAside = 0;
                for (int t = 0; t < K; ++t) {
                    const bool outlier = weights[t] < 0.01 * w[t];
                    setAside += outlier;
                    if (outlier) {
                        fit.explained[first + t] =
                            false;  // pair t pairs du_k with the state after k
                    }
                }
                fit.outlierShare[c] = static_cast<double>(setAside) / K;
            }
            for (int j = 0; j < q; ++j) {
                fit.bv(controls[j], c) = beta[j];
            }
            for (int i = 0; i < driftColumns; ++i) {
                fit.a(c, i) = beta[q + i];
            }
            prediction = X * beta;
            const Eigen::VectorXd rw = weights / weights.sum();
            const double meanY = rw.dot(y);
            const double total = (rw.array() * (y.array() - meanY).square()).sum();
            const double residual = (rw.array() * (y - prediction).array().square()).sum();
            residualRms = std::sqrt(residual);
            fit.rSquared[c] =
                total > 0.0 ? 1.0 - residual / total : std::numeric_limits<double>::quiet_NaN();
        }
        fit.residualRms[c] = controls.empty() && !options.drift
                                 ? std::sqrt((w.array() * (y - prediction).array().square()).sum())
                                 : residualRms;
    }

    fit.b = fit.bv.cwiseProduct(mapping.asDouble());
    // Only a degenerate demonstration gets here with these: actions that barely change against
    // states that jump (or numbers near the format's bounds). No B_v is better than a wrong one.
    const bool finite = fit.bv.allFinite() && fit.a.allFinite() &&
                        fit.unconstrainedBv.allFinite() && fit.residualRms.allFinite();
    if (!finite || fit.b.cwiseAbs().maxCoeff() > kMaxAbsB) {
        throw std::invalid_argument(
            QStringLiteral("the fit of B_v gives %1: the demonstration's action changes do not "
                           "explain its state changes (is it a recording of this plant?)")
                .arg(finite ? QStringLiteral("an entry of B beyond +-%1").arg(kMaxAbsB)
                            : QStringLiteral("a value that is not a number"))
                .toStdString());
    }
    return fit;
}

}  // namespace prisca::core
