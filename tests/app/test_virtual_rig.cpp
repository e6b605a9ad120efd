// The real-rig code end to end with no hardware: the synthetic camera renders a simulated car
// driven by the bytes the link writes to a pseudo-terminal; tracker, estimator, PRISCA and the
// link close the loop. The car parks; E-STOP leaves it neutral.
#include "app/VirtualRig.h"
#include "core/ActionMapping.h"
#include "sim/ControllerFactory.h"
#include "sim/PlantCatalog.h"
#include "sim/PlantProfile.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace prisca;

namespace {

std::unique_ptr<core::Controller> makeController(const QString& method,
                                                 std::shared_ptr<const core::Demonstration>* demo) {
    *demo = std::make_shared<core::Demonstration>(
        sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1));
    const sim::PlantProfile profile =
        sim::PlantProfile::forPlant(sim::PlantCatalog::describe(QStringLiteral("slidecar")));
    const Eigen::MatrixXd b =
        core::fitActionMapping(**demo, profile.mapping, profile.info.deviationModel()).b;
    return sim::ControllerFactory::create(method, profile, *demo, b);
}

}  // namespace

class TestVirtualRig : public QObject {
    Q_OBJECT
  private slots:
    void virtualRig_parksTheCarThroughCameraTrackerAndLink() {
        std::shared_ptr<const core::Demonstration> demo;
        app::VirtualRig rig({}, makeController(QStringLiteral("prisca"), &demo));
        QString error;
        QVERIFY2(rig.open(&error), qPrintable(error));
        const Eigen::VectorXd lot = demo->states.row(demo->length() - 1).transpose();
        const double seconds = demo->length() * demo->dt + 1.5;
        for (int trial = 0; trial < 2; ++trial) {
            const app::VirtualRig::Trial t = rig.runTrial(
                seconds, trial == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart,
                trial + 1);
            const double miss = std::hypot(t.finalPose.x - lot[0], t.finalPose.y - lot[1]);
            std::vector<double> latency = t.latencyMs;
            std::sort(latency.begin(), latency.end());
            qInfo(
                "trial %d: parked %.1f cm from the lot; %d of %d frames with a pose; %lld link "
                "frames decoded; frame -> bytes median %.2f ms",
                trial, miss * 100.0, t.framesWithPose, t.frames, t.linkFramesDecoded,
                latency.empty() ? -1.0 : latency[latency.size() / 2]);
            QVERIFY(t.framesWithPose >= t.frames - 2);
            QVERIFY(t.linkFramesDecoded >= t.frames);
            QVERIFY2(miss < 0.5, qPrintable(QString::number(miss)));
        }
    }

    void virtualRig_emergencyStopLeavesTheCarNeutral() {
        std::shared_ptr<const core::Demonstration> demo;
        app::VirtualRig rig({}, makeController(QStringLiteral("playback"), &demo));
        QString error;
        QVERIFY2(rig.open(&error), qPrintable(error));
        rig.link().emergencyStop();
        const app::VirtualRig::Trial t = rig.runTrial(1.0, core::ResetMode::Cold, 3);
        // Throttle neutral from the start: a brakeless car at rest stays (nearly) where it was.
        const double moved =
            std::hypot(t.path.back().x - t.path.front().x, t.path.back().y - t.path.front().y);
        QVERIFY2(moved < 0.02, qPrintable(QString::number(moved)));
    }
};

QTEST_GUILESS_MAIN(TestVirtualRig)
#include "test_virtual_rig.moc"
