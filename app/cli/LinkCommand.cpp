// prisca-cli link: send fixed channel values to a transmitter for a while (a bench test of the
// link, the protocol and the channel wiring, with no camera and no controller).
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "devices/ProcessFailsafe.h"
#include "devices/TransmitterLink.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonObject>
#include <QThread>

#include <cmath>
#include <cstdio>

namespace prisca::app::cli {

int linkCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("link"),
        QStringLiteral("Send channel values to a transmitter over a serial link at a fixed "
                       "rate, then failsafe (throttle neutral, steering centred) and close. "
                       "Ctrl-C stops at once, in failsafe."));
    line.addValue("port", "Serial device path (e.g. /dev/ttyUSB0, or a pseudo-terminal).", "path");
    line.addValue("protocol",
                  "crsf, sbus, multiprotocol or ppm-bridge (SBUS to the trainer-port bridge).",
                  "name", "crsf");
    line.addValue("baud",
                  "Baud rate (default: the protocol's: crsf 420000, sbus and "
                  "multiprotocol 100000 8E2).",
                  "B", "0");
    line.addValue("channels",
                  "Pulse widths [us] of CH1, CH2, ... (up to 16; the rest 1500), "
                  "e.g. \"1500,1500,1600\".",
                  "us,us,...");
    line.addValue("rate", "Frames per second.", "Hz", "50");
    line.addValue("duration", "How long to send [s].", "S", "5");
    addVerboseOption(line);
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    applyVerbosity(line);
    devices::LinkSettings settings;
    settings.port = line.required("port");
    const auto protocol = devices::parseProtocol(line.value("protocol"));
    if (!protocol) {
        throw UsageError(
            QStringLiteral("--protocol: '%1' is not crsf, sbus, multiprotocol or ppm-bridge")
                .arg(line.value("protocol")));
    }
    settings.protocol = *protocol;
    settings.baud = static_cast<int>(line.integer("baud", 0, 10000000));
    settings.rateHz = line.number("rate", 1.0, 1000.0);
    if (const double most = devices::maxFrameRate(settings.protocol, settings.baud);
        settings.rateHz > most) {
        throw UsageError(
            QStringLiteral("--rate %1: %2 at %3 baud carries %4 frames/s; at most %5 may be sent "
                           "(with room to spare, so frames never queue and a failsafe goes out "
                           "next)")
                .arg(settings.rateHz)
                .arg(devices::protocolName(settings.protocol))
                .arg(settings.baud > 0 ? settings.baud
                                       : devices::defaultSerialFormat(settings.protocol).baud)
                .arg(std::floor(devices::lineFrameCapacity(settings.protocol, settings.baud)))
                .arg(std::floor(most)));
    }
    const double duration = line.number("duration", 0.0, 86400.0);
    devices::ChannelPulses pulses;
    pulses.fill(1500.0);
    const QStringList values = line.required("channels").split(QLatin1Char(','));
    if (values.size() > 16) {
        throw UsageError(
            QStringLiteral("--channels: %1 values given, at most 16").arg(values.size()));
    }
    for (int c = 0; c < values.size(); ++c) {
        bool ok = false;
        const double us = values[c].trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(us) || us < 800.0 || us > 2200.0) {
            throw UsageError(QStringLiteral("--channels: CH%1 '%2' is not a pulse width of 800 to "
                                            "2200 us")
                                 .arg(c + 1)
                                 .arg(values[c].trimmed()));
        }
        pulses[c] = us;
    }

    // What cannot be a serial device is said at once (an unplugged device is waited for).
    if (const QString problem = devices::serialPortProblem(settings.port);
        !problem.isEmpty() && QFileInfo::exists(devices::serialPortPath(settings.port))) {
        throw UsageError(problem);
    }
    installInterruptHandler();
    devices::TransmitterLink link;
    devices::LinkStatus status;
    QObject::connect(&link, &devices::TransmitterLink::statusChanged,
                     [&status](const devices::LinkStatus& s) { status = s; });
    link.start(settings);
    QElapsedTimer clock;
    clock.start();
    bool faultInjected = false;
    while (clock.elapsed() < duration * 1000.0 && !interrupted()) {
        link.setCommand(pulses);  // fresh, so the link never sees it as stale
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        QThread::msleep(5);
        if (!faultInjected && link.framesSent() >= 10) {
            faultInjected = true;
            devices::processfailsafe::injectFaultForTesting();  // the tests' faults; else nothing
        }
        if (clock.elapsed() >= 1000 && status.framesSent == 0 && !status.lastError.isEmpty()) {
            break;  // the port never opened: say why below
        }
    }
    const long long beforeFailsafe = link.framesSent();
    link.emergencyStop();  // the last frames out are failsafe, if the port is there to take them
    QThread::msleep(static_cast<unsigned long>(std::ceil(2000.0 / settings.rateHz)));
    link.stopAndWait();  // and the closing frame, failsafe too
    QCoreApplication::processEvents();
    const long long frames = link.framesSent();
    const long long failsafeFrames = frames - beforeFailsafe;
    if (interrupted()) {
        std::fprintf(
            stderr, "prisca-cli: link: stopped by %s; %s\n",
            interruptionName().toLatin1().constData(),
            failsafeFrames > 0
                ? qPrintable(QStringLiteral("ended in failsafe (%1 frames)").arg(failsafeFrames))
                : "no failsafe frame could go out (the port was gone)");
    }
    const double seconds = clock.elapsed() / 1000.0;
    if (frames == 0) {
        throw UsageError(status.lastError.isEmpty()
                             ? QStringLiteral("nothing was sent on %1").arg(settings.port)
                             : status.lastError);
    }
    if (line.format() == QLatin1String("json")) {
        printJson({{"port", settings.port},
                   {"protocol", devices::protocolName(settings.protocol)},
                   {"framesSent", static_cast<double>(frames)},
                   {"seconds", seconds},
                   {"rateHz", frames / std::max(seconds, 1e-9)},
                   {"failsafeFramesAtEnd", static_cast<double>(failsafeFrames)},
                   {"lastError", status.lastError}});
    } else {
        // Only frames that went out can be failsafe: with the port gone (unplugged) the receiver
        // falls back to its own failsafe when frames stop.
        const QString ending =
            failsafeFrames > 0
                ? QStringLiteral("ending in failsafe (%1 frames)").arg(failsafeFrames)
                : QStringLiteral(
                      "no failsafe frame could go out at the end (the port was "
                      "gone); the receiver's own failsafe takes over when frames "
                      "stop");
        printText(QStringLiteral("%1 on %2: %3 frames in %4 s (%5 per second), %6%7\n")
                      .arg(devices::protocolName(settings.protocol), settings.port)
                      .arg(frames)
                      .arg(seconds, 0, 'f', 2)
                      .arg(frames / std::max(seconds, 1e-9), 0, 'f', 1)
                      .arg(ending)
                      .arg(status.lastError.isEmpty()
                               ? QString()
                               : QStringLiteral("; last error: %1").arg(status.lastError)));
    }
    return interrupted() ? interruptedExitCode() : 0;
}

}  // namespace prisca::app::cli
