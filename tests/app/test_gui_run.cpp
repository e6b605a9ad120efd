// The operator's application driven offscreen through its real widgets: run PRISCA on the
// simulated slide-car, E-STOP, pause, chart export read back, sessions saved and opened, bad
// files answered with a message box.
#include "app/ControllerPanel.h"
#include "app/ExperimentsPanel.h"
#include "app/LabSession.h"
#include "app/LanguageSwitcher.h"
#include "app/LiveChartsPanel.h"
#include "app/MainWindow.h"
#include "app/MappingPanel.h"
#include "app/RecordPanel.h"
#include "app/RigPanel.h"
#include "app/RunController.h"
#include "app/RunPanel.h"
#include "app/TaskPanel.h"
#include "app/plot/ChartDecimation.h"
#include "core/DemonstrationCsv.h"
#include "core/PriscaController.h"
#include "devices/SyntheticCamera.h"
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "support/FileSizeLimit.h"

#include <sys/stat.h>

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSet>
#include <QProcess>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolBar>
#include <QWheelEvent>
#include "sim/DemonstrationStyles.h"

#include <QtTest>

using namespace prisca::app;

namespace {

constexpr int kRunTimeoutMs = 60000;

// Reads and dismisses the next modal message box while `trigger` runs.
QString answerMessageBox(QObject* context, const std::function<void()>& trigger) {
    QString text;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
            text = box->text();
            box->accept();
        }
    });
    poll.start(20);
    trigger();
    poll.stop();
    return text;
}

// Answers the next file dialog with `path` while `trigger` runs.
void answerFileDialog(QObject* context, const QString& path, const std::function<void()>& trigger) {
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, context, [&] {
        if (auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
            // Typed into the file name field and confirmed, as an operator would.
            if (auto* edit = dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))) {
                edit->setText(path);
                QTest::keyClick(edit, Qt::Key_Return);
            }
        }
    });
    poll.start(20);
    trigger();
    poll.stop();
}

struct Window {
    LanguageSwitcher languages;
    MainWindow window{languages};
    Window() {
        window.resize(1280, 800);
        window.show();
        activate();
    }
    // Keys reach the shortcuts of the active window only (a window manager gives the window
    // back its activation when a popup closes; the offscreen platform does not): wait for it.
    void activate() {
        QApplication::setActiveWindow(&window);
        if (!QTest::qWaitForWindowActive(&window)) {
            qWarning("the window did not become active");
        }
    }
    template <class T>
    T* find(const char* name) {
        return window.findChild<T*>(QLatin1String(name));
    }
    void setSpeedIndex(int index) { find<QComboBox>("speed")->setCurrentIndex(index); }
    QTableWidget* results() { return find<QTableWidget>("trialResults"); }
};

// The virtual rig's camera running with a pose, and the link connected to its car.
bool startVirtualRig(Window& w, RigPanel* rig) {
    w.find<QComboBox>("cameraSource")->setCurrentIndex(0);
    rig->startCamera();
    if (!QTest::qWaitFor([&] { return rig->lastPose().has_value(); }, 10000)) {
        return false;
    }
    w.find<QComboBox>("linkPort")->setEditText(rig->virtualPort());
    rig->connectLink();
    return QTest::qWaitFor([&] { return rig->linkStatus().connected; }, 5000);
}

}  // namespace

