// The pre-trial check as a function of the rig's state: each item fails for its own reason,
// names what to do, and a failed blocking item keeps the trial from starting.
#include "devices/SyntheticCamera.h"
#include "rig/PreTrialCheck.h"
#include "sim/PlantCatalog.h"

#include <QtTest>

using namespace prisca;
using rig::PreTrialInputs;

namespace {

// A straight demonstration from (x0, 0) to (x1, 0) on the slide-car.
std::shared_ptr<const core::Demonstration> line(double x0, double x1) {
    auto demo = std::make_shared<core::Demonstration>();
    const int n = 50;
    demo->dt = 0.025;
    demo->states = Eigen::MatrixXd::Zero(n, 6);
    demo->actions = Eigen::MatrixXd::Zero(n, 2);
    for (int k = 0; k < n; ++k) {
        demo->states(k, 0) = x0 + (x1 - x0) * k / (n - 1);
    }
    return demo;
}

// Everything in order: the virtual rig, running, linked, a fence around a path in view.
PreTrialInputs ready() {
    PreTrialInputs in;
    in.cameraRunning = true;
    in.virtualCamera = true;
    in.carSeen = true;
    in.frameSize = cv::Size(640, 480);
    in.calibration = devices::syntheticCeilingCamera();
    in.calibrationIsVirtualRigs = true;
    in.link.connected = true;
    in.fence.polygon = {{-1.0, -1.0}, {3.0, -1.0}, {3.0, 1.0}, {-1.0, 1.0}};
    in.demonstration = line(0.0, 2.0);
    in.plant = sim::PlantCatalog::describe(QStringLiteral("slidecar"));
    in.methodLabel = QStringLiteral("OURS (PRISCA)");
    return in;
}

const rig::PreTrialItem& item(const rig::PreTrialCheck& check, const char* key) {
    const rig::PreTrialItem* found = check.find(QLatin1String(key));
    if (!found) {
        qFatal("no item %s", key);
    }
    return *found;
}

}  // namespace

class TestPreTrialCheck : public QObject {
    Q_OBJECT
  private slots:
    void everythingInOrder_isReady() {
        const rig::PreTrialCheck check = rig::evaluatePreTrialCheck(ready());
        QVERIFY2(check.ready(), qPrintable(check.missingDetails()));
        QVERIFY(check.missingLabels().isEmpty());
        QCOMPARE(check.items.size(), size_t(10));
        for (const rig::PreTrialItem& i : check.items) {
            QVERIFY2(i.ok, qPrintable(i.key + QStringLiteral(": ") + i.detail));
        }
    }

    void cameraOffLinkDownOrEstopLatched_eachBlocks() {
        PreTrialInputs in = ready();
        in.cameraRunning = false;
        in.link.connected = false;
        in.emergencyLatched = true;
        const rig::PreTrialCheck check = rig::evaluatePreTrialCheck(in);
        QVERIFY(!check.ready());
        QVERIFY(!item(check, "camera").ok && !item(check, "link").ok && !item(check, "estop").ok);
        QCOMPARE(check.missingLabels(), QStringLiteral("Camera, Link, E-STOP"));
        QVERIFY(check.missingDetails().contains(QLatin1String("Start the camera")));
    }

    void aLotOutsideTheCamerasView_blocks() {
        // The case: a demonstration ending at (7, 4) m, far past what the camera sees.
        PreTrialInputs in = ready();
        in.fence.polygon.clear();
        auto demo = std::make_shared<core::Demonstration>(*line(0.0, 7.0));
        demo->states(demo->length() - 1, 1) = 4.0;
        in.demonstration = demo;
        const rig::PreTrialCheck check = rig::evaluatePreTrialCheck(in);
        QVERIFY(!check.ready());
        QVERIFY(!item(check, "view").ok);
        QVERIFY2(item(check, "view").detail.contains(QLatin1String("(7.00, 4.00) m")),
                 qPrintable(item(check, "view").detail));
        // With no fence the check says so, but that alone does not block.
        QVERIFY(!item(check, "fence").ok && !item(check, "fence").blocking);
    }

