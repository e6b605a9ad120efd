// The rig session with no hardware and no window: the virtual car seen by the synthetic camera
// and driven through the real transmitter link; trials timed and scored by the session,
// recordings written on its worker thread.
#include "rig/RigSession.h"

#include "core/ActionMapping.h"
#include "core/DemonstrationCsv.h"
#include "core/DemonstrationStream.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace prisca;

namespace {

constexpr double kFps = 40.0;

struct SlideCar {
    sim::MethodTuning profile =
        sim::PlantCatalog::tuning(sim::PlantCatalog::describe(QStringLiteral("slidecar")));
    std::shared_ptr<const core::Demonstration> demonstration;
    Eigen::MatrixXd b;

    /// The scripted demonstration cut to its first `seconds`, so a trial is short.
    explicit SlideCar(double seconds) {
        core::Demonstration demo = sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1);
        const int keep = std::min(demo.length(), static_cast<int>(std::lround(seconds / demo.dt)));
        demo.states = demo.states.topRows(keep).eval();
        demo.actions = demo.actions.topRows(keep).eval();
        demo.time = demo.time.head(keep).eval();
        demonstration = std::make_shared<core::Demonstration>(std::move(demo));
        b = core::fitActionMapping(*demonstration, profile.mapping, profile.info.deviationModel())
                .b;
    }

    /// @param runOutLimit  how long a car still moving at the trial's end may run out [s]
    rig::TrialRequest trial(const QString& method, double runOutLimit = 0.0) const {
        sim::MethodTuning settling = profile;
        settling.settleTime = 0.5;
        settling.runOutLimit = runOutLimit;
        rig::TrialRequest request;
        request.setup =
            std::make_shared<const sim::RunSetup>(sim::makeTask(settling, demonstration), method);
        return request;
    }
};

/// The virtual camera running with the car in view and the link connected to the car.
bool startVirtual(rig::RigSession& rig) {
    rig::CameraRequest camera;
    camera.virtualFps = kFps;
    QString error;
    if (!rig.startCamera(camera, &error)) {
        qWarning("%s", qPrintable(error));
        return false;
    }
    if (!QTest::qWaitFor([&] { return rig.lastPose().has_value(); }, 10000)) {
        return false;
    }
    devices::LinkSettings link;
    link.port = rig.virtualPort();
    link.failsafe = rig.channels().failsafe();
    link.sendOnCommand = true;
    rig.connectLink(link);
    return QTest::qWaitFor([&] { return rig.linkStatus().connected; }, 5000);
}

}  // namespace

