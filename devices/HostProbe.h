#pragma once

// What this computer offers the rig, read from the operating system: the serial ports and
// whether this user may open each, the V4L2 cameras and their capture modes, the display, the
// free space of a folder. Plain facts for rig::doctor(); nothing here opens a device for longer
// than a query, or writes one.

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace prisca::devices {

/// Who may open a device node and whether this process may (read and write).
struct NodeAccess {
    bool exists = false;
    bool canOpen = false;        ///< read and write allowed for this process now
    QString group;               ///< the node's group ("dialout", "video"); empty if unknown
    bool inGroupNow = false;     ///< this process has that group
    bool inGroupListed = false;  ///< the user is listed in it (e.g. /etc/group): after a new login
    QString error;               ///< why not, when it cannot be opened (errno's words)
};

/// A serial port as the system lists it.
struct SerialPortFacts {
    QString path;         ///< "/dev/ttyUSB0"
    QStringList aliases;  ///< other names asked for that lead to it (/dev/serial/by-id/...)
    QString description;
    QString manufacturer;
    std::optional<std::uint16_t> vendorId, productId;
    NodeAccess access;
};

/// A video device node and what it can capture.
struct CameraFacts {
    QString path;  ///< "/dev/video0"
    QString card;  ///< the driver's name for it
    NodeAccess access;
    bool capture = false;  ///< a video capture device (not metadata, not output)
    QStringList modes;     ///< "YUYV 640x480", "MJPG 1280x720", ... (at most a dozen)
    QString error;         ///< what the query said when it failed
};

/// The serial ports (QSerialPortInfo's list, plus `extra` paths the caller names, such as a
/// configured port that is not a USB device), with each one's access.
std::vector<SerialPortFacts> probeSerialPorts(const QStringList& extra = {});
/// The /dev/video* nodes (and `extra`), each queried through V4L2.
std::vector<CameraFacts> probeCameras(const QStringList& extra = {});
/// Access to one node.
NodeAccess probeAccess(const QString& path);

/// The display the window would open on: "X11 :0", "Wayland wayland-0", or empty when none.
QString displayName();
/// The OpenGL libraries found (libGL, libEGL) and whether a GPU's render node exists.
struct OpenGlFacts {
    bool libraryFound = false;
    QString library;
    bool renderNode = false;  ///< /dev/dri/renderD* present (else software rendering)
};
OpenGlFacts probeOpenGl();

/// Free bytes for this user on the file system holding `folder` (its nearest existing
/// ancestor); nullopt when it cannot be read.
std::optional<std::int64_t> freeBytes(const QString& folder);

/// The udev rule files of the package found on this system (the shipped rule's known places).
QStringList installedUdevRules();

}  // namespace prisca::devices
