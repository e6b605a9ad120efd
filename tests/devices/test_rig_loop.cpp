// The rig loop one frame at a time: the state estimator's body rates from the frames' own
// timestamps, and tracker -> controller -> link with failsafe on a lost pose, a bad action or a
// car that left the demonstration. The link writes to a pseudo-terminal.
#include "devices/RigLoop.h"

#include "PseudoTerminal.h"
#include "core/DeviationModel.h"
#include "devices/SyntheticCamera.h"
#include "devices/TransmitterLink.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <random>

using namespace prisca;
using namespace prisca::devices;

namespace {

/// Returns a fixed action and remembers the states it saw; its deviation is the state's
/// distance from `reference` in x, y (what the lost-track guard reads).
class Recorder : public core::Controller {
  public:
    QString name() const override { return QStringLiteral("recorder"); }
    void reset(core::ResetMode) override { states.clear(); }
    const core::ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& s) override {
        states.push_back(s);
        record_.action = action;
        record_.referenceAction = Eigen::Vector2d::Zero();
        record_.deviation = Eigen::VectorXd::Zero(s.size());
        record_.deviation.head(2) = s.head(2) - reference;
        return record_;
    }
    std::unique_ptr<core::Controller> clone() const override {
        return std::make_unique<Recorder>(*this);
    }
    Eigen::Vector2d action{0.5, -0.2};
    Eigen::Vector2d reference{0.0, 0.0};
    std::vector<Eigen::VectorXd> states;

  private:
    core::ControlStep record_;
};

CameraFrame frameAt(const std::optional<PlanarPose>& pose, std::int64_t ns) {
    static const FloorCalibration camera = syntheticCeilingCamera();
    CameraFrame frame;
    frame.steadyNs = ns;
    frame.image = pose ? renderLeds(*pose, camera, {}, LedGeometry{}, 1)
                       : cv::Mat(480, 640, CV_8UC1, cv::Scalar(0));
    return frame;
}

// A link on `port` that sends each command as it comes; one command holds for the whole test.
LinkSettings heldCommandLink(const QString& port) {
    LinkSettings settings;
    settings.port = port;
    settings.sendOnCommand = true;
    settings.staleAfter = 30.0;
    return settings;
}

}  // namespace

class TestRigLoop : public QObject {
    Q_OBJECT
  private slots:
    void estimator_bodyRatesFromUnevenFrameTimes() {
        PoseStateEstimator estimator;
        // Heading 90 degrees, driving along +y at 2 m/s while turning at 0.5 rad/s, with frames
        // 20, 30 and 25 ms apart (dropped and late frames): body rates vx = 2, vy = 0, r = 0.5.
        const int intervals[] = {20, 30, 25};
        double t = 0.0;
        std::int64_t ns = 1'000'000'000;
        Eigen::VectorXd state;
        for (int k = 0; k < 30; ++k) {
            // Position integrated exactly for a constant-speed arc.
            const double heading = core::kPi / 2 + 0.5 * t;
            const double x = (2.0 / 0.5) * (std::sin(heading) - 1.0);
            const double y = (2.0 / 0.5) * (-std::cos(heading));
            state = estimator.update({x, y, std::remainder(heading, 2 * core::kPi)}, ns);
            const int ms = intervals[k % 3];
            t += ms * 1e-3;
            ns += ms * 1'000'000LL;
        }
        QVERIFY2(std::abs(state[3] - 2.0) < 1e-3, qPrintable(QString::number(state[3])));
        QVERIFY2(std::abs(state[4]) < 1e-3, qPrintable(QString::number(state[4])));
        QVERIFY2(std::abs(state[5] - 0.5) < 1e-3, qPrintable(QString::number(state[5])));
        // Heading wraps through +-pi without a spike in the yaw rate.
        PoseStateEstimator wrap(1.0);
        wrap.update({0.0, 0.0, core::kPi - 0.01}, 0);
        const Eigen::VectorXd across = wrap.update({0.0, 0.0, -core::kPi + 0.01}, 20'000'000);
        QVERIFY2(std::abs(across[5] - 1.0) < 1e-9, qPrintable(QString::number(across[5])));
        // A gap of half a second or more starts the rates afresh.
        const Eigen::VectorXd gap = wrap.update({1.0, 0.0, -core::kPi + 0.01}, 600'000'000);
        QCOMPARE(gap[3], 0.0);
        QCOMPARE(gap[5], 0.0);
    }

