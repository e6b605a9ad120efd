// prisca-cli doctor's and the Rig tab's check as a function of what the system says: each line
// fails for its own reason and says what to do; the verdict needs a USB adapter or the named
// port this user can open, a capture camera, the files asked for and the free space. Then the
// real probes on nodes this process makes (a pseudo-terminal, a missing path) and the folders.
#include "rig/RigDoctor.h"

#include <QTemporaryDir>
#include <QtTest>

#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

using namespace prisca;
using rig::DoctorRequest;
using rig::HostFacts;

namespace {

devices::NodeAccess openable(const QString& group = QStringLiteral("dialout")) {
    devices::NodeAccess access;
    access.exists = true;
    access.canOpen = true;
    access.group = group;
    access.inGroupNow = access.inGroupListed = true;
    return access;
}

devices::SerialPortFacts usbPort(const QString& path = QStringLiteral("/dev/ttyUSB0")) {
    devices::SerialPortFacts port;
    port.path = path;
    port.description = QStringLiteral("FT232R USB UART");
    port.vendorId = 0x0403;
    port.productId = 0x6001;
    port.access = openable();
    return port;
}

devices::CameraFacts captureCamera() {
    devices::CameraFacts camera;
    camera.path = QStringLiteral("/dev/video0");
    camera.card = QStringLiteral("IR ceiling camera");
    camera.access = openable(QStringLiteral("video"));
    camera.capture = true;
    camera.modes = {QStringLiteral("YUYV 640x480"), QStringLiteral("MJPG 1280x720")};
    return camera;
}

// Everything the rig needs.
HostFacts allThere() {
    HostFacts facts;
    facts.ports = {usbPort()};
    facts.cameras = {captureCamera()};
    facts.udevRules = {QStringLiteral("/usr/lib/udev/rules.d/70-prisca-lab.rules")};
    facts.display = QStringLiteral("X11 :0");
    facts.openGl.libraryFound = true;
    facts.openGl.library = QStringLiteral("libGL.so.1");
    facts.freeBytes = std::int64_t(20) << 30;
    return facts;
}

const rig::DoctorItem* find(const rig::DoctorReport& report, const char* key,
                            const QString& labelPart = {}) {
    for (const rig::DoctorItem& i : report.items) {
        if (i.key == QLatin1String(key) && i.label.contains(labelPart)) {
            return &i;
        }
    }
    return nullptr;
}

}  // namespace

