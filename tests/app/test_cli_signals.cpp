// However prisca-cli ends short of SIGKILL, the last frames on the serial line are failsafe
// (throttle neutral, steering centred) and stderr says so: every stopping signal, an exception,
// a failed assertion, an exception escaping a thread and a crash, on a pseudo-terminal whose
// frames this test decodes itself (not with the project's decoder).
#include "../devices/PseudoTerminal.h"

#include <QDeadlineTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <QThread>

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
        if (b[i] == 0xC8 && b[i + 1] == 24 && b[i + 2] == 0x16 && crc8(b + i + 2, 23) == b[i + 25]) {
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

}  // namespace

class TestCliSignals : public QObject {
    Q_OBJECT

  private slots:
    void link_endsInFailsafe_data();
    void link_endsInFailsafe();
    void rig_hangupEndsInFailsafe();
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
    // The second signal ends the process wherever the orderly stop is: failsafe either way.
    QTest::newRow("SIGTERM twice") << SIGTERM << true << "" << -1 << "failsafe";
    QTest::newRow("exception") << 0 << false << "exception" << 2
                               << "injected fault (PRISCA_INJECT_FAULT=exception) (the link "
                                  "ended in failsafe)";
    QTest::newRow("failed assertion") << 0 << false << "assertion" << -1
                                      << "crashed (SIGABRT); failsafe sent on 1 link";
    QTest::newRow("exception on a thread")
        << 0 << false << "terminate" << -1
        << "uncaught exception: injected fault on a worker thread; failsafe sent";
    QTest::newRow("crash") << 0 << false << "segfault" << -1
                           << "crashed (SIGSEGV); failsafe sent on 1 link";
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
    cli.start(QStringLiteral(PRISCA_CLI),
              {"link", "--port", pty.path, "--protocol", "crsf", "--channels", "1500,1700",
               "--duration", "60"});
    QVERIFY(cli.waitForStarted());

    // Wait until the commanded value is on the wire (the car is moving), then end the process.
    QByteArray bytes;
    const QDeadlineTimer guard(30000);
    auto commanded = [&bytes] {
        int count = 0;
        for (const auto& frame : decodeCrsf(bytes)) {
            count += std::abs(frame.second - 1700.0) < 1.0 ? 1 : 0;
        }
        return count;
    };
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
    QVERIFY2(isNeutral(frames.back()),
             qPrintable(QStringLiteral("last frame CH1 %1 us, CH2 %2 us")
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

QTEST_GUILESS_MAIN(TestCliSignals)
#include "test_cli_signals.moc"
