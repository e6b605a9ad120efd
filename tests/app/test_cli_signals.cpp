// However prisca-cli ends short of SIGKILL, the last frames on the serial line are failsafe
// (throttle neutral, steering centred) and stderr says so: every signal whose default action
// ends or stops the process, an exception, a failed assertion, an exception escaping a thread and
// a crash, on a pseudo-terminal whose frames this test decodes itself (not with the project's
// decoder). A process stopped (Ctrl-Z, SIGSTOP) and continued holds failsafe.
#include "../devices/PseudoTerminal.h"

#include <QDeadlineTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <QThread>

#include <QFile>

#include <csignal>
#include <cstdint>
#include <vector>

namespace {

// CRSF RC_CHANNELS_PACKED, decoded from the specification: sync 0xC8, length 24, type 0x16,
// 22 bytes of sixteen 11-bit channels LSB first, CRC-8 (polynomial 0xD5) over type and payload.
std::uint8_t crc8(const std::uint8_t* data, int size) {
    std::uint8_t crc = 0;
    for (int i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int b = 0; b < 8; ++b) {
            crc = (crc & 0x80) ? static_cast<std::uint8_t>((crc << 1) ^ 0xD5)
                               : static_cast<std::uint8_t>(crc << 1);
        }
    }
    return crc;
}

// Each complete frame's first two channels as pulse widths [us] (172..1811 is 988..2012 us).
std::vector<std::pair<double, double>> decodeCrsf(const QByteArray& bytes) {
    std::vector<std::pair<double, double>> frames;
    const auto* b = reinterpret_cast<const std::uint8_t*>(bytes.constData());
    for (int i = 0; i + 26 <= bytes.size();) {
        if (b[i] == 0xC8 && b[i + 1] == 24 && b[i + 2] == 0x16 &&
            crc8(b + i + 2, 23) == b[i + 25]) {
            const std::uint8_t* payload = b + i + 3;
            auto channel = [payload](int c) {
                int value = 0;
                for (int bit = 0; bit < 11; ++bit) {
                    const int at = c * 11 + bit;
                    if (payload[at / 8] & (1 << (at % 8))) {
                        value |= 1 << bit;
                    }
                }
                return 988.0 + (value - 172) * 1024.0 / (1811 - 172);
            };
            frames.emplace_back(channel(0), channel(1));
            i += 26;
        } else {
            ++i;
        }
    }
    return frames;
}

bool isNeutral(const std::pair<double, double>& frame) {
    return std::abs(frame.first - 1500.0) < 1.0 && std::abs(frame.second - 1500.0) < 1.0;
}

// The process's state letter in /proc (R, S, T stopped, ...).
char processState(qint64 pid) {
    QFile stat(QStringLiteral("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) {
        return '?';
    }
    const QByteArray text = stat.readAll();
    const int close = text.lastIndexOf(')');
    return close >= 0 && close + 2 < text.size() ? text.at(close + 2) : '?';
}

int commandedFrames(const QByteArray& bytes) {
    int count = 0;
    for (const auto& frame : decodeCrsf(bytes)) {
        count += std::abs(frame.second - 1700.0) < 1.0 ? 1 : 0;
    }
    return count;
}

}  // namespace

class TestCliSignals : public QObject {
    Q_OBJECT

  private slots:
    void link_endsInFailsafe_data();
    void link_endsInFailsafe();
    void link_stoppedAndContinuedHoldsFailsafe_data();
    void link_stoppedAndContinuedHoldsFailsafe();
    void link_rateAboveTheLineRefused();
    void rig_hangupEndsInFailsafe();
    void rig_stoppedAndContinuedEndsTheTrial();
};

