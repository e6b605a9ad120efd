// The pose filter (core/PoseFilter) on a moving car: prediction across the sensor's latency,
// dropped frames bridged, an outlier gated and a genuine jump accepted, the heading across +-pi,
// and the input term between measurements.

#include "PoseFilterTestSupport.h"

class TestPoseFilterTracking : public QObject {
    Q_OBJECT
  private slots:

    void latency_predictionToNowBeatsTheDelayedMeasurement() {
        // A turn at 1.5 m/s and 1.2 rad/s, seen 3 steps (75 ms) late.
        PoseFilterParameters parameters;
        parameters.loopLatencySteps = 3;
        parameters.accelerationDensity = {0.05, 0.05, 0.2};
        PoseFilter filter(parameters);
        FineTruth truth(turnStart(), {0.0, 0.0, 0.0}, parameters.controlPeriod, 3);
        std::deque<Vector6> past;
        std::mt19937_64 noise(4);
        double filtered = 0.0, raw = 0.0, filteredHeading = 0.0, rawHeading = 0.0;
        int counted = 0;
        for (int k = 0; k < 200; ++k) {
            past.push_back(truth.state());
            if (static_cast<int>(past.size()) > parameters.loopLatencySteps + 1) {
                past.pop_front();
            }
            const Eigen::VectorXd z = measure(past.front(), parameters, noise);
            const Eigen::VectorXd now = filter.step(z);
            filter.commanded(Eigen::Vector2d::Zero());
            if (k >= 20) {
                filtered += (now.head<2>() - truth.state().head<2>()).squaredNorm();
                raw += (z.head<2>() - truth.state().head<2>()).squaredNorm();
                filteredHeading += std::pow(core::wrapAngle(now[2] - truth.state()[2]), 2);
                rawHeading += std::pow(core::wrapAngle(z[2] - truth.state()[2]), 2);
                ++counted;
            }
            truth.advance();
        }
        const double rmsFiltered = std::sqrt(filtered / counted);
        const double rmsRaw = std::sqrt(raw / counted);
        const QString report =
            QStringLiteral("position RMS now %1 m, delayed %2 m; heading %3, %4 rad")
                .arg(rmsFiltered)
                .arg(rmsRaw)
                .arg(std::sqrt(filteredHeading / counted))
                .arg(std::sqrt(rawHeading / counted));
        qInfo("%s", qPrintable(report));
        QVERIFY2(rmsRaw > 0.1, qPrintable(report));  // 75 ms at 1.5 m/s
        QVERIFY2(rmsFiltered < 0.25 * rmsRaw, qPrintable(report));
        QVERIFY2(filteredHeading < 0.25 * rawHeading, qPrintable(report));
    }

    void accelerationStates_predictTheVelocityAcrossLatency() {
        // A car yawing up and speeding up (body accelerations 2 m/s^2 forward, 4 rad/s^2 of yaw),
        // seen 3 steps late: with jerk densities the filter estimates the trend and its velocity
        // of now is far closer than the random walk's, which is the velocity of then.
        PoseFilterParameters plain;
        plain.loopLatencySteps = 3;
        plain.accelerationDensity = {0.05, 0.05, 0.2};
        PoseFilterParameters trend = plain;
        trend.jerkDensity = {0.5, 0.5, 2.0};
        PoseFilter a(plain), b(trend);
        std::deque<Vector6> past;
        std::mt19937_64 noise(31);
        double plainError = 0.0, trendError = 0.0;
        const double dt = plain.controlPeriod;
        Vector6 truth;
        truth << 0.0, 0.0, 0.0, 0.5, 0.0, 0.0;
        for (int k = 0; k < 80; ++k) {
            past.push_back(truth);
            if (static_cast<int>(past.size()) > plain.loopLatencySteps + 1) {
                past.pop_front();
            }
            const Eigen::VectorXd z = measure(past.front(), plain, noise);
            a.step(z);
            b.step(z);
            a.commanded(Eigen::Vector2d::Zero());
            b.commanded(Eigen::Vector2d::Zero());
            if (k >= 30) {
                plainError += (a.nowEstimate().segment<3>(3) - truth.segment<3>(3)).squaredNorm();
                trendError += (b.nowEstimate().segment<3>(3) - truth.segment<3>(3)).squaredNorm();
            }
            // Constant body accelerations, integrated finely.
            for (int s = 0; s < 50; ++s) {
                Vector6 mid = truth;
                mid[3] += 2.0 * dt / 100.0;
                mid[5] += 4.0 * dt / 100.0;
                truth.head<3>() = PoseFilter::propagate(mid, dt / 50.0).head<3>();
                truth[3] += 2.0 * dt / 50.0;
                truth[5] += 4.0 * dt / 50.0;
            }
        }
        const QString report = QStringLiteral(
                                   "velocity RMS error of now: random walk %1, with "
                                   "accelerations %2; acceleration estimate %3, %4")
                                   .arg(std::sqrt(plainError / 50))
                                   .arg(std::sqrt(trendError / 50))
                                   .arg(b.nowAcceleration()[0])
                                   .arg(b.nowAcceleration()[2]);
        qInfo("%s", qPrintable(report));
        QVERIFY2(trendError < 0.25 * plainError, qPrintable(report));
        QVERIFY2(std::abs(b.nowAcceleration()[0] - 2.0) < 0.5, qPrintable(report));
        QVERIFY2(std::abs(b.nowAcceleration()[2] - 4.0) < 1.0, qPrintable(report));
        QVERIFY(a.nowAcceleration().isZero());
        // From a demonstration's states: a velocity ramp's second difference is zero but at its
        // corners.
        Eigen::MatrixXd states = Eigen::MatrixXd::Zero(200, 6);
        for (int k = 0; k < 200; ++k) {
            states(k, 3) = k < 100 ? 0.05 * k : 5.0;
        }
        const Eigen::Vector3d j = core::jerkDensityFromStates(states, {}, 0.025);
        QVERIFY(j[0] >= 1e-4 && j[1] == 1e-4 && j[2] == 1e-4);
    }

