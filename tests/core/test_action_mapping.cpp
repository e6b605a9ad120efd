// The intuitive mapping B~ and the fit of B_v (eq. 8).
#include "TestDemonstrations.h"
#include "core/ActionMapping.h"
#include "core/NestedExpectation.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace prisca::core;

namespace {

Demonstration emptyDemo(int T, int n, int m, double dt) {
    return prisca::test::namedDemonstration(T, n, m, dt);
}

// Random piecewise-constant actions: a human holding the stick, then moving it.
void excite(Demonstration& d, std::mt19937& rng, const std::vector<int>& channels) {
    std::uniform_real_distribution<double> level(-1.0, 1.0);
    std::uniform_int_distribution<int> hold(3, 15);
    for (int l : channels) {
        int k = 0;
        while (k < d.length()) {
            const double v = level(rng);
            const int end = std::min(d.length(), k + hold(rng));
            for (; k < end; ++k)
                d.actions(k, l) = v;
        }
    }
}

// An integrating plant, eq. 5's model: s_{k+1} = s_k + dt (-0.2 s_k) + dt B^T u_{k-delay} + noise.
void simulateIntegrator(Demonstration& d, const Eigen::MatrixXd& B, int delay, double noise,
                        std::mt19937& rng) {
    std::normal_distribution<double> normal(0.0, noise);
    for (int k = 0; k + 1 < d.length(); ++k) {
        const Eigen::VectorXd u = d.actions.row(std::max(0, k - delay)).transpose();
        Eigen::VectorXd s = d.states.row(k).transpose();
        s += d.dt * (-0.2 * s + B.transpose() * u);
        for (int c = 0; c < s.size(); ++c)
            s[c] += normal(rng);
        d.states.row(k + 1) = s.transpose();
    }
}

IntuitiveMapping mapping(const QString& text) {
    QString error;
    auto parsed = IntuitiveMapping::parse(text, &error);
    if (!parsed)
        qFatal("%s", qPrintable(error));
    return *parsed;
}

}  // namespace

class TestActionMapping : public QObject {
    Q_OBJECT
  private slots:
    void parse_readsSignsAndRoundTrips() {
        const IntuitiveMapping b = mapping(" 1, 0,0 ; 0,+1,-1");
        QCOMPARE(b.controls(), 2);
        QCOMPARE(b.states(), 3);
        QCOMPARE(b.signs(1, 2), -1);
        QCOMPARE(b.toString(), QStringLiteral("1,0,0;0,1,-1"));
    }

    void parse_namesRowAndColumnOfBadEntries() {
        QString error;
        QVERIFY(!IntuitiveMapping::parse("1,0;0,2", &error));
        QVERIFY2(error.contains("row 2") && error.contains("column 2") && error.contains("'2'"),
                 qPrintable(error));
        QVERIFY(!IntuitiveMapping::parse("1,0;0", &error));
        QVERIFY2(error.contains("row 2 has 1"), qPrintable(error));
        QVERIFY(!IntuitiveMapping::parse("", &error));
        QVERIFY(!IntuitiveMapping::parse("1,x", &error));
    }

    void fit_recoversKnownBvFromNoisyData() {
        std::mt19937 rng(5);
        const IntuitiveMapping signs = mapping("1,0,1;0,1,-1");  // m = 2, n = 3
        Eigen::MatrixXd bvTrue(2, 3);
        bvTrue << 2.0, 0.0, 0.5, 0.0, 3.0, 1.5;
        const Eigen::MatrixXd bTrue = bvTrue.cwiseProduct(signs.asDouble());
        Demonstration d = emptyDemo(4000, 3, 2, 0.025);
        excite(d, rng, {0, 1});
        simulateIntegrator(d, bTrue, 0, 1e-4, rng);
        const ActionMappingFit fit = fitActionMapping(d, signs, DeviationModel::euclidean(3));
        QVERIFY2((fit.bv - bvTrue).cwiseAbs().maxCoeff() < 0.05,
                 qPrintable(QString("max error %1").arg((fit.bv - bvTrue).cwiseAbs().maxCoeff())));
        QVERIFY(fit.b.isApprox(fit.bv.cwiseProduct(signs.asDouble())));
        QVERIFY(fit.signConflicts.empty());
        QVERIFY(fit.unexcitedChannels.empty());
        for (int c = 0; c < 3; ++c) {
            QVERIFY2(fit.rSquared[c] > 0.9,
                     qPrintable(QString("R2[%1] = %2").arg(c).arg(fit.rSquared[c])));
            QVERIFY(fit.residualRms[c] > 0.0 && fit.residualRms[c] < 1e-3);
        }
        QCOMPARE(fit.samples, 4000 - 2);
    }