void TestCliSignals::link_endsInFailsafe_data() {
    QTest::addColumn<int>("signal");     // sent once the link is sending (0: none)
    QTest::addColumn<bool>("twice");     // a second one right after the first
    QTest::addColumn<QString>("fault");  // PRISCA_INJECT_FAULT
    QTest::addColumn<int>("exitCode");   // -1: the process is killed by crashSignal
    QTest::addColumn<QString>("stderrSays");

    QTest::newRow("SIGTERM") << SIGTERM << false << "" << 128 + SIGTERM
                             << "stopped by SIGTERM; ended in failsafe";
    QTest::newRow("SIGINT") << SIGINT << false << "" << 128 + SIGINT
                            << "stopped by SIGINT; ended in failsafe";
    QTest::newRow("SIGHUP") << SIGHUP << false << "" << 128 + SIGHUP
                            << "stopped by SIGHUP; ended in failsafe";
    QTest::newRow("SIGPIPE") << SIGPIPE << false << "" << 128 + SIGPIPE
                             << "stopped by SIGPIPE; ended in failsafe";
    QTest::newRow("SIGQUIT") << SIGQUIT << false << "" << 128 + SIGQUIT
                             << "stopped by SIGQUIT; ended in failsafe";
    // Every other signal whose default action ends the process: none of them is the
    // project's, and each ends it as SIGTERM does (a timer's, a limit's, a user's).
    const std::vector<std::pair<int, const char*>> others = {
        {SIGUSR1, "SIGUSR1"},     {SIGUSR2, "SIGUSR2"},     {SIGALRM, "SIGALRM"},
        {SIGVTALRM, "SIGVTALRM"}, {SIGPROF, "SIGPROF"},     {SIGXCPU, "SIGXCPU"},
        {SIGPWR, "SIGPWR"},       {SIGSTKFLT, "SIGSTKFLT"}, {SIGIO, "SIGIO"}};
    for (const auto& [number, name] : others) {
        QTest::newRow(name) << number << false << "" << 128 + number
                            << QStringLiteral("stopped by %1").arg(QLatin1String(name));
    }
    // Those whose default action dumps core, as a crash does.
    QTest::newRow("SIGSYS") << SIGSYS << false << "" << -1
                            << "crashed (SIGSYS); failsafe sent on 1 link";
    QTest::newRow("SIGTRAP") << SIGTRAP << false << "" << -1
                             << "crashed (SIGTRAP); failsafe sent on 1 link";
    // The second signal ends the process wherever the orderly stop is: failsafe either way.
    QTest::newRow("SIGTERM twice") << SIGTERM << true << "" << -1 << "failsafe";
#ifdef PRISCA_FAULT_INJECTION  // the faults only a test build can raise
    QTest::newRow("exception") << 0 << false << "exception" << 2
                               << "injected fault (PRISCA_INJECT_FAULT=exception) (the link "
                                  "ended in failsafe)";
    QTest::newRow("failed assertion")
        << 0 << false << "assertion" << -1 << "crashed (SIGABRT); failsafe sent on 1 link";
    QTest::newRow("exception on a thread")
        << 0 << false << "terminate" << -1
        << "uncaught exception: injected fault on a worker thread; failsafe sent";
    QTest::newRow("crash") << 0 << false << "segfault" << -1
                           << "crashed (SIGSEGV); failsafe sent on 1 link";
#endif
}

void TestCliSignals::link_endsInFailsafe() {
    QFETCH(int, signal);
    QFETCH(bool, twice);
    QFETCH(QString, fault);
    QFETCH(int, exitCode);
    QFETCH(QString, stderrSays);

    Pty pty;
    QVERIFY(!pty.path.isEmpty());
    QProcess cli;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.insert(QStringLiteral("PRISCA_INJECT_FAULT"), fault);
    cli.setProcessEnvironment(environment);
    cli.start(QStringLiteral(PRISCA_CLI), {"link", "--port", pty.path, "--protocol", "crsf",
                                           "--channels", "1500,1700", "--duration", "60"});
    QVERIFY(cli.waitForStarted());

    // Wait until the commanded value is on the wire (the car is moving), then end the process.
    QByteArray bytes;
    const QDeadlineTimer guard(30000);
    auto commanded = [&bytes] { return commandedFrames(bytes); };
    while (commanded() < 5 && cli.state() == QProcess::Running && !guard.hasExpired()) {
        bytes += pty.read();
        QThread::msleep(5);
    }
    if (signal != 0) {
        QCOMPARE(cli.state(), QProcess::Running);
        ::kill(static_cast<pid_t>(cli.processId()), signal);
        if (twice) {
            ::kill(static_cast<pid_t>(cli.processId()), signal);
        }
    }
    QVERIFY2(cli.waitForFinished(30000), "prisca-cli did not end");
    bytes += pty.read();

    const auto frames = decodeCrsf(bytes);
    QVERIFY2(commanded() >= 5, "the command never reached the wire");
    QVERIFY(!frames.empty());
    QVERIFY2(isNeutral(frames.back()), qPrintable(QStringLiteral("last frame CH1 %1 us, CH2 %2 us")
                                                      .arg(frames.back().first)
                                                      .arg(frames.back().second)));
    const QString errors = QString::fromLocal8Bit(cli.readAllStandardError());
    QVERIFY2(errors.contains(stderrSays), qPrintable(errors));
    if (exitCode >= 0) {
        QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
        QCOMPARE(cli.exitCode(), exitCode);
    } else if (!twice) {
        QCOMPARE(cli.exitStatus(), QProcess::CrashExit);
    }
}

