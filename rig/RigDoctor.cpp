#include "rig/RigDoctor.h"

#include "devices/CameraLens.h"
#include "devices/FloorCalibration.h"

#include <QCoreApplication>
#include <QDir>
#include <QStandardPaths>

#include <algorithm>

namespace prisca::rig {

namespace {

// The report's sentences, in the window's language where a translator is installed.
class DoctorText {
    Q_DECLARE_TR_FUNCTIONS(prisca::rig::RigDoctor)
  public:
    static QString bytes(std::int64_t count) {
        return count >= (std::int64_t(1) << 30)
                   ? tr("%1 GiB").arg(static_cast<double>(count) / (1 << 30), 0, 'f', 1)
                   : tr("%1 MiB").arg(static_cast<double>(count) / (1 << 20), 0, 'f', 0);
    }
};

DoctorItem doctorItem(const char* key, const QString& label, bool ok, const QString& detail,
                      bool required) {
    return {QString::fromLatin1(key), label, ok, required, detail};
}

// What to do about a node this user cannot open.
QString accessAdvice(const devices::NodeAccess& access) {
    if (!access.exists) {
        return DoctorText::tr("not there (%1)").arg(access.error);
    }
    if (access.canOpen) {
        return QString();
    }
    if (access.group.isEmpty()) {
        return DoctorText::tr("cannot be opened (%1)").arg(access.error);
    }
    if (access.inGroupListed && !access.inGroupNow) {
        return DoctorText::tr(
                   "cannot be opened: you were added to the group %1 but have not logged in "
                   "since; log out and in again")
            .arg(access.group);
    }
    return DoctorText::tr(
               "cannot be opened: it belongs to the group %1, which you are not in; run "
               "sudo usermod -aG %1 $USER and log in again")
        .arg(access.group);
}

QString portName(const devices::SerialPortFacts& port) {
    QStringList parts;
    if (!port.description.isEmpty()) {
        parts << port.description;
    }
    if (port.vendorId && port.productId) {
        parts << QStringLiteral("%1:%2")
                     .arg(*port.vendorId, 4, 16, QLatin1Char('0'))
                     .arg(*port.productId, 4, 16, QLatin1Char('0'));
    }
    return parts.isEmpty() ? QString()
                           : QStringLiteral(" (%1)").arg(parts.join(QStringLiteral(", ")));
}

void serialItems(const DoctorRequest& request, const HostFacts& facts, DoctorReport& report) {
    bool anyOpens = false;
    bool askedOpen = true;
    bool anyAdapter = false;
    for (const devices::SerialPortFacts& port : facts.ports) {
        const bool asked =
            request.ports.contains(port.path) ||
            std::any_of(port.aliases.begin(), port.aliases.end(),
                        [&](const QString& alias) { return request.ports.contains(alias); });
        // A link goes through a USB adapter or a port the operator names; a motherboard's
        // legacy UART (ttyS0, no USB identity) is listed but does not make the link ready.
        const bool candidate = asked || port.vendorId.has_value();
        anyAdapter = anyAdapter || candidate;
        anyOpens = anyOpens || (candidate && port.access.canOpen);
        askedOpen = askedOpen && (!asked || port.access.canOpen);
        report.items.push_back(doctorItem(
            "serial-port", DoctorText::tr("Serial port %1").arg(port.path), port.access.canOpen,
            port.access.canOpen ? DoctorText::tr("can be opened%1").arg(portName(port))
                                : accessAdvice(port.access) + portName(port),
            asked));
    }
    const bool ok = anyOpens && askedOpen;
    report.items.push_back(doctorItem(
        "serial", DoctorText::tr("Transmitter link"), ok,
        ok            ? DoctorText::tr("a serial port this user can open")
        : !anyAdapter ? DoctorText::tr("no USB serial adapter found: plug in the transmitter's "
                                       "USB-serial adapter or the "
                                       "bridge board (the kernel's log, dmesg, says what it saw)")
                      : DoctorText::tr("no serial port this user can open: see the ports above"),
        true));
}

void udevItem(const HostFacts& facts, DoctorReport& report) {
    report.items.push_back(doctorItem(
        "udev", DoctorText::tr("Serial adapter rule"), !facts.udevRules.isEmpty(),
        !facts.udevRules.isEmpty()
            ? DoctorText::tr("installed: %1").arg(facts.udevRules.join(QStringLiteral(", ")))
            : DoctorText::tr("not installed: the package installs it; from a build, sudo cp "
                             "packaging/70-prisca-lab.rules /etc/udev/rules.d/ (or join the group "
                             "dialout)"),
        false));
}

void cameraItems(const DoctorRequest& request, const HostFacts& facts, DoctorReport& report) {
    bool anyCaptures = false;
    bool askedOpen = true;
    for (const devices::CameraFacts& camera : facts.cameras) {
        const bool asked = request.cameras.contains(camera.path);
        const bool ok = camera.access.canOpen && camera.capture;
        anyCaptures = anyCaptures || ok;
        askedOpen = askedOpen && (!asked || ok);
        if (!asked && camera.access.canOpen && !camera.capture && camera.error.isEmpty()) {
            continue;  // a webcam's metadata node: nothing to say
        }
        QString detail;
        if (!camera.access.canOpen) {
            detail = accessAdvice(camera.access);
        } else if (!camera.error.isEmpty()) {
            detail = DoctorText::tr("cannot be queried: %1").arg(camera.error);
        } else if (!camera.capture) {
            detail = DoctorText::tr("%1: no video capture").arg(camera.card);
        } else {
            detail = DoctorText::tr("%1: %2").arg(
                camera.card, camera.modes.isEmpty() ? DoctorText::tr("no modes listed")
                                                    : camera.modes.join(QStringLiteral(", ")));
        }
        report.items.push_back(doctorItem(
            "camera-device", DoctorText::tr("Camera %1").arg(camera.path), ok, detail, asked));
    }
    const bool ok = anyCaptures && askedOpen;
    report.items.push_back(doctorItem(
        "camera", DoctorText::tr("Camera"), ok,
        ok ? DoctorText::tr("a video capture device this user can open")
        : facts.cameras.empty()
            ? DoctorText::tr(
                  "no camera found (/dev/video*): plug in the ceiling camera; the virtual "
                  "rig needs none")
            : DoctorText::tr("no camera this user can open: see the devices above"),
        true));
}

void fileItem(const char* key, const QString& label, const QString& path,
              const std::optional<QString>& problem, DoctorReport& report) {
    if (path.isEmpty()) {
        return;  // not asked: the session's own are the pre-trial check's
    }
    const bool ok = problem && problem->isEmpty();
    report.items.push_back(doctorItem(key, label, ok,
                                      ok        ? DoctorText::tr("%1 reads and is valid").arg(path)
                                      : problem ? *problem
                                                : DoctorText::tr("%1 was not read").arg(path),
                                      true));
}

}  // namespace

WindowFolders windowFolders() {
    // As QStandardPaths places the window's own (organisation "PRISCA Lab", application
    // "prisca"), from a process of another name.
    const QString organisation = QStringLiteral("PRISCA Lab");
    const QString application = QStringLiteral("prisca");
    const auto under = [&](QStandardPaths::StandardLocation location) {
        return QDir(QStandardPaths::writableLocation(location))
            .filePath(organisation + QLatin1Char('/') + application);
    };
    WindowFolders folders;
    folders.settingsFile =
        QDir(QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation))
            .filePath(organisation + QLatin1Char('/') + application + QStringLiteral(".conf"));
    folders.data = under(QStandardPaths::GenericDataLocation);
    folders.recordings = QDir(folders.data).filePath(QStringLiteral("recordings"));
    folders.bundles = QDir(folders.data).filePath(QStringLiteral("trials"));
    folders.cache = under(QStandardPaths::GenericCacheLocation);
    return folders;
}