    void droppedFrames_bridgedAndFlagged() {
        PoseFilterParameters parameters;
        parameters.measurePoseOnly();
        parameters.loopLatencySteps = 1;
        parameters.accelerationDensity = {0.05, 0.05, 0.2};
        PoseFilter filter(parameters);
        FineTruth truth(turnStart(), {0.0, 0.0, 0.0}, parameters.controlPeriod, 5);
        std::mt19937_64 noise(6);
        Eigen::VectorXd held;
        Vector6 previous = truth.state();
        double worstInGap = 0.0, beforeGap = 0.0, afterGap = 0.0;
        for (int k = 0; k < 160; ++k) {
            const bool dropped = k >= 80 && k < 92;  // 12 frames (0.3 s) lost
            if (!dropped) {
                held = measure(previous, parameters, noise);
            }
            const Eigen::VectorXd now = filter.step(held, dropped);
            filter.commanded(Eigen::Vector2d::Zero());
            QCOMPARE(filter.status().predictedOnly, dropped);
            const double e = (now.head<2>() - truth.state().head<2>()).norm();
            if (k >= 60 && k < 80) {
                beforeGap = std::max(beforeGap, e);
            } else if (dropped) {
                worstInGap = std::max(worstInGap, e);
                // The covariance knows it is growing: the error stays within 4 sigma.
                const double sigma = std::sqrt(filter.nowCovariance().block<2, 2>(0, 0).trace());
                QVERIFY2(e < 4.0 * sigma + 1e-3, qPrintable(QString::number(k)));
            } else if (k >= 120) {
                afterGap = std::max(afterGap, e);
            }
            previous = truth.state();
            truth.advance();
        }
        const QString report =
            QStringLiteral("worst error before %1 m, in the gap %2 m, after %3 m")
                .arg(beforeGap)
                .arg(worstInGap)
                .arg(afterGap);
        qInfo("%s", qPrintable(report));
        QCOMPARE(filter.predictOnlyCount(), 12);
        QVERIFY2(worstInGap > beforeGap, qPrintable(report));  // it grows ...
        QVERIFY2(worstInGap < 0.05, qPrintable(report));       // ... but 0.3 s stays in 5 cm
        QVERIFY2(afterGap < 0.02, qPrintable(report));         // and recovers
    }

    void outlier_gatedThenGenuineJumpAccepted() {
        PoseFilterParameters parameters;
        parameters.measurePoseOnly();
        parameters.accelerationDensity = {0.05, 0.05, 0.2};
        PoseFilter filter(parameters);
        FineTruth truth(turnStart(), {0.0, 0.0, 0.0}, parameters.controlPeriod, 7);
        std::mt19937_64 noise(8);
        Eigen::Vector2d offset = Eigen::Vector2d::Zero();
        int firstAccepted = -1;
        for (int k = 0; k < 200; ++k) {
            Eigen::VectorXd z = measure(truth.state(), parameters, noise);
            if (k == 100) {
                z[0] += 1.0;  // one frame 1 m off
            }
            if (k >= 150) {
                offset = {1.0, 0.0};  // the car really is 1 m further from now on
            }
            z.head<2>() += offset;
            const Eigen::VectorXd now = filter.step(z);
            filter.commanded(Eigen::Vector2d::Zero());
            const double e = (now.head<2>() - truth.state().head<2>() - offset).norm();
            if (k == 100) {
                QVERIFY(filter.status().gated);
                QCOMPARE(filter.gatedCount(), 1);
                QVERIFY2(e < 0.02, qPrintable(QString::number(e)));
            }
            if (k > 100 && k < 150) {
                QVERIFY(!filter.status().gated);
                QVERIFY2(e < 0.02, qPrintable(QString::number(e)));
            }
            if (k >= 150 && k < 150 + parameters.reinitialiseAfter - 1) {
                QVERIFY(filter.status().gated);
            }
            if (filter.status().reinitialised) {
                QCOMPARE(k, 150 + parameters.reinitialiseAfter - 1);
            }
            if (k >= 150 && firstAccepted < 0 && e < 0.02) {
                firstAccepted = k;
            }
            truth.advance();
        }
        QCOMPARE(filter.reinitialisations(), 1);
        QCOMPARE(filter.gatedCount(), 1 + parameters.reinitialiseAfter);
        QVERIFY2(firstAccepted >= 0 && firstAccepted <= 150 + parameters.reinitialiseAfter + 10,
                 qPrintable(QString::number(firstAccepted)));
    }

