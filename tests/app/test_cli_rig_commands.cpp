// prisca-cli link and rig on pseudo-terminals: the channels on the wire, failsafe at every
// ending, a replugged port, the virtual rig's whole chain headless.
#include "CliCommandTest.h"

using namespace prisca::clitest;

class TestCliRigCommands : public QObject, private CliWorkspace {
    Q_OBJECT
  private slots:
    void initTestCase() { writeCarDemonstration(); }

    void rig_virtualRunsTheWholeChainHeadless() {
        // Camera -> tracker -> estimator -> PRISCA -> link -> pseudo-terminal -> car, in real
        // time: one trial of the scripted demonstration (about 6 s).
        const CliResult r = cli({"rig", "--virtual", "--trials", "1", "--format", "json"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(root.value("method").toString(), QStringLiteral("prisca"));
        const QJsonArray trials = root.value("trials").toArray();
        QCOMPARE(trials.size(), 1);
        const QJsonObject t = trials[0].toObject();
        QVERIFY(t.value("frames").toInt() > 100);
        QVERIFY(!t.value("stopped").toBool() && !t.value("failsafe").toBool());
        // The trial lasts the demonstration plus its settling by the frames' clock (4 + 2 s).
        QVERIFY2(t.value("seconds").toDouble() > 5.9 && t.value("seconds").toDouble() < 6.2,
                 qPrintable(QString::number(t.value("seconds").toDouble())));
        QVERIFY(t.value("framesWithPose").toInt() >= t.value("frames").toInt() - 2);
        QVERIFY(t.value("linkFramesDecoded").toDouble() >= t.value("frames").toInt());
        const double miss = t.value("finalPositionErrorCm").toDouble(-1.0);
        QVERIFY2(miss >= 0.0 && miss < 50.0, qPrintable(QString::number(miss)));
        // What a rig cannot run, and the real rig, are refused with the reason.
        // The rig's one rule, in the pre-trial check's words, before any device is opened.
        CliResult bad = cli({"rig", "--virtual", "--method", "oracle"});
        QVERIFY2(bad.exitCode == 2 &&
                     bad.err.contains(QStringLiteral("--method oracle: ") +
                                      prisca::rig::methodRigProblem(true, false, QString())),
                 qPrintable(bad.err));
        for (const QString& id : prisca::sim::MethodCatalog::ids()) {
            const prisca::sim::MethodSpec* spec = prisca::sim::MethodCatalog::find(id);
            if (spec->trainsOffline() && !spec->simulationOnly) {
                bad = cli({"rig", "--virtual", "--method", id});
                QVERIFY2(bad.exitCode == 2 && bad.err.contains(prisca::rig::methodRigProblem(
                                                  false, true, spec->label)),
                         qPrintable(bad.err));
            }
        }
        bad = cli({"rig", "--trials", "1"});
        QVERIFY(bad.exitCode != 0 && bad.err.contains("--virtual"));
    }

    void link_sendsTheChannelsOnAPseudoTerminalThenFailsafe() {
        // The far end of the "transmitter": the test reads the pty master.
        int master = -1, slave = -1;
        char name[256] = {};
        termios raw{};
        cfmakeraw(&raw);
        QCOMPARE(openpty(&master, &slave, name, &raw, nullptr), 0);
        fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
        QProcess process;
        process.setWorkingDirectory(dir_.path());
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", QString::fromLocal8Bit(name), "--protocol", "sbus",
                       "--channels", "1400, 1500,1700", "--duration", "1", "--format", "json"});
        QByteArray received;
        char buffer[4096];
        while (!process.waitForFinished(10)) {
            const ssize_t n = ::read(master, buffer, sizeof buffer);
            if (n > 0)
                received.append(buffer, static_cast<int>(n));
        }
        for (ssize_t n; (n = ::read(master, buffer, sizeof buffer)) > 0;) {
            received.append(buffer, static_cast<int>(n));
        }
        ::close(master);
        ::close(slave);
        QCOMPARE(process.exitCode(), 0);
        const QJsonObject summary = parseJson(QString::fromUtf8(process.readAllStandardOutput()));
        QCOMPARE(summary.value("protocol").toString(), QStringLiteral("sbus"));
        const int frames = summary.value("framesSent").toInt();
        QVERIFY2(frames >= 40 && frames <= 70, qPrintable(QString::number(frames)));
        // SBUS frames, 25 bytes each: the channels as given, then failsafe at the end.
        QVERIFY(received.size() >= 25 * 40);
        int start = received.indexOf('\x0f');
        QVERIFY(start >= 0);
        const auto channel = [&](int frameStart, int index) {
            int value = 0;
            for (int b = 0; b < 11; ++b) {
                const int bit = index * 11 + b;
                if (static_cast<unsigned char>(received[frameStart + 1 + bit / 8]) &
                    (1 << (bit % 8))) {
                    value |= 1 << b;
                }
            }
            return value;
        };
        QCOMPARE(channel(start, 0), 831);   // 1400 us
        QCOMPARE(channel(start, 1), 992);   // 1500 us
        QCOMPARE(channel(start, 2), 1312);  // 1700 us
        const int last = static_cast<int>(received.size()) - 25;
        QCOMPARE(static_cast<unsigned char>(received[last]), 0x0f);
        QCOMPARE(channel(last, 0), 992);  // failsafe: everything back to centre
        QCOMPARE(channel(last, 2), 992);
        QCOMPARE(static_cast<unsigned char>(received[last + 23]) & 0x08, 0x08);
    }

