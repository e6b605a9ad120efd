// Samples at their own times (a camera's frames, jittered and some dropped) onto one uniform
// demonstration step.
#include "core/DeviationModel.h"
#include "sim/DemonstrationRecorder.h"
#include "sim/PlantCatalog.h"

#include <QtTest>

#include <cmath>

using namespace prisca::sim;

class TestDemonstrationRecorder : public QObject {
    Q_OBJECT
  private slots:
    void timedSamples_areResampledOntoTheMedianFrameInterval() {
        // A 60 fps camera (not the simulations' 40 Hz), 1 ms of jitter, frames 10 and 11 lost.
        // The car drives at 2 m/s along x and turns through psi = pi at 3 rad/s.
        const PlantInfo info = PlantCatalog::describe("slidecar");
        std::vector<double> times;
        std::vector<Eigen::VectorXd> states, actions;
        for (int f = 0; f < 120; ++f) {
            if (f == 10 || f == 11)
                continue;
            const double t = f / 60.0 + (f % 3 == 1 ? 0.001 : 0.0);
            Eigen::VectorXd s(6);
            s << 2.0 * t, 0.0, prisca::core::wrapAngle(3.0 + 3.0 * t), 2.0, 0.0, 3.0;
            times.push_back(t);
            states.push_back(s);
            actions.push_back(Eigen::Vector2d(f < 60 ? 0.5 : 0.0, 0.1));
        }
        const prisca::core::Demonstration d =
            DemonstrationRecorder::fromTimedSamples(info, times, states, actions);
        QVERIFY(std::abs(d.dt - 1.0 / 60.0) < 1e-12);  // the median interval, not 1/40
        QCOMPARE(d.length(), static_cast<int>(std::floor(times.back() / d.dt + 1e-9)) + 1);
        for (int k = 0; k < d.length(); ++k) {
            const double t = k * d.dt;
            QVERIFY(std::abs(d.time[k] - t) < 1e-12);
            QVERIFY2(std::abs(d.states(k, 0) - 2.0 * t) < 1e-9, qPrintable(QString::number(k)));
            // Heading interpolated the short way round across the wrap at pi.
            QVERIFY2(std::abs(prisca::core::wrapAngle(d.states(k, 2) - (3.0 + 3.0 * t))) < 1e-9,
                     qPrintable(QString::number(k)));
        }
        // Each action is the one in force at t_k (the throttle cut at frame 60, t = 1 s).
        QCOMPARE(d.actions(0, 0), 0.5);
        QCOMPARE(d.actions(d.length() - 1, 0), 0.0);
        QCOMPARE(d.plant, QStringLiteral("slidecar"));
    }

    void timedSamples_refuseTooFewOrUnorderedTimes() {
        const PlantInfo info = PlantCatalog::describe("slidecar");
        const Eigen::VectorXd s = Eigen::VectorXd::Zero(6), u = Eigen::VectorXd::Zero(2);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 DemonstrationRecorder::fromTimedSamples(info, {0.0}, {s}, {u}));
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            DemonstrationRecorder::fromTimedSamples(info, {0.0, 0.1, 0.1}, {s, s, s}, {u, u, u}));
    }
};

QTEST_APPLESS_MAIN(TestDemonstrationRecorder)
#include "test_demonstration_recorder.moc"
