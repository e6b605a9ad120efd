// The window as a whole, driven offscreen: the status bar, the message log, quitting with work
// under way, E-STOP's latch and explanation, Help, the layout at 1280 x 800, one language at a
// time.
#include "GuiTestSupport.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include "app/CameraView.h"
#include "app/ExperimentArchive.h"
#include "app/MessageLog.h"
#include "app/MessageLogPanel.h"

#include <QClipboard>
#include <QDialog>
#include <QGroupBox>
#include <QHeaderView>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QTextBrowser>
#include <QThread>

#include <opencv2/videoio.hpp>

using namespace prisca::app;
using namespace prisca::test;

namespace {

Q_LOGGING_CATEGORY(lcTestWorker, "prisca.testworker")

// True when all of `widget` is inside the window and inside every scrolled view around it: an
// operator sees it without scrolling.
bool wholeInView(QWidget* widget) {
    QWidget* window = widget->window();
    const QRect rect(widget->mapTo(window, QPoint(0, 0)), widget->size());
    if (!widget->isVisible() || !window->rect().contains(rect)) {
        return false;
    }
    for (QWidget* p = widget->parentWidget(); p && p != window; p = p->parentWidget()) {
        if (auto* area = qobject_cast<QAbstractScrollArea*>(p)) {
            QWidget* port = area->viewport();
            const QRect seen(port->mapTo(window, QPoint(0, 0)), port->size());
            if (!seen.contains(rect)) {
                return false;
            }
        }
    }
    return true;
}

QDockWidget* dockOf(Window& w, const char* name) {
    return w.find<QDockWidget>(name);
}

// Every text an operator can read in the window: labels, buttons, tabs, dock titles, combo
// items, table headers and cells, menus, keyed by where it is.
QMap<QString, QString> visibleTexts(QWidget* root) {
    QMap<QString, QString> texts;
    const auto key = [](QObject* o, const QString& what) {
        QString path;
        for (QObject* p = o; p; p = p->parent()) {
            path.prepend(QStringLiteral("/") +
                         (p->objectName().isEmpty()
                              ? QString::fromLatin1(p->metaObject()->className())
                              : p->objectName()));
        }
        return path + QLatin1Char(':') + what + QLatin1Char('@') +
               QString::number(reinterpret_cast<quintptr>(o), 16);
    };
    QList<QWidget*> widgets = root->findChildren<QWidget*>();
    widgets.prepend(root);
    for (QWidget* widget : widgets) {
        // The message log keeps each line as it was said (a record, not the interface).
        bool inLog = false;
        for (QWidget* p = widget; p; p = p->parentWidget()) {
            inLog = inLog || qobject_cast<MessageLogPanel*>(p) != nullptr;
        }
        if (inLog && !qobject_cast<MessageLogPanel*>(widget) &&
            !qobject_cast<QHeaderView*>(widget) && !qobject_cast<QPushButton*>(widget)) {
            continue;
        }
        if (auto* label = qobject_cast<QLabel*>(widget)) {
            texts.insert(key(label, QStringLiteral("text")), label->text());
        } else if (auto* button = qobject_cast<QAbstractButton*>(widget)) {
            texts.insert(key(button, QStringLiteral("text")), button->text());
        } else if (auto* tabs = qobject_cast<QTabWidget*>(widget)) {
            for (int i = 0; i < tabs->count(); ++i) {
                texts.insert(key(tabs, QStringLiteral("tab%1").arg(i)), tabs->tabText(i));
            }
        } else if (auto* dock = qobject_cast<QDockWidget*>(widget)) {
            texts.insert(key(dock, QStringLiteral("title")), dock->windowTitle());
        } else if (auto* combo = qobject_cast<QComboBox*>(widget)) {
            for (int i = 0; i < combo->count(); ++i) {
                texts.insert(key(combo, QStringLiteral("item%1").arg(i)), combo->itemText(i));
            }
        } else if (auto* table = qobject_cast<QTableWidget*>(widget)) {
            for (int c = 0; c < table->columnCount(); ++c) {
                if (auto* item = table->horizontalHeaderItem(c)) {
                    texts.insert(key(table, QStringLiteral("header%1").arg(c)), item->text());
                }
                for (int r = 0; r < table->rowCount(); ++r) {
                    if (auto* item = table->item(r, c)) {
                        texts.insert(key(table, QStringLiteral("cell%1,%2").arg(r).arg(c)),
                                     item->text());
                    }
                }
            }
        } else if (auto* list = qobject_cast<QListWidget*>(widget)) {
            for (int i = 0; i < list->count(); ++i) {
                texts.insert(key(list, QStringLiteral("item%1").arg(i)), list->item(i)->text());
            }
        } else if (auto* group = qobject_cast<QGroupBox*>(widget)) {
            texts.insert(key(group, QStringLiteral("title")), group->title());
        } else if (auto* menu = qobject_cast<QMenu*>(widget)) {
            texts.insert(key(menu, QStringLiteral("title")), menu->title());
            for (QAction* action : menu->actions()) {
                texts.insert(key(action, QStringLiteral("action")), action->text());
            }
        }
    }
    return texts;
}

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

