// The loop's latency measured on the virtual rig: with a known delay injected into the virtual
// camera (0, 40 and 120 ms) the measurement recovers it within one frame (25 ms), and the
// trials then compensate the measured value.
#include "rig/RigSession.h"

#include <QSignalSpy>
#include <QtTest>

#include <cmath>

using namespace prisca;

class TestRigLatency : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { qRegisterMetaType<rig::LatencyMeasurement>(); }

    void measureLatency_recoversAnInjectedDelayWithinOneFrame() {
        const double frame = 1.0 / 40.0;
        std::vector<double> medians;
        for (const double injected : {0.0, 0.040, 0.120}) {
            rig::RigSession rig;
            rig::CameraRequest camera;
            camera.virtualFps = 40.0;
            camera.virtualPerturbation = 0.0;
            camera.virtualCameraDelay = injected;
            QString error;
            QVERIFY2(rig.startCamera(camera, &error), qPrintable(error));
            QVERIFY(QTest::qWaitFor([&] { return rig.lastPose().has_value(); }, 10000));
            // Refused until the link is up.
            QVERIFY(!rig.measureLatency({}, &error));
            devices::LinkSettings link;
            link.port = rig.virtualPort();
            link.failsafe = rig.channels().failsafe();
            link.sendOnCommand = true;
            rig.connectLink(link);
            QVERIFY(QTest::qWaitFor([&] { return rig.linkStatus().connected; }, 5000));
            QSignalSpy measured(&rig, &rig::RigSession::latencyMeasured);
            devices::LatencyProbeSettings probe;
            probe.steps = 3;
            QVERIFY2(rig.measureLatency(probe, &error), qPrintable(error));
            QVERIFY(rig.measuringLatency());
            QVERIFY(!rig.measureLatency({}, &error));  // one at a time
            QVERIFY(measured.wait(60000) || measured.count() == 1);
            const auto m = measured.takeFirst().at(0).value<rig::LatencyMeasurement>();
            QVERIFY2(m.error.isEmpty(), qPrintable(m.error));
            qInfo("injected %.0f ms: median %.1f ms, from %.1f to %.1f ms, std %.1f ms",
                  injected * 1e3, m.median * 1e3, m.min * 1e3, m.max * 1e3, m.spread * 1e3);
            QCOMPARE(static_cast<int>(m.stepsSeconds.size()), 3);
            QVERIFY2(std::abs(m.median - injected) < frame, qPrintable(QString::number(m.median)));
            medians.push_back(m.median);
            rig.stopCamera();
            rig.disconnectLink();
        }
        QVERIFY(medians[0] < medians[1] && medians[1] < medians[2]);
    }
};

QTEST_GUILESS_MAIN(TestRigLatency)
#include "test_rig_latency.moc"