void TestCliSignals::link_stoppedAndContinuedHoldsFailsafe_data() {
    QTest::addColumn<int>("signal");
    QTest::addColumn<QString>("stderrSays");  // when it stops
    QTest::newRow("SIGTSTP (Ctrl-Z)") << SIGTSTP << "stopped by SIGTSTP; failsafe sent on 1 link";
    QTest::newRow("SIGTTOU") << SIGTTOU << "stopped by SIGTTOU; failsafe sent on 1 link";
    QTest::newRow("SIGTTIN") << SIGTTIN << "stopped by SIGTTIN; failsafe sent on 1 link";
    QTest::newRow("SIGSTOP") << SIGSTOP << "";  // no handler sees it: only the continue
}

void TestCliSignals::link_stoppedAndContinuedHoldsFailsafe() {
    QFETCH(int, signal);
    QFETCH(QString, stderrSays);

    Pty pty;
    QVERIFY(!pty.path.isEmpty());
    QProcess cli;
    cli.setReadChannel(QProcess::StandardError);
    cli.start(QStringLiteral(PRISCA_CLI), {"link", "--port", pty.path, "--protocol", "crsf",
                                           "--channels", "1500,1700", "--duration", "120"});
    QVERIFY(cli.waitForStarted());
    const qint64 pid = cli.processId();
    QByteArray bytes;
    const QDeadlineTimer guard(60000);
    while (commandedFrames(bytes) < 5 && cli.state() == QProcess::Running && !guard.hasExpired()) {
        bytes += pty.read();
        QThread::msleep(5);
    }
    QVERIFY2(commandedFrames(bytes) >= 5, "the command never reached the wire");

    ::kill(static_cast<pid_t>(pid), signal);
    while (processState(pid) != 'T' && !guard.hasExpired()) {
        QThread::msleep(5);
    }
    QCOMPARE(processState(pid), 'T');
    bytes += pty.read();
    if (!stderrSays.isEmpty()) {
        // Stopped after failsafe went out: the car is not left driving while the process sleeps.
        const auto frames = decodeCrsf(bytes);
        QVERIFY(isNeutral(frames.back()));
        // Said before the stop: on stderr already.
        QByteArray said;
        while (!said.contains(stderrSays.toLatin1()) && !guard.hasExpired()) {
            cli.waitForReadyRead(50);
            said += cli.readAllStandardError();
        }
        QVERIFY2(said.contains(stderrSays.toLatin1()), said.constData());
    }

    // Continued: failsafe, not the command it had, until the process ends.
    const int framesBefore = static_cast<int>(decodeCrsf(bytes).size());
    ::kill(static_cast<pid_t>(pid), SIGCONT);
    QByteArray after;
    while (decodeCrsf(after).size() < 40 && cli.state() == QProcess::Running &&
           !guard.hasExpired()) {
        after += pty.read();
        QThread::msleep(5);
    }
    const auto resumed = decodeCrsf(after);
    QVERIFY2(resumed.size() >= 40, "no frames after the continue");
    // Caught stops held failsafe before stopping: every frame after is neutral. SIGSTOP's hold
    // starts with the SIGCONT handler, which may run just after the link's first frame.
    const size_t firstChecked = stderrSays.isEmpty() ? 2 : 0;
    for (size_t i = firstChecked; i < resumed.size(); ++i) {
        QVERIFY2(isNeutral(resumed[i]), qPrintable(QStringLiteral("frame %1 after the continue: "
                                                                  "CH2 %2 us")
                                                       .arg(i)
                                                       .arg(resumed[i].second)));
    }
    QVERIFY(framesBefore > 0);
    ::kill(static_cast<pid_t>(pid), SIGTERM);
    QVERIFY(cli.waitForFinished(30000));
    const QString errors = QString::fromLocal8Bit(cli.readAllStandardError());
    QVERIFY2(errors.contains("continued; the link holds failsafe"), qPrintable(errors));
    const auto last = decodeCrsf(after + pty.read());
    QVERIFY(isNeutral(last.back()));
}