    void heading_acrossPlusMinusPi() {
        // Spinning on the spot through +-pi many times, measured wrapped: the estimate's heading
        // error stays small; a plant counting whole turns gets its own branch back.
        PoseFilterParameters parameters;
        parameters.accelerationDensity = {0.05, 0.05, 0.2};
        for (bool unwrapped : {false, true}) {
            PoseFilter filter(parameters);
            std::mt19937_64 noise(9);
            double worst = 0.0;
            for (int k = 0; k < 400; ++k) {
                Vector6 truth;
                const double heading = 3.0 + 4.0 * k * parameters.controlPeriod;
                truth << 0.0, 0.0, core::wrapAngle(heading), 0.0, 0.0, 4.0;
                Eigen::VectorXd z = measure(truth, parameters, noise);
                if (unwrapped) {
                    z[2] = heading + core::wrapAngle(z[2] - core::wrapAngle(heading));
                }
                const Eigen::VectorXd now = filter.step(z);
                filter.commanded(Eigen::Vector2d::Zero());
                worst = std::max(worst, std::abs(core::wrapAngle(now[2] - heading)));
                QVERIFY(std::abs(filter.nowEstimate()[2]) <= core::kPi);
                // The output is on the measurement's branch.
                QVERIFY2(std::abs(now[2] - z[2]) < 0.1, qPrintable(QString::number(k)));
            }
            QVERIFY2(worst < 0.03, qPrintable(QString::number(worst)));
            QCOMPARE(filter.gatedCount(), 0);
        }
    }

    void inputTerm_actionChangesSinceTheMeasurementAccelerate() {
        // At rest, measured 2 steps late; the action steps from 0 to 1 at step 10. With
        // G = [2 0; 0 0; 0 3] the estimate of now carries the acceleration of the steps since the
        // newest measurement: the first step after the change dv = dt * 2, then 2 dt * 2 ...
        // until the measurement catches up (it shows the plant did not move: at rest the filter
        // believes the measurement of velocity).
        PoseFilterParameters parameters;
        parameters.loopLatencySteps = 2;
        parameters.accelerationDensity = {0.01, 0.01, 0.01};
        parameters.inputGain = Eigen::MatrixXd::Zero(3, 2);
        parameters.inputGain(0, 0) = 2.0;
        parameters.inputGain(2, 1) = 3.0;
        PoseFilter filter(parameters);
        const double dt = parameters.controlPeriod;
        Eigen::VectorXd still = Eigen::VectorXd::Zero(6);
        for (int k = 0; k < 13; ++k) {
            filter.step(still);
            if (k == 10) {
                QVERIFY(std::abs(filter.nowEstimate()[3]) < 1e-12);
            }
            if (k == 11) {  // one step of u = 1 since the measurement's action (0)
                QVERIFY2(std::abs(filter.nowEstimate()[3] - dt * 2.0) < 1e-3,
                         qPrintable(QString::number(filter.nowEstimate()[3])));
                QVERIFY2(std::abs(filter.nowEstimate()[5] - dt * 3.0) < 1e-3,
                         qPrintable(QString::number(filter.nowEstimate()[5])));
            }
            if (k == 12) {  // two steps
                QVERIFY2(std::abs(filter.nowEstimate()[3] - 2 * dt * 2.0) < 2e-3,
                         qPrintable(QString::number(filter.nowEstimate()[3])));
            }
            filter.commanded(k >= 10 ? Eigen::Vector2d(1.0, 1.0) : Eigen::Vector2d(0.0, 0.0));
        }
        // From the fit's B (m x n): the velocity columns, transposed.
        Eigen::MatrixXd b = Eigen::MatrixXd::Zero(2, 6);
        b(0, 3) = 2.5;
        b(1, 5) = 7.0;
        b(1, 4) = -1.0;
        const Eigen::MatrixXd g = core::inputGainFromFit(b, {});
        QCOMPARE(g.rows(), 3);
        QCOMPARE(g(0, 0), 2.5);
        QCOMPARE(g(1, 1), -1.0);
        QCOMPARE(g(2, 1), 7.0);
    }
};

QTEST_GUILESS_MAIN(TestPoseFilterTracking)
#include "test_pose_filter_tracking.moc"