    void messageLog_survivesARestart() {
        {
            Window w;
            logMessage(QStringLiteral("Test"), MessageLevel::Error,
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

    void help_listsTheShortcutsAndShowsTheOperatorGuide() {
        Window w;
        auto* shortcuts = w.find<QAction>("shortcutsAction");
        QVERIFY(shortcuts);
        const QString sheet = answerMessageBox(&w.window, [&] { shortcuts->trigger(); });
        for (const char* key : {"F5", "F6", "Shift+F5", "Ctrl+R", "Space or Esc", "Ctrl+Q",
                                "Ctrl+Shift+R", "Ctrl+O", "Ctrl+S", "F1"}) {
            QVERIFY2(sheet.contains(QLatin1String(key)), key);
        }
        w.find<QAction>("guideAction")->trigger();
        auto* guide = w.window.findChild<QDialog*>(QStringLiteral("operatorGuide"));
        QVERIFY(guide);
        auto* text = guide->findChild<QTextBrowser*>(QStringLiteral("guideText"));
        QVERIFY(text->toPlainText().contains(QLatin1String("E-STOP")));
        // The guide built in is the one in docs/ (not a stale copy).
        QFile source(QStringLiteral(PRISCA_SOURCE_DIR "/docs/operator-guide.md"));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QFile built(QStringLiteral(":/docs/operator-guide.md"));
        QVERIFY(built.open(QIODevice::ReadOnly));
        QCOMPARE(built.readAll(), source.readAll());
        guide->close();
    }

    void layout_at1280x800ShowsAWholeRunsResultsAndTheRigsButtons() {
        Window w;
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(5);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 5, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // Every row of a five-trial run and the export button, without scrolling.
        QTableWidget* results = w.results();
        for (int r = 0; r < 5; ++r) {
            QVERIFY2(results->visualItemRect(results->item(r, 0)).bottom() <=
                         results->viewport()->height(),
                     qPrintable(QString::number(r)));
        }
        QVERIFY(wholeInView(results));
        QVERIFY(wholeInView(w.find<QPushButton>("exportRunLog")));
        // The rig's buttons, in view whatever page of its tabs is shown.
        dockOf(w, "rigDock")->raise();
        for (int page = 0; page < 3; ++page) {
            w.find<QTabWidget>("rigTabs")->setCurrentIndex(page);
            for (const char* name :
                 {"startCamera", "connectLink", "runOnRig", "stopOnRig", "driveOnRig"}) {
                QTRY_VERIFY2(wholeInView(w.find<QPushButton>(name)), name);
            }
            // Every page as wide as the panel: no sideways scrolling. On failure, the widgets
            // wider than the page say which.
            auto* scroll =
                qobject_cast<QScrollArea*>(w.find<QTabWidget>("rigTabs")->currentWidget());
            QVERIFY(scroll);
            const auto tooWide = [scroll] {
                QStringList wide;
                for (QWidget* child : scroll->widget()->findChildren<QWidget*>()) {
                    if (child->isVisible() &&
                        child->minimumSizeHint().width() > scroll->viewport()->width() / 2) {
                        wide << QStringLiteral("%1 %2 (%3)")
                                    .arg(QString::fromLatin1(child->metaObject()->className()),
                                         child->objectName())
                                    .arg(child->minimumSizeHint().width());
                    }
                }
                return wide.join(QStringLiteral(", "));
            };
            // Waits for the page's layout to settle after the switch, on its state.
            QTRY_VERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                         qPrintable(QStringLiteral("page %1 of width %2 scrolls sideways: %3")
                                        .arg(page)
                                        .arg(scroll->viewport()->width())
                                        .arg(tooWide())));
        }
    }

    void layout_at1280x800ShowsTheWholeMappingTabAndTheNewestRunResult() {
        Window w;
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(6);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 6, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // The Mapping tab brought up: Fit B_v, the whole fit table and its warnings in view, no
        // sideways scrolling; the Run panel keeps its newest result in view.
        dockOf(w, "mappingDock")->raise();
        auto* fit = w.find<QTableWidget>("fitResult");
        QTRY_VERIFY2(wholeInView(fit), "the fit table");
        QVERIFY(wholeInView(w.find<QPushButton>("fitButton")));
        auto* warnings = w.find<QLabel>("fitWarnings");
        QVERIFY(!warnings->isVisible() || wholeInView(warnings));
        auto* scroll = qobject_cast<QScrollArea*>(dockOf(w, "mappingDock")->widget());
        QVERIFY(scroll && !scroll->horizontalScrollBar()->isVisible());
        QTableWidget* results = w.results();
        QTRY_VERIFY(results->visualItemRect(results->item(5, 0)).bottom() <=
                    results->viewport()->height());
        QVERIFY(results->visualItemRect(results->item(5, 0)).top() >= 0);
        // Back on the Task tab, the Run panel shows the whole run again.
        dockOf(w, "taskDock")->raise();
        QTRY_VERIFY(results->visualItemRect(results->item(1, 0)).top() >= 0 &&
                    results->visualItemRect(results->item(5, 0)).bottom() <=
                        results->viewport()->height());
    }

    void chartAxisTitles_fitTheirAxesInEachLanguage() {
        Window w;
        for (const char* language : {"en", "zh_HK"}) {
            QVERIFY(w.languages.setLanguage(QString::fromLatin1(language)));
            QCoreApplication::processEvents();
            // Every chart's vertical title fits the plot's height (else QtCharts elides it to
            // a sliver), with the chart dock at its smallest.
            for (QChartView* view :
                 w.find<LiveChartsPanel>("liveChartsPanel")->findChildren<QChartView*>()) {
                view->resize(view->width(), view->minimumHeight());
                view->chart()->resize(view->size());
                for (QAbstractAxis* axis : view->chart()->axes(Qt::Vertical)) {
                    const int title =
                        QFontMetrics(axis->titleFont()).horizontalAdvance(axis->titleText());
                    QVERIFY2(title < view->chart()->plotArea().height(),
                             qPrintable(QStringLiteral("%1: \"%2\" is %3 px on a %4 px axis")
                                            .arg(QLatin1String(language), axis->titleText())
                                            .arg(title)
                                            .arg(view->chart()->plotArea().height())));
                }
            }
        }
    }

    void layout_at1280x800ShowsTableIsRowsAndEveryColumn() {
        // A Table I of every method, kept as a finished experiment is, shown at start.
        auto table = std::make_shared<prisca::sim::Table1Result>();
        table->lot = Eigen::Vector3d(4.0, 0.8, 1.2);
        for (const QString& method : prisca::sim::MethodCatalog::table1Ids()) {
            prisca::sim::MethodTrials m;
            m.method = method;
            for (int t = 0; t < 3; ++t) {
                prisca::sim::TrialSummary trial;
                trial.finalPositionError = 0.1234 + 0.01 * t;
                trial.finalHeadingError = 0.2345 + 0.01 * t;
                m.trials.push_back(trial);
                m.completed.push_back(true);
            }
            table->methods.push_back(m);
        }
        KeptExperiment kept;
        kept.record.plant = QStringLiteral("slidecar");
        kept.record.count = 3;
        kept.record.seed = 1;
        kept.record.demonstration = QStringLiteral("a test");
        kept.record.finished = QDateTime::currentDateTime();
        kept.table1 = table;
        QString error;
        QVERIFY2(saveKeptExperiment(keptExperimentPath(), kept, &error), qPrintable(error));
        Window w;
        dockOf(w, "experimentsDock")->raise();
        auto* results = w.find<QTableWidget>("experimentTable");
        QTRY_VERIFY(results->isVisible());
        QCOMPARE(results->rowCount(), static_cast<int>(table->methods.size()));
        // Five rows and every column without scrolling, the controls and exports in view.
        QVERIFY(wholeInView(results));
        for (int r = 0; r < 5; ++r) {
            QVERIFY2(results->visualItemRect(results->item(r, 0)).bottom() <=
                         results->viewport()->height(),
                     qPrintable(QString::number(r)));
        }
        QTRY_VERIFY(!results->horizontalScrollBar()->isVisible());
        for (const char* name :
             {"startExperiment", "cancelExperiment", "exportTable", "exportFigure"}) {
            QVERIFY2(wholeInView(w.find<QWidget>(name)), name);
        }
        QVERIFY(wholeInView(w.find<QWidget>("experimentCount")));
        QVERIFY(!w.find<QLabel>("experimentFigure")->pixmap().isNull());
    }

    void language_everyVisibleTextFollowsASwitchBothWays() {
        Window w;
        // Some dynamic text first: a finished run's rows, a status, a Table I result.
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(1);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Idle, kRunTimeoutMs);
        QTRY_COMPARE(w.results()->rowCount(), 1);
        w.find<RunPanel>("runPanel")->emergencyAction()->trigger();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        w.find<RunPanel>("runPanel")->resetEmergencyAction()->trigger();
        QTRY_VERIFY(w.find<QLabel>("runStatus")->text().contains(QLatin1String("reset")));
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(1);
        auto* experiments = w.find<ExperimentsPanel>("experimentsPanel");
        experiments->start();
        QTRY_VERIFY_WITH_TIMEOUT(!experiments->isRunning(), 240000);
        auto* job = w.find<QLabel>("jobStatus");
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));  // the status bar has caught up
        const QMap<QString, QString> english = visibleTexts(&w.window);

