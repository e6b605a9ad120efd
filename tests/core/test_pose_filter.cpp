// The pose filter (core/PoseFilter): its quantiles against published tables, consistency (NEES
// and NIS within their chi-square bounds over seeded Monte Carlo runs) on a truth drawn from its
// own process model and on a finely integrated constant turn, the time-stamped calls, and bad
// input refused by name (on a moving car: test_pose_filter_tracking).

#include "PoseFilterTestSupport.h"

class TestPoseFilter : public QObject {
    Q_OBJECT
  private slots:
    void quantiles_matchTables() {
        QVERIFY(std::abs(core::normalQuantile(0.975) - 1.959963984540054) < 1e-9);
        QVERIFY(std::abs(core::normalQuantile(0.5)) < 1e-12);
        QVERIFY(std::abs(core::normalQuantile(0.001) + 3.090232306167814) < 1e-9);
        QVERIFY(std::abs(core::normalQuantile(1e-10) + 6.361340902404056) < 1e-7);
        // Chi-square values (the distribution function inverted numerically): Wilson-Hilferty
        // is within 1e-4 at the 95% bounds of 100 or more degrees of freedom (what the
        // consistency checks below use), and 1.7% (3) and 1% (6) high in the gate's 99.9% tail.
        const struct {
            double p;
            int dof;
            double value;
            double tolerance;
        } table[] = {{0.975, 100, 129.56120, 1e-4}, {0.025, 100, 74.22193, 1e-4},
                     {0.975, 600, 669.76915, 1e-5}, {0.025, 600, 534.01855, 1e-5},
                     {0.999, 3, 16.26624, 2e-2},    {0.999, 6, 22.45774, 1.2e-2}};
        for (const auto& row : table) {
            const double q = core::chiSquareQuantile(row.p, row.dof);
            QVERIFY2(std::abs(q / row.value - 1.0) < row.tolerance,
                     qPrintable(QStringLiteral("chi2(%1, %2) = %3, table %4")
                                    .arg(row.p)
                                    .arg(row.dof)
                                    .arg(q)
                                    .arg(row.value)));
        }
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, core::normalQuantile(1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, core::chiSquareQuantile(0.5, 0));
    }

    void propagate_jacobianMatchesDifferences() {
        for (double r : {0.0, 1e-5, 0.8, -3.0}) {
            Vector6 x;
            x << 0.4, -1.0, 3.0, 1.7, -0.3, r;
            Matrix6 f;
            PoseFilter::propagate(x, 0.04, &f);
            for (int j = 0; j < 6; ++j) {
                const double h = 1e-6;
                Vector6 plus = x, minus = x;
                plus[j] += h;
                minus[j] -= h;
                Vector6 column =
                    PoseFilter::propagate(plus, 0.04) - PoseFilter::propagate(minus, 0.04);
                column[2] = core::wrapAngle(column[2]);
                column /= 2 * h;
                QVERIFY2((column - f.col(j)).cwiseAbs().maxCoeff() < 1e-6,
                         qPrintable(QStringLiteral("r %1, column %2").arg(r).arg(j)));
            }
        }
        // A full circle at constant speed comes back to its start.
        Vector6 x;
        x << 1.0, 2.0, 0.3, 2.0, 0.0, 2.0 * core::kPi;
        const Vector6 back = PoseFilter::propagate(x, 1.0);
        QVERIFY((back.head<2>() - x.head<2>()).norm() < 1e-12);
        QVERIFY(std::abs(core::wrapAngle(back[2] - x[2])) < 1e-12);
    }

