// The window and the command line set a run up one way (sim::RunSetup): the window's run log is
// `prisca-cli run`'s byte for byte at any demonstration rate. Starts prisca-cli as a child
// process, so it is not among the ThreadSanitizer suites (a threaded process that forks).
#include "GuiTestSupport.h"

#include <QProcess>

using namespace prisca::app;
using namespace prisca::test;

class TestGuiCliParity : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_cli_parity"); }
    void init() { resetGuiState(); }

    // The window's Run panel and `prisca-cli run` set a run up the same way (sim::RunSetup): on a
    // demonstration recorded at 25, 30, 50 or 60 Hz the same seed gives the same run log byte for
    // byte, and on the nominal plant with a perfect sensor playback and PRISCA repeat it exactly.
    void runLog_ofTheWindowAndTheCliAreTheSameBytesAtAnyRate_data() {
        QTest::addColumn<int>("hertz");
        for (int hertz : {25, 30, 50, 60}) {
            QTest::addRow("%d Hz", hertz) << hertz;
        }
    }
    void runLog_ofTheWindowAndTheCliAreTheSameBytesAtAnyRate() {
        QFETCH(int, hertz);
        QTemporaryDir dir;
        prisca::sim::SimulationTiming timing;
        timing.controlPeriod = 1.0 / hertz;
        const QString demoPath = dir.filePath(QStringLiteral("car-%1hz.csv").arg(hertz));
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
            if (!w.runToEnd() || !w.find<QAbstractButton>("exportRunLog")->isEnabled()) {
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
            cli.start(
                QStringLiteral(PRISCA_CLI),
                {"run", "--plant", "slidecar", "--demo", demoPath, "--method", method, "--trials",
                 "2", "--seed", "5", "--perturbation", QString::number(perturbation), "--sensor",
                 QString::number(sensor), "--out", file});
            if (!cli.waitForFinished(kRunTimeoutMs) || cli.exitCode() != 0) {
                qWarning("%s", cli.readAllStandardError().constData());
                return QByteArray();
            }
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        };
        // PRISCA on the realistic plant and sensor: learning, noise and latency included.
        const QByteArray window = runOnce("prisca", 1, 1, dir.filePath("window.csv"));
        const int dtAt = window.indexOf("# dt: ");
        QVERIFY(dtAt >= 0);
        const double dt = window.mid(dtAt + 6, window.indexOf('\n', dtAt) - dtAt - 6).toDouble();
        QVERIFY2(std::abs(dt - 1.0 / hertz) < 1e-12, window.left(300).constData());
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
};

QTEST_MAIN(TestGuiCliParity)
#include "test_gui_cli_parity.moc"
