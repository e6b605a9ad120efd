#include "devices/TransmitterLink.h"

#include "devices/ProcessFailsafe.h"
#include "devices/ThreadHandOff.h"
#include "devices/ThreadPriority.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QLoggingCategory>
#include <QMetaObject>
#include <QSerialPort>
#include <QTimer>

#include <chrono>
#include <cmath>

#include <unistd.h>

Q_LOGGING_CATEGORY(lcLink, "prisca.devices.link")

namespace prisca::devices {

namespace {
constexpr unsigned long kShutdownWaitMs = 3000;
constexpr int kStatusMs = 200;

std::int64_t steadyNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
}  // namespace

QString failsafeReasonText(FailsafeReason reason) {
    switch (reason) {
        // In the interface's language where a translator is installed (the window), English
        // otherwise (the command line).
        case FailsafeReason::None:
            return QCoreApplication::translate("prisca::devices::TransmitterLink", "none");
        case FailsafeReason::NoCommand:
            return QCoreApplication::translate("prisca::devices::TransmitterLink",
                                               "no command yet");
        case FailsafeReason::Stale:
            return QCoreApplication::translate("prisca::devices::TransmitterLink", "stale command");
        case FailsafeReason::EmergencyStop:
            return QCoreApplication::translate("prisca::devices::TransmitterLink", "E-STOP");
        case FailsafeReason::PoseLost:
            return QCoreApplication::translate("prisca::devices::TransmitterLink",
                                               "camera pose lost");
        case FailsafeReason::ControllerFault:
            return QCoreApplication::translate("prisca::devices::TransmitterLink",
                                               "controller fault");
        case FailsafeReason::Geofence:
            return QCoreApplication::translate("prisca::devices::TransmitterLink",
                                               "fence breached");
    }
    return {};
}

// ---- facade -------------------------------------------------------------------------------

TransmitterLink::TransmitterLink(QObject* parent)
    : QObject(parent), worker_(new TransmitterLinkWorker) {
    qRegisterMetaType<LinkSettings>();
    qRegisterMetaType<LinkStatus>();
    thread_.setObjectName(QStringLiteral("prisca-link"));
    worker_->moveToThread(&thread_);
    connect(worker_, &TransmitterLinkWorker::statusChanged, this, &TransmitterLink::statusChanged);
    markThreadEnd(thread_);
    thread_.start();
    // Frames are written on this thread: ahead of other programs' work.
    postTo(worker_, [] { raiseCurrentThreadPriority(); });
}

TransmitterLink::~TransmitterLink() {
    // Failsafe first, so the last frame the far end sees is neutral, then close.
    worker_->emergency.store(true);
    QMetaObject::invokeMethod(worker_, &TransmitterLinkWorker::stop, Qt::BlockingQueuedConnection);
    endWorkerThread(thread_, worker_, kShutdownWaitMs);
}

void TransmitterLink::start(const LinkSettings& settings) {
    postTo(worker_, [w = worker_, settings] { w->start(settings); });
}

void TransmitterLink::stop() {
    postTo(worker_, [w = worker_] { w->stop(); });
}

void TransmitterLink::stopAndWait() {
    QMetaObject::invokeMethod(worker_, &TransmitterLinkWorker::stop, Qt::BlockingQueuedConnection);
}

void TransmitterLink::setCommand(const ChannelPulses& pulses) {
    worker_->setCommand(pulses);
    if (worker_->sendOnCommand.load()) {
        postTo(worker_, [w = worker_] { w->sendNow(); });
    }
}

std::int64_t TransmitterLink::lastCommandNs() const {
    return worker_->lastCommandNs.load();
}

std::int64_t TransmitterLink::lastWriteNs() const {
    return worker_->lastWriteNs.load();
}

void TransmitterLink::emergencyStop() {
    worker_->emergency.store(true);
}

void TransmitterLink::resetEmergencyStop() {
    processfailsafe::releaseHold();  // the operator takes over after a stop and continue
    worker_->fault.store(false);
    worker_->fenceBreached.store(false);
    worker_->emergency.store(false);
}

void TransmitterLink::setPoseLost(bool lost) {
    worker_->poseLost.store(lost);
}

void TransmitterLink::reportControllerFault() {
    worker_->fault.store(true);
}

void TransmitterLink::clearFault() {
    worker_->fault.store(false);
    worker_->fenceBreached.store(false);
}

bool TransmitterLink::emergencyLatched() const {
    return worker_->emergency.load() || processfailsafe::held();
}

void TransmitterLink::reportGeofenceBreach() {
    worker_->fenceBreached.store(true);
    worker_->fault.store(true);
}

long long TransmitterLink::framesSent() const {
    return worker_->framesSent.load();
}

// ---- worker -------------------------------------------------------------------------------

TransmitterLinkWorker::TransmitterLinkWorker(QObject* parent) : QObject(parent) {}

TransmitterLinkWorker::~TransmitterLinkWorker() {
    unregisterFailsafe();  // before the port (a child) closes its descriptor
}

void TransmitterLinkWorker::setCommand(const ChannelPulses& pulses) {
    std::lock_guard<std::mutex> lock(commandMutex_);
    command_ = pulses;
    commandAge_.restart();
    commandNs_ = steadyNs();
}

void TransmitterLinkWorker::sendNow() {
    if (!running_ || !timer_) {
        return;
    }
    // Never sooner after the last frame than the line allows (maxFrameRate): frames would queue
    // behind each other, and SBUS receivers (the bridge too) find frames by the gap between.
    const double spacing = 1.0 / maxFrameRate(settings_.protocol, settings_.baud);
    const double since =
        lastFrameClock_.isValid() ? lastFrameClock_.nsecsElapsed() * 1e-9 : spacing;
    if (since < spacing) {
        if (!deferredSend_) {
            deferredSend_ = new QTimer(this);
            deferredSend_->setSingleShot(true);
            deferredSend_->setTimerType(Qt::PreciseTimer);
            connect(deferredSend_, &QTimer::timeout, this, &TransmitterLinkWorker::sendNow);
        }
        if (!deferredSend_->isActive()) {
            deferredSend_->start(static_cast<int>(std::ceil((spacing - since) * 1000.0)));
        }
        return;
    }
    tick();
    timer_->start();  // the next fixed-rate frame a full period after this one
}

void TransmitterLinkWorker::start(const LinkSettings& settings) {
    stop();
    settings_ = settings;
    sendOnCommand.store(settings.sendOnCommand);
    if (settings_.baud <= 0) {
        settings_.baud = defaultSerialFormat(settings_.protocol).baud;
    }
    if (!port_) {
        port_ = new QSerialPort(this);
        // A port that goes away mid-run (unplugged, pty closed): close and try again later.
        connect(port_, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
            if (e == QSerialPort::ResourceError || e == QSerialPort::WriteError ||
                e == QSerialPort::ReadError) {
                closePort(port_->errorString());
            }
        });
        // Whatever the far end sends (telemetry, garbage) is read and dropped: never a crash,
        // never an unbounded buffer.
        connect(port_, &QSerialPort::readyRead, this, [this] { port_->readAll(); });
    }
    if (!timer_) {
        timer_ = new QTimer(this);
        timer_->setTimerType(Qt::PreciseTimer);
        connect(timer_, &QTimer::timeout, this, &TransmitterLinkWorker::tick);
    }
    status_ = LinkStatus{};
    running_ = true;
    openPort();
    statusClock_.start();
    rateClock_.start();
    framesAtRateMark_ = framesSent.load();
    // Never faster than the line carries (LinkCommand refuses more; others get the limit).
    const double rate =
        std::min(settings_.rateHz, maxFrameRate(settings_.protocol, settings_.baud));
    timer_->start(std::max(1, static_cast<int>(std::lround(1000.0 / rate))));
    emit statusChanged(status_);
}

