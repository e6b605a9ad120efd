// The window as a whole, driven offscreen: the status bar, the message log, quitting with work
// under way, E-STOP's latch and explanation, the layout at 1280 x 800 (Help and the languages:
// test_gui_language).

#include "GuiWindowTestSupport.h"

namespace {
Q_LOGGING_CATEGORY(lcTestWorker, "prisca.testworker")
}  // namespace

class TestGuiWindow : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_window"); }
    void init() { resetGuiState(); }

    void window_opensInsideTheScreensAvailableArea() {
        LanguageSwitcher languages;
        MainWindow window(languages);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const QRect available = window.screen()->availableGeometry();
        const QString sizes = QStringLiteral("%1x%2+%3+%4 in %5x%6")
                                  .arg(window.width())
                                  .arg(window.height())
                                  .arg(window.x())
                                  .arg(window.y())
                                  .arg(available.width())
                                  .arg(available.height());
        QVERIFY2(available.contains(window.geometry().topLeft()), qPrintable(sizes));
        QVERIFY2(window.geometry().bottom() <= available.bottom(), qPrintable(sizes));
        // As wide as the screen allows (the offscreen screen may be narrower than the panels
        // can be; then as narrow as they allow).
        QVERIFY2(window.width() <= std::max(available.width(), window.minimumSizeHint().width()),
                 qPrintable(sizes));
        // Room left for a title bar: the status bar is on screen under a window manager too.
        QVERIFY(window.height() <= available.height() - 40);
    }

    void statusBar_showsJobLinkCameraAndEmergencyAt1280x800() {
        Window w;
        auto* job = w.find<QLabel>("jobStatus");
        auto* link = w.find<QLabel>("linkStatusField");
        auto* camera = w.find<QLabel>("cameraStatusField");
        auto* emergency = w.find<QLabel>("emergencyStatus");
        QVERIFY(job && link && camera && emergency);
        for (QLabel* field : {job, link, camera, emergency}) {
            QVERIFY2(wholeInView(field), qPrintable(field->objectName()));
        }
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));
        QCOMPARE(camera->text(), QStringLiteral("Camera: off"));
        QCOMPARE(link->text(), QStringLiteral("Link: off"));
        QCOMPARE(emergency->text(), QStringLiteral("E-STOP ready"));

        // A run: the job says so, and so do E-STOP's field and button once it is pressed.
        w.setSpeedIndex(0);
        w.find<QSpinBox>("trials")->setValue(3);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(job->text(), QStringLiteral("Job: simulated run"), kRunTimeoutMs);
        w.find<RunPanel>("runPanel")->emergencyAction()->trigger();
        QTRY_COMPARE(emergency->text(), QStringLiteral("E-STOP LATCHED"));
        auto* button = w.find<QPushButton>("emergencyStopButton");
        QCOMPARE(button->text(), QStringLiteral("E-STOP LATCHED"));
        QVERIFY(button->styleSheet().contains(QLatin1String("inset")));  // looks pressed in
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));
        w.find<RunPanel>("runPanel")->resetEmergencyAction()->trigger();
        QTRY_COMPARE(emergency->text(), QStringLiteral("E-STOP ready"));
        QVERIFY(!button->styleSheet().contains(QLatin1String("inset")));

        // The virtual rig: link and camera fields follow it; a stopped camera leaves no image.
        auto* rig = w.find<RigPanel>("rigPanel");
        QVERIFY(startVirtualRig(w, rig));
        QTRY_VERIFY_WITH_TIMEOUT(camera->text().contains(QLatin1String("tracking")), 10000);
        QVERIFY2(camera->text().contains(QLatin1String("fps")), qPrintable(camera->text()));
        QTRY_VERIFY_WITH_TIMEOUT(link->text().startsWith(QLatin1String("Link: CRSF")), 10000);
        auto* view = w.find<CameraView>("cameraView");
        QVERIFY(view->hasFrame());
        rig->stopCamera();
        QTRY_COMPARE(camera->text(), QStringLiteral("Camera: off"));
        QTRY_VERIFY(!view->hasFrame());
        QCOMPARE(w.find<QLabel>("cameraInfo")->text(), QStringLiteral("Camera stopped."));
        rig->disconnectLink();
        QTRY_COMPARE(link->text(), QStringLiteral("Link: off"));
    }

    void cameraFailure_isTheCamerasNotTheLinks() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        w.find<QComboBox>("cameraSource")->setCurrentIndex(1);  // a V4L2 device
        w.find<QLineEdit>("cameraPath")->setText(QStringLiteral("/dev/no-such-camera"));
        answerMessageBox(&w.window, [&] { rig->startCamera(); });  // refused at once, or later
        QTRY_COMPARE_WITH_TIMEOUT(w.find<QLabel>("cameraStatusField")->text(),
                                  QStringLiteral("Camera: failed"), 15000);
        QVERIFY(!w.find<QLabel>("cameraInfo")->text().isEmpty());
        QVERIFY(!w.find<QLabel>("linkStatus")->text().contains(QLatin1String("no-such-camera")));
    }

    void aVideoPlayedToItsEnd_isNoCameraFailure() {
        QTemporaryDir dir;
        const QString video = dir.filePath(QStringLiteral("short.avi"));
        {
            cv::VideoWriter writer(video.toStdString(), cv::CAP_OPENCV_MJPEG,
                                   cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                                   cv::Size(320, 240), true);
            QVERIFY(writer.isOpened());
            for (int k = 0; k < 20; ++k) {
                writer.write(cv::Mat(240, 320, CV_8UC3, cv::Scalar(20, 20, 20)));
            }
        }
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        w.find<QComboBox>("cameraSource")->setCurrentIndex(2);
        w.find<QLineEdit>("cameraPath")->setText(video);
        rig->startCamera();
        auto* camera = w.find<QLabel>("cameraStatusField");
        QTRY_COMPARE_WITH_TIMEOUT(camera->text(), QStringLiteral("Camera: video ended"), 15000);
        QVERIFY2(camera->styleSheet().isEmpty(), qPrintable(camera->styleSheet()));  // no alarm
        QVERIFY2(w.find<QLabel>("cameraInfo")->text().contains(QLatin1String("video ended")),
                 qPrintable(w.find<QLabel>("cameraInfo")->text()));
    }

    void tab_leavesTheResultsTables() {
        Window w;
        QTableWidget* results = w.results();
        results->setRowCount(2);
        results->setFocus();
        QTRY_VERIFY(results->hasFocus());
        QTest::keyClick(results, Qt::Key_Tab);
        QVERIFY(!results->hasFocus());
    }

    void realCamera_withTheVirtualRigsCalibrationIsWarnedAndRefused() {
        QTemporaryDir dir;
        const QString video = dir.filePath(QStringLiteral("floor.avi"));
        {
            cv::VideoWriter writer(video.toStdString(), cv::CAP_OPENCV_MJPEG,
                                   cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                                   cv::Size(640, 480), true);
            QVERIFY(writer.isOpened());
            for (int k = 0; k < 400; ++k) {
                writer.write(cv::Mat(480, 640, CV_8UC3, cv::Scalar(20, 20, 20)));
            }
        }
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        w.find<QComboBox>("cameraSource")->setCurrentIndex(2);  // a video file: a real camera
        w.find<QLineEdit>("cameraPath")->setText(video);
        rig->startCamera();
        auto* calibration = w.find<QLabel>("calibrationInfo");
        QTRY_VERIFY(calibration->text().contains(QLatin1String("virtual rig's")));
        QVERIFY(!rig->startDriving());
        QVERIFY(w.find<QLabel>("rigTrialInfo")->text().contains(QLatin1String("virtual rig's")));
        // This camera's own calibration: no warning, driving is no longer refused for it.
        const std::vector<prisca::devices::CalibrationPoint> points = {{{100, 100}, {0.0, 2.0}},
                                                                       {{540, 100}, {3.0, 2.0}},
                                                                       {{540, 380}, {3.0, 0.0}},
                                                                       {{100, 380}, {0.0, 0.0}},
                                                                       {{320, 240}, {1.5, 1.0}}};
        QString error;
        const auto own = prisca::devices::FloorCalibration::fit(points, &error);
        QVERIFY2(own, qPrintable(error));
        QVERIFY(own->save(dir.filePath(QStringLiteral("own.json")), &error));
        QVERIFY(rig->loadCalibration(dir.filePath(QStringLiteral("own.json"))));
        QVERIFY(!calibration->text().contains(QLatin1String("virtual rig's")));
        rig->stopCamera();
    }

    void panels_sayWhatTheirNumbersAreAndWhatToDo() {
        Window w;
        // The fit's table: each state with its unit in its header, numbers not elided.
        auto* fit = w.find<QTableWidget>("fitResult");
        QVERIFY(fit->horizontalHeaderItem(0)->text().contains(QLatin1String("[m]")));
        QCOMPARE(fit->horizontalHeader()->sectionResizeMode(0), QHeaderView::ResizeToContents);
        // Calibrate says what to do on the panel, not only in a tooltip.
        auto* calibrate = w.find<QPushButton>("calibrate");
        QVERIFY(calibrate);
        calibrate->click();
        QVERIFY(
            w.find<QLabel>("calibrationInfo")->text().startsWith(QLatin1String("Calibrating:")));
        calibrate->click();
    }

    void fitWarning_followsALanguageSwitch() {
        Window w;
        // A demonstration whose steering never changes: the fit warns about it.
        auto demo =
            std::make_shared<prisca::core::Demonstration>(*w.window.session().demonstration());
        demo->actions.col(1).setConstant(0.0);
        w.window.session().setDemonstration(demo, QStringLiteral("held-steering.csv"));
        auto* warnings = w.find<QLabel>("fitWarnings");
        const auto shown = [&] { return warnings->text(); };
        QVERIFY2(shown().contains(QLatin1String("never changed")), qPrintable(shown()));
        // ... and the message log has it, once.
        const auto logged = [&] {
            return std::count_if(w.window.messageLog().entries().begin(),
                                 w.window.messageLog().entries().end(), [](const LogEntry& e) {
                                     return e.source == QLatin1String("Mapping") &&
                                            e.level == MessageLevel::Warning;
                                 });
        };
        QTRY_COMPARE(logged(), 1);
        QVERIFY(w.languages.setLanguage(QStringLiteral("zh_HK")));
        QTRY_VERIFY2(!shown().contains(QLatin1String("never changed")) &&
                         shown().contains(QStringLiteral("從未改變")),
                     qPrintable(shown()));
        QVERIFY(w.languages.setLanguage(QStringLiteral("en")));
        QTRY_VERIFY2(shown().contains(QLatin1String("never changed")), qPrintable(shown()));
        QCOMPARE(logged(), 1);  // a language switch is no new warning
    }

    void messageLog_collectsPanelsAndWorkersAndIsSavedWithTheSession() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("with-log.json"));
        {
            Window w;
            MessageLog& log = w.window.messageLog();
            w.setSpeedIndex(2);
            w.find<QSpinBox>("trials")->setValue(1);
            w.find<RunPanel>("runPanel")->startRun();
            QTRY_VERIFY_WITH_TIMEOUT(
                std::any_of(
                    log.entries().begin(), log.entries().end(),
                    [](const LogEntry& e) { return e.text.startsWith(QLatin1String("Trial 1:")); }),
                kRunTimeoutMs);
            const auto has = [&](const QString& source, const QString& start, MessageLevel level) {
                return std::any_of(log.entries().begin(), log.entries().end(),
                                   [&](const LogEntry& e) {
                                       return e.source == source && e.text.startsWith(start) &&
                                              e.level == level && e.time.isValid();
                                   });
            };
            QVERIFY(has(QStringLiteral("Run"), QStringLiteral("Run started:"), MessageLevel::Info));
            QVERIFY(
                has(QStringLiteral("Run"), QStringLiteral("Trial 1: parked"), MessageLevel::Info));
            // A worker's warning, from its own thread, under a prisca.* category.
            std::unique_ptr<QThread> worker(
                QThread::create([] { qCWarning(lcTestWorker, "the worker's own warning"); }));
            worker->start();
            QVERIFY(worker->wait(10000));
            QTRY_VERIFY(has(QStringLiteral("testworker"),
                            QStringLiteral("the worker's own warning"), MessageLevel::Warning));
            // Copy: time, level, source and text, tab-separated, on the clipboard.
            dockOf(w, "logDock")->raise();
            auto* panel = w.find<MessageLogPanel>("messageLogPanel");
            w.find<QPushButton>("copyMessages")->click();
            const QString copied = QApplication::clipboard()->text();
            QVERIFY2(
                copied.contains(QLatin1String("\twarning\ttestworker\tthe worker's own warning")),
                qPrintable(copied));
            QCOMPARE(copied, panel->selectedOrAllText());
            // The filter shows warnings and errors only.
            w.find<QComboBox>("messageFilter")->setCurrentIndex(1);
            QCOMPARE(panel->table()->rowCount(), 1);
            QVERIFY(w.window.saveSession(path));
        }
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject saved = QJsonDocument::fromJson(file.readAll()).object();
        const QJsonArray lines = saved.value(QStringLiteral("messages")).toArray();
        QVERIFY(!lines.isEmpty());
        QVERIFY(std::any_of(lines.begin(), lines.end(), [](const QJsonValue& v) {
            return v.toObject().value(QStringLiteral("text")).toString() ==
                   QLatin1String("the worker's own warning");
        }));
        // Opened again (in a fresh window), the lines are back in the log.
        QSettings().clear();
        Window again;
        QVERIFY(again.window.openSession(path));
        const auto& entries = again.window.messageLog().entries();
        QVERIFY(std::any_of(entries.begin(), entries.end(), [](const LogEntry& e) {
            return e.text == QLatin1String("the worker's own warning") &&
                   e.level == MessageLevel::Warning;
        }));
    }

    // No global log: a label's status goes to the log of the window it sits in, found up the
    // object tree; a label in no window logs nowhere; the workers' categories go to the log
    // that took them, and nowhere once it is gone.
    void messageLog_isTheWindowsOwnFoundUpTheTree() {
        QWidget first;
        QWidget second;
        auto* firstLog = new MessageLog(&first);
        auto* secondLog = new MessageLog(&second);
        auto* inner = new QWidget(&first);
        auto* firstLabel = new QLabel(inner);
        auto* secondLabel = new QLabel(&second);
        QLabel orphan;
        QCOMPARE(MessageLog::of(firstLabel), firstLog);
        QCOMPARE(MessageLog::of(secondLabel), secondLog);
        QCOMPARE(MessageLog::of(&orphan), nullptr);
        showStatus(firstLabel, QStringLiteral("First"), QStringLiteral("to the first"));
        showStatus(secondLabel, QStringLiteral("Second"), QStringLiteral("to the second"));
        showStatus(&orphan, QStringLiteral("Orphan"), QStringLiteral("to no log"));
        QCOMPARE(orphan.text(), QStringLiteral("to no log"));  // shown all the same
        QCOMPARE(firstLog->entries().size(), 1);
        QCOMPARE(firstLog->entries().front().text, QStringLiteral("to the first"));
        QCOMPARE(secondLog->entries().size(), 1);
        QCOMPARE(secondLog->entries().front().source, QStringLiteral("Second"));

        secondLog->captureQtMessages();
        const auto fromWorker = [](const char* text) {
            std::unique_ptr<QThread> worker(
                QThread::create([text] { qCWarning(lcTestWorker, "%s", text); }));
            worker->start();
            return worker->wait(10000);
        };
        QVERIFY(fromWorker("to the capturing log"));
        QTRY_COMPARE(secondLog->entries().size(), 2);
        QCOMPARE(secondLog->entries().back().text, QStringLiteral("to the capturing log"));
        QCOMPARE(firstLog->entries().size(), 1);
        delete secondLog;
        QVERIFY(fromWorker("after the log is gone"));  // dropped, not posted to a dead log
        QCoreApplication::processEvents();
        QCOMPARE(firstLog->entries().size(), 1);
    }

    void messageLog_survivesARestart() {
        {
            Window w;
            logMessage(&w.window, QStringLiteral("Test"), MessageLevel::Error,
                       QStringLiteral("before the restart"));
            QTRY_VERIFY(!w.window.messageLog().entries().isEmpty());
            QVERIFY(w.window.close());  // nothing under way: no question
        }
        Window w;
        const auto& entries = w.window.messageLog().entries();
        QVERIFY(std::any_of(entries.begin(), entries.end(), [](const LogEntry& e) {
            return e.text == QLatin1String("before the restart") && e.level == MessageLevel::Error;
        }));
    }

    void quit_withNothingUnderWayClosesWithoutAsking() {
        Window w;
        bool closed = false;
        const QString asked =
            answerQuitQuestion(&w.window, "quitCancel", [&] { closed = w.window.close(); });
        QVERIFY(asked.isEmpty());
        QVERIFY(closed);
    }

    void quit_duringARunAsks_cancelKeepsItAndKeepSavesWhatIsDone() {
        Window w;
        w.setSpeedIndex(0);  // real time: the run is still going when the question comes
        w.find<QSpinBox>("trials")->setValue(20);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_VERIFY_WITH_TIMEOUT(w.results()->rowCount() >= 1, kRunTimeoutMs);
        // Cancel: the window stays and the run goes on.
        bool closed = true;
        QString asked =
            answerQuitQuestion(&w.window, "quitCancel", [&] { closed = w.window.close(); });
        QVERIFY2(asked.contains(QLatin1String("a simulated run")), qPrintable(asked));
        QVERIFY(!closed);
        QVERIFY(w.window.isVisible());
        QCOMPARE(w.window.run().phase(), RunPhase::Running);
        // Keep: the run stops, its finished trials are saved, then the window closes.
        QDir(MainWindow::keptFolder()).removeRecursively();
        asked = answerQuitQuestion(&w.window, "quitKeep", [&] { w.window.close(); });
        QVERIFY(!asked.isEmpty());
        QTRY_VERIFY_WITH_TIMEOUT(!w.window.isVisible(), kRunTimeoutMs);
        const QStringList kept =
            QDir(MainWindow::keptFolder()).entryList({QStringLiteral("run-*.csv")}, QDir::Files);
        QCOMPARE(kept.size(), 1);
        QFile log(QDir(MainWindow::keptFolder()).filePath(kept.first()));
        QVERIFY(log.open(QIODevice::ReadOnly));
        const QByteArray text = log.readAll();
        QVERIFY(text.startsWith("# prisca-run-log"));
        QVERIFY(text.contains("\n0,"));  // the first trial's rows
    }

    void quit_finishWaitsForTheExperimentThenSavesItsTable() {
        Window w;
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(2);
        QDir(MainWindow::keptFolder()).removeRecursively();
        auto* experiments = w.find<ExperimentsPanel>("experimentsPanel");
        experiments->start();
        QVERIFY(experiments->isRunning());
        const QString asked =
            answerQuitQuestion(&w.window, "quitFinish", [&] { w.window.close(); });
        QVERIFY2(asked.contains(QLatin1String("an experiment")), qPrintable(asked));
        QVERIFY(w.window.isVisible());  // still there while the experiment runs
        QTRY_VERIFY_WITH_TIMEOUT(!w.window.isVisible(), 240000);
        const QStringList kept = QDir(MainWindow::keptFolder())
                                     .entryList({QStringLiteral("experiment-*.md")}, QDir::Files);
        QCOMPARE(kept.size(), 1);
        QFile table(QDir(MainWindow::keptFolder()).filePath(kept.first()));
        QVERIFY(table.open(QIODevice::ReadOnly));
        QVERIFY(table.readAll().contains("PRISCA"));
    }

    void emergencyStop_explanationStaysThroughCtrlRAndResetUntilTheNextRun() {
        Window w;
        auto* panel = w.find<RunPanel>("runPanel");
        auto* status = w.find<QLabel>("runStatus");
        QVERIFY(status);
        panel->emergencyAction()->trigger();
        QTRY_VERIFY(status->text().contains(QLatin1String("E-STOP pressed at")));
        const QString explanation = status->text();
        // Ctrl+R (Reset) does not wipe it while E-STOP stays latched.
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTest::keyClick(&w.window, Qt::Key_R, Qt::ControlModifier);
        QCOMPARE(status->text(), explanation);
        QCOMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        // Reset E-STOP: what happened, and when, stays readable.
        panel->resetEmergencyAction()->trigger();
        QTRY_VERIFY(status->text().contains(QLatin1String("E-STOP was pressed at")));
        QVERIFY(status->text().contains(
            explanation.mid(explanation.indexOf(QLatin1String("at ")) + 3, 8)));
        // Running again clears it.
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(1);
        panel->startRun();
        QTRY_VERIFY(!status->text().contains(QLatin1String("E-STOP")));
    }
};

QTEST_MAIN(TestGuiWindow)
#include "test_gui_window.moc"
