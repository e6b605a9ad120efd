// The real-rig code end to end with no hardware: the synthetic camera renders a simulated car
// driven by the bytes the link writes to a pseudo-terminal; tracker, estimator, PRISCA and the
// link close the loop. The car parks; E-STOP leaves it neutral.
#include "core/ActionMapping.h"
#include "rigsim/VirtualRig.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/tuning/MethodTuning.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace prisca;

namespace {

std::unique_ptr<core::Controller> makeController(const QString& method,
                                                 std::shared_ptr<const core::Demonstration>* demo) {
    *demo = std::make_shared<core::Demonstration>(
        sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1));
    const sim::MethodTuning profile =
        sim::PlantCatalog::tuning(sim::PlantCatalog::describe(QStringLiteral("slidecar")));
    const Eigen::MatrixXd b =
        core::fitActionMapping(**demo, profile.mapping, profile.info.deviationModel()).b;
    return sim::MethodCatalog::create(method, profile, *demo, b);
}

// Full throttle straight ahead whatever it sees; its deviation is the pose's distance from where
// the trial started (a demonstration standing there).
class Runaway : public core::Controller {
  public:
    QString name() const override { return QStringLiteral("runaway"); }
    void reset(core::ResetMode) override { start_.reset(); }
    const core::ControlStep& step(const Eigen::Ref<const Eigen::VectorXd>& s) override {
        if (!start_) {
            start_ = s;
        }
        record_.action = Eigen::Vector2d(1.0, 0.0);
        record_.referenceAction = Eigen::Vector2d::Zero();
        record_.deviation = s - *start_;
        return record_;
    }
    std::unique_ptr<core::Controller> clone() const override {
        return std::make_unique<Runaway>(*this);
    }

  private:
    std::optional<Eigen::VectorXd> start_;
    core::ControlStep record_;
};

}  // namespace

class TestVirtualRig : public QObject {
    Q_OBJECT
  private slots:
    void virtualRig_parksTheCarThroughCameraTrackerAndLink() {
        std::shared_ptr<const core::Demonstration> demo;
        rigsim::VirtualRig rig({}, makeController(QStringLiteral("prisca"), &demo));
        QString error;
        QVERIFY2(rig.open(&error), qPrintable(error));
        const Eigen::VectorXd lot = demo->states.row(demo->length() - 1).transpose();
        const double seconds = demo->length() * demo->dt + 1.5;
        for (int trial = 0; trial < 2; ++trial) {
            const rigsim::VirtualRig::Trial t = rig.runTrial(
                seconds, trial == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart,
                trial + 1);
            const double miss = std::hypot(t.finalPose.x - lot[0], t.finalPose.y - lot[1]);
            std::vector<double> latency = t.loopLatencyMs;
            std::sort(latency.begin(), latency.end());
            qInfo(
                "trial %d: parked %.1f cm from the lot; %d of %d frames with a pose; %lld link "
                "frames decoded; frame -> bytes median %.2f ms",
                trial, miss * 100.0, t.framesWithPose, t.frames, t.linkFramesDecoded,
                latency.empty() ? -1.0 : latency[latency.size() / 2]);
            QVERIFY(t.framesWithPose >= t.frames - 2);
            QVERIFY(t.linkFramesDecoded >= t.frames);
            // The chain's check: camera, tracker, controller, link and car together bring the car
            // to the lot (a broken link or a wrong sign leaves it metres away: the runaway below
            // covers 8 m). How close depends on the loop's timing, which a loaded machine changes:
            // idle, a few cm; with both cores busy, the warm trial 1.1-53.4 cm in four runs and
            // once the cold trial 75.2 cm (busy loops and a build on 2 cores). The accuracy on an
            // unloaded machine is in docs/results.md ("The rig's chain"), not this test's.
            const double bound = 1.0;
            QVERIFY2(miss < bound, qPrintable(QString::number(miss)));
        }
    }

    void virtualRig_carThatLeavesTheDemonstrationGoesToFailsafe() {
        // Full throttle for 3 s drives the car many metres away; with the lost-track failsafe at
        // 0.3 m the link goes neutral once the car is 0.3 m out, and the brakeless car coasts
        // from the speed it had then to a stop far short of the unguarded run.
        double travelled[2] = {0.0, 0.0};
        for (const int guarded : {0, 1}) {
            rigsim::VirtualRigSettings settings;
            settings.perturbation = 0.0;
            settings.lostTrackDistance = guarded ? 0.3 : 0.0;
            rigsim::VirtualRig rig(settings, std::make_unique<Runaway>());
            QString error;
            QVERIFY2(rig.open(&error), qPrintable(error));
            const rigsim::VirtualRig::Trial t = rig.runTrial(3.0, core::ResetMode::Cold, 5);
            travelled[guarded] =
                std::hypot(t.path.back().x - t.path.front().x, t.path.back().y - t.path.front().y);
        }
        qInfo("full throttle for 3 s: %.2f m unguarded, %.2f m with the failsafe at 0.3 m",
              travelled[0], travelled[1]);
        QVERIFY2(travelled[0] > 3.0, qPrintable(QString::number(travelled[0])));
        QVERIFY2(travelled[1] > 0.3 && travelled[1] < 0.4 * travelled[0],
                 qPrintable(QString::number(travelled[1])));
    }