QString serialPortPath(const QString& port) {
    if (port.contains(QLatin1Char('/'))) {
        return port;
    }
    // A bare name: a file of that name here is meant (as for any other path); else the device
    // of that name, as the serial port library reads it (ttyUSB0 is /dev/ttyUSB0).
    if (QFileInfo::exists(port)) {
        return QFileInfo(port).absoluteFilePath();
    }
    return QStringLiteral("/dev/") + port;
}

QString serialPortProblem(const QString& port) {
    const QString path = serialPortPath(port);
    const QFileInfo info(path);
    if (!info.exists()) {
        return QStringLiteral("%1: no such device (is the transmitter plugged in?)").arg(path);
    }
    if (info.isDir()) {
        return QStringLiteral("%1: is a folder, not a serial device").arg(path);
    }
    if (info.isFile()) {
        return QStringLiteral("%1: is a regular file, not a serial device").arg(path);
    }
    return QString();
}

bool TransmitterLinkWorker::openPort() {
    reconnectClock_.restart();
    const QString path = serialPortPath(settings_.port);
    if (const QString problem = serialPortProblem(path); !problem.isEmpty()) {
        status_.connected = false;
        status_.lastError = problem;
        return false;
    }
    port_->setPortName(path);
    if (!port_->open(QIODevice::ReadWrite)) {
        status_.connected = false;
        QString why = port_->errorString();
        if (port_->error() == QSerialPort::PermissionError) {
            // Qt says "permission" for a port another program holds (its lock) as well as for
            // one this user may not open: which it is, in the operator's words.
            const QByteArray native = QFile::encodeName(path);
            why = ::access(native.constData(), R_OK | W_OK) == 0
                      ? QStringLiteral(
                            "in use by another program (a second link, a terminal "
                            "program): close it first")
                      : QStringLiteral(
                            "this user may not open it (add the user to the group "
                            "that owns it, usually dialout, and log in again)");
        }
        status_.lastError = QStringLiteral("%1: %2").arg(path, why);
        return false;
    }
    const SerialFormat format = defaultSerialFormat(settings_.protocol);
    // Line settings a pseudo-terminal cannot take (odd baud rates, DTR/RTS) are noted, not
    // fatal: the bytes still flow, and on real hardware the port accepts them.
    if (!port_->setBaudRate(settings_.baud)) {
        qCInfo(lcLink) << "baud rate" << settings_.baud << "not applied:" << port_->errorString();
    }
    port_->setDataBits(QSerialPort::Data8);
    port_->setParity(format.evenParity ? QSerialPort::EvenParity : QSerialPort::NoParity);
    port_->setStopBits(format.twoStopBits ? QSerialPort::TwoStop : QSerialPort::OneStop);
    port_->setFlowControl(QSerialPort::NoFlowControl);
    if (!port_->setDataTerminalReady(true) || !port_->setRequestToSend(false)) {
        qCInfo(lcLink) << "DTR/RTS not set on" << settings_.port << "(a pseudo-terminal?)";
    }
    port_->clearError();
    // The last resort's copy: however the process ends, failsafe goes out on this port.
    failsafeSlot_ = processfailsafe::registerPort(static_cast<int>(port_->handle()),
                                                  encode(settings_.failsafe, true));
    status_.connected = true;
    status_.lastError.clear();
    qCInfo(lcLink) << "sending" << protocolName(settings_.protocol) << "on" << settings_.port;
    return true;
}