    void fit_literalStateChangeMissesAnIntegratingPlant() {
        // Why RateChange is the default: on eq. 5's own model the literal pairing of
        // s_{k+1} - s_k with u_k - u_{k-1} does not recover the gain.
        std::mt19937 rng(6);
        const IntuitiveMapping signs = mapping("1");
        Demonstration d = emptyDemo(3000, 1, 1, 0.025);
        excite(d, rng, {0});
        simulateIntegrator(d, Eigen::MatrixXd::Constant(1, 1, 2.0), 0, 0.0, rng);
        ActionMappingFitOptions literal;
        literal.target = ActionMappingFitOptions::Target::StateChange;
        const double literalGain =
            fitActionMapping(d, signs, DeviationModel::euclidean(1), literal).bv(0, 0);
        const double rateGain = fitActionMapping(d, signs, DeviationModel::euclidean(1)).bv(0, 0);
        QVERIFY2(std::abs(rateGain - 2.0) < 0.02, qPrintable(QString::number(rateGain)));
        QVERIFY2(std::abs(literalGain - 2.0) > 0.5, qPrintable(QString::number(literalGain)));
    }

    void fit_driftRegressorsRecoverEq5InFullWhereTheDefaultIsBiased() {
        // eq. 5's own model with a drift that couples the states, s_{k+1} = s_k + dt (A s_k +
        // B^T u_k), B = (1, 3): differencing gives d2s_{k+1} = dt A ds_k + dt B^T du_k. The
        // default target leaves dt A ds_k in the residual; with a smooth input (ds correlated
        // with du) that biases B. The drift regressors recover A and B.
        const Eigen::Matrix2d A = (Eigen::Matrix2d() << -0.8, 0.5, -1.5, -2.0).finished();
        const Eigen::RowVector2d B(1.0, 3.0);
        const double dt = 0.025;
        const IntuitiveMapping signs = mapping("1,1");
        ActionMappingFitOptions plain;
        plain.robust = false;
        ActionMappingFitOptions full = plain;
        full.drift = true;
        auto demonstrate = [&](bool closedLoop) {
            Demonstration d = emptyDemo(4000, 2, 1, dt);
            Eigen::Vector2d s(0.0, 0.0);
            for (int k = 0; k < d.length(); ++k) {
                const double t = k * dt;
                // A smooth operator's input, or an operator closing the loop on the state.
                double u = std::sin(0.7 * t) + 0.5 * std::sin(1.9 * t + 1.0);
                if (closedLoop) {
                    u = 0.6 * std::sin(0.5 * t) - 0.8 * s[0] - 0.3 * s[1];
                }
                d.actions(k, 0) = u;
                d.states.row(k) = s.transpose();
                s += dt * (A * s + B.transpose() * u);
            }
            return d;
        };
        for (bool closedLoop : {false, true}) {
            const Demonstration d = demonstrate(closedLoop);
            const ActionMappingFit biased =
                fitActionMapping(d, signs, DeviationModel::euclidean(2), plain);
            const ActionMappingFit fit =
                fitActionMapping(d, signs, DeviationModel::euclidean(2), full);
            const QString what = QStringLiteral("%1: default (%2, %3), full (%4, %5)")
                                     .arg(closedLoop ? "closed loop" : "open loop")
                                     .arg(biased.bv(0, 0))
                                     .arg(biased.bv(0, 1))
                                     .arg(fit.bv(0, 0))
                                     .arg(fit.bv(0, 1));
            QVERIFY2(std::abs(fit.bv(0, 0) - 1.0) < 0.05 && std::abs(fit.bv(0, 1) - 3.0) < 0.15,
                     qPrintable(what));  // within 5 %
            QVERIFY2(std::abs(biased.bv(0, 1) - 3.0) > 0.3, qPrintable(what));
            QVERIFY2(
                (fit.a - A).cwiseAbs().maxCoeff() < 0.1,
                qPrintable(QStringLiteral("A off by %1").arg((fit.a - A).cwiseAbs().maxCoeff())));
            QVERIFY(biased.a.isZero());
            QVERIFY(fit.rSquared.minCoeff() > 0.99);
        }
        // The drift needs the one-step rate-change target.
        ActionMappingFitOptions bad = full;
        bad.responseSteps = 3;
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            fitActionMapping(demonstrate(false), signs, DeviationModel::euclidean(2), bad));
    }

    void fit_stateChangeTargetRecoversDataOfItsOwnModel() {
        std::mt19937 rng(7);
        std::normal_distribution<double> normal(0.0, 1e-4);
        const IntuitiveMapping signs = mapping("1,1");
        Demonstration d = emptyDemo(2000, 2, 1, 0.04);
        excite(d, rng, {0});
        for (int k = 1; k + 1 < d.length(); ++k) {
            const double du = d.actions(k, 0) - d.actions(k - 1, 0);
            d.states(k + 1, 0) = d.states(k, 0) + 0.04 * 1.5 * du + normal(rng);
            d.states(k + 1, 1) = d.states(k, 1) + 0.04 * 4.0 * du + normal(rng);
        }
        ActionMappingFitOptions options;
        options.target = ActionMappingFitOptions::Target::StateChange;
        const ActionMappingFit fit =
            fitActionMapping(d, signs, DeviationModel::euclidean(2), options);
        QVERIFY(std::abs(fit.bv(0, 0) - 1.5) < 0.01);
        QVERIFY(std::abs(fit.bv(0, 1) - 4.0) < 0.01);
    }

    void fit_equalsBruteForceWeightedNormalEquations() {
        std::mt19937 rng(8);
        const IntuitiveMapping signs = mapping("1,-1;1,1");
        Demonstration d = emptyDemo(60, 2, 2, 0.1);
        excite(d, rng, {0, 1});
        std::normal_distribution<double> normal(0.0, 0.3);
        for (int k = 0; k < d.length(); ++k)
            d.states.row(k) << normal(rng), normal(rng);
        ActionMappingFitOptions options;
        options.latency = 1;
        options.nonNegative = false;  // the plain normal equations, unconstrained
        options.robust = false;
        const ActionMappingFit fit =
            fitActionMapping(d, signs, DeviationModel::euclidean(2), options);
        // Normal equations written out: pairs k = 1..T-3, weights of E_{i=0:K-1} E_{j=i:K-1}.
        const int K = d.length() - 3;
        std::vector<double> w(K);
        for (int t = 0; t < K; ++t) {
            double inner = 0;
            for (int i = 0; i <= t; ++i)
                inner += 1.0 / (K - i);
            w[t] = inner / K;
        }
        for (int c = 0; c < 2; ++c) {
            double xx[2][2] = {{0, 0}, {0, 0}}, xy[2] = {0, 0};
            for (int t = 0; t < K; ++t) {
                const int k = t + 1;
                const double y = (d.states(k + 2, c) - d.states(k + 1, c)) -
                                 (d.states(k + 1, c) - d.states(k, c));
                double x[2];
                for (int l = 0; l < 2; ++l)
                    x[l] = signs.signs(l, c) * d.dt * (d.actions(k, l) - d.actions(k - 1, l));
                for (int a = 0; a < 2; ++a) {
                    xy[a] += w[t] * x[a] * y;
                    for (int b = 0; b < 2; ++b)
                        xx[a][b] += w[t] * x[a] * x[b];
                }
            }
            const double det = xx[0][0] * xx[1][1] - xx[0][1] * xx[1][0];
            const double b0 = (xy[0] * xx[1][1] - xx[0][1] * xy[1]) / det;
            const double b1 = (xx[0][0] * xy[1] - xx[1][0] * xy[0]) / det;
            QVERIFY2(std::abs(fit.bv(0, c) - b0) <= 1e-9 * (1 + std::abs(b0)),
                     qPrintable(QString("%1 vs %2").arg(fit.bv(0, c)).arg(b0)));
            QVERIFY2(std::abs(fit.bv(1, c) - b1) <= 1e-9 * (1 + std::abs(b1)),
                     qPrintable(QString("%1 vs %2").arg(fit.bv(1, c)).arg(b1)));
        }
    }

    void fit_latencyShiftRecoversDelayedResponse() {
        std::mt19937 rng(9);
        const IntuitiveMapping signs = mapping("1");
        Demonstration d = emptyDemo(3000, 1, 1, 0.025);
        excite(d, rng, {0});
        simulateIntegrator(d, Eigen::MatrixXd::Constant(1, 1, 3.0), 2, 0.0, rng);
        ActionMappingFitOptions shifted;
        shifted.latency = 2;
        const ActionMappingFit fit =
            fitActionMapping(d, signs, DeviationModel::euclidean(1), shifted);
        QVERIFY2(std::abs(fit.bv(0, 0) - 3.0) < 0.05, qPrintable(QString::number(fit.bv(0, 0))));
        const ActionMappingFit unshifted = fitActionMapping(d, signs, DeviationModel::euclidean(1));
        QVERIFY(std::abs(unshifted.bv(0, 0)) < 0.5);
        QVERIFY(fit.rSquared[0] > unshifted.rSquared[0]);
    }

    void fit_reportsSignConflictsAndUnexcitedChannels() {
        std::mt19937 rng(10);
        const IntuitiveMapping signs = mapping("1,1;1,0");
        Demonstration d = emptyDemo(1000, 2, 2, 0.025);
        excite(d, rng, {0});  // channel 1 is held at 0 throughout
        Eigen::MatrixXd bTrue(2, 2);
        bTrue << 1.0, -2.0, 0.0, 0.0;  // control 0 moves state 1 the "wrong" way
        simulateIntegrator(d, bTrue, 0, 1e-5, rng);
        ActionMappingFitOptions unconstrained;
        unconstrained.nonNegative = false;
        const ActionMappingFit fit =
            fitActionMapping(d, signs, DeviationModel::euclidean(2), unconstrained);
        QCOMPARE(fit.unexcitedChannels, std::vector<int>{1});
        QCOMPARE(fit.bv(1, 0), 0.0);
        QCOMPARE(static_cast<int>(fit.signConflicts.size()), 1);
        QCOMPARE(fit.signConflicts[0], std::make_pair(0, 1));
        QVERIFY(std::abs(fit.bv(0, 1) + 2.0) < 0.05);
        const QString all = fit.warnings.join('\n');
        QVERIFY2(
            all.contains("'u1' never changed") && all.contains("'u0' moved 's1' the opposite way"),
            qPrintable(all));
        // By default B_v >= 0: the contradicted entry is reported and set to 0.
        const ActionMappingFit constrained =
            fitActionMapping(d, signs, DeviationModel::euclidean(2));
        QCOMPARE(constrained.bv(0, 1), 0.0);
        QCOMPARE(static_cast<int>(constrained.signConflicts.size()), 1);
        QVERIFY(constrained.warnings.join('\n').contains("set to 0"));
        QVERIFY(std::abs(constrained.bv(0, 0) - fit.bv(0, 0)) < 1e-12);
    }

    void fit_nonNegativeRefitsTheRemainingControls() {
        // Two controls on one state; the data makes the second one's share negative. The
        // constrained answer is the one-control least-squares fit of the first.
        std::mt19937 rng(13);
        Demonstration d = emptyDemo(800, 1, 2, 0.025);
        excite(d, rng, {0, 1});
        simulateIntegrator(d, (Eigen::MatrixXd(2, 1) << 1.5, -0.7).finished(), 0, 1e-5, rng);
        ActionMappingFitOptions plain;
        plain.robust = false;
        const ActionMappingFit fit =
            fitActionMapping(d, mapping("1;1"), DeviationModel::euclidean(1), plain);
        QCOMPARE(fit.bv(1, 0), 0.0);
        const int K = d.length() - 2;
        const Eigen::VectorXd w = nestedExpectationWeights(K);
        double xy = 0.0, xx = 0.0;
        for (int t = 0; t < K; ++t) {
            const int k = t + 1;
            const double y =
                (d.states(k + 1, 0) - d.states(k, 0)) - (d.states(k, 0) - d.states(k - 1, 0));
            const double x = d.dt * (d.actions(k, 0) - d.actions(k - 1, 0));
            xy += w[t] * x * y;
            xx += w[t] * x * x;
        }
        QVERIFY2(std::abs(fit.bv(0, 0) - xy / xx) <= 1e-9 * std::abs(xy / xx),
                 qPrintable(QString("%1 vs %2").arg(fit.bv(0, 0)).arg(xy / xx)));
        QCOMPARE(fit.signConflicts, (std::vector<std::pair<int, int>>{{1, 0}}));
    }

    void fit_robustIgnoresSamplesTheModelCannotExplain() {
        // An integrator whose response saturates in a fifth of the samples (a car sliding):
        // there the action barely acts and the state jolts by amounts no action explains.
        std::mt19937 rng(14);
        std::uniform_real_distribution<double> jolt(-0.02, 0.02);
        Demonstration d = emptyDemo(2000, 1, 1, 0.025);
        excite(d, rng, {0});
        for (int k = 0; k + 1 < d.length(); ++k) {
            const bool sliding = k >= 1200 && k < 1600;
            d.states(k + 1, 0) = d.states(k, 0) + d.dt * (sliding ? 0.2 : 2.0) * d.actions(k, 0) +
                                 (sliding ? jolt(rng) : 0.0);
        }
        ActionMappingFitOptions plain;
        plain.robust = false;
        const ActionMappingFit ols =
            fitActionMapping(d, mapping("1"), DeviationModel::euclidean(1), plain);
        const ActionMappingFit robust =
            fitActionMapping(d, mapping("1"), DeviationModel::euclidean(1));
        qInfo("true B_v 2: plain fit %.3f (R^2 %.3f), robust fit %.3f (R^2 %.3f, %.0f%% set aside)",
              ols.bv(0, 0), ols.rSquared[0], robust.bv(0, 0), robust.rSquared[0],
              100 * robust.outlierShare[0]);
        QVERIFY(std::abs(robust.bv(0, 0) - 2.0) < 0.05);
        QVERIFY(std::abs(ols.bv(0, 0) - 2.0) > 0.2);
        QVERIFY(ols.rSquared[0] < 0.5);
        QVERIFY(robust.outlierShare[0] > 0.15 && robust.outlierShare[0] < 0.3);
        QVERIFY(robust.rSquared[0] > 0.9);
        // The samples set aside are the sliding ones: the model is said not to hold there.
        QCOMPARE(static_cast<int>(robust.explained.size()), d.length());
        int outside = 0, inside = 0;
        for (int k = 0; k < d.length(); ++k) {
            const bool sliding = k >= 1199 && k <= 1602;  // pairs reach a sample either side
            outside += !robust.explained[k] && !sliding;
            inside += !robust.explained[k] && sliding;
        }
        QVERIFY2(outside == 0 && inside > 200,
                 qPrintable(QStringLiteral("%1 %2").arg(outside).arg(inside)));
        QVERIFY(std::all_of(ols.explained.begin(), ols.explained.end(), [](bool b) { return b; }));
    }

    void fit_unmodelledStateHasNoRSquared() {
        std::mt19937 rng(12);
        Demonstration d = emptyDemo(200, 2, 1, 0.025);
        excite(d, rng, {0});
        simulateIntegrator(d, (Eigen::MatrixXd(1, 2) << 1.0, 1.0).finished(), 0, 1e-3, rng);
        const ActionMappingFit fit =
            fitActionMapping(d, mapping("1,0"), DeviationModel::euclidean(2));
        QVERIFY(std::isnan(fit.rSquared[1]));
        QCOMPARE(fit.bv(0, 1), 0.0);
        QVERIFY(fit.residualRms[1] > 0.0);
    }

    void fit_rejectsWrongDimensionsAndShortDemonstrations() {
        Demonstration d = emptyDemo(10, 2, 1, 0.025);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            fitActionMapping(d, mapping("1,0,1"), DeviationModel::euclidean(2)));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 fitActionMapping(d, mapping("1,0"), DeviationModel::euclidean(3)));
        ActionMappingFitOptions longDelay;
        longDelay.latency = 9;
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            fitActionMapping(d, mapping("1,0"), DeviationModel::euclidean(2), longDelay));
    }
};

QTEST_APPLESS_MAIN(TestActionMapping)
#include "test_action_mapping.moc"
