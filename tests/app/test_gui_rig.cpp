// The Rig panel driven offscreen on the virtual rig: camera, link, trials, driving and
// recording, the channel map and the floor calibration.
#include "GuiTestSupport.h"
#include "app/panels/ReplayDialog.h"
#include "app/rig/RigDoctorPage.h"
#include "app/widgets/BundleChooser.h"
#include "rig/TrialBundle.h"
#include "sim/PlantCatalog.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QJsonObject>
#include <QSettings>
#include <QSlider>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QTreeWidget>
#include <algorithm>

using namespace prisca::app;
using namespace prisca::test;

class TestGuiRig : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_rig"); }
    void init() { resetGuiState(); }

    void rig_virtualCameraTracksTheCarAndTheLinkConnects() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        w.find<QComboBox>("cameraSource")->setCurrentIndex(0);  // the virtual rig
        rig->startCamera();
        QTRY_VERIFY_WITH_TIMEOUT(rig->framesSeen() > 20, 10000);
        QTRY_VERIFY(rig->lastPose().has_value());
        // The simulated car stands at its (perturbed) start: within a few cm of the origin.
        QVERIFY(std::hypot(rig->lastPose()->x, rig->lastPose()->y) < 0.1);
        QVERIFY(!rig->virtualPort().isEmpty());
        w.find<QComboBox>("linkPort")->setEditText(rig->virtualPort());
        rig->connectLink();
        QTRY_VERIFY_WITH_TIMEOUT(rig->linkStatus().connected && rig->linkStatus().framesSent > 5,
                                 5000);
        QCOMPARE(rig->linkStatus().failsafe, prisca::devices::FailsafeReason::NoCommand);
        QVERIFY(w.find<QLabel>("linkStatus")->text().contains("failsafe"));
        rig->stopCamera();
        rig->disconnectLink();
        QTRY_VERIFY(!rig->linkStatus().connected);
    }

    // The Rig tab's "This computer" page: checked when first shown, on its own thread, with
    // prisca-cli doctor's lines; the port the window is set to is among them; checked again
    // on the button; the summary is logged.
    void rig_thisComputerPageShowsTheDoctorsLines() {
        QSettings().setValue("rig/port", QStringLiteral("/dev/prisca-test-no-such-port"));
        Window w;
        auto* page = w.find<RigDoctorPage>("rigDoctorPage");
        QVERIFY(!page->report().has_value());
        auto* tabs = w.find<QTabWidget>("rigTabs");
        w.find<QDockWidget>("rigDock")->raise();
        tabs->setCurrentIndex(3);
        QTRY_VERIFY_WITH_TIMEOUT(page->report().has_value() && !page->checking(), 10000);
        auto* lines = w.find<QTreeWidget>("computerReport");
        QCOMPARE(lines->topLevelItemCount(), static_cast<int>(page->report()->items.size()));
        bool named = false;
        for (int i = 0; i < lines->topLevelItemCount(); ++i) {
            const QTreeWidgetItem* line = lines->topLevelItem(i);
            named = named || (line->text(1).contains("/dev/prisca-test-no-such-port") &&
                              line->text(0) == "Fix" && line->text(2).contains("not there"));
        }
        QVERIFY(named);
        QVERIFY(!page->report()->ready());  // the port it is set to is not there
        QVERIFY(w.find<QLabel>("computerSummary")->text().contains("to fix"));
        QSignalSpy again(page, &RigDoctorPage::checked);
        QTest::mouseClick(w.find<QPushButton>("checkComputer"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(again.count(), 1, 10000);
        QVERIFY(w.find<QPushButton>("checkComputer")->isEnabled());
    }

    void rig_priscaParksTheVirtualCarThroughTheLinkAndEstopLatchesFailsafe() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        // Not before camera and link are up: said plainly.
        QVERIFY(!rig->runTrial());
        QVERIFY(w.find<QLabel>("rigTrialInfo")->text().contains("camera"));
        QVERIFY(startVirtualRig(w, rig));
        // Connected: Connect and Start camera are spent, their opposites ready.
        QTRY_VERIFY(!w.find<QAbstractButton>("connectLink")->isEnabled());
        QVERIFY(w.find<QAbstractButton>("disconnectLink")->isEnabled());
        QVERIFY(!w.find<QAbstractButton>("startCamera")->isEnabled());
        QVERIFY(w.find<QAbstractButton>("stopCamera")->isEnabled());
        // A car trial while the target is the aircraft: refused, and said why.
        w.window.session().setPlant(QStringLiteral("aircraft"));
        QVERIFY(!rig->runTrial());
        QVERIFY2(w.find<QLabel>("rigTrialInfo")->text().contains(QLatin1String("slide-car")),
                 qPrintable(w.find<QLabel>("rigTrialInfo")->text()));
        w.window.session().setPlant(QStringLiteral("slidecar"));
        QSignalSpy finished(rig, &RigPanel::trialFinished);
        QVERIFY(rig->runTrial());
        QVERIFY(finished.wait(20000));
        const QString result = finished.last().at(0).toString();
        const QRegularExpression cm(QStringLiteral("parked ([0-9.]+) cm"));
        const QRegularExpressionMatch m = cm.match(result);
        QVERIFY2(m.hasMatch(), qPrintable(result));
        qInfo("virtual rig from the window: %s", qPrintable(result));
        QVERIFY2(m.captured(1).toDouble() < 50.0, qPrintable(result));
        // A second trial, stopped by E-STOP (Space): failsafe latched on the link.
        QVERIFY(rig->runTrial());
        const long long framesAtStart = rig->framesSeen();
        QTRY_VERIFY_WITH_TIMEOUT(rig->framesSeen() >= framesAtStart + 10, 30000);  // under way
        QVERIFY(rig->isRunning());
        QTest::keyClick(&w.window, Qt::Key_Space);
        QTRY_VERIFY(!rig->isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(rig->linkStatus().failsafe,
                                  prisca::devices::FailsafeReason::EmergencyStop, 3000);
        QVERIFY(rig->linkStatus().emergencyLatched);
        w.find<QAbstractButton>("resetEmergencyButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(!rig->linkStatus().emergencyLatched, 3000);
        rig->stopCamera();
        rig->disconnectLink();
    }

    void rig_fenceEndsTheTrialAndItsBundleReplays() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        QVERIFY(w.find<QCheckBox>("saveBundles")->isChecked());  // on by default
        // A fence across the demonstration's path, 3 m ahead: the car leaves it.
        for (const QPointF& corner :
             {QPointF(-0.8, -1.6), QPointF(3.0, -1.6), QPointF(3.0, 2.0), QPointF(-0.8, 2.0)}) {
            rig->addFenceCorner(corner);
        }
        QCOMPARE(rig->geofence().polygon.size(), size_t(4));
        QVERIFY(w.find<QLabel>("fenceInfo")->text().contains("4 corners"));
        {  // remembered: the next window has it
            Window next;
            QCOMPARE(next.find<RigPanel>("rigPanel")->geofence().polygon.size(), size_t(4));
        }
        QVERIFY(startVirtualRig(w, rig));
        // The pre-trial check: the demonstration's lot lies outside this fence, so no trial.
        QVERIFY(!rig->runTrial());
        auto* ready = w.find<QLabel>("rigReadiness");
        QVERIFY2(ready->text().contains(QLatin1String("Not ready")) &&
                     ready->text().contains(QLatin1String("Fence")),
                 qPrintable(ready->text()));
        QVERIFY2(
            w.find<QLabel>("rigTrialInfo")->text().contains(QLatin1String("outside the fence")),
            qPrintable(w.find<QLabel>("rigTrialInfo")->text()));
        QVERIFY(!rig->isRunning());
        // A fence around the whole path, with a speed limit the demonstration's slide exceeds:
        // the trial starts, and the limit ends it in failsafe.
        rig->clearFence();
        for (const QPointF& corner :
             {QPointF(-0.8, -1.6), QPointF(5.5, -1.6), QPointF(5.5, 2.0), QPointF(-0.8, 2.0)}) {
            rig->addFenceCorner(corner);
        }
        w.find<QDoubleSpinBox>("fenceMaxSpeed")->setValue(2.5);
        QTRY_VERIFY2(ready->text().startsWith(QLatin1String("Ready")), qPrintable(ready->text()));
        QSignalSpy finished(rig, &RigPanel::trialFinished);
        QVERIFY(rig->runTrial());
        QVERIFY(finished.wait(20000));
        const QString result = finished.last().at(0).toString();
        QVERIFY2(result.contains("over the fence's"), qPrintable(result));
        QTRY_VERIFY_WITH_TIMEOUT(!rig->lastBundle().isEmpty(), 10000);
        QVERIFY(w.find<QAbstractButton>("replayLastTrial")->isEnabled());
        // The replay window: its slider moves the frame, the arena and the chart's cursor.
        ReplayDialog* replay = w.window.openReplay(rig->lastBundle());
        QVERIFY(replay);
        QVERIFY(replay->sampleCount() > 20);
        auto* slider = replay->findChild<QSlider*>("replaySlider");
        QVERIFY(slider);
        QCOMPARE(slider->maximum(), replay->sampleCount() - 1);
        replay->showSample(replay->sampleCount() / 2);
        QCOMPARE(slider->value(), replay->sampleCount() / 2);
        QTest::keyClick(slider, Qt::Key_Right);
        QCOMPARE(replay->currentSample(), replay->sampleCount() / 2 + 1);
        // It fits its screen with every control in view, and never covers the red button.
        const QRect screen = replay->screen()->availableGeometry();
        QVERIFY2(screen.contains(replay->frameGeometry()),
                 qPrintable(QStringLiteral("%1x%2 at %3,%4 on a %5x%6 screen")
                                .arg(replay->frameGeometry().width())
                                .arg(replay->frameGeometry().height())
                                .arg(replay->x())
                                .arg(replay->y())
                                .arg(screen.width())
                                .arg(screen.height())));
        for (QWidget* control :
             {static_cast<QWidget*>(slider), replay->findChild<QWidget*>("replayPlay")}) {
            QVERIFY(control->isVisible());
            QVERIFY(replay->rect().contains(
                QRect(control->mapTo(replay, QPoint(0, 0)), control->size())));
        }
        auto* red = w.find<QWidget>("emergencyStopButton");
        QVERIFY(!replay->frameGeometry().intersects(
            QRect(red->mapToGlobal(QPoint(0, 0)), red->size())));
        replay->close();
        // File > Replay lists the bundles newest first, the rig's apart from the simulated.
        const std::vector<BundleEntry> listed = BundleChooser::scan({rig->bundleParent()});
        QVERIFY(!listed.empty());
        QVERIFY(listed.front().rig);
        QCOMPARE(QFileInfo(listed.front().folder).absoluteFilePath(),
                 QFileInfo(rig->lastBundle()).absoluteFilePath());
        QVERIFY2(listed.front().outcome.contains(QLatin1String("failsafe")),
                 qPrintable(listed.front().outcome));
        // A folder that is no bundle: refused (a message box the test closes), no window.
        QTimer::singleShot(200, [] {
            if (QWidget* box = prisca::app::ModalDialog::top()) {
                box->close();
            }
        });
        QVERIFY(!w.window.openReplay(QStringLiteral("/nonexistent")));
        rig->clearFence();
        QVERIFY(rig->geofence().polygon.empty());
    }

    void replay_hostileBundlesAreRefusedOrDrawnInBoundedTime() {
        // Bundles the replay reader refuses (an unknown plant, a pose 1e9 m out) give a message
        // and no window; one far out but on the floor (9 km) opens and paints, its grid bounded.
        QTemporaryDir dir;
        const auto write = [&](const QString& name, const QString& plant, double x) {
            const QString folder = dir.filePath(name);
            prisca::rig::TrialBundleWriter writer;
            QString error;
            if (!writer.open(folder, QJsonObject{{"kind", "rig"}, {"plant", plant}},
                             prisca::sim::PlantCatalog::demonstrate("slidecar", 1), &error)) {
                return QString();
            }
            for (int k = 0; k < 20; ++k) {
                prisca::rig::BundleSample s;
                s.t = 0.04 * k;
                s.found = true;
                s.x = x + 0.01 * k;
                s.y = 0.0;
                writer.append(s);
            }
            writer.finish(QJsonObject{{"failsafe", false}}, &error);
            return folder;
        };
        Window w;
        for (const QString& refused :
             {write("unknown", "hovercraft", 0.0), write("far", "slidecar", 1e9)}) {
            QVERIFY(!refused.isEmpty());
            QTimer::singleShot(200, [] {
                if (QWidget* box = prisca::app::ModalDialog::top()) {
                    box->close();
                }
            });
            QVERIFY(!w.window.openReplay(refused));
        }
        ReplayDialog* replay = w.window.openReplay(write("distant", "slidecar", 9000.0));
        QVERIFY(replay);
        auto* slider = replay->findChild<QSlider*>(QStringLiteral("replaySlider"));
        QVERIFY(slider);
        slider->setValue(slider->maximum());
        QVERIFY(!replay->grab().isNull());  // painted: the grid no longer loops for ever
        replay->close();
    }

    void bundleChooser_listsTheRigsTrialsApartNewestFirst() {
        QTemporaryDir dir;
        const auto write = [&](const QString& name, const char* kind, const QString& started,
                               const char* result) {
            QDir(dir.path()).mkpath(name);
            QFile f(QDir(dir.path()).filePath(name + QStringLiteral("/bundle.json")));
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QStringLiteral("{\"kind\": \"%1\", \"method\": \"prisca\", \"trial\": 1, "
                                   "\"started\": \"%2\"%3}")
                        .arg(QLatin1String(kind), started, QLatin1String(result))
                        .toUtf8());
        };
        // Thirty simulated trials named to sort before the rig's, and two rig trials.
        for (int i = 0; i < 30; ++i) {
            write(QStringLiteral("sim-%1").arg(i, 2, 10, QLatin1Char('0')), "simulation",
                  QStringLiteral("2026-12-03T10:%1:00").arg(i, 2, 10, QLatin1Char('0')),
                  ", \"result\": {\"finalPositionErrorCm\": 3.5}");
        }
        write(QStringLiteral("trial-old"), "rig", QStringLiteral("2026-12-03T09:00:00"),
              ", \"result\": {\"failsafe\": true, \"reason\": \"the car left the fence\"}");
        write(QStringLiteral("trial-new"), "rig", QStringLiteral("2026-12-03T11:00:00"), "");
        QDir(dir.path()).mkpath(QStringLiteral("not-a-bundle"));
        BundleChooser chooser({dir.path()});
        auto* list = chooser.findChild<QTreeWidget*>(QStringLiteral("bundleList"));
        QVERIFY(list);
        QCOMPARE(list->topLevelItemCount(), 2);
        QTreeWidgetItem* rigGroup = list->topLevelItem(0);
        QVERIFY(rigGroup->text(0).contains(QLatin1String("(2)")));
        QCOMPARE(list->topLevelItem(1)->childCount(), 30);
        // Newest first, and what became of each.
        QCOMPARE(rigGroup->child(0)->text(0), QStringLiteral("2026-12-03 11:00:00"));
        QCOMPARE(rigGroup->child(0)->text(3), QStringLiteral("incomplete"));
        QVERIFY(rigGroup->child(1)->text(3).contains(QLatin1String("left the fence")));
        QCOMPARE(list->topLevelItem(1)->child(0)->text(0), QStringLiteral("2026-12-03 10:29:00"));
        QVERIFY(list->topLevelItem(1)->child(0)->text(3).contains(QLatin1String("3.5 cm")));
        // The newest rig trial is the one offered.
        QCOMPARE(list->currentItem(), rigGroup->child(0));
    }

    void rig_drivingThroughTheLinkRecordsADemonstration() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        QVERIFY(startVirtualRig(w, rig));
        const auto before = w.window.session().demonstration();
        QVERIFY(rig->startDriving());
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(rig->drivingInput()[0] > 0.99);
        // Full throttle for 0.7 s of the take's own (frame) time, then 0.3 s coasting. Counted
        // from now: on a slow machine the take may already be longer than that while the input
        // ramps up, and the throttle would never reach a recorded frame.
        const double throttleFrom = std::max(0.0, rig->recordedSeconds());
        QTRY_VERIFY_WITH_TIMEOUT(rig->recordedSeconds() >= throttleFrom + 0.7, 30000);
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QTRY_VERIFY_WITH_TIMEOUT(rig->recordedSeconds() >= throttleFrom + 1.0, 30000);
        rig->stopDriving();
        // The take is resampled and written on the rig's worker thread, then handed over.
        QTRY_VERIFY_WITH_TIMEOUT(w.window.session().demonstration() != before, 10000);
        const auto demo = w.window.session().demonstration();
        QVERIFY2(demo->length() >= 30, qPrintable(QString::number(demo->length())));
        QVERIFY(demo->actions.col(0).maxCoeff() > 0.99);
        // The car, driven through the link, moved forward; the camera saw it do so.
        const double moved = demo->states(demo->length() - 1, 0) - demo->states(0, 0);
        QVERIFY2(moved > 0.3, qPrintable(QString::number(moved)));
        QVERIFY(demo->states.col(3).maxCoeff() > 0.5);  // and measured its speed
        // The stream on disk reads back as the same demonstration.
        prisca::core::FileError error;
        const auto onDisk =
            prisca::core::readDemonstrationCsv(w.window.session().demonstrationSource(), &error);
        QVERIFY2(onDisk, qPrintable(error.toString()));
        QCOMPARE(onDisk->length(), demo->length());
        rig->stopCamera();
        rig->disconnectLink();
    }

    void rig_closingTheWindowWhileDrivingKeepsTheRecordingOnDisk() {
        QString stream;
        {
            Window w;
            auto* rig = w.find<RigPanel>("rigPanel");
            QVERIFY(startVirtualRig(w, rig));
            QVERIFY(rig->startDriving());
            QTRY_VERIFY_WITH_TIMEOUT(rig->recordedSeconds() >= 0.4, 30000);
            QVERIFY(rig->isDriving());
            // Closing asks first; "discard" quits at once, the recording still running.
            bool closed = false;
            const QString asked =
                answerQuitQuestion(&w.window, "quitDiscard", [&] { closed = w.window.close(); });
            QVERIFY2(asked.contains(QStringLiteral("recording")), qPrintable(asked));
            QVERIFY(closed);
        }  // the window, its session and the panel go while the recording runs: no crash
        const QDir folder(RecordPanel::recordingsFolder());
        const QStringList files =
            folder.entryList({QStringLiteral("rig-*.csv")}, QDir::Files, QDir::Time);
        QVERIFY(!files.isEmpty());
        prisca::core::FileError error;
        const auto kept =
            prisca::core::readDemonstrationCsv(folder.filePath(files.first()), &error);
        QVERIFY2(kept, qPrintable(error.toString()));
        QVERIFY(kept->length() > 5);
    }

    void rig_channelMapIsCheckedAppliedAndRemembered() {
        {
            Window w;
            auto* rig = w.find<RigPanel>("rigPanel");
            auto* table = w.find<QTableWidget>("channelMap");
            auto* problem = w.find<QLabel>("channelProblem");
            QCOMPARE(table->item(0, 0)->text(), QStringLiteral("3"));  // throttle on CH3
            QCOMPARE(table->item(1, 0)->text(), QStringLiteral("1"));  // steering on CH1
            table->item(1, 0)->setText(QStringLiteral("3"));
            QVERIFY2(problem->text().contains("twice"), qPrintable(problem->text()));
            QCOMPARE(rig->channels().controls[1].channel, 0);  // refused, unchanged
            table->item(1, 0)->setText(QStringLiteral("2"));
            table->item(1, 1)->setText(QStringLiteral("20"));
            table->item(1, 4)->setCheckState(Qt::Checked);
            QVERIFY(problem->text().isEmpty());
            QCOMPARE(rig->channels().controls[1].channel, 1);
            QCOMPARE(rig->channels().controls[1].trim, 20.0);
            QVERIFY(rig->channels().controls[1].reversed);
            // Failsafe centres steering with its trim: 1520 us on CH2.
            QCOMPARE(rig->channels().failsafe()[1], 1520.0);
        }
        Window again;
        auto* rig = again.find<RigPanel>("rigPanel");
        QCOMPARE(rig->channels().controls[1].channel, 1);
        QCOMPARE(rig->channels().controls[1].trim, 20.0);
        QVERIFY(rig->channels().controls[1].reversed);
    }

    void rig_calibrationByClicksSavedAndBadFilesRefused() {
        QTemporaryDir dir;
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        const prisca::devices::FloorCalibration truth = prisca::devices::syntheticCeilingCamera();
        // Four clicks on points whose floor position the operator knows.
        for (const auto& floor :
             {QPointF(0.0, 0.0), QPointF(3.0, 0.0), QPointF(3.0, 1.5), QPointF(0.0, 1.5)}) {
            const cv::Point2d image = truth.toImage({floor.x(), floor.y()});
            rig->addCalibrationPoint(QPointF(image.x, image.y), floor);
        }
        QCOMPARE(rig->calibration().points.size(), size_t(4));
        QVERIFY(rig->calibration().rmsMetres < 1e-6);
        QVERIFY(w.find<QLabel>("calibrationInfo")->text().contains("4 points"));
        QVERIFY(rig->saveCalibration(dir.filePath("cal.json")));
        QFile bad(dir.filePath("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"homography\": \"no\"}");
        bad.close();
        const QString text = answerMessageBox(
            this, [&] { QVERIFY(!rig->loadCalibration(dir.filePath("bad.json"))); });
        QVERIFY2(text.contains("bad.json") && text.contains("homography"), qPrintable(text));
        QCOMPARE(rig->calibration().points.size(), size_t(4));  // unchanged
        QVERIFY(rig->loadCalibration(dir.filePath("cal.json")));
    }
};

QTEST_MAIN(TestGuiRig)
#include "test_gui_rig.moc"