    void consistency_ownProcessModel_data() {
        QTest::addColumn<bool>("poseOnly");
        QTest::newRow("full state") << false;
        QTest::newRow("pose only") << true;
    }
    void consistency_ownProcessModel() {
        QFETCH(bool, poseOnly);
        PoseFilterParameters parameters;
        parameters.gateProbability = 1.0;  // a pure EKF: nothing set aside
        parameters.accelerationDensity = {0.4, 0.9, 4.0};
        parameters.initialStd << 1.0, 1.0, 1.0, 1.0, 0.5, 1.0;
        if (poseOnly) {
            parameters.measurePoseOnly();
        }
        const int runs = 100, steps = 200;
        const Consistency c = ownModelRuns(parameters, runs, steps, poseOnly ? 11 : 12);
        // Each step's average over the runs lies inside its 95% bounds about 95% of the time;
        // steps are correlated, so allow some slack, and check the overall mean too.
        const double neesInside = shareInside(c.nees, runs, 6, 0);
        const double nisInside =
            shareInside(c.nis, runs, static_cast<int>(parameters.measured.size()), 1);
        const double neesMean = mean(c.nees, 0);
        const double nisMean = mean(c.nis, 1);
        const QString report = QStringLiteral("NEES mean %1 (%2 inside), NIS mean %3 (%4 inside)")
                                   .arg(neesMean)
                                   .arg(neesInside)
                                   .arg(nisMean)
                                   .arg(nisInside);
        qInfo("%s", qPrintable(report));
        QVERIFY2(neesInside >= 0.9, qPrintable(report));
        QVERIFY2(nisInside >= 0.9, qPrintable(report));
        QVERIFY2(std::abs(neesMean / 6.0 - 1.0) < 0.05, qPrintable(report));
        QVERIFY2(std::abs(nisMean / parameters.measured.size() - 1.0) < 0.05, qPrintable(report));
    }

    void consistency_constantTurn() {
        // A truth integrated finely (not by the filter's own discretisation), turning through
        // +-pi, with the same white accelerations; full-state measurement.
        PoseFilterParameters parameters;
        parameters.gateProbability = 1.0;
        parameters.accelerationDensity = {0.2, 0.2, 1.0};
        const int runs = 100, steps = 200;
        std::vector<double> nees(steps, 0.0), nis(steps, 0.0);
        std::mt19937_64 noise(21);
        for (int run = 0; run < runs; ++run) {
            FineTruth truth(turnStart(), parameters.accelerationDensity, parameters.controlPeriod,
                            1000 + run);
            PoseFilter filter(parameters);
            for (int k = 0; k < steps; ++k) {
                if (k > 0) {
                    truth.advance();
                }
                filter.step(measure(truth.state(), parameters, noise));
                filter.commanded(Eigen::Vector2d::Zero());
                const Vector6 e = error(truth.state(), filter.nowEstimate());
                nees[k] += e.dot(filter.nowCovariance().ldlt().solve(e)) / runs;
                nis[k] += filter.status().nis / runs;
            }
        }
        const double neesInside = shareInside(nees, runs, 6, 0);
        const double nisInside = shareInside(nis, runs, 6, 1);
        const QString report = QStringLiteral("NEES mean %1 (%2 inside), NIS mean %3 (%4 inside)")
                                   .arg(mean(nees, 0))
                                   .arg(neesInside)
                                   .arg(mean(nis, 1))
                                   .arg(nisInside);
        qInfo("%s", qPrintable(report));
        QVERIFY2(neesInside >= 0.9, qPrintable(report));
        QVERIFY2(nisInside >= 0.9, qPrintable(report));
    }

