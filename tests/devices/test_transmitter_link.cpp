// The transmitter link on pseudo-terminals: frames at the set rate, failsafe within one period
// of a stale command, E-STOP latched, the port reopened after the far end goes away, garbage
// from the far end harmless.
#include "PseudoTerminal.h"
#include "devices/ChannelMap.h"
#include "devices/TransmitterLink.h"

#include <QtTest>

#include <cerrno>
#include <cmath>

using namespace prisca::devices;

namespace {

// Reads frames from the master for `ms`, returning them with their arrival time [ms].
struct Capture {
    std::vector<ChannelValues> frames;
    std::vector<qint64> times;
};
Capture capture(const Pty& pty, RcFrameDecoder& decoder, int ms) {
    Capture c;
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms) {
        for (const ChannelValues& f : decoder.push(pty.read())) {
            c.frames.push_back(f);
            c.times.push_back(clock.elapsed());
        }
        QTest::qWait(2);
    }
    return c;
}

ChannelPulses pulses(double throttleUs, double steeringUs) {
    ChannelPulses p;
    p.fill(1500.0);
    p[2] = throttleUs;
    p[0] = steeringUs;
    return p;
}

LinkSettings settings(const QString& port, RcProtocol protocol) {
    LinkSettings s;
    s.port = port;
    s.protocol = protocol;
    s.rateHz = 50.0;
    s.staleAfter = 0.1;
    s.reconnectIntervalMs = 100;
    return s;
}

}  // namespace

