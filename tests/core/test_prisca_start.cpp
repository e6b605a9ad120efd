// PRISCA from a feedback law: its PD prior, and the law derived from the demonstration alone.

#include "PriscaControllerTestSupport.h"

class TestPriscaStart : public QObject {
    Q_OBJECT
  private slots:
    void prior_withThetaZeroIsThePdLawExactly() {
        // PRISCA starting from a PD law: with theta held at 0 it must be that PD, step by step,
        // bit for bit (smoothing, rate and saturation included), on a least-state-deviation
        // reference; once it learns, it departs from it.
        std::mt19937 rng(17);
        auto demo = randomDemonstration(80, 3, 2, 0.05, rng);
        PdParameters pd;
        pd.errorCombination = (Eigen::MatrixXd(2, 3) << 1, 0, 0.5, 0, 1, 0.25).finished();
        pd.kp = Eigen::Vector2d(0.8, 1.5);
        pd.kd = Eigen::Vector2d(0.1, 0.05);
        pd.horizon = 4;
        const TrackingProblem problem =
            problemFor(demo, MatchingParameters::Mode::LeastStateDeviation, 0.7);
        PdController reference(problem, pd, QStringLiteral("pd-h-lsd"));
        PriscaParameters held;
        held.prior = pd;
        held.learning = false;
        PriscaParameters learning = held;
        learning.learning = true;
        const FeatureMap features = FeatureMap::deviationFeatures(2, {0, 2});
        PriscaController fixed(problem, features, Eigen::MatrixXd::Ones(2, 3), held);
        PriscaController learner(problem, features, Eigen::MatrixXd::Ones(2, 3), learning);
        std::normal_distribution<double> noise(0.0, 0.2);
        bool departed = false;
        for (int trial = 0; trial < 2; ++trial) {
            reference.reset();
            fixed.reset(ResetMode::WarmStart);
            learner.reset(ResetMode::WarmStart);
            for (int k = 0; k < 60; ++k) {
                Eigen::VectorXd s = demo->states.row(k).transpose();
                for (int c = 0; c < 3; ++c)
                    s[c] += noise(rng);
                const ControlStep& pdStep = reference.step(s);
                const Eigen::VectorXd u = pdStep.action;
                const int j = pdStep.referenceIndex;
                const ControlStep& v = fixed.step(s);
                QVERIFY2(u == v.action,
                         qPrintable(QStringLiteral("trial %1 step %2").arg(trial).arg(k)));
                QCOMPARE(v.referenceIndex, j);
                departed = departed || learner.step(s).action != u;
            }
        }
        QVERIFY(departed);
    }

    // The demonstration-only start on a scalar integrator x' = b u: the derived gain is the
    // discrete Riccati optimum for Bryson's weights (closed form), and a brute-force search of
    // the closed loop's cost over gains finds its minimum there.
    void demoStart_onAnIntegratorIsTheRiccatiOptimum() {
        const double dt = 0.02, b = 2.0;
        const int T = 400, lag = 50;
        Demonstration demo = prisca::test::namedDemonstration(T, 1, 1, dt);
        for (int k = 0; k < T; ++k) {
            demo.states(k, 0) = 0.3 * std::sin(0.8 * k * dt) + 0.1 * k * dt;
        }
        const ActionLimits limits = ActionLimits::symmetric(1, 0.5);
        StartLawOptions options;
        options.scaleLag = lag;
        options.horizon = 3;
        const StartLaw law = deriveStartLaw(demo, Eigen::MatrixXd::Constant(1, 1, b),
                                            DeviationModel::euclidean(1), limits, options);
        // Bryson's weights, recomputed: sigma from the states lag samples apart, ubar = 0.5.
        double sum = 0.0;
        for (int k = 0; k + lag < T; ++k) {
            sum += std::pow(demo.states(k + lag, 0) - demo.states(k, 0), 2);
        }
        const double sigma = std::sqrt(sum / (T - lag));
        QVERIFY(std::abs(law.errorScale[0] - sigma) < 1e-12 * sigma);
        const double q = 1.0 / (sigma * sigma), r = 1.0 / (0.5 * 0.5);
        // x+ = x + bd u: b^2 P^2 + (r - q b^2 - r) P - q r = 0 with a = 1, bd = dt b.
        const double bd = dt * b;
        const double c1 = -q * bd * bd;
        const double P = (-c1 + std::sqrt(c1 * c1 + 4.0 * bd * bd * q * r)) / (2.0 * bd * bd);
        const double expected = bd * P / (r + bd * bd * P);
        QVERIFY2(
            std::abs(law.gain(0, 0) - expected) < 1e-9 * expected,
            qPrintable(QStringLiteral("K %1, closed form %2").arg(law.gain(0, 0)).arg(expected)));
        // As the PD family forms it: u = u* - 1 * (K e), smoothed over the horizon asked for.
        QCOMPARE(law.law.errorCombination.rows(), 1);
        QCOMPARE(law.law.errorCombination(0, 0), law.gain(0, 0));
        QCOMPARE(law.law.kp[0], 1.0);
        QCOMPARE(law.law.kd[0], 0.0);
        QCOMPARE(law.law.horizon, 3);
        // Brute force: the cost sum q x^2 + r u^2 of the closed loop from x = 1, over a grid of
        // gains around the derived one (independent of the Riccati equation).
        auto cost = [&](double k) {
            double x = 1.0, total = 0.0;
            for (int i = 0; i < 20000; ++i) {
                const double u = -k * x;
                total += q * x * x + r * u * u;
                x += bd * u;
            }
            return total;
        };
        double best = 0.0, bestCost = 1e300;
        for (int i = 1; i <= 400; ++i) {
            const double k = expected * i / 200.0;  // 0.005 K .. 2 K
            const double c = cost(k);
            if (c < bestCost) {
                bestCost = c;
                best = k;
            }
        }
        QVERIFY2(
            std::abs(best - law.gain(0, 0)) <= expected / 200.0 + 1e-12,
            qPrintable(QStringLiteral("grid best %1, derived %2").arg(best).arg(law.gain(0, 0))));
    }