    void virtualRig_carLeavingTheFenceIsInFailsafeWithinOneFrame() {
        // Full throttle straight ahead out of a fence 1.2 m ahead of the start: the trial ends
        // in failsafe in the frame whose pose is first outside (the fault latched on the link
        // in that frame), and the receiver holds neutral from the link's next frames.
        rigsim::VirtualRigSettings settings;
        settings.perturbation = 0.0;
        settings.fence.polygon = {{-0.8, -1.0}, {1.2, -1.0}, {1.2, 1.0}, {-0.8, 1.0}};
        QVERIFY(settings.fence.problem().isEmpty());
        rigsim::VirtualRig rig(settings, std::make_unique<Runaway>());
        QString error;
        QVERIFY2(rig.open(&error), qPrintable(error));
        const rigsim::VirtualRig::Trial t = rig.runTrial(3.0, core::ResetMode::Cold, 5);
        int firstOutside = -1;
        for (size_t k = 0; k < t.path.size() && firstOutside < 0; ++k) {
            if (!settings.fence.contains({t.path[k].x, t.path[k].y})) {
                firstOutside = static_cast<int>(k);
            }
        }
        qInfo("first frame outside %d, trial ended in frame %d: %s", firstOutside, t.stopFrame,
              qPrintable(t.stopReason));
        QVERIFY(firstOutside > 0);
        QVERIFY(t.stopFrame >= firstOutside && t.stopFrame <= firstOutside + 1);
        QVERIFY2(t.stopReason.contains("left the fence"), qPrintable(t.stopReason));
        QVERIFY(t.receivedAtStop.has_value());
        QVERIFY2(t.receivedAtStop->cwiseAbs().maxCoeff() < 0.02,
                 qPrintable(QString::number(t.receivedAtStop->cwiseAbs().maxCoeff())));
        // A speed limit alone trips on the same run, earlier; a lost track too.
        rigsim::VirtualRigSettings fast;
        fast.perturbation = 0.0;
        fast.fence.maxSpeed = 1.0;
        rigsim::VirtualRig limited(fast, std::make_unique<Runaway>());
        QVERIFY2(limited.open(&error), qPrintable(error));
        const rigsim::VirtualRig::Trial s = limited.runTrial(3.0, core::ResetMode::Cold, 5);
        QVERIFY2(s.stopReason.contains("m/s"), qPrintable(s.stopReason));
        QVERIFY(s.stopFrame > 0 && s.stopFrame < t.stopFrame);
    }

    void geofence_refusesWhatIsNoFence() {
        devices::Geofence f;
        QVERIFY(f.problem().isEmpty() && !f.enabled());
        f.polygon = {{0, 0}, {1, 0}};
        QVERIFY(f.problem().contains("at least 3"));
        f.polygon = {{0, 0}, {1, 0}, {2, 0}};
        QVERIFY(f.problem().contains("one line"));
        f.polygon = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};  // a bow tie
        QVERIFY2(f.problem().contains("cross"), qPrintable(f.problem()));
        f.polygon = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        QVERIFY(f.problem().isEmpty());
        QVERIFY(f.contains({0.5, 0.5}) && !f.contains({1.5, 0.5}));
        f.maxLostSeconds = 0.5;
        QVERIFY(f.breach(std::nullopt, 0.0, 0.4).isEmpty());
        QVERIFY(f.breach(std::nullopt, 0.0, 0.6).contains("lost"));
        QString error;
        QVERIFY(!devices::Geofence::parsePolygon("0,0;1,x", &error));
        QVERIFY(error.contains("corner 2"));
        const auto back = devices::Geofence::fromJson(f.toJson(), &error);
        QVERIFY(back && back->polygon.size() == 4 && back->maxLostSeconds == 0.5);
    }

    void virtualRig_emergencyStopLeavesTheCarNeutral() {
        std::shared_ptr<const core::Demonstration> demo;
        rigsim::VirtualRig rig({}, makeController(QStringLiteral("playback"), &demo));
        QString error;
        QVERIFY2(rig.open(&error), qPrintable(error));
        rig.link().emergencyStop();
        const rigsim::VirtualRig::Trial t = rig.runTrial(1.0, core::ResetMode::Cold, 3);
        // Throttle neutral from the start: a brakeless car at rest stays (nearly) where it was.
        const double moved =
            std::hypot(t.path.back().x - t.path.front().x, t.path.back().y - t.path.front().y);
        QVERIFY2(moved < 0.02, qPrintable(QString::number(moved)));
    }
};

QTEST_GUILESS_MAIN(TestVirtualRig)
#include "test_virtual_rig.moc"
