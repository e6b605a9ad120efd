// What prisca-cli says when something is wrong names the thing that is wrong (the reliability
// pass's findings): a value in an actions file by file:line:column, a plant the demonstration
// cannot fly by its parameter, a port another program holds as in use, a camera delayed on
// purpose waited for; and the link's own notes only with --verbose.
#include "../devices/PseudoTerminal.h"
#include "support/CliProcess.h"

#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>

#include <cmath>
#include <csignal>

namespace {

using Result = prisca::test::CliResult;

Result cli(const QStringList& arguments, const QString& directory) {
    return prisca::test::runCli(arguments, directory);
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

}  // namespace

class TestCliMessages : public QObject {
    Q_OBJECT
  private slots:
    void simulate_anActionBeyondAnyNamesItsCell() {
        QTemporaryDir dir;
        writeFile(dir.filePath("a.csv"), "throttle,steering\n0.2,0\n1e300,0\n");
        const Result r =
            cli({"simulate", "--plant", "slidecar", "--actions", "a.csv", "--out", "s.csv"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("a.csv:3:1: '1e300' in column 'throttle' is beyond the +-1e+06"),
                 qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("s.csv")));
    }

    void simulate_workBeyondItsBudgetIsRefusedFirst() {
        QTemporaryDir dir;
        Result r = cli({"simulate", "--plant", "slidecar", "--zero-action", "--duration", "86400",
                        "--dt", "0.0001", "--out", "s.csv"},
                       dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("864000000 control steps") && r.err.contains("1000000"),
                 qPrintable(r.err));
        r = cli({"simulate", "--plant", "slidecar", "--zero-action", "--duration", "600",
                 "--substeps", "1000", "--out", "s.csv"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("physics steps a simulation may take"), qPrintable(r.err));
        // An output that cannot be written is refused before anything is computed.
        QVERIFY(QDir(dir.path()).mkdir("folder"));
        r = cli({"table1", "--plant", "slidecar", "--trials", "200", "--out", "folder"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--out: ") && r.err.contains("is a folder"), qPrintable(r.err));
        QVERIFY(!r.err.contains("table1: trial"));  // no progress: nothing ran
    }

    void demo_anAircraftThatCannotFlyNamesTheParameter() {
        QTemporaryDir dir;
        writeFile(dir.filePath("ac.json"),
                  "{\"plant\": \"aircraft\", \"parameters\": {\"propellerPitchSpeed\": 12}}");
        const Result r =
            cli({"demo", "--plant", "aircraft", "--plant-params", "ac.json", "--out", "d.csv"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no thrust at 12 m/s and above (propellerPitchSpeed)"),
                 qPrintable(r.err));
        QVERIFY2(!r.err.contains("d.csv"), qPrintable(r.err));
    }

    void link_aPortInUseIsSaidSo() {
        Pty pty;
        QVERIFY(!pty.path.isEmpty());
        QProcess first;
        first.start(QStringLiteral(PRISCA_CLI), {"link", "--port", pty.path, "--protocol", "crsf",
                                                 "--channels", "1500", "--duration", "60"});
        QVERIFY(first.waitForStarted());
        QByteArray bytes;
        const QDeadlineTimer guard(30000);
        while (bytes.size() < 260 && !guard.hasExpired()) {
            bytes += pty.read();
            QThread::msleep(5);
        }
        QVERIFY(bytes.size() >= 260);  // the first link holds the port and sends
        const Result second = cli({"link", "--port", pty.path, "--protocol", "crsf", "--channels",
                                   "1500", "--duration", "2"},
                                  QDir::currentPath());
        ::kill(static_cast<pid_t>(first.processId()), SIGTERM);
        QVERIFY(first.waitForFinished(30000));
        QCOMPARE(second.exitCode, 2);
        QVERIFY2(second.err.contains("in use by another program"), qPrintable(second.err));
        // Without --verbose the link's notes (the port opened, line settings a pty cannot
        // take) stay off stderr: the first link said only how it ended.
        const QString said = QString::fromLocal8Bit(first.readAllStandardError());
        QVERIFY2(!said.contains("prisca.devices.link:"), qPrintable(said));
        QVERIFY2(said.contains("stopped by SIGTERM"), qPrintable(said));
    }

    void rig_aCameraDelayedOnPurposeIsWaitedFor() {
        // --inject-camera-delay's largest value: the latency probe waits that much longer for
        // the car's answer (it gave up after 1 s, "did not answer").
        const Result r = cli({"rig", "--virtual", "--trials", "0", "--measure-latency",
                              "--latency-steps", "2", "--inject-camera-delay", "2000"},
                             QDir::currentPath());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QRegularExpression median(QStringLiteral("median (\\d+\\.\\d) ms"));
        const QRegularExpressionMatch found = median.match(r.out);
        QVERIFY2(found.hasMatch(), qPrintable(r.out));
        QVERIFY2(std::abs(found.captured(1).toDouble() - 2000.0) < 60.0, qPrintable(r.out));
    }

    void link_verboseShowsTheDevicesNotes() {
        Pty pty;
        const Result r = cli({"link", "--port", pty.path, "--protocol", "crsf", "--channels",
                              "1500", "--duration", "0.3", "--verbose"},
                             QDir::currentPath());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("prisca.devices.link: sending \"crsf\""), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliMessages)
#include "test_cli_messages.moc"
