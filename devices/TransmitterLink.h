#pragma once

#include "devices/RcProtocols.h"

#include <QElapsedTimer>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QThread>

#include <atomic>
#include <cstdint>
#include <mutex>

class QSerialPort;
class QTimer;

namespace prisca::devices {

/// Plain settings of a link, copied into its thread.
struct LinkSettings {
    QString port;  ///< device path, e.g. /dev/ttyUSB0 or a pty
    RcProtocol protocol = RcProtocol::Crsf;
    int baud = 0;             ///< 0: the protocol's default
    double rateHz = 50.0;     ///< frames per second
    double staleAfter = 0.1;  ///< a command older than this [s] gives failsafe
    ChannelPulses failsafe = [] {
        ChannelPulses p;
        p.fill(1500.0);
        return p;
    }();                                ///< pulses sent in failsafe [us]
    MultiprotocolHeader multiprotocol;  ///< header fields for the Multiprotocol module
    int reconnectIntervalMs = 300;      ///< how often a lost port is tried again
    /// Also send at once whenever a new command arrives (the fixed rate stays the slowest
    /// pace), so a camera frame's command goes out without waiting for the next tick.
    bool sendOnCommand = false;
};

/// The device a port name means: a path as given; a bare name is a file of that name in the
/// working folder if there is one, else /dev/NAME.
QString serialPortPath(const QString& port);
/// Empty when the port is something a serial link can open; else why not, naming the path
/// (missing, a folder, a regular file).
QString serialPortProblem(const QString& port);

/// Why failsafe is being sent (None: the command is).
enum class FailsafeReason {
    None,
    NoCommand,
    Stale,
    EmergencyStop,
    PoseLost,
    ControllerFault,
    Geofence,  ///< the trial breached its fence (RigLoop)
};
QString failsafeReasonText(FailsafeReason reason);

/// What the link is doing, for the status line.
struct LinkStatus {
    bool connected = false;
    long long framesSent = 0;
    double measuredRateHz = 0.0;  ///< from the last second of writes
    FailsafeReason failsafe = FailsafeReason::NoCommand;
    bool emergencyLatched = false;
    QString lastError;  ///< the last port error (cleared when connected again)
};

class TransmitterLinkWorker;

/// The transmitter link: a QSerialPort in a worker object on its own thread sends the latest
/// command at a fixed rate in the chosen protocol, and failsafe (throttle neutral, steering
/// centred) at once on a stale command, a lost camera pose, a controller fault or E-STOP (latched
/// until resetEmergencyStop()). A port that goes away (unplugged, the far end of a pty closed) is
/// reopened by itself. Every method may be called from any thread; status arrives through the
/// queued statusChanged() signal.
class TransmitterLink : public QObject {
    Q_OBJECT
  public:
    explicit TransmitterLink(QObject* parent = nullptr);
    /// Stops sending, closes the port, quits the thread (bounded wait, never terminated).
    ~TransmitterLink() override;

    /// Opens the port and starts sending (failsafe until the first command).
    void start(const LinkSettings& settings);
    /// Ends with a failsafe frame and closes the port (queued; returns at once).
    void stop();
    /// stop(), returning once the failsafe frame is out and the port closed.
    void stopAndWait();
    /// The command to send, as 16 pulses [us]; stamped now.
    void setCommand(const ChannelPulses& pulses);
    /// Latches E-STOP: failsafe from the next frame on, whatever commands arrive.
    void emergencyStop();
    void resetEmergencyStop();
    /// The camera lost (true) or found again (false) the pose.
    void setPoseLost(bool lost);
    /// The controller failed (latched like E-STOP until resetEmergencyStop()).
    void reportControllerFault();
    /// The trial breached its fence (latched the same way; the status says so).
    void reportGeofenceBreach();
    /// Clears a controller fault or fence breach (a new trial), not E-STOP.
    void clearFault();
    /// Whether E-STOP is latched (any thread).
    bool emergencyLatched() const;

    /// Frames written so far (any thread).
    long long framesSent() const;
    /// For the last frame written that carried a fresh command: steady-clock time [ns] of the
    /// setCommand() it carried, and of the write (0 before any). Any thread.
    std::int64_t lastCommandNs() const;
    std::int64_t lastWriteNs() const;

  signals:
    void statusChanged(const prisca::devices::LinkStatus& status);

  private:
    QThread thread_;
    TransmitterLinkWorker* worker_;
};

/// The worker behind TransmitterLink (its own thread). Public for the link only.
class TransmitterLinkWorker : public QObject {
    Q_OBJECT
  public:
    explicit TransmitterLinkWorker(QObject* parent = nullptr);
    ~TransmitterLinkWorker() override;

    // Thread-safe inputs (a mutex for the command, atomics for the flags).
    void setCommand(const ChannelPulses& pulses);
    std::atomic<bool> emergency{false};
    std::atomic<bool> poseLost{false};
    std::atomic<bool> fault{false};
    std::atomic<bool> fenceBreached{false};  ///< with `fault`: the fault was the fence
    std::atomic<long long> framesSent{0};
    std::atomic<std::int64_t> lastCommandNs{0};
    std::atomic<std::int64_t> lastWriteNs{0};
    std::atomic<bool> sendOnCommand{false};

  public slots:
    void start(const prisca::devices::LinkSettings& settings);
    void stop();
    /// Sends the current command now (sendOnCommand).
    void sendNow();

  signals:
    void statusChanged(const prisca::devices::LinkStatus& status);

  private:
    void tick();
    bool openPort();
    void closePort(const QString& error);
    QByteArray encode(const ChannelPulses& pulses, bool failsafe) const;
    void unregisterFailsafe();

    LinkSettings settings_;
    QSerialPort* port_ = nullptr;
    QTimer* timer_ = nullptr;
    QTimer* deferredSend_ = nullptr;  ///< a command's frame that came too soon after the last
    QElapsedTimer lastFrameClock_;    ///< since the last frame went out (invalid: none yet)
    QElapsedTimer reconnectClock_;
    QElapsedTimer statusClock_;
    QElapsedTimer rateClock_;
    long long framesAtRateMark_ = 0;
    LinkStatus status_;
    std::mutex commandMutex_;
    ChannelPulses command_{};
    QElapsedTimer commandAge_;    ///< invalid until the first command
    std::int64_t commandNs_ = 0;  ///< steady time of the last setCommand()
    bool running_ = false;
    int failsafeSlot_ = -1;  ///< this port's slot in the process failsafe (-1: none)
};

}  // namespace prisca::devices

Q_DECLARE_METATYPE(prisca::devices::LinkSettings)
Q_DECLARE_METATYPE(prisca::devices::LinkStatus)
