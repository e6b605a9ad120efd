// Least-state-deviation matching (eq. 12) against a brute-force argmin, and the time-driven mode.
#include "core/DeviationModel.h"
#include "core/LeastStateDeviationMatcher.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace prisca::core;

class TestLeastStateDeviation : public QObject {
    Q_OBJECT
  private slots:
    void match_equalsBruteForceArgminInForwardWindow() {
        std::mt19937 rng(11);
        std::normal_distribution<double> normal(0.0, 1.0);
        const int T = 300, n = 4, window = 15;
        Eigen::MatrixXd demo(T, n);
        for (int j = 0; j < T; ++j)
            for (int c = 0; c < n; ++c)
                demo(j, c) = std::sin(0.05 * j * (c + 1)) + 0.1 * normal(rng);
        Eigen::VectorXd weights(n);
        weights << 1.0, 0.5, 2.0, 0.1;
        MatchingParameters parameters;
        parameters.window = window;
        parameters.weights = weights;
        parameters.angleIndices = {2};
        LeastStateDeviationMatcher matcher(demo, parameters);

        int previous = 0;
        for (int k = 0; k < 400; ++k) {
            const int near = std::min(T - 1, k * 3 / 4);
            Eigen::VectorXd s = demo.row(near).transpose();
            for (int c = 0; c < n; ++c)
                s[c] += 0.2 * normal(rng);
            s[2] += (k % 7 == 0) ? 2 * M_PI : 0.0;  // an angle off by a full turn is no deviation
            const int got = matcher.match(s);
            int best = -1;
            double bestDistance = std::numeric_limits<double>::infinity();
            for (int j = previous; j <= std::min(T - 1, previous + window); ++j) {
                double d = 0.0;
                for (int c = 0; c < n; ++c) {
                    double diff = s[c] - demo(j, c);
                    if (c == 2)
                        diff = std::remainder(diff, 2 * M_PI);
                    d += weights[c] * std::abs(diff);
                }
                if (d < bestDistance) {
                    bestDistance = d;
                    best = j;
                }
            }
            QCOMPARE(got, best);
            QVERIFY(got >= previous);  // progress is monotone
            previous = got;
        }
    }

    void match_tiesFollowTheDemonstrationClockThroughItsStandstillThenWait() {
        Eigen::MatrixXd demo = Eigen::MatrixXd::Zero(50, 2);  // demonstration starts at rest
        for (int j = 10; j < 50; ++j)
            demo(j, 0) = 0.1 * (j - 9);
        MatchingParameters parameters;
        parameters.window = 30;
        LeastStateDeviationMatcher matcher(demo, parameters);
        // Samples 0..9 are equal: a robot standing there goes through them one per step, as the
        // demonstration did (the first sample forever would never ask it to move off).
        for (int k = 0; k < 10; ++k)
            QCOMPARE(matcher.match(Eigen::Vector2d(0, 0)), k);
        // Where the demonstration moved on, a robot still standing waits at its last rest sample.
        for (int k = 0; k < 5; ++k)
            QCOMPARE(matcher.match(Eigen::Vector2d(0, 0)), 9);
        // Equal distance at a lateral offset: still the tie rule, not the earliest sample.
        matcher.reset();
        QCOMPARE(matcher.match(Eigen::Vector2d(0, 0.03)), 0);
        QCOMPARE(matcher.match(Eigen::Vector2d(0, 0.03)), 1);
        QCOMPARE(matcher.match(Eigen::Vector2d(1.0, 0)), 19);
        matcher.reset();
        QCOMPARE(matcher.match(Eigen::Vector2d(10.0, 0)), 30);  // first step searches 0..window
    }

    void maxLag_keepsTheReferenceWithinReachOfTheClock() {
        // The demonstration rests for 10 samples, then moves (state: position, speed). A robot
        // at rest a little ahead of the start is nearer the last resting sample than any moving
        // one: unbounded, the reference waits there for ever (and a controller told "you are
        // ahead" waits too).
        Eigen::MatrixXd demo = Eigen::MatrixXd::Zero(60, 2);
        for (int j = 10; j < 60; ++j) {
            demo(j, 0) = 0.02 * (j - 9) * (j - 9);
            demo(j, 1) = 1.0;
        }
        const Eigen::Vector2d ahead(0.05, 0.0);
        MatchingParameters unbounded;
        unbounded.window = 30;
        LeastStateDeviationMatcher waiting(demo, unbounded);
        for (int k = 0; k < 40; ++k)
            QVERIFY(waiting.match(ahead) <= 9);
        MatchingParameters bounded = unbounded;
        bounded.maxLag = 5;
        LeastStateDeviationMatcher matcher(demo, bounded);
        for (int k = 0; k < 40; ++k) {
            const int j = matcher.match(ahead);
            QVERIFY2(j >= k - 5, qPrintable(QStringLiteral("k %1 j %2").arg(k).arg(j)));
        }
        // Within the lag, the state decides as before.
        matcher.reset();
        QCOMPARE(matcher.match(Eigen::Vector2d(demo(3, 0), demo(3, 1))), 0);
    }

    void timeDriven_returnsStepClampedToEnd() {
        Eigen::MatrixXd demo = Eigen::MatrixXd::Random(5, 3);
        MatchingParameters parameters;
        parameters.mode = MatchingParameters::Mode::TimeDriven;
        LeastStateDeviationMatcher matcher(demo, parameters);
        const Eigen::VectorXd far = Eigen::VectorXd::Constant(3, 100.0);
        for (int k = 0; k < 8; ++k)
            QCOMPARE(matcher.match(far), std::min(k, 4));
        matcher.reset();
        QCOMPARE(matcher.match(far), 0);
    }

    void construction_rejectsInconsistentParameters() {
        Eigen::MatrixXd demo = Eigen::MatrixXd::Zero(5, 3);
        MatchingParameters badWeights;
        badWeights.weights = Eigen::VectorXd::Ones(2);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 LeastStateDeviationMatcher(demo, badWeights));
        MatchingParameters badAngle;
        badAngle.angleIndices = {3};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, LeastStateDeviationMatcher(demo, badAngle));
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            LeastStateDeviationMatcher(Eigen::MatrixXd(0, 3), MatchingParameters{}));
    }
};

QTEST_APPLESS_MAIN(TestLeastStateDeviation)
#include "test_least_state_deviation.moc"