    void aPathLeavingTheFence_blocks() {
        PreTrialInputs in = ready();
        in.fence.polygon = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
        const rig::PreTrialCheck check = rig::evaluatePreTrialCheck(in);
        QVERIFY(!check.ready());
        QCOMPARE(check.missingLabels(), QStringLiteral("Fence"));
        QVERIFY(item(check, "fence").detail.contains(QLatin1String("(2.00, 0.00) m")));
        // No frame yet: the view cannot be checked.
        in = ready();
        in.frameSize = cv::Size();
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "view").ok);
    }

    void aRealCamera_needsItsOwnCalibrationALensAndTheLatency() {
        PreTrialInputs in = ready();
        in.virtualCamera = false;
        rig::PreTrialCheck check = rig::evaluatePreTrialCheck(in);
        QVERIFY(!item(check, "calibration").ok);  // still the virtual rig's
        QVERIFY(!item(check, "lens").ok);
        QVERIFY(!item(check, "latency").ok);  // neither measured nor declared
        in.calibrationIsVirtualRigs = false;
        in.calibration.lens = devices::CameraLens{};
        in.loopLatency = 0.080;
        in.loopLatencySource = rig::LoopLatencySource::Declared;
        check = rig::evaluatePreTrialCheck(in);
        QVERIFY(item(check, "lens").ok);
        QVERIFY(item(check, "latency").ok);
        QVERIFY(item(check, "latency").detail.contains(QLatin1String("declared: 80.0 ms")));
        in.loopLatencySource = rig::LoopLatencySource::Measured;
        QVERIFY(item(rig::evaluatePreTrialCheck(in), "latency")
                    .detail.contains(QLatin1String("measured")));
    }

    void theVirtualCamerasLatency_isKnownUnlessADelayIsInjected() {
        PreTrialInputs in = ready();
        QVERIFY(item(rig::evaluatePreTrialCheck(in), "latency").ok);
        in.injectedCameraDelay = 0.1;
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "latency").ok);
    }

    // E-STOP blocks, and the line names its cause: the operator's latch, or failsafe held
    // after the process was stopped and continued.
    void emergency_blocksAndNamesItsCause() {
        PreTrialInputs in = ready();
        QVERIFY(item(rig::evaluatePreTrialCheck(in), "estop").ok);
        in.emergencyLatched = true;
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "estop").ok);
        QCOMPARE(item(rig::evaluatePreTrialCheck(in), "estop").detail,
                 rig::emergencyProblem(false));
        in.failsafeHeld = true;
        const QString held = item(rig::evaluatePreTrialCheck(in), "estop").detail;
        QCOMPARE(held, rig::emergencyProblem(true));
        QVERIFY2(held.contains(QLatin1String("stopped and continued")) &&
                     held.contains(QLatin1String("reset E-STOP")),
                 qPrintable(held));
        QVERIFY(!rig::evaluatePreTrialCheck(in).ready());
    }

    void aTaskTheRigCannotRun_blocks() {
        PreTrialInputs in = ready();
        in.methodSimulationOnly = true;  // the oracle
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "task").ok);
        // The rig's one rule for methods, which `prisca-cli rig` says too.
        QCOMPARE(item(rig::evaluatePreTrialCheck(in), "task").detail,
                 rig::methodRigProblem(true, false, in.methodLabel));
        in = ready();
        in.methodTrainsOffline = true;
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "task").ok);
        QCOMPARE(item(rig::evaluatePreTrialCheck(in), "task").detail,
                 rig::methodRigProblem(false, true, in.methodLabel));
        QVERIFY(rig::methodRigProblem(false, false, in.methodLabel).isEmpty());
        in = ready();
        in.plant = sim::PlantCatalog::describe(QStringLiteral("diffdrive"));
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "task").ok);
        in = ready();
        in.demonstration.reset();
        QVERIFY(!item(rig::evaluatePreTrialCheck(in), "task").ok);
        // mpc without the car's model: identify first (it would identify on the spot, seconds
        // with the window waiting); with one it may start.
        in = ready();
        in.methodLabel = QStringLiteral("MPC");
        in.methodPlansThroughModel = true;
        const rig::PreTrialItem noModel = item(rig::evaluatePreTrialCheck(in), "task");
        QVERIFY(!noModel.ok && noModel.blocking);
        QVERIFY2(noModel.detail.contains(QLatin1String("identify")), qPrintable(noModel.detail));
        in.modelIdentified = true;
        QVERIFY(item(rig::evaluatePreTrialCheck(in), "task").ok);
    }
};

QTEST_MAIN(TestPreTrialCheck)
#include "test_pre_trial_check.moc"