    // The link ended by a signal: SIGTERM and SIGINT send failsafe frames before exiting and say
    // so; unplugged first, it says no failsafe frame could go out; SIGKILL leaves the last
    // command as the last frame and silence after it (the receiver's own failsafe then acts).
    void link_endedBySignals_data() {
        QTest::addColumn<int>("signal");
        QTest::addColumn<bool>("unplugFirst");
        QTest::newRow("SIGTERM") << int(SIGTERM) << false;
        QTest::newRow("SIGINT") << int(SIGINT) << false;
        QTest::newRow("SIGTERM while unplugged") << int(SIGTERM) << true;
        QTest::newRow("SIGKILL") << int(SIGKILL) << false;
    }

    void link_endedBySignals() {
        QFETCH(int, signal);
        QFETCH(bool, unplugFirst);
        Pty pty;
        QVERIFY(keptFromChildren(pty));
        QTemporaryDir ports;
        const QString port = ports.filePath("ttyRC");  // a stable path, as udev gives
        QVERIFY(QFile::link(pty.path, port));
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", port, "--protocol", "sbus", "--channels", "1400,1500,1700",
                       "--duration", "600"});
        QByteArray received;
        const auto drain = [&] { received += pty.read(); };
        // Wait on the frames themselves: ten of them.
        QVERIFY(QTest::qWaitFor(
            [&] {
                drain();
                return received.size() >= 250;
            },
            30000));
        if (unplugFirst) {
            pty.closeAll();
            QFile::remove(port);  // the device node goes with the cable
        }
        QElapsedTimer sinceSignal;
        sinceSignal.start();
        ::kill(static_cast<pid_t>(process.processId()), signal);
        qint64 lastByteMs = -1;
        while (!process.waitForFinished(5)) {
            if (!unplugFirst) {
                const qsizetype before = received.size();
                drain();
                if (received.size() > before) {
                    lastByteMs = sinceSignal.elapsed();
                }
            }
        }
        if (!unplugFirst) {
            drain();
            pty.closeAll();
        }
        const QString out = QString::fromLocal8Bit(process.readAllStandardOutput());
        if (signal == SIGKILL) {
            QCOMPARE(process.exitStatus(), QProcess::CrashExit);
            // The last whole frame is the command, not failsafe: nothing ran after the kill.
            const qsizetype last = received.lastIndexOf('\x0f', received.size() - 25);
            QVERIFY(last >= 0);
            QCOMPARE(static_cast<unsigned char>(received[last + 23]) & 0x08, 0);  // no failsafe
            if (lastByteMs < 0) {
                qInfo("SIGKILL: no byte after the signal, silence from then on");
            } else {
                qInfo("SIGKILL: the last bytes %lld ms after the signal, then silence",
                      static_cast<long long>(lastByteMs));
            }
            return;
        }
        QCOMPARE(process.exitCode(), 128 + signal);
        if (unplugFirst) {
            QVERIFY2(out.contains("no failsafe frame could go out"), qPrintable(out));
            return;
        }
        QVERIFY2(out.contains("ending in failsafe"), qPrintable(out));
        // The last frame on the wire carries SBUS's failsafe flag.
        const qsizetype last = received.size() - 25;
        QCOMPARE(static_cast<unsigned char>(received[last]), 0x0f);
        QVERIFY2(static_cast<unsigned char>(received[last + 23]) & 0x08,
                 "the last frame is not failsafe");
    }

    // The cable pulled and put back while prisca-cli link runs: the pty's far end goes away
    // and a new one appears behind the same path; frames resume on it.
    void link_resumesAfterUnplugAndReplug() {
        auto first = std::make_unique<Pty>();
        QVERIFY(keptFromChildren(*first));
        QTemporaryDir ports;
        const QString port = ports.filePath("ttyRC");
        QVERIFY(QFile::link(first->path, port));
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"link", "--port", port, "--protocol", "sbus", "--channels", "1400,1500,1700",
                       "--duration", "600"});
        QByteArray received;
        QVERIFY(QTest::qWaitFor(
            [&] {
                received += first->read();
                return received.size() >= 250;
            },
            30000));
        first.reset();  // unplugged: the device node goes with the cable
        QFile::remove(port);
        Pty second;
        QVERIFY(keptFromChildren(second));
        QElapsedTimer sincePlug;
        sincePlug.start();
        QVERIFY(QFile::link(second.path, port));
        QByteArray resumed;
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         resumed += second.read();
                         return resumed.size() >= 250;  // ten frames on the new port
                     },
                     30000),
                 qPrintable(process.readAllStandardError()));
        qInfo("frames resumed on the replugged port; ten frames %lld ms after the plug",
              static_cast<long long>(sincePlug.elapsed()));
        const qsizetype at = resumed.indexOf('\x0f');
        QVERIFY(at >= 0 && at + 25 <= resumed.size());
        QCOMPARE(static_cast<unsigned char>(resumed[at + 24]), 0x00);  // an SBUS frame's end
        ::kill(static_cast<pid_t>(process.processId()), SIGTERM);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitCode(), 128 + SIGTERM);
    }

    // SIGTERM or SIGINT in the middle of a trial of prisca-cli rig --virtual: the trial ends
    // stopped, the link's last frames are failsafe, and the car's receiver is left neutral.
    void rig_endedBySignalLeavesTheCarNeutral_data() {
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGTERM") << int(SIGTERM);
        QTest::newRow("SIGINT") << int(SIGINT);
    }

    void rig_endedBySignalLeavesTheCarNeutral() {
        QFETCH(int, signal);
        QProcess process;
        process.start(QStringLiteral(PRISCA_CLI),
                      {"rig", "--virtual", "--trials", "1", "--format", "json"});
        QByteArray err;
        // One second into the trial the car is being driven (the demonstration's commands).
        QVERIFY2(QTest::qWaitFor(
                     [&] {
                         process.waitForReadyRead(5);
                         err += process.readAllStandardError();
                         return err.contains("rig: trial 1/1: 1 of") ||
                                process.state() == QProcess::NotRunning;
                     },
                     60000),
                 err.constData());
        QVERIFY2(process.state() == QProcess::Running, err.constData());
        ::kill(static_cast<pid_t>(process.processId()), signal);
        QVERIFY(process.waitForFinished(30000));
        QCOMPARE(process.exitCode(), 128 + signal);
        const QJsonObject out = QJsonDocument::fromJson(process.readAllStandardOutput()).object();
        const QJsonObject trial = out["trials"].toArray().at(0).toObject();
        QVERIFY2(trial["stopped"].toBool(), qPrintable(QJsonDocument(out).toJson()));
        QVERIFY(trial["linkFramesDecoded"].toDouble() > 0);
        // The frame-to-command latency's median, 99th percentile and worst, in order.
        const double median = trial["medianFrameToCommandMs"].toDouble(-2.0);
        const double p99 = trial["p99FrameToCommandMs"].toDouble(-2.0);
        const double worst = trial["worstFrameToCommandMs"].toDouble(-2.0);
        QVERIFY2(median >= 0.0 && median <= p99 && p99 <= worst,
                 qPrintable(QJsonDocument(trial).toJson()));
        const QJsonArray held = out["receiverLastCommand"].toArray();
        QCOMPARE(held.size(), 2);  // steering, throttle
        for (const QJsonValue& u : held) {
            QVERIFY2(std::abs(u.toDouble()) <= 2.0 / 512.0,
                     qPrintable(QJsonDocument(out).toJson()));
        }
        QVERIFY(out["receiverNeutral"].toBool());
    }

    // doctor: a port this process opened is listed as one the user can open; a calibration
    // that does not read keeps the rig from being ready (exit 1) and is named; the window's
    // folders are the XDG ones; the text says FIX where something is missing.
    void doctor_listsWhatTheRigNeedsAndExitsOneWhenSomethingIsMissing() {
        int master = -1;
        int slave = -1;
        char name[256] = {};
        QCOMPARE(openpty(&master, &slave, name, nullptr, nullptr), 0);
        const QString pty = QString::fromLocal8Bit(name);
        writeFile(path("broken-floor.json"), "{ \"points\": ");
        const QByteArray oldData = qgetenv("XDG_DATA_HOME");
        qputenv("XDG_DATA_HOME", path("xdg-data").toLocal8Bit());
        const CliResult r = cli({"doctor", "--port", pty, "--calibration",
                                 path("broken-floor.json"), "--format", "json"});
        const CliResult text =
            cli({"doctor", "--port", pty, "--calibration", path("broken-floor.json")});
        qputenv("XDG_DATA_HOME", oldData);
        ::close(slave);
        ::close(master);
        QVERIFY2(r.exitCode == 1, qPrintable(r.err + r.out));
        const QJsonObject root = parseJson(r.out);
        QCOMPARE(root.value("ready").toBool(true), false);
        bool portListed = false;
        bool calibrationNamed = false;
        for (const QJsonValue& v : root.value("items").toArray()) {
            const QJsonObject item = v.toObject();
            portListed =
                portListed || (item.value("key").toString() == "serial-port" &&
                               item.value("label").toString().contains(pty) &&
                               item.value("ok").toBool() && item.value("required").toBool());
            calibrationNamed =
                calibrationNamed ||
                (item.value("key").toString() == "calibration" && !item.value("ok").toBool(true) &&
                 item.value("detail").toString().contains("broken-floor"));
        }
        QVERIFY2(portListed, qPrintable(r.out));
        QVERIFY2(calibrationNamed, qPrintable(r.out));
        QCOMPARE(root.value("folders").toObject().value("bundles").toString(),
                 path("xdg-data") + "/PRISCA Lab/prisca/trials");
        QCOMPARE(text.exitCode, 1);
        QVERIFY2(text.out.contains(QRegularExpression("^FIX +Floor calibration: ",
                                                      QRegularExpression::MultilineOption)),
                 qPrintable(text.out));
        QVERIFY(text.out.contains(QStringLiteral("OK    Serial port %1: can be opened").arg(pty)));
    }

    void link_badInputGivesOneLineAndExitTwo() {
        CliResult r = cli({"link", "--port", "/dev/null", "--channels", "1500,abc"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("CH2") && r.err.count('\n') == 1, qPrintable(r.err));
        r = cli({"link", "--port", "/dev/null", "--protocol", "ppm", "--channels", "1500"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("ppm"), qPrintable(r.err));
        r = cli({"link", "--port", "/dev/no-such-transmitter", "--channels", "1500", "--duration",
                 "3"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("/dev/no-such-transmitter"), qPrintable(r.err));
        r = cli({"link", "--port", "/dev/null", "--channels", "1500,2500"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("800 to 2200"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliRigCommands)
#include "test_cli_rig_commands.moc"