    void timeStamped_unevenFramesPoseOnly() {
        // Pose-only frames 20, 30 and 25 ms apart, 40 ms old on arrival; the estimate of the
        // arrival time has the body velocities and the pose of then.
        PoseFilterParameters parameters;
        parameters.measurePoseOnly();
        // A truth of constant velocities: a slow random walk suits it (pose-only, the velocity
        // estimate's steady spread grows with the density to the power 3/4).
        parameters.accelerationDensity = {0.001, 0.001, 0.001};
        PoseFilter filter(parameters);
        const int intervals[] = {20, 30, 25};
        double t = 100.0;
        Vector6 start;
        start << 0.0, 0.0, 1.0, 2.0, 0.0, 0.5;
        std::mt19937_64 noise(10);
        Eigen::VectorXd now;
        Vector6 truthNow;
        for (int k = 0; k < 120; ++k) {
            const Vector6 taken = PoseFilter::propagate(start, t - 100.0);
            filter.commandedAt(Eigen::Vector2d(0.3, 0.1), t);
            filter.update(measure(taken, parameters, noise), t);
            now = filter.predictTo(t + 0.04);
            truthNow = PoseFilter::propagate(start, t + 0.04 - 100.0);
            t += intervals[k % 3] * 1e-3;
        }
        QVERIFY2(std::abs(now[3] - 2.0) < 0.05, qPrintable(QString::number(now[3])));
        QVERIFY2(std::abs(now[4]) < 0.05, qPrintable(QString::number(now[4])));
        QVERIFY2(std::abs(now[5] - 0.5) < 0.05, qPrintable(QString::number(now[5])));
        QVERIFY2((now.head<2>() - truthNow.head<2>()).norm() < 0.01,
                 qPrintable(QString::number((now.head<2>() - truthNow.head<2>()).norm())));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 filter.update(Eigen::VectorXd::Zero(6), t - 1.0));
    }

    void badInput_refusedByName() {
        PoseFilterParameters parameters;
        PoseFilter filter(parameters);
        auto message = [](auto&& call) -> QString {
            try {
                call();
            } catch (const std::invalid_argument& e) {
                return QString::fromUtf8(e.what());
            }
            return {};
        };
        QVERIFY(message([&] {
                    filter.step(Eigen::VectorXd::Zero(5));
                }).contains(QStringLiteral("observation has 5 components, expected 6")));
        Eigen::VectorXd nan = Eigen::VectorXd::Zero(6);
        nan[2] = std::numeric_limits<double>::quiet_NaN();
        QVERIFY(message([&] { filter.step(nan); }).contains(QStringLiteral("heading")));
        QVERIFY(!filter.status().initialised);  // nothing taken from a refused sample
        filter.step(Eigen::VectorXd::Zero(6));
        QVERIFY(message([&] {
                    filter.commanded(Eigen::VectorXd::Zero(3));
                }).contains(QStringLiteral("action has 3 components")));
        QVERIFY_THROWS_EXCEPTION(std::logic_error, PoseFilter(parameters).predictTo(0.0));

        PoseFilterParameters bad = parameters;
        bad.measured = {0, 1, 7};
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("measured index 7")));
        bad = parameters;
        bad.measurementStd[4] = 0.0;
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("component 4")));
        bad = parameters;
        bad.velocity.yawRate = 2;
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("share index 2")));
        bad = parameters;
        bad.accelerationDensity[1] = -1.0;
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("lateral velocity")));
        bad = parameters;
        bad.inputGain = Eigen::MatrixXd::Zero(2, 2);
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("input gain")));
        bad = parameters;
        bad.stateDimension = 4;
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("state dimension")));
        bad = parameters;
        bad.loopLatencySteps = -1;
        QVERIFY(message([&] { PoseFilter f(bad); }).contains(QStringLiteral("latency")));
    }

    void passThrough_otherComponentsFollowTheMeasurement() {
        // An 8-component state with the pose and velocities elsewhere.
        PoseFilterParameters parameters;
        parameters.stateDimension = 8;
        parameters.pose = {2, 3, 4};
        parameters.velocity = {5, 6, 7};
        parameters.measurementStd = Eigen::VectorXd::Constant(8, 0.01);
        parameters.measureFullState();
        PoseFilter filter(parameters);
        Eigen::VectorXd z = Eigen::VectorXd::Zero(8);
        z << 42.0, -1.0, 1.0, 2.0, 0.5, 1.0, 0.0, 0.0;
        const Eigen::VectorXd& out = filter.step(z);
        QCOMPARE(out[0], 42.0);
        QCOMPARE(out[1], -1.0);
        QVERIFY(std::abs(out[2] - 1.0) < 1e-9);
        QVERIFY(std::abs(filter.nowEstimate()[3] - 1.0) < 1e-9);
    }
};

QTEST_GUILESS_MAIN(TestPoseFilter)
#include "test_pose_filter.moc"