void TransmitterLinkWorker::closePort(const QString& error) {
    if (port_ && port_->isOpen()) {
        qCWarning(lcLink) << "lost" << settings_.port << ":" << error;
        unregisterFailsafe();
        port_->close();
    }
    status_.connected = false;
    status_.lastError = error;
    reconnectClock_.restart();
    emit statusChanged(status_);
}

void TransmitterLinkWorker::stop() {
    if (!running_) {
        return;
    }
    running_ = false;
    if (timer_) {
        timer_->stop();
    }
    if (deferredSend_) {
        deferredSend_->stop();
    }
    if (port_ && port_->isOpen()) {
        // The last frame out is failsafe, counted like any other once the device has taken it.
        const QByteArray frame = encode(settings_.failsafe, true);
        port_->clear(QSerialPort::Output);  // nothing queued goes out after it
        if (port_->write(frame) == frame.size()) {
            port_->flush();
            if (port_->bytesToWrite() == 0 || port_->waitForBytesWritten(50)) {
                framesSent.fetch_add(1);
                status_.framesSent = framesSent.load();
                processfailsafe::noteFailsafeEnding();
            }
        }
        unregisterFailsafe();
        port_->close();
    }
    status_.connected = false;
    emit statusChanged(status_);
}

void TransmitterLinkWorker::unregisterFailsafe() {
    processfailsafe::unregisterPort(failsafeSlot_);
    failsafeSlot_ = -1;
}