        QVERIFY(w.languages.setLanguage(QStringLiteral("zh_HK")));
        QTRY_COMPARE(job->text(), QStringLiteral("工作：無"));  // the switch has reached the window
        const QMap<QString, QString> chinese = visibleTexts(&w.window);
        // Texts with English words left after the switch (names and units aside).
        static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
        static const QSet<QString> names = {QStringLiteral("PRISCA"),  QStringLiteral("PGSD"),
                                            QStringLiteral("PEGASUS"), QStringLiteral("STOP"),
                                            QStringLiteral("CRSF"),    QStringLiteral("SBUS"),
                                            QStringLiteral("LATCHED"), QStringLiteral("V4L2")};
        // Kept as they are in every language, by design: the methods' labels (Table I's row
        // names, as in the paper), a parameter's choices (its --param values), the plant's
        // control names (the demonstration file's columns), each language's own name, ports.
        QSet<QString> asIs;
        for (const QString& id : prisca::sim::MethodCatalog::ids()) {
            asIs.insert(prisca::sim::MethodCatalog::get(id).label);
        }
        for (const prisca::sim::MethodParameter* parameter :
             prisca::sim::MethodCatalog::parameters()) {
            for (const char* choice : parameter->choices) {
                asIs.insert(QString::fromLatin1(choice));
            }
        }
        for (const QString& name : w.window.session().profile().info.actionNames) {
            asIs.insert(name);
        }
        QStringList english_left;
        for (auto it = chinese.begin(); it != chinese.end(); ++it) {
            if (it.value() != english.value(it.key())) {
                continue;  // translated
            }
            if (asIs.contains(it.value()) || it.key().contains(QLatin1String("languageAction_")) ||
                it.value().startsWith(QLatin1String("/dev/")) ||
                it.value() == it.value().toUpper()) {  // a protocol's name: CRSF, MULTIPROTOCOL
                continue;
            }
            auto match = word.globalMatch(it.value());
            while (match.hasNext()) {
                const QString w = match.next().captured();
                if (!names.contains(w.toUpper()) && !names.contains(w)) {
                    english_left << it.key().section(QLatin1Char('@'), 0, 0) +
                                        QStringLiteral(" = ") + it.value().left(80);
                    break;
                }
            }
        }
        // Back to English: every text is the one it was.
        QVERIFY(w.languages.setLanguage(QStringLiteral("en")));
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));
        const QMap<QString, QString> back = visibleTexts(&w.window);
        QStringList changed;
        for (auto it = english.begin(); it != english.end(); ++it) {
            if (back.value(it.key()) != it.value()) {
                changed << it.key().section(QLatin1Char('@'), 0, 0) + QStringLiteral(": '") +
                               it.value().left(60) + QStringLiteral("' -> '") +
                               back.value(it.key()).left(60) + QLatin1Char('\'');
            }
        }
        QVERIFY2(changed.isEmpty(), qPrintable(changed.join(QLatin1Char('\n'))));
        for (const QString& left : english_left) {
            qInfo("left in English: %s", qPrintable(left));
        }
        QVERIFY2(english_left.isEmpty(), qPrintable(english_left.join(QLatin1Char('\n'))));
    }
};

QTEST_MAIN(TestGuiWindow)
#include "test_gui_window.moc"