    void loop_tracksStepsAndCommandsThenFailsafeOnNoPoseBadActionOrLostTrack() {
        Pty pty;
        QVERIFY(!pty.path.isEmpty());
        TransmitterLink link;
        link.start(heldCommandLink(pty.path));
        LinkStatus status;
        connect(&link, &TransmitterLink::statusChanged,
                [&status](const LinkStatus& s) { status = s; });
        QTRY_VERIFY_WITH_TIMEOUT(status.connected, 5000);

        auto owned = std::make_unique<Recorder>();
        Recorder* controller = owned.get();
        RigLoop loop(syntheticCeilingCamera(), TrackerSettings{}, std::move(owned),
                     ChannelMap::car(), link);
        loop.setLostTrackDistance(1.0);
        loop.startTrial(core::ResetMode::Cold);

        // A car in view: tracked, its state handed to the controller, the command sent.
        const PlanarPose pose{1.5, 0.4, 0.3};
        controller->reference = Eigen::Vector2d(pose.x, pose.y);
        std::int64_t ns = steadyNowNs();
        RigStep step = loop.onFrame(frameAt(pose, ns));
        QVERIFY(step.pose.has_value());
        QVERIFY2(std::hypot(step.pose->x - pose.x, step.pose->y - pose.y) < 0.01,
                 qPrintable(QStringLiteral("%1 %2").arg(step.pose->x).arg(step.pose->y)));
        QVERIFY(std::abs(step.pose->heading - pose.heading) < 1.0 * core::kPi / 180.0);
        QCOMPARE(controller->states.size(), size_t(1));
        QCOMPARE(controller->states[0].head(3), step.state.head(3));
        QCOMPARE(step.action, controller->action);
        QVERIFY(!step.fault);
        QVERIFY(step.commandNs >= step.frameNs);
        QTRY_COMPARE_WITH_TIMEOUT(status.failsafe, FailsafeReason::None, 3000);

        // No car in the frame: no pose, no controller step, failsafe (pose lost).
        ns += 25'000'000;
        step = loop.onFrame(frameAt(std::nullopt, ns));
        QVERIFY(!step.pose);
        QCOMPARE(controller->states.size(), size_t(1));
        QTRY_COMPARE_WITH_TIMEOUT(status.failsafe, FailsafeReason::PoseLost, 3000);

        // A non-finite action: a fault, failsafe.
        controller->action = Eigen::Vector2d(std::numeric_limits<double>::quiet_NaN(), 0.0);
        ns += 25'000'000;
        step = loop.onFrame(frameAt(pose, ns));
        QVERIFY(step.fault);
        QTRY_COMPARE_WITH_TIMEOUT(status.failsafe, FailsafeReason::ControllerFault, 3000);

        // A new trial clears it; then a car 1.6 m from its reference trips the lost-track guard,
        // and the failsafe stays for the rest of the trial even back on track.
        link.resetEmergencyStop();
        controller->action = Eigen::Vector2d(0.3, 0.0);
        loop.startTrial(core::ResetMode::WarmStart);
        ns += 25'000'000;
        step = loop.onFrame(frameAt(pose, ns));
        QVERIFY(!step.fault);
        controller->reference = Eigen::Vector2d(pose.x + 1.6, pose.y);
        ns += 25'000'000;
        QVERIFY(loop.onFrame(frameAt(pose, ns)).fault);
        controller->reference = Eigen::Vector2d(pose.x, pose.y);
        ns += 25'000'000;
        QVERIFY(loop.onFrame(frameAt(pose, ns)).fault);
        loop.startTrial(core::ResetMode::WarmStart);
        ns += 25'000'000;
        QVERIFY(!loop.onFrame(frameAt(pose, ns)).fault);
        link.stop();
        pty.read();  // what the link wrote, discarded
    }

