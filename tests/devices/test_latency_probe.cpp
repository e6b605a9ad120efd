// The latency probe on poses with a known response: a car that starts to move a known time
// after the step command, with the camera's noise, is timed to a fraction of a frame; a car
// that is never seen or never answers is a failure with its reason, not a figure.
#include "devices/LatencyProbe.h"

#include <QtTest>

#include <cmath>

using namespace prisca::devices;

namespace {

// Runs the probe against a simulated car: the throttle acts `latency` after the frame that
// commanded it, accelerating at 3 m/s^2 (a motor's pull) in the commanded direction; no
// throttle: the car slows at 2 m/s^2 (rolling friction) to rest. Frames at 40 Hz, poses with
// 0.5 mm noise.
LatencyProbe run(double latency, bool seen = true, bool answers = true) {
    LatencyProbe probe;
    const double dt = 0.025, physics = 0.0005;
    double x = 0.0, v = 0.0, t = 0.0;
    std::vector<std::pair<double, double>> commands;  // effective time, throttle
    cv::RNG rng(3);
    for (int frame = 0; frame < 40 * 60 && !probe.finished(); ++frame) {
        const double now = frame * dt;
        for (; t < now; t += physics) {
            double throttle = 0.0;
            for (const auto& [at, u] : commands) {
                if (at <= t) {
                    throttle = u;
                }
            }
            const double a = answers && throttle != 0.0    ? 3.0 * (throttle > 0 ? 1 : -1)
                             : std::abs(v) < 2.0 * physics ? -v / physics
                                                           : -2.0 * (v > 0 ? 1 : -1);
            v += a * physics;
            x += v * physics;
        }
        std::optional<PlanarPose> pose;
        if (seen) {
            pose = PlanarPose{x + rng.gaussian(0.0005), rng.gaussian(0.0005), 0.0};
        }
        const Eigen::VectorXd action =
            probe.onFrame(static_cast<std::int64_t>(std::llround(now * 1e9)), pose);
        commands.emplace_back(now + latency, action[0]);
    }
    return probe;
}

}  // namespace

class TestLatencyProbe : public QObject {
    Q_OBJECT
  private slots:
    void probe_timesAKnownLatencyToAFractionOfAFrame() {
        for (const double latency : {0.0, 0.040, 0.120}) {
            const LatencyProbe probe = run(latency);
            QVERIFY2(probe.finished() && probe.failure().empty(), probe.failure().c_str());
            QCOMPARE(static_cast<int>(probe.steps().size()), 5);
            qInfo("latency %.0f ms: median %.1f ms, from %.1f to %.1f, std %.1f", latency * 1e3,
                  probe.medianSeconds() * 1e3, probe.minSeconds() * 1e3, probe.maxSeconds() * 1e3,
                  probe.spreadSeconds() * 1e3);
            QVERIFY(std::abs(probe.medianSeconds() - latency) < 0.006);
            QVERIFY(probe.maxSeconds() - probe.minSeconds() < 0.0125);
        }
    }

    void probe_failsWithItsReason() {
        const LatencyProbe unseen = run(0.0, false);
        QVERIFY(unseen.finished());
        QVERIFY2(QString::fromStdString(unseen.failure()).contains("no pose"),
                 unseen.failure().c_str());
        const LatencyProbe deaf = run(0.0, true, false);
        QVERIFY(deaf.finished());
        QVERIFY2(QString::fromStdString(deaf.failure()).contains("did not answer"),
                 deaf.failure().c_str());
        QVERIFY(deaf.steps().empty() && deaf.medianSeconds() < 0.0);
    }
};

QTEST_GUILESS_MAIN(TestLatencyProbe)
#include "test_latency_probe.moc"
