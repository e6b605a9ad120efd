// prisca-cli doctor: whether this computer has what the rig needs, each line OK or what to do.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "rig/RigDoctor.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QSettings>

namespace prisca::app::cli {

namespace {

constexpr int kExitNotReady = 1;

QJsonObject toJson(const rig::DoctorRequest& request, const rig::DoctorReport& report) {
    QJsonArray items;
    for (const rig::DoctorItem& i : report.items) {
        items.append(QJsonObject{{"key", i.key},
                                 {"label", i.label},
                                 {"ok", i.ok},
                                 {"required", i.required},
                                 {"detail", i.detail}});
    }
    const rig::WindowFolders& f = request.folders;
    return QJsonObject{{"ready", report.ready()},
                       {"items", items},
                       {"folders", QJsonObject{{"settings", f.settingsFile},
                                               {"data", f.data},
                                               {"recordings", f.recordings},
                                               {"bundles", f.bundles},
                                               {"cache", f.cache}}}};
}

}  // namespace

int doctorCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("doctor"),
        QStringLiteral(
            "Check this computer for the rig: the serial ports and whether you may open each "
            "(group, udev rule), the cameras and their modes, the calibration and lens files, "
            "the display and OpenGL for the window, free space for the trial bundles, and the "
            "folders in use. Each line is OK or says what to do. Exit 0 when everything the rig "
            "needs is there, 1 when not. The port and the camera the window was last set to are "
            "checked too."));
    line.addValue(QStringLiteral("port"),
                  QStringLiteral("A serial port to check besides those listed (e.g. a bridge "
                                 "on /dev/ttyACM0); may be given several times."),
                  QStringLiteral("path"));
    line.addValue(QStringLiteral("camera"),
                  QStringLiteral("A camera device to check besides /dev/video*."),
                  QStringLiteral("path"));
    line.addValue(QStringLiteral("calibration"),
                  QStringLiteral("A floor calibration file (Rig tab Save..., calibrate-floor) "
                                 "to read and check."),
                  QStringLiteral("file"));
    line.addValue(QStringLiteral("lens"),
                  QStringLiteral("A lens file (calibrate-camera) to read and check."),
                  QStringLiteral("file"));
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    rig::DoctorRequest request;
    request.ports = line.values(QStringLiteral("port"));
    request.cameras = line.values(QStringLiteral("camera"));
    request.calibrationFile = line.value(QStringLiteral("calibration"));
    request.lensFile = line.value(QStringLiteral("lens"));
    // The window's own choices (its settings file), so the check covers what it will open.
    const QSettings window(request.folders.settingsFile, QSettings::IniFormat);
    const QString port = window.value(QStringLiteral("rig/port")).toString();
    if (!port.isEmpty() && !request.ports.contains(port)) {
        request.ports << port;
    }
    const QString camera = window.value(QStringLiteral("rig/path")).toString();
    if (window.value(QStringLiteral("rig/source"), 0).toInt() != 0 &&
        camera.startsWith(QLatin1String("/dev/")) && !request.cameras.contains(camera)) {
        request.cameras << camera;
    }
    const rig::DoctorReport report = rig::diagnose(request, rig::gatherFacts(request));
    if (line.format() == QLatin1String("json")) {
        printJson(toJson(request, report));
    } else {
        QString text;
        for (const rig::DoctorItem& i : report.items) {
            const QString mark = i.ok         ? QStringLiteral("OK  ")
                                 : i.required ? QStringLiteral("FIX ")
                                              : QStringLiteral("note");
            text += QStringLiteral("%1  %2: %3\n").arg(mark, i.label, i.detail);
        }
        text += report.ready() ? QStringLiteral("The rig has what it needs.\n")
                               : QStringLiteral("The rig is missing what the FIX lines say.\n");
        printText(text);
    }
    return report.ready() ? 0 : kExitNotReady;
}

}  // namespace prisca::app::cli