    void loop_poseFilterSmootherThanFiniteDifferences() {
        // The same noisy pose stream (a 0.8 m/s arc at 1 rad/s; 3 mm and 0.01 rad of noise on
        // top of what the tracker adds; frames 20, 30 and 25 ms apart) through two loops: the
        // finite-difference estimator and the pose filter. The filter's body velocities are
        // closer to the truth and change less from frame to frame.
        Pty pty;
        QVERIFY(!pty.path.isEmpty());
        TransmitterLink link;
        link.start(heldCommandLink(pty.path));

        auto ownedPlain = std::make_unique<Recorder>();
        auto ownedFiltered = std::make_unique<Recorder>();
        Recorder* plain = ownedPlain.get();
        Recorder* filtered = ownedFiltered.get();
        RigLoop plainLoop(syntheticCeilingCamera(), TrackerSettings{}, std::move(ownedPlain),
                          ChannelMap::car(), link);
        RigLoop filteredLoop(syntheticCeilingCamera(), TrackerSettings{}, std::move(ownedFiltered),
                             ChannelMap::car(), link);
        core::PoseFilterParameters parameters;
        parameters.measurementStd << 0.004, 0.004, 0.012, 0.03, 0.03, 0.05;
        // Densities for a car on a steady arc (pose only, the velocities' steady spread grows
        // with the density to the power 3/4: the slide-car's simulation densities, made for a
        // measured velocity, would smooth far less).
        parameters.accelerationDensity = {0.05, 0.05, 0.1};
        filteredLoop.usePoseFilter(parameters, 0.0);
        QVERIFY(filteredLoop.poseFilter());
        plainLoop.startTrial(core::ResetMode::Cold);
        filteredLoop.startTrial(core::ResetMode::Cold);

        std::mt19937_64 random(17);
        std::normal_distribution<double> normal(0.0, 1.0);
        const int intervals[] = {20, 30, 25};
        const double speed = 0.8, rate = 1.0;
        std::int64_t ns = 1'000'000'000;
        double t = 0.0;
        std::vector<double> truthHeading;
        for (int k = 0; k < 120; ++k) {
            const double heading = 0.3 + rate * t;
            const PlanarPose truth{2.0 + (speed / rate) * (std::sin(heading) - std::sin(0.3)),
                                   0.5 - (speed / rate) * (std::cos(heading) - std::cos(0.3)),
                                   std::remainder(heading, 2 * core::kPi)};
            const PlanarPose noisy{truth.x + 0.003 * normal(random),
                                   truth.y + 0.003 * normal(random),
                                   truth.heading + 0.01 * normal(random)};
            const CameraFrame frame = frameAt(noisy, ns);
            QVERIFY(plainLoop.onFrame(frame).pose.has_value());
            QVERIFY(filteredLoop.onFrame(frame).pose.has_value());
            const int ms = intervals[k % 3];
            t += ms * 1e-3;
            ns += ms * 1'000'000LL;
        }
        QCOMPARE(plain->states.size(), size_t(120));
        QCOMPARE(filtered->states.size(), size_t(120));
        auto score = [&](const std::vector<Eigen::VectorXd>& states, double* error,
                         double* roughness) {
            double e = 0.0, r = 0.0;
            int n = 0;
            for (std::size_t k = 30; k < states.size(); ++k) {
                const Eigen::Vector3d v = states[k].segment<3>(3);
                const Eigen::Vector3d previous = states[k - 1].segment<3>(3);
                e += (v - Eigen::Vector3d(speed, 0.0, rate)).squaredNorm();
                r += (v - previous).squaredNorm();
                ++n;
            }
            *error = std::sqrt(e / n);
            *roughness = std::sqrt(r / n);
        };
        double plainError = 0.0, plainRough = 0.0, filterError = 0.0, filterRough = 0.0;
        score(plain->states, &plainError, &plainRough);
        score(filtered->states, &filterError, &filterRough);
        const QString report = QStringLiteral(
                                   "velocity RMS error: differences %1, filter %2; frame-to-frame "
                                   "change: differences %3, filter %4")
                                   .arg(plainError)
                                   .arg(filterError)
                                   .arg(plainRough)
                                   .arg(filterRough);
        qInfo("%s", qPrintable(report));
        QVERIFY2(filterError < 0.5 * plainError, qPrintable(report));
        QVERIFY2(filterRough < 0.3 * plainRough, qPrintable(report));
        // Nothing set aside on an honest stream.
        QCOMPARE(filteredLoop.poseFilter()->gatedCount(), 0);
        link.stop();
        pty.read();
    }
};

QTEST_GUILESS_MAIN(TestRigLoop)
#include "test_rig_loop.moc"
