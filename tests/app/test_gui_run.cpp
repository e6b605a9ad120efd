// The Run panel and the live charts driven offscreen through their real widgets: runs on the
// simulated plants, the run log (the CLI's, byte for byte), E-STOP, pause, shortcuts, layout.
#include "GuiTestSupport.h"
#include "rig/TrialBundle.h"

#include <QDir>
#include <QRegularExpression>
#include <QStandardPaths>

using namespace prisca::app;
using namespace prisca::test;

class TestGuiRun : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_run"); }
    void init() { resetGuiState(); }

    void decimation_keepsEverySpikeWithBoundedPoints() {
        QVector<QPointF> points;
        for (int i = 0; i < 100000; ++i) {
            points.push_back({i * 0.025, std::sin(i * 0.01)});
        }
        points[54321].setY(25.0);   // one spike up
        points[77777].setY(-30.0);  // one down
        const QVector<QPointF> drawn = plot::decimateMinMax(points, 500);
        QVERIFY(drawn.size() <= 4 * 500);
        QVERIFY(drawn.size() >= 500);
        double high = -1e9, low = 1e9;
        for (int i = 0; i < drawn.size(); ++i) {
            high = std::max(high, drawn[i].y());
            low = std::min(low, drawn[i].y());
            if (i > 0) {
                QVERIFY(drawn[i].x() > drawn[i - 1].x());  // still a function of x
            }
        }
        QCOMPARE(high, 25.0);
        QCOMPARE(low, -30.0);
        QCOMPARE(drawn.front(), points.front());
        QCOMPARE(drawn.back(), points.back());
        // Short series pass through untouched.
        const QVector<QPointF> few = {{0, 1}, {1, 2}, {2, 0}};
        QCOMPARE(plot::decimateMinMax(few, 500), few);
    }

    void runLog_ofTheWindowIsTheClisFormatWithOnlyFinishedTrials() {
        QTemporaryDir dir;
        Window w;
        auto* exportButton = w.find<QAbstractButton>("exportRunLog");
        QVERIFY(!exportButton->isEnabled());  // nothing run yet
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(2);
        QVERIFY(w.runToEnd());
        QVERIFY(exportButton->isEnabled());  // the log is told before the end
        const QString path = dir.filePath("run.csv");
        QString error;
        QVERIFY2(w.find<RunPanel>("runPanel")->exportRunLog(path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines[0], QStringLiteral("# prisca-run-log 1"));
        QVERIFY(lines.contains(QStringLiteral("# method: prisca")));
        QVERIFY(lines.contains(QStringLiteral("# trials: 2")));
        QVERIFY(lines.contains(QStringLiteral("# demonstration: scripted stick-180-left, seed 1")));
        // The header `prisca-cli run --out` writes for the slide-car's PRISCA.
        const QString header =
            "trial,t,x,y,psi,vx,vy,r,obs_x,obs_y,obs_psi,obs_vx,obs_vy,obs_r,ref_index,e_lon,"
            "e_lat,e_heading,e_vx,e_vy,e_r,u_throttle,u_steering,ustar_throttle,ustar_steering,"
            "cost,theta_0_throttle,theta_0_steering";
        const int at = lines.indexOf(header);
        QVERIFY2(at > 0, qPrintable(lines.mid(0, 12).join('\n')));
        // Both trials, each at least the demonstration's 158 steps, numbered 0 and 1.
        QSet<QString> trials;
        for (int i = at + 1; i < lines.size(); ++i) {
            trials.insert(lines[i].section(',', 0, 0));
        }
        QCOMPARE(trials, QSet<QString>({"0", "1"}));
        QVERIFY(lines.size() - at - 1 >= 2 * 158);
        // Each trial was also kept as a bundle (the default), with the session in it.
        const QDir bundles(
            QDir(QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation))
                .filePath("trials"));
        const QStringList made =
            bundles.entryList({"sim-*-prisca-trial-2"}, QDir::Dirs, QDir::Name);
        QVERIFY2(!made.isEmpty(), qPrintable(bundles.path()));
        const auto bundle = prisca::rig::TrialBundle::load(bundles.filePath(made.last()), &error);
        QVERIFY2(bundle, qPrintable(error));
        QVERIFY(bundle->complete());
        QVERIFY(bundle->samples.size() >= 158);
        QVERIFY(bundle->header.value("session").toObject().contains("format"));
    }

    void run_priscaOnTheSlideCarFillsTheResultsAndCharts() {
        Window w;
        QCOMPARE(w.window.session().method(), QStringLiteral("prisca"));
        w.setSpeedIndex(2);  // as fast as possible
        w.find<QSpinBox>("trials")->setValue(2);
        QVERIFY(w.runToEnd());
        QCOMPARE(w.results()->rowCount(), 2);
        // A slide-park ends within a metre of the lot even on the first, untrained trial.
        for (int row = 0; row < 2; ++row) {
            const double cm = w.results()->item(row, 1)->text().toDouble();
            QVERIFY2(cm >= 0.0 && cm < 100.0, qPrintable(w.results()->item(row, 1)->text()));
        }
        auto* charts = w.find<LiveChartsPanel>("liveChartsPanel");
        // Two trials of at least the demonstration's 158 steps each, all buffered, fewer drawn.
        QVERIFY2(charts->bufferedPoints() >= 2 * 158,
                 qPrintable(QString::number(charts->bufferedPoints())));
        QTRY_VERIFY(charts->drawnPoints() > 0);
        QVERIFY(w.find<QAbstractButton>("runButton")->isEnabled());

        // Export the charts and read the CSV back: one row per buffered step.
        QTemporaryDir dir;
        QString error;
        const QString csv = dir.filePath("charts.csv");
        QVERIFY2(charts->exportCsv(csv, &error), qPrintable(error));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), charts->bufferedPoints() + 4);  // three comments + header
        // The export says what it shows: method, target and demonstration.
        QVERIFY2(lines[1].contains("OURS (PRISCA)") &&
                     lines[1].contains("demonstration: the scripted operator"),
                 lines[1].constData());
        // Units, one per column, then the columns: the trial first, as in the run log.
        QVERIFY2(lines[2].startsWith("# units: 1,s,m,m,1"), lines[2].constData());
        QVERIFY(lines[3].startsWith("trial,t,error,error_smoothed,theta_0"));
        QVERIFY(lines[3].contains("u_throttle") && lines[3].contains("ustar_steering"));
        QCOMPARE(lines[2].split(',').size(), lines[3].split(',').size());
        const QList<QByteArray> last = lines.back().split(',');
        QCOMPARE(last.size(), lines[3].split(',').size());
        // Every trial of the run is in the file, its boundary drawn on the charts.
        QCOMPARE(last.first().toInt(), w.results()->rowCount() - 1);
        QCOMPARE(charts->trialStarts().size(), w.results()->rowCount() - 1);
        // The hover readout names the trial and the values under the mouse.
        const QString readout = charts->readoutAt(charts->trialStarts().value(0) + 0.01);
        QVERIFY2(readout.startsWith(QLatin1String("Trial 2, run time")) &&
                     readout.contains(QLatin1String("error")) &&
                     readout.contains(QLatin1String(" m")),
                 qPrintable(readout));
        const QString png = dir.filePath("charts.png");
        QVERIFY2(charts->exportPng(png, &error), qPrintable(error));
        if (qEnvironmentVariableIsSet("PRISCA_KEEP_CHART_PNG")) {
            QFile::copy(png, qEnvironmentVariable("PRISCA_KEEP_CHART_PNG"));
        }
        // The three charts at their on-screen size, one under the other, each drawn in full
        // (not only the tab on show): every third of the picture has dark ink (axes, labels).
        const QImage picture(png);
        auto* tabs = charts->findChild<QTabWidget*>();
        QVERIFY(picture.width() >= tabs->currentWidget()->width() - 2);
        QVERIFY(picture.height() >= 3 * 150);
        for (int part = 0; part < 3; ++part) {
            int dark = 0;
            const int top = part * picture.height() / 3;
            for (int y = top; y < top + picture.height() / 3; y += 2) {
                for (int x = 0; x < picture.width(); x += 2) {
                    dark += qGray(picture.pixel(x, y)) < 100 ? 1 : 0;
                }
            }
            // (A chart not drawn is blank: no dark ink at all. A drawn one has its axes' text
            // and lines, about 200 sampled pixels at this size.)
            QVERIFY2(dark > 150,
                     qPrintable(QStringLiteral("chart %1: %2 dark px").arg(part).arg(dark)));
        }

        // The theta chart has one series per entry of the method's theta: PRISCA's own features
        // on the slide-car, the shared ones for PGSD.
        const prisca::sim::MethodTuning& profile = w.window.session().profile();
        const auto count = [](const prisca::core::FeatureMap& f) {
            return f.featureCount() * f.channelCount();
        };
        QCOMPARE(charts->parameterCount(),
                 count(profile.priscaFeatures.value_or(profile.features)));
        auto* method = w.find<QComboBox>("method");
        method->setCurrentIndex(method->findData(QStringLiteral("pgsd")));
        emit method->activated(method->currentIndex());
        QCOMPARE(charts->parameterCount(), count(profile.features));
        method->setCurrentIndex(method->findData(QStringLiteral("prisca-paper")));
        emit method->activated(method->currentIndex());
        QCOMPARE(charts->parameterCount(),
                 count(profile.priscaFeatures.value_or(profile.features)));
    }

    void run_aircraftSamplesCarryTheWindTheCarsDoNot() {
        Window w;
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(1);
        QVector<LiveSample> seen;
        connect(&w.window.run(), &RunThread::samplesReady, this,
                [&](const QVector<LiveSample>& s) { seen += s; });
        QVERIFY(w.runToEnd());
        QVERIFY(!seen.isEmpty());
        QVERIFY(!seen.back().wind.has_value());

        w.find<QComboBox>("target")->setCurrentIndex(2);
        emit w.find<QComboBox>("target")->activated(2);
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
        seen.clear();
        QVERIFY(w.runToEnd());
        QVERIFY(seen.size() > 100);
        QVERIFY(seen.back().wind.has_value());
        // The trial's wind is a steady part plus gusts: not zero, not the same at every step.
        QVERIFY(seen.back().wind->norm() > 0.0);
        QVERIFY(*seen.back().wind != *seen[seen.size() / 2].wind);
    }

    void emergencyStop_spaceStopsWithinOneControlPeriodAndLatches() {
        Window w;
        w.setSpeedIndex(2);  // as fast as possible: the hardest case for stopping promptly
        w.find<QSpinBox>("trials")->setValue(50);
        const RunWorker* worker = w.window.run().worker();
        w.find<QAbstractButton>("runButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(worker->stepsTaken() > 100, kRunTimeoutMs);
        QTest::keyClick(&w.window, Qt::Key_Space);
        const int atPress = worker->stepsTaken();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        // The flag is read before every step: at most the step already under way completes.
        QVERIFY2(worker->stepsTaken() - atPress <= 1,
                 qPrintable(
                     QStringLiteral("%1 steps after E-STOP").arg(worker->stepsTaken() - atPress)));
        QTest::qWait(200);
        QVERIFY(worker->stepsTaken() - atPress <= 1);
        // Latched: Run is refused until E-STOP is reset.
        auto* run = w.find<QAbstractButton>("runButton");
        auto* reset = w.find<QAbstractButton>("resetEmergencyButton");
        QVERIFY(!run->isEnabled());
        QVERIFY(reset->isVisible());
        reset->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        QVERIFY(run->isEnabled());
        // Esc works the same, here while idle.
        QTest::keyClick(&w.window, Qt::Key_Escape);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
    }

    void layout_at1280x800GivesTheArenaRoomAndNoSidewaysScrolling() {
        Window w;  // a fresh start (init() cleared the settings): the space shared out
        auto* arena = w.window.centralWidget();
        QTRY_VERIFY2(
            arena->height() >= w.window.height() * 2 / 5,
            qPrintable(
                QStringLiteral("arena %1 of %2 px").arg(arena->height()).arg(w.window.height())));
        for (QDockWidget* dock : w.window.findChildren<QDockWidget*>()) {
            if (w.window.dockWidgetArea(dock) != Qt::RightDockWidgetArea) {
                continue;
            }
            dock->raise();
            QCoreApplication::processEvents();
            auto* scroll = qobject_cast<QScrollArea*>(dock->widget());
            if (!scroll) {
                // A panel that fits its dock (the Run panel): as wide as it needs, never cut.
                QWidget* panel = dock->widget();
                QVERIFY2(panel->width() >= panel->minimumSizeHint().width(),
                         qPrintable(dock->objectName()));
                continue;
            }
            QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                     qPrintable(dock->objectName() + QStringLiteral(" scrolls sideways")));
        }
    }

    void longRun_saysHowFarHowLongSoFarAndAboutHowLongIsLeft() {
        Window w;
        w.setSpeedIndex(1);  // 10x: a trial of 4 s in about 0.4 s
        w.find<QSpinBox>("trials")->setValue(40);
        w.find<RunPanel>("runPanel")->startRun();
        auto* status = w.find<QLabel>("runStatus");
        // From the third trial on (a loaded machine may show the third and fourth in one go):
        // by then the time so far gives an estimate of the time left.
        const QRegularExpression laterTrial(QStringLiteral("Trial ([0-9]+) of 40 running"));
        QString seen;
        const auto laterTrialShown = [&] {
            seen = status->text();
            const QRegularExpressionMatch match = laterTrial.match(seen);
            return match.hasMatch() && match.captured(1).toInt() >= 3;
        };
        QTRY_VERIFY2_WITH_TIMEOUT(laterTrialShown(), qPrintable(seen), kRunTimeoutMs);
        QVERIFY2(seen.contains(QLatin1String("so far")) && seen.contains(QLatin1String("left")),
                 qPrintable(seen));
        w.find<QAbstractButton>("stopButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        QTRY_VERIFY2(status->text().contains(QLatin1String("stopped")), qPrintable(status->text()));
    }

    void divergingTrial_isShownWithAWayOut() {
        Window w;
        w.setSpeedIndex(0);
        auto* warning = w.find<QWidget>("divergenceWarning");
        QVERIFY(!warning->isVisible());
        // Trials as the run reports them: the second within reach of the first, the third five
        // times the first's tracking error.
        prisca::sim::TrialSummary summary;
        summary.trackingRms = 0.10;
        emit w.window.run().trialFinished(0, summary);
        summary.trackingRms = 0.25;
        emit w.window.run().trialFinished(1, summary);
        QVERIFY(!warning->isVisible());
        summary.trackingRms = 0.50;
        emit w.window.run().trialFinished(2, summary);
        QVERIFY(warning->isVisible());
        QVERIFY2(warning->findChild<QLabel*>()->text().contains(QLatin1String("5.0")),
                 qPrintable(warning->findChild<QLabel*>()->text()));
        QCOMPARE(w.results()->item(2, 0)->background().color(), QColor(0xfd, 0xd8, 0xd8));
        // "Start learning again": a new run, from the method's start, the warning gone.
        w.find<QAbstractButton>("divergenceRestart")->click();
        QVERIFY(!warning->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Running, kRunTimeoutMs);
        QCOMPARE(w.results()->rowCount(), 0);
        w.find<QAbstractButton>("stopButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
    }

    void escOnAnOpenComboList_onlyClosesIt() {
        Window w;
        auto* speed = w.find<QComboBox>("speed");
        QSignalSpy estop(&w.window.emergencyStop(), &EmergencyStop::engaged);
        speed->showPopup();
        QTRY_VERIFY(QApplication::activePopupWidget() != nullptr);
        QTest::keyClick(QApplication::activePopupWidget(), Qt::Key_Escape);
        QTRY_VERIFY(QApplication::activePopupWidget() == nullptr);
        QCOMPARE(estop.count(), 0);
        QCOMPARE(w.window.run().phase(), RunPhase::Idle);
        QVERIFY(w.find<QAction>("resetEmergencyAction") != nullptr);
        QVERIFY(!w.find<QAction>("resetEmergencyAction")->isEnabled());
    }

    void shortcuts_workWithTheFocusInAComboBox() {
        Window w;
        w.setSpeedIndex(0);  // real time: the run is still going when the keys arrive
        w.find<QSpinBox>("trials")->setValue(3);
        auto* speed = w.find<QComboBox>("speed");
        speed->setFocus();
        QSignalSpy estop(&w.window.emergencyStop(), &EmergencyStop::engaged);
        // F5, F6, Shift+F5 and Ctrl+R with the focus in a combo box.
        QTest::keyClick(speed, Qt::Key_F5);
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Running, kRunTimeoutMs);
        QTest::keyClick(speed, Qt::Key_F6);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Paused);
        QTest::keyClick(speed, Qt::Key_F6);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Running);
        QTest::keyClick(speed, Qt::Key_F5, Qt::ShiftModifier);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        QVERIFY(w.results()->rowCount() >= 0);
        QTest::keyClick(w.find<QSpinBox>("seed"), Qt::Key_R, Qt::ControlModifier);
        QTRY_COMPARE(w.results()->rowCount(), 0);
        // Space in a text field types (the camera's path may hold one); elsewhere, a number
        // field included, it is E-STOP.
        auto* path = w.find<QLineEdit>("cameraPath");
        path->setEnabled(true);
        path->setText(QStringLiteral("my"));
        path->setFocus();
        path->setCursorPosition(2);
        QTest::keyClick(path, Qt::Key_Space);
        QCOMPARE(estop.count(), 0);
        QCOMPARE(path->text(), QStringLiteral("my "));
        // In a number field (the Seed box) a space is no part of a number: E-STOP.
        auto* seed = w.find<QSpinBox>("seed");
        const int seedBefore = seed->value();
        QTest::keyClick(seed, Qt::Key_Space);
        QCOMPARE(estop.count(), 1);
        QCOMPARE(seed->value(), seedBefore);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTest::keyClick(speed, Qt::Key_F5);  // refused while latched
        QCOMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        w.find<QAbstractButton>("resetEmergencyButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // Reset keeps the explanation (what stopped the run, when) until the next run.
        QVERIFY2(w.find<QLabel>("runStatus")->text().contains(QLatin1String("ready to run")),
                 qPrintable(w.find<QLabel>("runStatus")->text()));
    }

    void emergencyStop_staysVisibleWhateverTheDocks() {
        Window w;
        auto* button = w.find<QAbstractButton>("emergencyStopButton");
        const auto inView = [&] {
            const QRect inWindow(button->mapTo(&w.window, QPoint(0, 0)), button->size());
            return button->isVisible() && w.window.rect().contains(inWindow) &&
                   !button->visibleRegion().isEmpty();
        };
        QVERIFY(inView());
        // Every dock made as large as the window allows, then every dock closed.
        QList<QDockWidget*> docks = w.window.findChildren<QDockWidget*>();
        QVERIFY(docks.size() >= 8);
        for (QDockWidget* dock : docks) {
            w.window.resizeDocks({dock}, {2000}, Qt::Vertical);
            w.window.resizeDocks({dock}, {2000}, Qt::Horizontal);
            QCoreApplication::processEvents();
            QVERIFY2(inView(), qPrintable(dock->objectName()));
        }
        for (QDockWidget* dock : docks) {
            dock->close();
        }
        QCoreApplication::processEvents();
        QVERIFY(inView());
        // The toolbar cannot be hidden or moved by the operator.
        auto* bar = w.find<QToolBar>("runToolBar");
        QVERIFY(!bar->isMovable() && !bar->toggleViewAction()->isVisible());
        // A click on it (a mouse press) latches E-STOP.
        QTest::mousePress(button, Qt::LeftButton);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTest::mouseRelease(button, Qt::LeftButton);
    }

    void pauseAndStop_holdAndEndTheRun() {
        Window w;
        w.setSpeedIndex(0);  // real time
        w.find<QSpinBox>("trials")->setValue(3);
        const RunWorker* worker = w.window.run().worker();
        w.find<QAbstractButton>("runButton")->click();
        QTRY_VERIFY_WITH_TIMEOUT(worker->stepsTaken() > 10, kRunTimeoutMs);
        w.find<QAbstractButton>("pauseButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Paused);
        const int paused = worker->stepsTaken();
        QTest::qWait(300);  // 12 control periods at 40 Hz
        QCOMPARE(worker->stepsTaken(), paused);
        w.find<QAbstractButton>("pauseButton")->click();  // resume
        QTRY_VERIFY(worker->stepsTaken() > paused);
        w.find<QAbstractButton>("stopButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // The interrupted trial is reported as far as it went, and marked as stopped.
        QTRY_COMPARE(w.results()->rowCount(), 1);
        QVERIFY2(w.results()->item(0, 0)->text().contains(QLatin1String("stopped")),
                 qPrintable(w.results()->item(0, 0)->text()));
        // Another plant: the previous plant's results go, and the RMS column says rad.
        w.window.session().setPlant(QStringLiteral("acrobot"));
        QCOMPARE(w.results()->rowCount(), 0);
        QVERIFY(w.results()->horizontalHeaderItem(3)->text().contains(QLatin1String("rad")));
    }
};

QTEST_MAIN(TestGuiRun)
#include "test_gui_run.moc"