class TestRigSession : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { qRegisterMetaType<rig::RigTrialResult>(); }

    void bundleFrameAt_isTheStoredFrameNearestInTime() {
        // Frames kept at a quarter of the camera's rate (0, 4, 8, ...): a sample at frame 7 is
        // shown with frame 8 (one frame later), not frame 4 (three earlier).
        rig::TrialBundle bundle;
        for (long long f = 0; f <= 12; f += 4) {
            bundle.frames.push_back({f, QStringLiteral("frames/%1.jpg").arg(f)});
        }
        for (long long f : {0LL, 1LL, 2LL, 3LL, 6LL, 7LL, 13LL}) {
            rig::BundleSample sample;
            sample.frame = f;
            bundle.samples.push_back(sample);
        }
        const QStringList expected = {"0", "0", "0", "4", "4", "8", "12"};
        for (size_t i = 0; i < bundle.samples.size(); ++i) {
            QCOMPARE(bundle.frameAt(i), QStringLiteral("frames/%1.jpg").arg(expected[int(i)]));
        }
        QVERIFY(bundle.frameAt(99).isEmpty());
    }

    void startTrial_refusedWithoutCameraOrLink() {
        rig::RigSession rig;
        const SlideCar car(1.0);
        QString error;
        QVERIFY(!rig.startTrial(car.trial(QStringLiteral("pd")), &error));
        QVERIFY2(error.contains(QLatin1String("camera")), qPrintable(error));
        rig::CameraRequest camera;
        camera.virtualFps = kFps;
        QVERIFY(rig.startCamera(camera, &error));
        QTRY_VERIFY_WITH_TIMEOUT(rig.framesSeen() > 0, 10000);
        QVERIFY(!rig.startTrial(car.trial(QStringLiteral("pd")), &error));
        QVERIFY2(error.contains(QLatin1String("link")), qPrintable(error));
        QVERIFY(!rig.trialRunning());
        camera.virtualFps = 0.0;  // a second start while running changes nothing
        QVERIFY(rig.startCamera(camera, &error));
    }

    void trial_lastsItsLengthByTheFrameClockAndKeepsTheLoopPerMethod() {
        rig::RigSession rig;
        QVERIFY(startVirtual(rig));
        const SlideCar car(60.0);  // the whole 4 s manoeuvre
        const double length = car.demonstration->length() * car.demonstration->dt + 0.5;
        QSignalSpy finished(&rig, &rig::RigSession::trialFinished);
        QString error;
        for (int trial = 1; trial <= 2; ++trial) {
            QVERIFY2(rig.startTrial(car.trial(QStringLiteral("pd")), &error), qPrintable(error));
            QVERIFY(rig.trialRunning());
            QCOMPARE(rig.trialNumber(), trial);  // one loop for both trials of one method
            QVERIFY(!rig.startTrial(car.trial(QStringLiteral("pd")), &error));
            QTRY_COMPARE_WITH_TIMEOUT(finished.count(), trial, 20000);
            const auto result = finished.last().at(0).value<rig::RigTrialResult>();
            QCOMPARE(result.trial, trial);
            QVERIFY(!result.stopped);
            QVERIFY(!result.fault);
            // The demonstration and 0.5 s of settling, by the frames' own timestamps.
            QVERIFY2(result.seconds >= length && result.seconds < length + 3.0 / kFps,
                     qPrintable(QString::number(result.seconds)));
            QVERIFY(result.frames >= 2);
            QVERIFY(result.framesWithPose >= result.frames - 2);
            QVERIFY(result.parked.has_value());
            // PD parks the car near the lot (the demonstration's end).
            QVERIFY2(result.parked->position < 0.5,
                     qPrintable(QString::number(result.parked->position)));
        }
        QVERIFY(rig.startTrial(car.trial(QStringLiteral("pd-h-lsd")), &error));
        QCOMPARE(rig.trialNumber(), 1);  // a new method, a new loop, counting from 1
        rig.stopTrial();
        QCOMPARE(finished.count(), 3);  // said at once, on the caller's thread
        const auto stopped = finished.last().at(0).value<rig::RigTrialResult>();
        QVERIFY(stopped.stopped);
        QVERIFY(stopped.seconds < length);
        QVERIFY(!rig.trialRunning());
    }

    void runOut_aCarStillMovingCoastsInNeutralAndIsScoredWhereItRests() {
        // The manoeuvre cut at 1.5 s, the car at speed on the straight when the time is up.
        rig::RigSession rig;
        QVERIFY(startVirtual(rig));
        QTemporaryDir bundles;
        rig.setBundles(bundles.path(), 0.0);
        const SlideCar car(1.5);
        const double length = car.demonstration->length() * car.demonstration->dt + 0.5;
        QSignalSpy finished(&rig, &rig::RigSession::trialFinished);
        QSignalSpy saved(&rig, &rig::RigSession::bundleSaved);
        QString error;
        QVERIFY2(rig.startTrial(car.trial(QStringLiteral("pd"), 10.0), &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 30000);
        const auto result = finished.last().at(0).value<rig::RigTrialResult>();
        QVERIFY(!result.stopped && !result.fault);
        QVERIFY2(result.runOutSeconds > 0.2 && result.runOutSeconds < 10.0,
                 qPrintable(QString::number(result.runOutSeconds)));
        QVERIFY2(std::abs(result.seconds - length - result.runOutSeconds) < 3.0 / kFps,
                 qPrintable(QStringLiteral("%1 %2").arg(result.seconds).arg(length)));
        QVERIFY(rig::trialSentence(result).contains(QLatin1String("in neutral")));
        // Loop latencies are the controller's frames only.
        QVERIFY(static_cast<double>(result.loopLatencyMs.size()) <
                result.framesWithPose - 0.2 * kFps);
        // Scored where it rests: the car is where the score says a while later.
        QVERIFY(result.parked.has_value());
        QTRY_VERIFY_WITH_TIMEOUT(saved.count() == 1, 10000);
        const QString folder = saved.last().at(0).toString();
        const auto bundle = rig::TrialBundle::load(folder, &error);
        QVERIFY2(bundle.has_value(), qPrintable(error));
        QVERIFY(!bundle->samples.empty());
        const rig::BundleSample& last = bundle->samples.back();
        QVERIFY(last.found);
        const double moved = std::hypot(rig.lastPose()->x - last.x, rig.lastPose()->y - last.y);
        QVERIFY2(moved < 0.02, qPrintable(QString::number(moved)));
        // The run-out's commands were neutral: the zero action, not the controller's.
        int neutral = 0;
        int driven = 0;
        for (const rig::BundleSample& sample : bundle->samples) {
            if (sample.t >= length + 1.0 / kFps && !sample.action.empty()) {
                QVERIFY2(std::abs(sample.action[0]) < 1e-12 && std::abs(sample.action[1]) < 1e-12,
                         qPrintable(QString::number(sample.t)));
                ++neutral;
            } else if (sample.t < 1.0 && !sample.action.empty() &&
                       std::abs(sample.action[0]) > 1e-3) {
                ++driven;
            }
        }
        QVERIFY(neutral >= 5);
        QVERIFY(driven >= 5);
    }

    void emergencyStop_endsTheTrialAndLatchesFailsafe() {
        rig::RigSession rig;
        QVERIFY(startVirtual(rig));
        const SlideCar car(1.5);
        QSignalSpy finished(&rig, &rig::RigSession::trialFinished);
        QString error;
        QVERIFY(rig.startTrial(car.trial(QStringLiteral("pd")), &error));
        rig.emergencyStop();
        QCOMPARE(finished.count(), 1);
        QVERIFY(finished.last().at(0).value<rig::RigTrialResult>().stopped);
        QTRY_VERIFY_WITH_TIMEOUT(rig.linkStatus().emergencyLatched, 3000);
        QCOMPARE(rig.linkStatus().failsafe, devices::FailsafeReason::EmergencyStop);
        rig.resetEmergencyStop();
        QTRY_VERIFY_WITH_TIMEOUT(!rig.linkStatus().emergencyLatched, 3000);
    }

    void recording_resampledOnTheFramesClockAndWrittenToDisk() {
        QTemporaryDir dir;
        rig::RigSession rig;
        QVERIFY(startVirtual(rig));
        const SlideCar car(1.0);
        const QString path = dir.filePath(QStringLiteral("take.csv"));
        QString error;
        QVERIFY2(rig.startRecording(car.profile.info, path, &error), qPrintable(error));
        QVERIFY(rig.recording());
        QVERIFY(!rig.startTrial(car.trial(QStringLiteral("pd")), &error));  // not while driving
        // The header is on disk at once, under the partial name until the take ends.
        QVERIFY(QFile::exists(core::DemonstrationStream::partPath(path)));
        QVERIFY(!QFile::exists(path));
        qRegisterMetaType<rig::RigRecording>();
        QSignalSpy done(&rig, &rig::RigSession::recordingFinished);
        // Full throttle until the camera has seen 30 frames more.
        const long long start = rig.framesSeen();
        QVERIFY(QTest::qWaitFor(
            [&] {
                rig.setDriveCommand(Eigen::Vector2d(1.0, 0.0));
                return rig.framesSeen() > start + 30;
            },
            10000));
        rig.stopRecording();
        QVERIFY(!rig.recording());
        QTRY_COMPARE_WITH_TIMEOUT(done.count(), 1, 10000);
        const auto recording = done.last().at(0).value<rig::RigRecording>();
        QVERIFY2(recording.demonstration, qPrintable(recording.error));
        const core::Demonstration& demo = *recording.demonstration;
        QCOMPARE(recording.path, path);
        QVERIFY(demo.length() >= 20);
        // The frame period of a 40 fps camera.
        QVERIFY2(std::abs(demo.dt - 1.0 / kFps) < 0.1 / kFps, qPrintable(QString::number(demo.dt)));
        QVERIFY(demo.actions.col(0).maxCoeff() > 0.99);
        QVERIFY(demo.states(demo.length() - 1, 0) - demo.states(0, 0) > 0.05);  // it drove off
        core::FileError readError;
        const auto onDisk = core::readDemonstrationCsv(path, &readError);
        QVERIFY2(onDisk, qPrintable(readError.toString()));
        QCOMPARE(onDisk->length(), demo.length());
        QCOMPARE(onDisk->dt, demo.dt);
        QVERIFY(!QFile::exists(core::DemonstrationStream::partPath(path)));
    }

    void destroyedWhileRecording_keepsTheTakeOnDisk() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("crash.csv"));
        {
            rig::RigSession rig;
            QVERIFY(startVirtual(rig));
            const SlideCar car(1.0);
            QString error;
            QVERIFY(rig.startRecording(car.profile.info, path, &error));
            const long long start = rig.framesSeen();
            QVERIFY(QTest::qWaitFor([&] { return rig.framesSeen() > start + 12; }, 10000));
        }  // no stopRecording(): the session goes while the take runs
        core::FileError error;
        const auto kept =
            core::readDemonstrationCsv(core::DemonstrationStream::partPath(path), &error);
        QVERIFY2(kept, qPrintable(error.toString()));
        QVERIFY(kept->length() >= 10);
    }

    void calibration_badFileRefusedAndNothingChanged() {
        QTemporaryDir dir;
        rig::RigSession rig;
        const cv::Matx33d before = rig.calibration().imageToFloor;
        QFile bad(dir.filePath(QStringLiteral("bad.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"homography\": [1, 2]}");
        bad.close();
        QString error;
        QVERIFY(!rig.loadCalibration(bad.fileName(), &error));
        QVERIFY2(error.contains(QLatin1String("bad.json")), qPrintable(error));
        QVERIFY(rig.calibration().imageToFloor == before);
        QVERIFY(rig.saveCalibration(dir.filePath(QStringLiteral("good.json")), &error));
        QVERIFY(rig.loadCalibration(dir.filePath(QStringLiteral("good.json")), &error));
    }
};

QTEST_GUILESS_MAIN(TestRigSession)
#include "test_rig_session.moc"