QByteArray TransmitterLinkWorker::encode(const ChannelPulses& pulses, bool failsafe) const {
    ChannelValues values{};
    for (int c = 0; c < 16; ++c) {
        values[c] = pulseToValue(settings_.protocol, pulses[c]);
    }
    switch (settings_.protocol) {
        case RcProtocol::Crsf:
            return encodeCrsf(values);
        case RcProtocol::Sbus:
        case RcProtocol::PpmBridge:
            return encodeSbus(values, failsafe);
        case RcProtocol::Multiprotocol:
            return encodeMultiprotocol(values, settings_.multiprotocol);
    }
    return {};
}

void TransmitterLinkWorker::tick() {
    if (!running_) {
        return;
    }
    if (!port_->isOpen()) {
        if (reconnectClock_.elapsed() >= settings_.reconnectIntervalMs && openPort()) {
            emit statusChanged(status_);
        }
        if (!port_->isOpen()) {
            return;
        }
    }
    // Decide what goes out: the command, or failsafe and why.
    ChannelPulses pulses;
    FailsafeReason reason = FailsafeReason::None;
    std::int64_t commandNs = 0;
    {
        std::lock_guard<std::mutex> lock(commandMutex_);
        pulses = command_;
        commandNs = commandNs_;
        if (!commandAge_.isValid()) {
            reason = FailsafeReason::NoCommand;
        } else if (commandAge_.nsecsElapsed() * 1e-9 > settings_.staleAfter) {
            reason = FailsafeReason::Stale;
        }
    }
    if (emergency.load() || processfailsafe::ending() || processfailsafe::held()) {
        reason = FailsafeReason::EmergencyStop;
    } else if (fault.load()) {
        reason = fenceBreached.load() ? FailsafeReason::Geofence : FailsafeReason::ControllerFault;
    } else if (poseLost.load()) {
        reason = FailsafeReason::PoseLost;
    }
    const bool failsafe = reason != FailsafeReason::None;
    if (failsafe && status_.failsafe == FailsafeReason::None) {
        port_->clear(QSerialPort::Output);  // failsafe replaces commands still queued, never after
    }
    const QByteArray frame = encode(failsafe ? settings_.failsafe : pulses, failsafe);
    if (port_->write(frame) != frame.size()) {
        closePort(port_->errorString());
        return;
    }
    // Into the device now: a port that is gone (unplugged, the far end of a pty closed) fails
    // here, and a frame is counted as sent only once the device has taken it, so "ending in
    // failsafe" is said only when failsafe frames really went out.
    port_->flush();
    if (port_->error() != QSerialPort::NoError && port_->error() != QSerialPort::TimeoutError) {
        closePort(port_->errorString());
        return;
    }
    if (port_->bytesToWrite() > 0) {
        return;  // the device is not taking bytes as fast as they come: not sent (yet)
    }
    framesSent.fetch_add(1);
    lastFrameClock_.restart();
    if (!failsafe) {
        lastCommandNs.store(commandNs);
        lastWriteNs.store(steadyNs());
    }
    status_.framesSent = framesSent.load();
    status_.failsafe = reason;
    status_.emergencyLatched = emergency.load() || fault.load() || processfailsafe::held();
    if (rateClock_.elapsed() >= 1000) {
        status_.measuredRateHz =
            (framesSent.load() - framesAtRateMark_) * 1000.0 / rateClock_.restart();
        framesAtRateMark_ = framesSent.load();
    }
    if (statusClock_.elapsed() >= kStatusMs) {
        statusClock_.restart();
        emit statusChanged(status_);
    }
}

}  // namespace prisca::devices