    // On a double integrator (position and speed, the speed driven by the control, the position
    // by the speed through the fitted drift), the derived gain is the continuous-time LQR
    // optimum for Bryson's weights, K = (sqrt(q1/r), sqrt(q2/r + 2 sqrt(q1/r)/b)), within the
    // discretisation's error.
    void demoStart_onADoubleIntegratorIsTheContinuousLqrGain() {
        const double dt = 0.001, b = 3.0;
        const int T = 6000, lag = 1000;
        Demonstration demo = prisca::test::namedDemonstration(T, 2, 1, dt);
        for (int k = 0; k < T; ++k) {
            const double t = k * dt;
            demo.states(k, 0) = std::sin(t) + 0.5 * t;  // position
            demo.states(k, 1) = std::cos(t) + 0.5;      // its rate
            demo.actions(k, 0) = -std::sin(t) / b;
        }
        StartLawOptions options;
        options.scaleLag = lag;
        options.drift = (Eigen::MatrixXd(2, 2) << 0.0, 1.0, 0.0, 0.0).finished();
        const Eigen::MatrixXd B = (Eigen::MatrixXd(1, 2) << 0.0, b).finished();
        const StartLaw law = deriveStartLaw(demo, B, DeviationModel::euclidean(2),
                                            ActionLimits::symmetric(1, 1.0), options);
        const double q1 = 1.0 / std::pow(law.errorScale[0], 2);
        const double q2 = 1.0 / std::pow(law.errorScale[1], 2);
        const double r = 1.0;
        const double k1 = std::sqrt(q1 / r);
        const double k2 = std::sqrt(q2 / r + 2.0 * std::sqrt(q1 / r) / b);
        QVERIFY2(
            std::abs(law.gain(0, 0) - k1) < 0.01 * k1 && std::abs(law.gain(0, 1) - k2) < 0.01 * k2,
            qPrintable(QStringLiteral("K (%1, %2), continuous optimum (%3, %4)")
                           .arg(law.gain(0, 0))
                           .arg(law.gain(0, 1))
                           .arg(k1)
                           .arg(k2)));
        // Shapes it refuses.
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            deriveStartLaw(demo, Eigen::MatrixXd::Ones(2, 2), DeviationModel::euclidean(2),
                           ActionLimits::symmetric(1, 1.0), options));
        options.scaleLag = T;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 deriveStartLaw(demo, B, DeviationModel::euclidean(2),
                                                ActionLimits::symmetric(1, 1.0), options));
    }

    // A component the action sets (a rate that follows the control's level within a step)
    // leaves the loop: heading psi' = r with r = g u is, for the law, the integrator psi' = g u,
    // so the gain on psi is the scalar Riccati optimum of that integrator and r gets none. The
    // heading, given as set too, integrates the rate and stays a state.
    void demoStart_aComponentTheActionSetsLeavesTheLoop() {
        const double dt = 0.02, g = 4.0;
        const int T = 400, lag = 50;
        Demonstration demo = prisca::test::namedDemonstration(T, 2, 1, dt);
        for (int k = 0; k < T; ++k) {
            demo.states(k, 0) = 0.5 * std::sin(0.9 * k * dt);   // heading
            demo.states(k, 1) = 0.45 * std::cos(0.9 * k * dt);  // its rate
            demo.actions(k, 0) = demo.states(k, 1) / g;
        }
        StartLawOptions options;
        options.scaleLag = lag;
        options.drift = (Eigen::MatrixXd(2, 2) << 0.0, 1.0, 0.0, 0.0).finished();
        options.proportional = (Eigen::MatrixXd(1, 2) << 0.0, g).finished();
        const Eigen::MatrixXd B = (Eigen::MatrixXd(1, 2) << 0.0, 7.0).finished();  // ignored
        const ActionLimits limits = ActionLimits::symmetric(1, 1.0);
        const StartLaw law = deriveStartLaw(demo, B, DeviationModel::euclidean(2), limits, options);
        const double q = 1.0 / std::pow(law.errorScale[0], 2), r = 1.0, bd = dt * g;
        const double c1 = -q * bd * bd;
        const double P = (-c1 + std::sqrt(c1 * c1 + 4.0 * bd * bd * q * r)) / (2.0 * bd * bd);
        const double expected = bd * P / (r + bd * bd * P);
        QVERIFY2(
            std::abs(law.gain(0, 0) - expected) < 1e-9 * expected,
            qPrintable(QStringLiteral("K %1, closed form %2").arg(law.gain(0, 0)).arg(expected)));
        QCOMPARE(law.gain(0, 1), 0.0);
        QCOMPARE(law.reducedEffect(0, 0), g);
        // Both given as set: the heading integrates the rate, so only the rate leaves.
        options.proportional(0, 0) = 1.0;
        const StartLaw both =
            deriveStartLaw(demo, B, DeviationModel::euclidean(2), limits, options);
        QCOMPARE(both.gain(0, 0), law.gain(0, 0));
        QCOMPARE(both.gain(0, 1), 0.0);
    }
};

QTEST_APPLESS_MAIN(TestPriscaStart)
#include "test_prisca_start.moc"