void TestCliSignals::link_rateAboveTheLineRefused() {
    // SBUS at 100000 baud 8E2 carries 333 frames/s, 166 with the gap receivers find frames by:
    // more would queue behind a failsafe.
    Pty pty;
    QProcess cli;
    cli.start(QStringLiteral(PRISCA_CLI),
              {"link", "--port", pty.path, "--protocol", "sbus", "--channels", "1500,1700",
               "--rate", "1000", "--duration", "1"});
    QVERIFY(cli.waitForFinished(30000));
    QCOMPARE(cli.exitCode(), 2);
    const QString errors = QString::fromLocal8Bit(cli.readAllStandardError());
    QVERIFY2(errors.contains("--rate 1000: sbus at 100000 baud carries 333 frames/s; at most 166"),
             qPrintable(errors));
    QVERIFY(pty.read().isEmpty());  // refused before the port was opened
}

void TestCliSignals::rig_hangupEndsInFailsafe() {
    // The whole rig chain: closing the terminal mid-trial leaves the car's receiver neutral.
    QProcess cli;
    cli.start(QStringLiteral(PRISCA_CLI), {"rig", "--virtual", "--trials", "1"});
    QVERIFY(cli.waitForStarted());
    QByteArray errors;
    const QDeadlineTimer guard(60000);
    while (!errors.contains("rig: trial 1/1: 1 of") && cli.state() == QProcess::Running &&
           !guard.hasExpired()) {
        cli.waitForReadyRead(100);
        errors += cli.readAllStandardError();
    }
    QVERIFY2(errors.contains("rig: trial 1/1: 1 of"), errors.constData());
    ::kill(static_cast<pid_t>(cli.processId()), SIGHUP);
    QVERIFY(cli.waitForFinished(30000));
    errors += cli.readAllStandardError();
    QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
    QCOMPARE(cli.exitCode(), 128 + SIGHUP);
    QVERIFY2(errors.contains("stopped by SIGHUP; the link ended in failsafe (the car's receiver "
                             "holds neutral)"),
             errors.constData());
}

void TestCliSignals::rig_stoppedAndContinuedEndsTheTrial() {
    // Ctrl-Z mid-trial: failsafe before the stop; continued, the trial ends held in failsafe and
    // the next one does not start by itself.
    QProcess cli;
    cli.start(QStringLiteral(PRISCA_CLI), {"rig", "--virtual", "--trials", "2"});
    QVERIFY(cli.waitForStarted());
    const qint64 pid = cli.processId();
    QByteArray errors;
    const QDeadlineTimer guard(90000);
    while (!errors.contains("rig: trial 1/2: 1 of") && cli.state() == QProcess::Running &&
           !guard.hasExpired()) {
        cli.waitForReadyRead(100);
        errors += cli.readAllStandardError();
    }
    QVERIFY2(errors.contains("rig: trial 1/2: 1 of"), errors.constData());
    ::kill(static_cast<pid_t>(pid), SIGTSTP);
    while (processState(pid) != 'T' && !guard.hasExpired()) {
        QThread::msleep(5);
    }
    QCOMPARE(processState(pid), 'T');
    ::kill(static_cast<pid_t>(pid), SIGCONT);
    QVERIFY(cli.waitForFinished(60000));
    errors += cli.readAllStandardError();
    QVERIFY2(errors.contains("stopped by SIGTSTP; failsafe sent on"), errors.constData());
    QVERIFY2(errors.contains("continued; the link holds failsafe"), errors.constData());
    const QByteArray out = cli.readAllStandardOutput();
    QVERIFY2(out.contains("trial 1: ") &&
                 out.contains("(stopped early: the process was stopped and continued: failsafe "
                              "held)"),
             out.constData());
    QVERIFY2(errors.contains("no further trial started"), errors.constData());
    QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
    QCOMPARE(cli.exitCode(), 2);
    QVERIFY2(!errors.contains("rig: trial 2/2 ("), errors.constData());
}

QTEST_GUILESS_MAIN(TestCliSignals)
#include "test_cli_signals.moc"