HostFacts gatherFacts(const DoctorRequest& request) {
    HostFacts facts;
    facts.ports = devices::probeSerialPorts(request.ports);
    facts.cameras = devices::probeCameras(request.cameras);
    facts.udevRules = devices::installedUdevRules();
    facts.display = devices::displayName();
    facts.openGl = devices::probeOpenGl();
    facts.freeBytes = devices::freeBytes(request.folders.bundles);
    if (!request.calibrationFile.isEmpty()) {
        QString error;
        facts.calibrationProblem =
            devices::FloorCalibration::load(request.calibrationFile, &error) ? QString() : error;
    }
    if (!request.lensFile.isEmpty()) {
        QString error;
        facts.lensProblem = devices::CameraLens::load(request.lensFile, &error) ? QString() : error;
    }
    return facts;
}

bool DoctorReport::ready() const {
    return std::all_of(items.begin(), items.end(),
                       [](const DoctorItem& i) { return i.ok || !i.required; });
}

DoctorReport diagnose(const DoctorRequest& request, const HostFacts& facts) {
    DoctorReport report;
    serialItems(request, facts, report);
    udevItem(facts, report);
    cameraItems(request, facts, report);
    fileItem("calibration", DoctorText::tr("Floor calibration"), request.calibrationFile,
             facts.calibrationProblem, report);
    fileItem("lens", DoctorText::tr("Lens"), request.lensFile, facts.lensProblem, report);
    report.items.push_back(doctorItem(
        "display", DoctorText::tr("Display"), !facts.display.isEmpty(),
        !facts.display.isEmpty()
            ? facts.display
            : DoctorText::tr("none (DISPLAY and WAYLAND_DISPLAY unset): the window needs one; "
                             "prisca-cli does not"),
        false));
    report.items.push_back(doctorItem(
        "opengl", DoctorText::tr("OpenGL"), facts.openGl.libraryFound,
        facts.openGl.libraryFound
            ? (facts.openGl.renderNode
                   ? DoctorText::tr("%1, a GPU render node").arg(facts.openGl.library)
                   : DoctorText::tr("%1, software rendering (no GPU render node)")
                         .arg(facts.openGl.library))
            : DoctorText::tr("no OpenGL library: install libgl1 (the window's charts need it)"),
        false));
    const bool roomy = facts.freeBytes && *facts.freeBytes >= request.minimumFreeBytes;
    QString space;
    if (!facts.freeBytes) {
        space = DoctorText::tr("cannot read the free space under %1").arg(request.folders.bundles);
    } else if (roomy) {
        space = DoctorText::tr("%1 free under %2")
                    .arg(DoctorText::bytes(*facts.freeBytes), request.folders.bundles);
    } else {
        space = DoctorText::tr(
                    "only %1 free under %2: a session's bundles need %3; free some space "
                    "or choose another folder")
                    .arg(DoctorText::bytes(*facts.freeBytes), request.folders.bundles,
                         DoctorText::bytes(request.minimumFreeBytes));
    }
    report.items.push_back(
        doctorItem("disk", DoctorText::tr("Free space for trial bundles"), roomy, space, true));
    report.items.push_back(
        doctorItem("folders", DoctorText::tr("Folders"), true,
                   DoctorText::tr("settings %1; recordings %2; trial bundles %3; cache %4")
                       .arg(request.folders.settingsFile, request.folders.recordings,
                            request.folders.bundles, request.folders.cache),
                   false));
    return report;
}

}  // namespace prisca::rig