class TestTransmitterLink : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { qRegisterMetaType<LinkStatus>(); }

    void frames_arriveAtTheSetRateCarryingTheCommand_data() {
        QTest::addColumn<int>("protocol");
        QTest::newRow("crsf") << static_cast<int>(RcProtocol::Crsf);
        QTest::newRow("sbus") << static_cast<int>(RcProtocol::Sbus);
        QTest::newRow("multiprotocol") << static_cast<int>(RcProtocol::Multiprotocol);
    }
    void frames_arriveAtTheSetRateCarryingTheCommand() {
        QFETCH(int, protocol);
        const auto p = static_cast<RcProtocol>(protocol);
        Pty pty;
        QVERIFY(!pty.path.isEmpty());
        TransmitterLink link;
        RcFrameDecoder decoder(p);
        link.start(settings(pty.path, p));
        // Keep the command fresh while capturing one second.
        QTimer feeder;
        connect(&feeder, &QTimer::timeout, this, [&] { link.setCommand(pulses(1700, 1300)); });
        feeder.start(10);
        capture(pty, decoder, 1000);  // settle: the link at its steady rate before it is counted
        const Capture c = capture(pty, decoder, 1000);
        feeder.stop();
        // 50 Hz: 50 frames a second, give or take a few for a shared machine's scheduling.
        QVERIFY2(c.frames.size() >= 44 && c.frames.size() <= 56,
                 qPrintable(QString::number(c.frames.size())));
        const ChannelValues& last = c.frames.back();
        QCOMPARE(valueToPulse(p, last[2]), valueToPulse(p, pulseToValue(p, 1700)));
        QVERIFY(std::abs(valueToPulse(p, last[2]) - 1700) < 1.0);
        QVERIFY(std::abs(valueToPulse(p, last[0]) - 1300) < 1.0);
        QVERIFY(std::abs(valueToPulse(p, last[5]) - 1500) < 1.0);
        QCOMPARE(decoder.skippedBytes(), 0LL);
    }

    void staleCommand_givesFailsafeWithinOnePeriod() {
        Pty pty;
        TransmitterLink link;
        RcFrameDecoder decoder(RcProtocol::Crsf);
        LinkSettings s = settings(pty.path, RcProtocol::Crsf);
        s.failsafe = pulses(1500, 1500);
        link.start(s);
        link.setCommand(pulses(2000, 1000));
        QElapsedTimer sinceCommand;
        sinceCommand.start();
        const Capture c = capture(pty, decoder, 400);
        // Every frame sent more than stale + one period (100 + 20 ms) after the last command
        // is failsafe: throttle neutral, steering centred.
        bool sawCommand = false, sawFailsafe = false;
        for (size_t i = 0; i < c.frames.size(); ++i) {
            const double throttle = valueToPulse(RcProtocol::Crsf, c.frames[i][2]);
            const double steering = valueToPulse(RcProtocol::Crsf, c.frames[i][0]);
            if (throttle > 1990)
                sawCommand = true;
            if (std::abs(throttle - 1500) < 1 && std::abs(steering - 1500) < 1)
                sawFailsafe = true;
            if (c.times[i] > 100 + 20 + 15) {  // + a read-loop margin
                QVERIFY2(
                    std::abs(throttle - 1500) < 1,
                    qPrintable(
                        QStringLiteral("frame at %1 ms: %2 us").arg(c.times[i]).arg(throttle)));
            }
        }
        QVERIFY(sawCommand);
        QVERIFY(sawFailsafe);
    }

    void emergencyStop_latchesUntilReset() {
        Pty pty;
        TransmitterLink link;
        RcFrameDecoder decoder(RcProtocol::Sbus);
        link.start(settings(pty.path, RcProtocol::Sbus));
        QTimer feeder;
        connect(&feeder, &QTimer::timeout, this, [&] { link.setCommand(pulses(1800, 1200)); });
        feeder.start(10);
        capture(pty, decoder, 200);
        link.emergencyStop();
        capture(pty, decoder, 30);  // the frame under way when it was pressed
        Capture c = capture(pty, decoder, 300);
        QVERIFY(c.frames.size() > 10);
        for (const ChannelValues& f : c.frames) {
            QVERIFY(std::abs(valueToPulse(RcProtocol::Sbus, f[2]) - 1500) < 1);  // neutral
        }
        QVERIFY(decoder.lastFailsafe());  // SBUS says so in its flags too
        // Fresh commands keep coming; E-STOP holds until reset.
        link.resetEmergencyStop();
        capture(pty, decoder, 60);
        c = capture(pty, decoder, 200);
        QVERIFY(std::abs(valueToPulse(RcProtocol::Sbus, c.frames.back()[2]) - 1800) < 1);
        QVERIFY(!decoder.lastFailsafe());
        feeder.stop();
    }

    void poseLostAndControllerFault_giveFailsafe() {
        Pty pty;
        TransmitterLink link;
        RcFrameDecoder decoder(RcProtocol::Crsf);
        link.start(settings(pty.path, RcProtocol::Crsf));
        QTimer feeder;
        connect(&feeder, &QTimer::timeout, this, [&] { link.setCommand(pulses(1800, 1200)); });
        feeder.start(10);
        capture(pty, decoder, 150);
        link.setPoseLost(true);
        capture(pty, decoder, 30);
        Capture c = capture(pty, decoder, 150);
        QVERIFY(std::abs(valueToPulse(RcProtocol::Crsf, c.frames.back()[2]) - 1500) < 1);
        link.setPoseLost(false);
        capture(pty, decoder, 30);
        c = capture(pty, decoder, 100);
        QVERIFY(std::abs(valueToPulse(RcProtocol::Crsf, c.frames.back()[2]) - 1800) < 1);
        link.reportControllerFault();
        capture(pty, decoder, 30);
        c = capture(pty, decoder, 100);
        QVERIFY(std::abs(valueToPulse(RcProtocol::Crsf, c.frames.back()[2]) - 1500) < 1);
        feeder.stop();
    }

    void missingPort_isReportedAndTriedAgain() {
        TransmitterLink link;
        QSignalSpy status(&link, &TransmitterLink::statusChanged);
        link.start(settings(QStringLiteral("/dev/no-such-transmitter"), RcProtocol::Crsf));
        QVERIFY(status.wait(2000));
        const LinkStatus s = status.last().at(0).value<LinkStatus>();
        QVERIFY(!s.connected);
        QVERIFY2(s.lastError.contains("/dev/no-such-transmitter"), qPrintable(s.lastError));
        QCOMPARE(link.framesSent(), 0LL);
    }

    void farEndClosedAndReopened_reconnectsByItself() {
        // socat-style: a stable path (a symlink) to whichever pty is the far end now.
        QTemporaryDir dir;
        const QString link1 = dir.filePath("ttyRC");
        auto first = std::make_unique<Pty>();
        QVERIFY(QFile::link(first->path, link1));
        TransmitterLink link;
        link.start(settings(link1, RcProtocol::Crsf));
        QTimer feeder;
        connect(&feeder, &QTimer::timeout, this, [&] { link.setCommand(pulses(1600, 1500)); });
        feeder.start(10);
        RcFrameDecoder decoder(RcProtocol::Crsf);
        QVERIFY(!capture(*first, decoder, 200).frames.empty());
        // Unplug: the pty goes away; plug in: a new one behind the same path.
        first->closeAll();
        QTest::qWait(200);
        auto second = std::make_unique<Pty>();
        QFile::remove(link1);
        QVERIFY(QFile::link(second->path, link1));
        RcFrameDecoder again(RcProtocol::Crsf);
        QTRY_VERIFY_WITH_TIMEOUT(!capture(*second, again, 100).frames.empty(), 5000);
        feeder.stop();
    }

    void garbageFromTheFarEnd_isIgnored() {
        Pty pty;
        TransmitterLink link;
        RcFrameDecoder decoder(RcProtocol::Crsf);
        link.start(settings(pty.path, RcProtocol::Crsf));
        QByteArray junk(20000, '\0');
        for (int i = 0; i < junk.size(); ++i)
            junk[i] = static_cast<char>((i * 131 + 7) & 0xFF);
        // In slices, as fast as the pty takes them, while the link keeps sending.
        qsizetype written = 0;
        QElapsedTimer clock;
        clock.start();
        while (written < junk.size() && clock.elapsed() < 3000) {
            const ssize_t n = ::write(pty.master, junk.constData() + written,
                                      std::min<qsizetype>(1024, junk.size() - written));
            if (n > 0)
                written += n;
            pty.read();
            QTest::qWait(5);
        }
        QCOMPARE(written, junk.size());
        const Capture c = capture(pty, decoder, 300);
        QVERIFY(c.frames.size() >= 10);  // still sending, unharmed
    }
};

QTEST_GUILESS_MAIN(TestTransmitterLink)
#include "test_transmitter_link.moc"