class TestRigDoctor : public QObject {
    Q_OBJECT
  private slots:
    void everythingThere_isReady() {
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), allThere());
        QVERIFY(report.ready());
        for (const char* key : {"serial-port", "serial", "udev", "camera-device", "camera",
                                "display", "opengl", "disk", "folders"}) {
            const rig::DoctorItem* item = find(report, key);
            QVERIFY2(item && item->ok, key);
        }
        QVERIFY(find(report, "camera-device")->detail.contains(QLatin1String("MJPG 1280x720")));
        QVERIFY(find(report, "serial-port")->detail.contains(QLatin1String("0403:6001")));
    }

    void noAdapter_isNotReadyAndSaysToPlugOneIn() {
        HostFacts facts = allThere();
        facts.ports.clear();
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(!report.ready());
        QVERIFY(!find(report, "serial")->ok);
        QVERIFY(find(report, "serial")->detail.contains(QLatin1String("plug in")));
    }

    void aLegacyUartAlone_doesNotMakeTheLinkReady() {
        HostFacts facts = allThere();
        devices::SerialPortFacts uart;
        uart.path = QStringLiteral("/dev/ttyS0");
        uart.access = openable();
        facts.ports = {uart};
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(find(report, "serial-port", QStringLiteral("ttyS0"))->ok);  // listed, opens
        QVERIFY(!find(report, "serial")->ok);
        QVERIFY(!report.ready());
        // Named by the operator (a bridge on a board without USB identity), it counts.
        DoctorRequest named;
        named.ports = {QStringLiteral("/dev/ttyS0")};
        QVERIFY(rig::diagnose(named, facts).ready());
    }

    void aPortOfAGroupTheUserIsNotIn_saysHowToJoinIt() {
        HostFacts facts = allThere();
        facts.ports[0].access.canOpen = false;
        facts.ports[0].access.inGroupNow = facts.ports[0].access.inGroupListed = false;
        facts.ports[0].access.error = QStringLiteral("Permission denied");
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(!report.ready());
        const rig::DoctorItem* port = find(report, "serial-port");
        QVERIFY(!port->ok);
        QVERIFY2(port->detail.contains(QLatin1String("usermod -aG dialout")),
                 qPrintable(port->detail));
        // Added to the group but not logged in since: log in again, not usermod.
        facts.ports[0].access.inGroupListed = true;
        const QString detail = rig::diagnose(DoctorRequest(), facts).items.front().detail;
        QVERIFY2(
            detail.contains(QLatin1String("log out")) && !detail.contains(QLatin1String("usermod")),
            qPrintable(detail));
    }

    void theNamedPortMustOpenEvenWhenAnotherDoes() {
        HostFacts facts = allThere();
        devices::SerialPortFacts bridge = usbPort(QStringLiteral("/dev/ttyACM0"));
        bridge.access.canOpen = false;
        bridge.access.error = QStringLiteral("Permission denied");
        facts.ports.push_back(bridge);
        DoctorRequest request;
        QVERIFY(rig::diagnose(request, facts).ready());  // not the one the operator uses
        request.ports = {QStringLiteral("/dev/ttyACM0")};
        const rig::DoctorReport report = rig::diagnose(request, facts);
        QVERIFY(!report.ready());
        QVERIFY(find(report, "serial-port", QStringLiteral("ttyACM0"))->required);
    }

    // The window set to a stable name of the adapter (/dev/serial/by-id/...): the port it
    // leads to is the one that must open.
    void aPortNamedThroughAnAlias_isTheOneRequired() {
        HostFacts facts = allThere();
        const QString alias = QStringLiteral("/dev/serial/by-id/usb-FTDI_FT232R-if00-port0");
        facts.ports[0].aliases = {alias};
        facts.ports[0].access.canOpen = false;
        facts.ports[0].access.error = QStringLiteral("Permission denied");
        devices::SerialPortFacts other = usbPort(QStringLiteral("/dev/ttyUSB1"));
        facts.ports.push_back(other);
        DoctorRequest request;
        request.ports = {alias};
        const rig::DoctorReport report = rig::diagnose(request, facts);
        QVERIFY(!report.ready());
        QVERIFY(find(report, "serial-port", QStringLiteral("ttyUSB0"))->required);
    }

    void noCaptureCamera_isNotReady() {
        HostFacts facts = allThere();
        facts.cameras.clear();
        rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(!report.ready());
        QVERIFY(find(report, "camera")->detail.contains(QLatin1String("/dev/video")));
        facts.cameras = {captureCamera()};
        facts.cameras[0].capture = false;  // a metadata node only
        QVERIFY(!rig::diagnose(DoctorRequest(), facts).ready());
    }

    void theWindowsNeedsAreNotes_theRigDoesNotNeedThem() {
        HostFacts facts = allThere();
        facts.display.clear();
        facts.openGl.libraryFound = false;
        facts.udevRules.clear();
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(report.ready());
        for (const char* key : {"display", "opengl", "udev"}) {
            QVERIFY2(!find(report, key)->ok && !find(report, key)->required, key);
        }
        QVERIFY(find(report, "udev")->detail.contains(QLatin1String("70-prisca-lab.rules")));
    }

    void littleFreeSpace_isNotReady() {
        HostFacts facts = allThere();
        facts.freeBytes = std::int64_t(200) << 20;
        const rig::DoctorReport report = rig::diagnose(DoctorRequest(), facts);
        QVERIFY(!report.ready());
        QVERIFY2(find(report, "disk")->detail.contains(QLatin1String("200 MiB")),
                 qPrintable(find(report, "disk")->detail));
        facts.freeBytes.reset();
        QVERIFY(!rig::diagnose(DoctorRequest(), facts).ready());
    }

    void filesAskedFor_areRequiredAndNamed() {
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("floor.json"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{ not json");
        file.close();
        DoctorRequest request;
        request.calibrationFile = broken;
        request.lensFile = dir.filePath(QStringLiteral("missing-lens.json"));
        request.folders.bundles = dir.path();
        const HostFacts facts = rig::gatherFacts(request);
        QVERIFY(facts.calibrationProblem && !facts.calibrationProblem->isEmpty());
        QVERIFY(facts.lensProblem && facts.lensProblem->contains(QLatin1String("missing-lens")));
        HostFacts there = allThere();
        there.calibrationProblem = facts.calibrationProblem;
        there.lensProblem = facts.lensProblem;
        const rig::DoctorReport report = rig::diagnose(request, there);
        QVERIFY(!report.ready());
        QVERIFY(!find(report, "calibration")->ok && !find(report, "lens")->ok);
        // Not asked: a note, not a failure.
        QVERIFY(rig::diagnose(DoctorRequest(), allThere()).ready());
    }

    // The real probes: a pseudo-terminal this process opened is a port it can open; a missing
    // node is said to be missing; the free space of a temporary folder is read.
    void probes_readThisSystem() {
        int master = -1;
        int slave = -1;
        char name[256] = {};
        QVERIFY(openpty(&master, &slave, name, nullptr, nullptr) == 0);
        const QString pty = QString::fromLocal8Bit(name);
        const devices::NodeAccess access = devices::probeAccess(pty);
        QVERIFY(access.exists);
        QVERIFY2(access.canOpen, qPrintable(access.error));
        const auto ports = devices::probeSerialPorts({pty});
        QVERIFY(std::any_of(ports.begin(), ports.end(), [&](const devices::SerialPortFacts& p) {
            return p.path == pty && p.access.canOpen;
        }));
        ::close(slave);
        ::close(master);
        const devices::NodeAccess missing =
            devices::probeAccess(QStringLiteral("/dev/no-such-port"));
        QVERIFY(!missing.exists && !missing.canOpen && !missing.error.isEmpty());
        const auto cameras = devices::probeCameras({QStringLiteral("/dev/no-such-camera")});
        QVERIFY(std::any_of(cameras.begin(), cameras.end(), [](const devices::CameraFacts& c) {
            return c.path == QLatin1String("/dev/no-such-camera") && !c.access.exists;
        }));
        QTemporaryDir dir;
        const auto free = devices::freeBytes(dir.filePath(QStringLiteral("not/yet/made")));
        QVERIFY(free && *free > 0);
    }

    void folders_followXdg() {
        QTemporaryDir dir;
        qputenv("XDG_DATA_HOME", dir.filePath(QStringLiteral("data")).toLocal8Bit());
        qputenv("XDG_CONFIG_HOME", dir.filePath(QStringLiteral("config")).toLocal8Bit());
        const rig::WindowFolders folders = rig::windowFolders();
        QCOMPARE(folders.bundles, dir.filePath(QStringLiteral("data/PRISCA Lab/prisca/trials")));
        QCOMPARE(folders.recordings,
                 dir.filePath(QStringLiteral("data/PRISCA Lab/prisca/recordings")));
        QCOMPARE(folders.settingsFile,
                 dir.filePath(QStringLiteral("config/PRISCA Lab/prisca.conf")));
    }
};

QTEST_GUILESS_MAIN(TestRigDoctor)
#include "test_rig_doctor.moc"
