// The pose filter (core/PoseFilter): its quantiles against published tables, consistency (NEES
// and NIS within their chi-square bounds over seeded Monte Carlo runs) on a truth drawn from its
// own process model and on a finely integrated constant turn, prediction across the sensor's
// latency, dropped frames bridged, an outlier gated and a genuine jump accepted, the heading
// across +-pi, the input term, the time-stamped calls, and bad input refused by name.
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
std::pair<double, double> meanBounds(int runs, int dof) {
    const int total = runs * dof;
    return {core::chiSquareQuantile(0.025, total) / runs,
            core::chiSquareQuantile(0.975, total) / runs};
}

Vector6 error(const Vector6& truth, const Vector6& estimate) {
    Vector6 e = truth - estimate;
    e[2] = core::wrapAngle(e[2]);
    return e;
}

/// z = truth's measured components plus noise, the rest of the 6-vector as the truth.
Eigen::VectorXd measure(const Vector6& truth, const PoseFilterParameters& parameters,
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
Consistency ownModelRuns(const PoseFilterParameters& parameters, int runs, int steps,
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
double shareInside(const std::vector<double>& averages, int runs, int dof, int from) {
    const auto [low, high] = meanBounds(runs, dof);
    int inside = 0;
    for (std::size_t k = from; k < averages.size(); ++k) {
        inside += averages[k] >= low && averages[k] <= high;
    }
    return static_cast<double>(inside) / static_cast<double>(averages.size() - from);
}

double mean(const std::vector<double>& values, int from) {
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

Vector6 turnStart() {
    Vector6 start;
    start << 0.0, 0.0, 2.8, 1.5, 0.2, 1.2;  // heading crosses +-pi within the first second
    return start;
}

}  // namespace

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

    void latency_predictionToNowBeatsTheDelayedMeasurement() {
        // A turn at 1.5 m/s and 1.2 rad/s, seen 3 steps (75 ms) late.
        PoseFilterParameters parameters;
        parameters.latencySteps = 3;
        parameters.accelerationDensity = {0.05, 0.05, 0.2};
        PoseFilter filter(parameters);
        FineTruth truth(turnStart(), {0.0, 0.0, 0.0}, parameters.controlPeriod, 3);
        std::deque<Vector6> past;
        std::mt19937_64 noise(4);
        double filtered = 0.0, raw = 0.0, filteredHeading = 0.0, rawHeading = 0.0;
        int counted = 0;
        for (int k = 0; k < 200; ++k) {
            past.push_back(truth.state());
            if (static_cast<int>(past.size()) > parameters.latencySteps + 1) {
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
        plain.latencySteps = 3;
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
            if (static_cast<int>(past.size()) > plain.latencySteps + 1) {
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
        parameters.latencySteps = 1;
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
        parameters.latencySteps = 2;
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
        bad.latencySteps = -1;
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