class TestGuiRun : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("PRISCA Lab Tests"));
        QCoreApplication::setApplicationName(QStringLiteral("test_gui_run"));
        QApplication::setQuitOnLastWindowClosed(false);
    }
    void init() { QSettings().clear(); }

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

    void record_drivingWithTheKeyboardMakesTheDemonstration() {
        Window w;
        auto* panel = w.find<RecordPanel>("recordPanel");
        w.find<QSpinBox>("countdown")->setValue(0);
        const auto scripted = w.window.session().demonstration();
        w.find<QAbstractButton>("recordButton")->click();
        QVERIFY(panel->isRecording());
        // Full throttle by ramp (2 per second), then a left turn, then hands off.
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input()[0] > 0.99);
        // The operator sees the time and what is commanded, and the brakeless car's warning.
        QTRY_VERIFY2(
            w.find<QLabel>("recordStatus")->text().contains(QLatin1String("throttle 1.00")),
            qPrintable(w.find<QLabel>("recordStatus")->text()));
        QVERIFY(w.find<QLabel>("recordStatus")->text().contains(QLatin1String("no brakes")));
        // Full throttle for 0.6 s of the recording's own time (not the wall clock's), counted
        // from the first samples that arrive now.
        double throttleFrom = -1.0, recorded = -1.0;
        const QMetaObject::Connection seen = QObject::connect(
            panel, &RecordPanel::samplesReady, panel,
            [&](const QVector<prisca::app::LiveSample>& samples) {
                if (!samples.isEmpty()) {
                    throttleFrom = throttleFrom < 0.0 ? samples.front().time : throttleFrom;
                    recorded = samples.back().time;
                }
            });
        QTRY_VERIFY_WITH_TIMEOUT(throttleFrom >= 0.0 && recorded >= throttleFrom + 0.6, 30000);
        QObject::disconnect(seen);
        QTest::keyPress(&w.window, Qt::Key_A);
        QTRY_VERIFY(panel->input()[1] > 0.5);
        QTest::keyRelease(&w.window, Qt::Key_A);
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input().isZero());
        w.find<QAbstractButton>("stopRecordingButton")->click();
        QTRY_VERIFY(!panel->isRecording());
        QTRY_VERIFY(w.window.session().demonstration() != scripted);

        const auto demo = w.window.session().demonstration();
        const QString stream = w.window.session().demonstrationSource();
        QVERIFY2(stream.contains("recordings"), qPrintable(stream));
        QVERIFY2(demo->length() >= 40, qPrintable(QString::number(demo->length())));
        QVERIFY(demo->actions.col(0).maxCoeff() > 0.99);  // full throttle was recorded
        QVERIFY(demo->actions.col(1).maxCoeff() > 0.5);   // so was the left steer
        QVERIFY(demo->states.col(0).maxCoeff() > 0.3);    // and the car drove forward
        QVERIFY(demo->states.col(1).maxCoeff() > 0.0);    // and turned left
        // The stream on disk is a complete demonstration file of the same samples.
        prisca::core::FileError error;
        const auto onDisk = prisca::core::readDemonstrationCsv(stream, &error);
        QVERIFY2(onDisk, qPrintable(error.toString()));
        QCOMPARE(onDisk->length(), demo->length());
        QVERIFY(onDisk->states == demo->states);
        QVERIFY(onDisk->actions == demo->actions);
        // The fit follows the new demonstration.
        QCOMPARE(w.window.session().fit().samples > 0, true);

        // Discard: the scripted demonstration is back and the recording is gone.
        w.find<QAbstractButton>("discardRecordingButton")->click();
        QCOMPARE(w.window.session().demonstration(), scripted);
        QVERIFY(!QFile::exists(stream));
    }

    void record_emergencyStopEndsTheRecording() {
        Window w;
        auto* panel = w.find<RecordPanel>("recordPanel");
        w.find<QSpinBox>("countdown")->setValue(0);
        const auto before = w.window.session().demonstration();
        w.find<QAbstractButton>("recordButton")->click();
        QVERIFY(panel->isRecording());
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(panel->input()[0] > 0.5);
        QTest::keyClick(&w.window, Qt::Key_Space);
        QTRY_VERIFY(!panel->isRecording());
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QVERIFY(panel->input().isZero());
        // The take E-STOP cut short is kept on disk but not made the demonstration.
        QTRY_VERIFY(w.find<QLabel>("recordStatus")->text().contains(QLatin1String("E-STOP")));
        QCOMPARE(w.window.session().demonstration(), before);
    }

    void mapping_editAndFitShowsValuesAndSignConflicts() {
        Window w;
        auto* panel = w.find<MappingPanel>("mappingPanel");
        auto* result = w.find<QTableWidget>("fitResult");
        auto* signs = w.find<QTableWidget>("signs");
        const double steeringToPsi = w.window.session().fit().b(1, 2);
        QVERIFY(steeringToPsi > 0.0);
        QCOMPARE(result->item(1, 2)->text(), QString::number(steeringToPsi, 'g', 2));
        // R² row under the two controls.
        QCOMPARE(result->verticalHeaderItem(2)->text(), QStringLiteral("R²"));
        // Clicking cycles 0 -> +1 -> -1; "steering turns right" contradicts the demonstration.
        QCOMPARE(signs->item(1, 2)->text(), QStringLiteral("+1"));
        signs->setCurrentCell(1, 2);
        emit signs->cellClicked(1, 2);
        QCOMPARE(signs->item(1, 2)->text(), QStringLiteral("−1"));
        w.find<QAbstractButton>("fitButton")->click();
        QCOMPARE(w.window.session().profile().mapping.signs(1, 2), -1);
        QCOMPARE(w.window.session().fit().b(1, 2), 0.0);  // B_v >= 0 keeps B~'s sign: set to 0
        QCOMPARE(result->item(1, 2)->text(), QStringLiteral("·"));
        auto* warnings = w.find<QListWidget>("fitWarnings");
        QVERIFY(warnings->count() >= 1);
        bool named = false;
        for (int i = 0; i < warnings->count(); ++i) {
            named |= warnings->item(i)->text().contains("steering") &&
                     warnings->item(i)->text().contains("psi");
        }
        QVERIFY(named);
        // Back to +1 through the panel's setter and the fit returns.
        panel->setSign(1, 2, 1);
        panel->fit();
        QCOMPARE(w.window.session().fit().b(1, 2), steeringToPsi);
    }

    void experiments_table1InTheBackgroundThenExportedAndReadBack() {
        Window w;
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(3);
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        QVERIFY(panel->isRunning());
        QVERIFY(w.find<QAbstractButton>("cancelExperiment")->isEnabled());
        QVERIFY(finished.wait(kRunTimeoutMs));
        QVERIFY(!panel->isRunning());
        auto* table = w.find<QTableWidget>("experimentTable");
        QCOMPARE(table->rowCount(), 11);  // every Table I row: PRISCA's two, PGSD, ILC, the limit
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("OURS (PRISCA)"));
        QVERIFY(table->item(0, 1)->text().contains(QStringLiteral("±")));
        QVERIFY(!w.find<QLabel>("experimentFigure")->pixmap().isNull());
        // The result names the demonstration it is about.
        QVERIFY2(
            panel->tableText(prisca::core::TableFormat::Markdown)
                .contains(QLatin1String("demonstration: the scripted operator (stick-180-left")),
            qPrintable(panel->tableText(prisca::core::TableFormat::Markdown).left(300)));

        QTemporaryDir dir;
        QString error;
        for (const char* name : {"t.md", "t.csv", "t.tex"}) {
            const QString path = dir.filePath(name);
            QVERIFY2(panel->exportTable(path, &error), qPrintable(error));
            QFile file(path);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QString text = QString::fromUtf8(file.readAll());
            QVERIFY2(text.contains("PRISCA") && text.contains("PLAYBACK"), qPrintable(text));
        }
        QFile tex(dir.filePath("t.tex"));
        QVERIFY(tex.open(QIODevice::ReadOnly));
        QVERIFY(tex.readAll().contains("\\begin{tabular}"));
        const QString png = dir.filePath("fig7.png");
        QVERIFY2(panel->exportFigure(png, &error), qPrintable(error));
        QVERIFY(!QImage(png).isNull());
    }

    void experiments_cancelledTable1ShowsDashesNotNan() {
        Window w;
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(20);
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        w.find<QAbstractButton>("cancelExperiment")->click();  // the trials under way finish
        QVERIFY(finished.wait(kRunTimeoutMs));
        auto* table = w.find<QTableWidget>("experimentTable");
        QVERIFY(table->rowCount() > 0);
        int dashes = 0;
        for (int r = 0; r < table->rowCount(); ++r) {
            for (int c = 1; c < table->columnCount(); ++c) {
                const QString text = table->item(r, c)->text();
                QVERIFY2(!text.contains(QLatin1String("nan"), Qt::CaseInsensitive),
                         qPrintable(QStringLiteral("row %1 col %2: %3").arg(r).arg(c).arg(text)));
                dashes += text == QStringLiteral("—") ? 1 : 0;
            }
        }
        if (dashes == 0) {
            // On a loaded machine every method may have run a trial before the cancel took
            // effect: then there is no untouched row to look at.
            QSKIP("every method ran a trial before the cancel took effect");
        }
    }

    void experiments_cancelStopsTheCurvesAndKeepsWhatFinished() {
        Window w;
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);  // the acrobot
        auto* panel = w.find<ExperimentsPanel>("experimentsPanel");
        w.find<QComboBox>("experimentKind")->setCurrentIndex(1);
        w.find<QSpinBox>("experimentCount")->setValue(20);
        w.find<QSpinBox>("experimentBudget")->setValue(2000000);  // far more than the test waits
        QSignalSpy finished(panel, &ExperimentsPanel::finished);
        w.find<QAbstractButton>("startExperiment")->click();
        QVERIFY(panel->isRunning());  // cancelled while it runs
        w.find<QAbstractButton>("cancelExperiment")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
        QVERIFY(!panel->isRunning());
        QVERIFY(panel->tableText(prisca::core::TableFormat::Markdown).contains("cancelled"));
        QCOMPARE(w.find<QTableWidget>("experimentTable")->rowCount(), 3);
    }

    void runLog_ofTheWindowIsTheClisFormatWithOnlyFinishedTrials() {
        QTemporaryDir dir;
        Window w;
        auto* exportButton = w.find<QAbstractButton>("exportRunLog");
        QVERIFY(!exportButton->isEnabled());  // nothing run yet
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(2);
        QSignalSpy finished(&w.window.run(), &RunController::runFinished);
        w.find<QAbstractButton>("runButton")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
        QTRY_VERIFY(exportButton->isEnabled());
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
    }

    // The window's Run panel and `prisca-cli run` set a run up the same way (sim::RunSetup): on a
    // demonstration recorded at 60 Hz the same seed gives the same run log byte for byte, and on
    // the nominal plant with a perfect sensor playback and PRISCA repeat it exactly.
    void runLog_ofTheWindowAndTheCliAreTheSameBytesAt60Hz() {
        QTemporaryDir dir;
        prisca::sim::SimulationTiming timing;
        timing.controlPeriod = 1.0 / 60.0;
        const QString demoPath = dir.filePath("car-60hz.csv");
        prisca::core::FileError fileError;
        QVERIFY(prisca::core::writeDemonstrationCsv(
            prisca::sim::PlantCatalog::demonstrate("slidecar", 1, timing), demoPath, &fileError));
        Window w;
        auto demo = prisca::core::readDemonstrationCsv(demoPath, &fileError);
        QVERIFY(demo);
        w.window.session().setDemonstration(
            std::make_shared<const prisca::core::Demonstration>(std::move(*demo)), demoPath);
        w.setSpeedIndex(2);
        const auto runOnce = [&](const QString& method, int perturbation, int sensor,
                                 const QString& file) -> QByteArray {
            w.window.session().setMethod(method);
            w.find<QSpinBox>("trials")->setValue(2);
            w.find<QSpinBox>("seed")->setValue(5);
            w.find<QDoubleSpinBox>("perturbation")->setValue(perturbation);
            w.find<QDoubleSpinBox>("sensor")->setValue(sensor);
            QSignalSpy finished(&w.window.run(), &RunController::runFinished);
            w.find<QAbstractButton>("runButton")->click();
            if (!finished.wait(kRunTimeoutMs)) {
                return QByteArray();
            }
            if (!QTest::qWaitFor(
                    [&] { return w.find<QAbstractButton>("exportRunLog")->isEnabled(); }, 5000)) {
                return QByteArray();
            }
            QString error;
            if (!w.find<RunPanel>("runPanel")->exportRunLog(file, &error)) {
                qWarning("%s", qPrintable(error));
                return QByteArray();
            }
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        const auto cliRun = [&](const QString& method, int perturbation, int sensor,
                                const QString& file) -> QByteArray {
            QProcess cli;
            cli.setWorkingDirectory(dir.path());
            cli.start(QStringLiteral(PRISCA_CLI),
                      {"run", "--plant", "slidecar", "--demo", demoPath, "--method", method,
                       "--trials", "2", "--seed", "5", "--perturbation",
                       QString::number(perturbation), "--sensor", QString::number(sensor),
                       "--out", file});
            if (!cli.waitForFinished(kRunTimeoutMs) || cli.exitCode() != 0) {
                qWarning("%s", cli.readAllStandardError().constData());
                return QByteArray();
            }
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        // PRISCA on the realistic plant and sensor: learning, noise and latency included.
        const QByteArray window = runOnce("prisca", 1, 1, dir.filePath("window.csv"));
        QVERIFY(window.contains("# dt: 0.0166666"));
        QCOMPARE(window, cliRun("prisca", 1, 1, dir.filePath("cli.csv")));
        // The nominal case: playback and PRISCA park on the lot (the table shows cm).
        for (const QString method : {"playback", "prisca"}) {
            const QByteArray nominal = runOnce(method, 0, 0, dir.filePath(method + "-0.csv"));
            QVERIFY(!nominal.isEmpty());
            QCOMPARE(nominal, cliRun(method, 0, 0, dir.filePath(method + "-cli-0.csv")));
            QCOMPARE(w.results()->rowCount(), 2);
            for (int row = 0; row < 2; ++row) {
                QCOMPARE(w.results()->item(row, 1)->text(), QStringLiteral("0.0"));
            }
        }
    }

    void run_priscaOnTheSlideCarFillsTheResultsAndCharts() {
        Window w;
        QCOMPARE(w.window.session().method(), QStringLiteral("prisca"));
        w.setSpeedIndex(2);  // as fast as possible
        w.find<QSpinBox>("trials")->setValue(2);
        QSignalSpy finished(&w.window.run(), &RunController::runFinished);
        w.find<QAbstractButton>("runButton")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
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
        QCOMPARE(lines.size(), charts->bufferedPoints() + 3);  // two comments + header
        // The export says what it shows: method, target and demonstration.
        QVERIFY2(lines[1].contains("OURS (PRISCA)") &&
                     lines[1].contains("demonstration: the scripted operator"),
                 lines[1].constData());
        QVERIFY(lines[2].startsWith("t,error,error_smoothed,theta_0"));
        QVERIFY(lines[2].contains("u_throttle") && lines[2].contains("ustar_steering"));
        const QList<QByteArray> last = lines.back().split(',');
        QCOMPARE(last.size(), lines[2].split(',').size());
        const QString png = dir.filePath("charts.png");
        QVERIFY2(charts->exportPng(png, &error), qPrintable(error));
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
            QVERIFY2(dark > 200,
                     qPrintable(QStringLiteral("chart %1: %2 dark px").arg(part).arg(dark)));
        }

        // The theta chart has one series per entry of the method's theta: PRISCA's own features
        // on the slide-car, the shared ones for PGSD.
        const prisca::sim::PlantProfile& profile = w.window.session().profile();
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
        connect(&w.window.run(), &RunController::samplesReady, this,
                [&](const QVector<LiveSample>& s) { seen += s; });
        QSignalSpy finished(&w.window.run(), &RunController::runFinished);
        w.find<QAbstractButton>("runButton")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
        QVERIFY(!seen.isEmpty());
        QVERIFY(!seen.back().wind.has_value());

        w.find<QComboBox>("target")->setCurrentIndex(2);
        emit w.find<QComboBox>("target")->activated(2);
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
        seen.clear();
        w.find<QAbstractButton>("runButton")->click();
        QVERIFY(finished.wait(kRunTimeoutMs));
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
            QVERIFY(scroll != nullptr);
            QVERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                     qPrintable(dock->objectName() + QStringLiteral(" scrolls sideways")));
        }
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
        QSignalSpy estop(w.find<RunPanel>("runPanel"), &RunPanel::emergencyStopRequested);
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
        QSignalSpy estop(w.find<RunPanel>("runPanel"), &RunPanel::emergencyStopRequested);
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
        // Space in a text field types; elsewhere it is E-STOP.
        QTest::keyClick(w.find<QSpinBox>("seed"), Qt::Key_Space);
        QCOMPARE(estop.count(), 0);
        QTest::keyClick(speed, Qt::Key_Space);
        QCOMPARE(estop.count(), 1);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        QTest::keyClick(speed, Qt::Key_F5);  // refused while latched
        QCOMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        w.find<QAbstractButton>("resetEmergencyButton")->click();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        QVERIFY2(!w.find<QLabel>("runStatus")->text().contains(QLatin1String("engaged")),
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

    void session_fullDiskRefusedAndThePreviousFileKept() {
        QTemporaryDir dir;
        const QString path = dir.filePath("session.json");
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("{\"the previous session\": true}\n");
        old.close();
        LabSession session;
        session.setPlant(QStringLiteral("slidecar"));
        QString error;
        {
            const FileSizeLimit full(64);
            QVERIFY(full.active());
            QVERIFY(!session.save(path, &error));
        }
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("{\"the previous session\": true}\n"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
                 QStringList{"session.json"});
        // Hostile files are refused before they are read: a device, a FIFO.
        QVERIFY(!session.open(QStringLiteral("/dev/zero"), &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        const QByteArray fifo = QFile::encodeName(dir.filePath("fifo"));
        QCOMPARE(::mkfifo(fifo.constData(), 0600), 0);
        QVERIFY(!session.open(dir.filePath("fifo"), &error));  // would block forever if opened
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        QCOMPARE(session.plant(), QStringLiteral("slidecar"));
    }

    void session_savedAndOpenedWithItsParameters() {
        QTemporaryDir dir;
        const QString path = dir.filePath("session.json");
        {
            Window w;
            w.find<QComboBox>("target")->setCurrentIndex(
                w.find<QComboBox>("target")->findData(QStringLiteral("aircraft")));
            // activated() is what an operator's choice emits.
            emit w.find<QComboBox>("target")->activated(
                w.find<QComboBox>("target")->currentIndex());
            QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
            w.find<QSpinBox>("horizon")->setValue(17);
            auto* method = w.find<QComboBox>("method");
            method->setCurrentIndex(method->findData(QStringLiteral("pgsd")));
            emit method->activated(method->currentIndex());
            QCOMPARE(w.window.session().method(), QStringLiteral("pgsd"));
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));  // remembered target
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);
        QCOMPARE(w.window.session().plant(), QStringLiteral("acrobot"));
        QVERIFY(w.window.openSession(path));
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
        QCOMPARE(w.window.session().method(), QStringLiteral("pgsd"));
        QCOMPARE(w.window.session().profile().prisca.horizon, 17);
        QCOMPARE(w.find<QSpinBox>("horizon")->value(), 17);
        QCOMPARE(w.find<QComboBox>("target")->currentData().toString(), QStringLiteral("aircraft"));
    }

    void task_savedAsNamesTheSavedFile() {
        QTemporaryDir dir;
        Window w;
        const QString path = dir.filePath(QStringLiteral("kept.csv"));
        answerFileDialog(this, path,
                         [&] { w.find<QAbstractButton>("saveDemonstration")->click(); });
        QVERIFY(QFile::exists(path));
        QCOMPARE(w.window.session().demonstrationSource(), path);
        QVERIFY2(w.find<QLabel>("demonstrationInfo")->text().contains(QLatin1String("kept.csv")),
                 qPrintable(w.find<QLabel>("demonstrationInfo")->text()));
    }

    void task_scriptedStyleAndSeedAreUsedShownAndSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath("styled.json");
        {
            Window w;
            auto* style = w.find<QComboBox>("demonstrationStyle");
            QCOMPARE(style->count(),
                     static_cast<int>(
                         prisca::sim::DemonstrationStyles::of(QStringLiteral("slidecar")).size()));
            QCOMPARE(style->currentData().toString(), QStringLiteral("stick-180-left"));
            style->setCurrentIndex(style->findData(QStringLiteral("keyboard-90-right")));
            w.find<QSpinBox>("demonstrationSeed")->setValue(5);
            QTest::mouseClick(w.find<QPushButton>("scriptedDemonstration"), Qt::LeftButton);
            QCOMPARE(w.window.session().scriptedStyle(), QStringLiteral("keyboard-90-right"));
            QCOMPARE(w.window.session().scriptedSeed(), std::uint64_t(5));
            const auto expected = prisca::sim::DemonstrationStyles::record(
                QStringLiteral("slidecar"), QStringLiteral("keyboard-90-right"), 5);
            QCOMPARE(w.window.session().demonstration()->actions, expected.actions);
            QVERIFY2(
                w.find<QLabel>("demonstrationInfo")->text().contains("keyboard-90-right, seed 5"),
                qPrintable(w.find<QLabel>("demonstrationInfo")->text()));
            // The ILC fields apply to the session like every other parameter.
            w.find<QSpinBox>("ilcLead")->setValue(4);
            QCOMPARE(w.window.session().profile().ilcLead, 4);
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        w.find<QComboBox>("target")->setCurrentIndex(1);
        emit w.find<QComboBox>("target")->activated(1);
        QVERIFY(w.window.openSession(path));
        QCOMPARE(w.window.session().scriptedStyle(), QStringLiteral("keyboard-90-right"));
        QCOMPARE(w.window.session().scriptedSeed(), std::uint64_t(5));
        QCOMPARE(w.find<QComboBox>("demonstrationStyle")->currentData().toString(),
                 QStringLiteral("keyboard-90-right"));
        QCOMPARE(w.find<QSpinBox>("demonstrationSeed")->value(), 5);
        QCOMPARE(w.window.session().profile().ilcLead, 4);
        // A session naming a style the plant does not have is refused, naming the choices.
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QByteArray json = file.readAll();
        file.close();
        json.replace("keyboard-90-right", "moonwalk");
        QString error;
        QVERIFY(!w.window.session().fromJson(json, QStringLiteral("bad.json"), &error));
        QVERIFY2(error.contains("scriptedStyle") && error.contains("stick-180-left"),
                 qPrintable(error));
    }

    void controller_featureScalesAndLimitsAreCheckedAppliedAndSaved() {
        QTemporaryDir dir;
        const QString path = dir.filePath("limits.json");
        {
            Window w;
            // Every parameter is labelled (with the paper's symbol).
            auto* form = w.find<QWidget>("controllerPanel")->findChild<QFormLayout*>();
            QVERIFY(form);
            for (const char* name : {"method", "horizon", "gamma", "beta", "priscaAutomatic",
                                     "stepScale", "thetaBound", "priscaFromPd", "priscaGradient",
                                     "effortWeight", "matchingWindow", "pgsdStep"}) {
                auto* label = qobject_cast<QLabel*>(form->labelForField(w.find<QWidget>(name)));
                QVERIFY2(label && !label->text().isEmpty(), name);
            }
            QCOMPARE(qobject_cast<QLabel*>(form->labelForField(w.find<QWidget>("horizon")))->text(),
                     QStringLiteral("Horizon H:"));
            auto* features = w.find<QTableWidget>("featureScales");
            auto* limits = w.find<QTableWidget>("actionLimits");
            auto* problem = w.find<QLabel>("controllerProblem");
            // The slide-car's PRISCA derives alpha_0 and its feature scales from the
            // demonstration: those fields are not the operator's until automatic is off.
            auto* automatic = w.find<QCheckBox>("priscaAutomatic");
            QVERIFY(automatic->isChecked());
            QVERIFY(!features->isEnabled());
            QVERIFY(!w.find<QDoubleSpinBox>("stepScale")->isEnabled());
            automatic->setChecked(false);
            QVERIFY(!w.window.session().profile().priscaAutomatic);
            QVERIFY(features->isEnabled());
            QVERIFY(w.find<QDoubleSpinBox>("stepScale")->isEnabled());
            // PRISCA (the method shown) has features of its own: those are the ones edited.
            auto edited = [&w] {
                const auto& profile = w.window.session().profile();
                return profile.priscaFeatures.value_or(profile.features).terms()[1][0].scale;
            };
            const double before = edited();
            features->item(1, 0)->setText(QStringLiteral("lots"));
            QVERIFY2(problem->text().contains("steering"), qPrintable(problem->text()));
            QCOMPARE(edited(), before);
            features->item(1, 0)->setText(QStringLiteral("2.5"));
            QVERIFY(problem->text().isEmpty());
            QCOMPARE(edited(), 2.5);
            // Beyond what the car can do: refused with the range named.
            limits->item(1, 1)->setText(QStringLiteral("3"));
            QVERIFY2(problem->text().contains("[-1, 1]"), qPrintable(problem->text()));
            QCOMPARE(w.window.session().profile().info.actionUpper[1], 1.0);
            limits->item(1, 1)->setText(QStringLiteral("0.6"));
            QCOMPARE(w.window.session().profile().info.actionUpper[1], 0.6);
            // PRISCA's form: the slide-car's starts from the PD law and learns through the
            // closed loop with an effort cost; the operator can go back to the paper's start
            // and gradient.
            auto* fromPd = w.find<QCheckBox>("priscaFromPd");
            auto* gradient = w.find<QComboBox>("priscaGradient");
            auto* effort = w.find<QDoubleSpinBox>("effortWeight");
            QVERIFY(fromPd->isChecked());
            QCOMPARE(gradient->currentIndex(), 1);
            QCOMPARE(effort->value(), 3.0);
            QCOMPARE(w.find<QDoubleSpinBox>("thetaBound")->text(), QStringLiteral("none"));
            fromPd->setChecked(false);
            gradient->setCurrentIndex(0);
            emit gradient->activated(0);
            effort->setValue(0.0);
            QVERIFY(!w.window.session().profile().priscaFromPd);
            QCOMPARE(w.window.session().profile().prisca.gradient,
                     prisca::core::PriscaParameters::Gradient::OneStep);
            QCOMPARE(w.window.session().profile().prisca.effortWeights.size(), 0);
            effort->setValue(1.5);
            QVERIFY(w.window.saveSession(path));
        }
        Window w;
        QVERIFY(w.window.openSession(path));
        const auto& reopened = w.window.session().profile();
        QCOMPARE(reopened.priscaFeatures.value_or(reopened.features).terms()[1][0].scale, 2.5);
        QCOMPARE(w.window.session().profile().info.actionUpper[1], 0.6);
        QCOMPARE(w.find<QTableWidget>("actionLimits")->item(1, 1)->text(), QStringLiteral("0.6"));
        QVERIFY(!w.window.session().profile().priscaFromPd);
        QCOMPARE(w.window.session().profile().prisca.gradient,
                 prisca::core::PriscaParameters::Gradient::OneStep);
        QCOMPARE(w.window.session().profile().prisca.effortWeights,
                 Eigen::Vector2d(1.5, 1.5).eval());
        QVERIFY(!w.find<QCheckBox>("priscaFromPd")->isChecked());
        QCOMPARE(w.find<QDoubleSpinBox>("effortWeight")->value(), 1.5);
        QVERIFY(!w.window.session().profile().priscaAutomatic);
        QVERIFY(!w.find<QCheckBox>("priscaAutomatic")->isChecked());
        QVERIFY(w.find<QTableWidget>("featureScales")->isEnabled());
    }

    void session_isRememberedBetweenRunsOfTheApplication() {
        {
            Window w;
            w.find<QSpinBox>("horizon")->setValue(23);
            QVERIFY(w.window.close());
        }
        Window w;
        QCOMPARE(w.window.session().profile().prisca.horizon, 23);
        QCOMPARE(w.find<QSpinBox>("horizon")->value(), 23);
        // A damaged copy in the settings is ignored: the application still starts.
        QSettings().setValue("session/last", QByteArray("{ not json"));
        Window fresh;
        QCOMPARE(fresh.window.session().plant(), QStringLiteral("slidecar"));
        QCOMPARE(fresh.window.session().profile().prisca.horizon,
                 prisca::sim::PlantProfile::forPlant(
                     prisca::sim::PlantCatalog::describe(QStringLiteral("slidecar")))
                     .prisca.horizon);
    }

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

    void rig_drivingThroughTheLinkRecordsADemonstration() {
        Window w;
        auto* rig = w.find<RigPanel>("rigPanel");
        QVERIFY(startVirtualRig(w, rig));
        const auto before = w.window.session().demonstration();
        QVERIFY(rig->startDriving());
        QTest::keyPress(&w.window, Qt::Key_Up);
        QTRY_VERIFY(rig->drivingInput()[0] > 0.99);
        // Full throttle for 0.7 s of the take's own (frame) time, then 0.3 s coasting.
        QTRY_VERIFY_WITH_TIMEOUT(rig->recordedSeconds() >= 0.7, 30000);
        QTest::keyRelease(&w.window, Qt::Key_Up);
        QTRY_VERIFY_WITH_TIMEOUT(rig->recordedSeconds() >= 1.0, 30000);
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
            QVERIFY(w.window.close());
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

    void session_ofAnEarlierVersionGetsTodaysTuning() {
        Window w;
        QTemporaryDir dir;
        // A session of an earlier version: its PRISCA/PD/ILC parameters were tuned for an
        // earlier PRISCA, so today's defaults stand in for them and the operator is told; the
        // rest (here the matching window) is read as saved. The same values in a session of
        // today's version are applied.
        for (const int version : {1, 2}) {
            const QString old = dir.filePath(QStringLiteral("v%1.json").arg(version));
            QFile v(old);
            QVERIFY(v.open(QIODevice::WriteOnly));
            v.write(QStringLiteral("{ \"format\": \"prisca-session\", \"version\": %1, "
                                   "\"plant\": \"slidecar\", \"matchingWindow\": 33, "
                                   "\"prisca\": {\"stepScale\": 3, \"thetaBound\": 1}, "
                                   "\"pd\": {\"kp\": [0.5, 1]} }")
                        .arg(version)
                        .toUtf8());
            v.close();
            QVERIFY(w.window.openSession(old));
            const prisca::sim::PlantProfile& opened = w.window.session().profile();
            const prisca::sim::PlantProfile defaults = prisca::sim::PlantProfile::forPlant(
                prisca::sim::PlantCatalog::describe("slidecar"));
            QCOMPARE(opened.matchingWindow, 33);
            const QString status = w.window.statusBar()->currentMessage();
            if (version == 1) {
                QCOMPARE(opened.prisca.stepSize.scale, defaults.prisca.stepSize.scale);
                QCOMPARE(opened.prisca.thetaBound, defaults.prisca.thetaBound);
                QCOMPARE(opened.pd.kp, defaults.pd.kp);
                QVERIFY2(status.contains("earlier"), qPrintable(status));
            } else {
                QCOMPARE(opened.prisca.stepSize.scale, 3.0);
                QCOMPARE(opened.prisca.thetaBound, 1.0);
                QCOMPARE(opened.pd.kp, Eigen::Vector2d(0.5, 1.0));
                QVERIFY2(!status.contains("earlier"), qPrintable(status));
            }
        }
    }

    void demonstrationOfAnotherPlantOrTooShort_isRefusedAndTheSessionKeepsItsOwn() {
        QTemporaryDir dir;
        Window w;
        w.window.session().setPlant("aircraft");
        const auto before = w.window.session().demonstration();
        const Eigen::MatrixXd fitBefore = w.window.session().fit().b;
        // A slide-car's demonstration in an aircraft session: same column count, another plant.
        const QString car = dir.filePath("car.csv");
        prisca::core::FileError error;
        QVERIFY(prisca::core::writeDemonstrationCsv(
            prisca::sim::PlantCatalog::demonstrate("slidecar", 2), car, &error));
        QString text = answerMessageBox(this, [&] {
            QVERIFY(!w.find<prisca::app::TaskPanel>("taskPanel")->openDemonstration(car));
        });
        QVERIFY2(text.contains("car.csv") && text.contains("slidecar"), qPrintable(text));
        QCOMPARE(w.window.session().demonstration(), before);
        QCOMPARE(w.window.session().fit().b, fitBefore);
        // An aircraft demonstration of three samples: refused, and nothing half-changed.
        prisca::core::Demonstration shortDemo =
            prisca::sim::PlantCatalog::demonstrate("aircraft", 2);
        shortDemo.states.conservativeResize(3, Eigen::NoChange);
        shortDemo.actions.conservativeResize(3, Eigen::NoChange);
        shortDemo.time.conservativeResize(3);
        QVERIFY_THROWS_EXCEPTION(
            std::invalid_argument,
            w.window.session().setDemonstration(
                std::make_shared<prisca::core::Demonstration>(shortDemo), "short.csv"));
        QCOMPARE(w.window.session().demonstration(), before);
        QCOMPARE(w.window.session().fit().b, fitBefore);
        QCOMPARE(w.window.session().plant(), QStringLiteral("aircraft"));
    }

    void badFiles_getAClearMessageAndChangeNothing() {
        QTemporaryDir dir;
        Window w;
        const auto demoBefore = w.window.session().demonstration();

        const QString garbage = dir.filePath("garbage.json");
        QFile f(garbage);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", \"prisca\": {\"gamma\": 7} "
            "}");
        f.close();
        QString text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("garbage.json") && text.contains("gamma"), qPrintable(text));
        QFile f2(garbage);
        QVERIFY(f2.open(QIODevice::WriteOnly));
        f2.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", "
            "\"prisca\": {\"gradient\": \"sideways\"} }");
        f2.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("gradient") && text.contains("closed-loop"), qPrintable(text));
        QFile f3(garbage);
        QVERIFY(f3.open(QIODevice::WriteOnly));
        f3.write(
            "{ \"format\": \"prisca-session\", \"plant\": \"slidecar\", "
            "\"prisca\": {\"automatic\": \"yes\"} }");
        f3.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(garbage)); });
        QVERIFY2(text.contains("'automatic'"), qPrintable(text));

        const QString notJson = dir.filePath("not.json");
        QFile g(notJson);
        QVERIFY(g.open(QIODevice::WriteOnly));
        g.write("\x01\x02 nonsense");
        g.close();
        text = answerMessageBox(this, [&] { QVERIFY(!w.window.openSession(notJson)); });
        QVERIFY2(text.contains("not valid JSON"), qPrintable(text));

        // A demonstration with a NaN: the reader names the line; the session keeps its own.
        const QString csv = dir.filePath("bad-demo.csv");
        QFile h(csv);
        QVERIFY(h.open(QIODevice::WriteOnly));
        h.write(
            "# prisca-demonstration 1\n# plant: slidecar\n# dt: 0.025\n"
            "# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"
            "# actions: throttle[1], steering[1]\n"
            "t,x,y,psi,vx,vy,r,throttle,steering\n"
            "0,0,0,0,0,0,0,0,0\n0.025,0,nan,0,0,0,0,0,0\n");
        h.close();
        auto* task = w.find<TaskPanel>("taskPanel");
        text = answerMessageBox(this, [&] { QVERIFY(!task->openDemonstration(csv)); });
        QVERIFY2(text.contains("bad-demo.csv") && text.contains(":8"), qPrintable(text));
        QCOMPARE(w.window.session().demonstration(), demoBefore);
    }
};

QTEST_MAIN(TestGuiRun)
#include "test_gui_run.moc"
