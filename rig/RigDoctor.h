#pragma once

// `prisca-cli doctor` and the Rig tab's "Check this computer": whether this computer has what
// the rig needs (a serial port this user may open, a camera, the calibration and lens files,
// free space for the trial bundles) and what the window needs (a display, OpenGL), each line OK
// or what to do. The verdict is a pure function of the facts (testable with any facts); the
// facts come from devices/HostProbe.

#include "devices/HostProbe.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>
#include <vector>

namespace prisca::rig {

/// The window's folders as the platform's conventions (XDG) place them for this user.
struct WindowFolders {
    QString settingsFile;  ///< ~/.config/PRISCA Lab/prisca.conf
    QString data;          ///< ~/.local/share/PRISCA Lab/prisca
    QString recordings;    ///< data/recordings
    QString bundles;       ///< data/trials: the rig's trial bundles
    QString cache;         ///< ~/.cache/PRISCA Lab/prisca
};
/// From any process (prisca-cli's own names differ from the window's).
WindowFolders windowFolders();

/// What to check beyond what the system lists.
struct DoctorRequest {
    QStringList ports;        ///< serial ports the operator uses (checked even when not listed)
    QStringList cameras;      ///< camera devices the operator uses
    QString calibrationFile;  ///< a floor calibration to check; empty: not asked
    QString lensFile;         ///< a lens (intrinsics) file to check; empty: not asked
    WindowFolders folders = windowFolders();
    /// Free space the trial bundles need [bytes]: a session's bundles with their video.
    std::int64_t minimumFreeBytes = std::int64_t(1) << 30;
};

/// What the system said, gathered by gatherFacts().
struct HostFacts {
    std::vector<devices::SerialPortFacts> ports;
    std::vector<devices::CameraFacts> cameras;
    QStringList udevRules;
    QString display;
    devices::OpenGlFacts openGl;
    std::optional<std::int64_t> freeBytes;  ///< where the bundles go
    /// The files asked for: empty when read and valid, else why not.
    std::optional<QString> calibrationProblem;
    std::optional<QString> lensProblem;
};
HostFacts gatherFacts(const DoctorRequest& request);

/// One line of the report.
struct DoctorItem {
    QString key;    ///< "serial", "serial-port", "udev", "camera", "camera-device",
                    ///< "calibration", "lens", "display", "opengl", "disk", "folders"
    QString label;  ///< what it is ("Serial port /dev/ttyUSB0")
    bool ok = false;
    bool required = true;  ///< the rig cannot run without it (doctor's exit status)
    QString detail;        ///< what was found, or what to do
};

struct DoctorReport {
    std::vector<DoctorItem> items;
    /// Every required line holds: the rig has what it needs.
    bool ready() const;
};

/// The report for these facts (pure).
DoctorReport diagnose(const DoctorRequest& request, const HostFacts& facts);

}  // namespace prisca::rig
