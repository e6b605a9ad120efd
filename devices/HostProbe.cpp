#include "devices/HostProbe.h"

#include <QDir>
#include <QFileInfo>
#include <QSerialPortInfo>
#include <QStorageInfo>

#include <dlfcn.h>
#include <fcntl.h>
#include <grp.h>
#include <linux/videodev2.h>
#include <pwd.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace prisca::devices {

namespace {

QString errnoText(int error) {
    return QString::fromLocal8Bit(std::strerror(error));
}

bool processHasGroup(gid_t gid) {
    if (getegid() == gid) {
        return true;
    }
    const int count = getgroups(0, nullptr);
    if (count <= 0) {
        return false;
    }
    std::vector<gid_t> groups(static_cast<size_t>(count));
    const int read = getgroups(count, groups.data());
    return read > 0 &&
           std::find(groups.begin(), groups.begin() + read, gid) != groups.begin() + read;
}

// The reentrant lookups: the Rig tab probes on a thread of its own.
std::vector<char> lookupBuffer() {
    const long size = sysconf(_SC_GETPW_R_SIZE_MAX);
    return std::vector<char>(static_cast<size_t>(size > 0 ? size : 16384));
}

bool userListedInGroup(gid_t gid) {
    passwd entry{};
    passwd* user = nullptr;
    std::vector<char> buffer = lookupBuffer();
    if (getpwuid_r(geteuid(), &entry, buffer.data(), buffer.size(), &user) != 0 || !user) {
        return false;
    }
    int count = 64;
    std::vector<gid_t> groups(static_cast<size_t>(count));
    if (getgrouplist(user->pw_name, user->pw_gid, groups.data(), &count) < 0) {
        groups.resize(static_cast<size_t>(count));
        if (getgrouplist(user->pw_name, user->pw_gid, groups.data(), &count) < 0) {
            return false;
        }
    }
    return std::find(groups.begin(), groups.begin() + count, gid) != groups.begin() + count;
}

// A fourcc as its four letters ("YUYV").
QString fourcc(std::uint32_t code) {
    QString text;
    for (int i = 0; i < 4; ++i) {
        const char c = static_cast<char>((code >> (8 * i)) & 0xff);
        text += QLatin1Char(c >= 32 && c < 127 ? c : '?');
    }
    return text.trimmed();
}

int xioctl(int fd, unsigned long request, void* argument) {
    int result = 0;
    do {
        result = ioctl(fd, request, argument);
    } while (result < 0 && errno == EINTR);
    return result;
}

void queryCamera(CameraFacts& camera) {
    const QByteArray path = QFile::encodeName(camera.path);
    const int fd = ::open(path.constData(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        camera.error = errnoText(errno);
        return;
    }
    v4l2_capability capability{};
    if (xioctl(fd, VIDIOC_QUERYCAP, &capability) < 0) {
        camera.error = QStringLiteral("not a V4L2 device (%1)").arg(errnoText(errno));
        ::close(fd);
        return;
    }
    camera.card = QString::fromUtf8(reinterpret_cast<const char*>(capability.card)).trimmed();
    const std::uint32_t caps = (capability.capabilities & V4L2_CAP_DEVICE_CAPS)
                                   ? capability.device_caps
                                   : capability.capabilities;
    camera.capture = (caps & V4L2_CAP_VIDEO_CAPTURE) != 0;
    constexpr int kMostModes = 12;
    for (std::uint32_t f = 0; camera.capture && camera.modes.size() < kMostModes; ++f) {
        v4l2_fmtdesc format{};
        format.index = f;
        format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (xioctl(fd, VIDIOC_ENUM_FMT, &format) < 0) {
            break;
        }
        bool sized = false;
        for (std::uint32_t s = 0; camera.modes.size() < kMostModes; ++s) {
            v4l2_frmsizeenum size{};
            size.index = s;
            size.pixel_format = format.pixelformat;
            if (xioctl(fd, VIDIOC_ENUM_FRAMESIZES, &size) < 0) {
                break;
            }
            sized = true;
            if (size.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                camera.modes << QStringLiteral("%1 %2x%3")
                                    .arg(fourcc(format.pixelformat))
                                    .arg(size.discrete.width)
                                    .arg(size.discrete.height);
            } else {
                camera.modes << QStringLiteral("%1 up to %2x%3")
                                    .arg(fourcc(format.pixelformat))
                                    .arg(size.stepwise.max_width)
                                    .arg(size.stepwise.max_height);
                break;
            }
        }
        if (!sized) {
            camera.modes << fourcc(format.pixelformat);
        }
    }
    ::close(fd);
}

}  // namespace

NodeAccess probeAccess(const QString& path) {
    NodeAccess access;
    const QByteArray name = QFile::encodeName(path);
    struct stat info {};
    if (::stat(name.constData(), &info) != 0) {
        access.error = errnoText(errno);
        return access;
    }
    access.exists = true;
    group entry{};
    group* owner = nullptr;
    std::vector<char> buffer = lookupBuffer();
    if (getgrgid_r(info.st_gid, &entry, buffer.data(), buffer.size(), &owner) == 0 && owner) {
        access.group = QString::fromLocal8Bit(owner->gr_name);
    }
    access.inGroupNow = processHasGroup(info.st_gid);
    access.inGroupListed = access.inGroupNow || userListedInGroup(info.st_gid);
    access.canOpen = ::access(name.constData(), R_OK | W_OK) == 0;
    if (!access.canOpen) {
        access.error = errnoText(errno);
    }
    return access;
}

std::vector<SerialPortFacts> probeSerialPorts(const QStringList& extra) {
    std::vector<SerialPortFacts> ports;
    QStringList seen;
    for (const QSerialPortInfo& info : QSerialPortInfo::availablePorts()) {
        SerialPortFacts port;
        port.path = info.systemLocation();
        port.description = info.description();
        port.manufacturer = info.manufacturer();
        if (info.hasVendorIdentifier()) {
            port.vendorId = info.vendorIdentifier();
        }
        if (info.hasProductIdentifier()) {
            port.productId = info.productIdentifier();
        }
        port.access = probeAccess(port.path);
        seen << QFileInfo(port.path).canonicalFilePath();
        ports.push_back(std::move(port));
    }
    for (const QString& path : extra) {
        if (path.isEmpty()) {
            continue;
        }
        // A name for a listed port (/dev/serial/by-id/...): that port, known by it too.
        if (const qsizetype listed = seen.indexOf(QFileInfo(path).canonicalFilePath());
            listed >= 0 && !seen[listed].isEmpty()) {
            if (ports[static_cast<size_t>(listed)].path != path) {
                ports[static_cast<size_t>(listed)].aliases << path;
            }
            continue;
        }
        SerialPortFacts port;
        port.path = path;
        port.access = probeAccess(path);
        ports.push_back(std::move(port));
    }
    return ports;
}

std::vector<CameraFacts> probeCameras(const QStringList& extra) {
    QStringList paths;
    const QDir dev(QStringLiteral("/dev"));
    QStringList nodes = dev.entryList({QStringLiteral("video*")}, QDir::System);
    std::sort(nodes.begin(), nodes.end(), [](const QString& a, const QString& b) {
        return a.mid(5).toInt() < b.mid(5).toInt();
    });
    for (const QString& node : nodes) {
        paths << dev.filePath(node);
    }
    for (const QString& path : extra) {
        if (!path.isEmpty() && !paths.contains(path)) {
            paths << path;
        }
    }
    std::vector<CameraFacts> cameras;
    for (const QString& path : paths) {
        CameraFacts camera;
        camera.path = path;
        camera.access = probeAccess(path);
        if (camera.access.canOpen) {
            queryCamera(camera);
        }
        cameras.push_back(std::move(camera));
    }
    return cameras;
}

QString displayName() {
    const QString wayland = qEnvironmentVariable("WAYLAND_DISPLAY");
    if (!wayland.isEmpty()) {
        return QStringLiteral("Wayland %1").arg(wayland);
    }
    const QString x11 = qEnvironmentVariable("DISPLAY");
    return x11.isEmpty() ? QString() : QStringLiteral("X11 %1").arg(x11);
}

OpenGlFacts probeOpenGl() {
    OpenGlFacts facts;
    for (const char* library : {"libGL.so.1", "libEGL.so.1"}) {
        if (void* handle = dlopen(library, RTLD_LAZY | RTLD_LOCAL)) {
            dlclose(handle);
            facts.libraryFound = true;
            facts.library = QString::fromLatin1(library);
            break;
        }
    }
    facts.renderNode = !QDir(QStringLiteral("/dev/dri"))
                            .entryList({QStringLiteral("renderD*")}, QDir::System)
                            .isEmpty();
    return facts;
}

std::optional<std::int64_t> freeBytes(const QString& folder) {
    QFileInfo existing(folder);
    while (!existing.exists() && !existing.isRoot() && !existing.absoluteFilePath().isEmpty()) {
        const QString parent = existing.absolutePath();
        if (parent == existing.absoluteFilePath()) {
            break;
        }
        existing = QFileInfo(parent);
    }
    const QStorageInfo storage(existing.absoluteFilePath());
    if (!storage.isValid() || storage.bytesAvailable() < 0) {
        return std::nullopt;
    }
    return storage.bytesAvailable();
}

QStringList installedUdevRules() {
    QStringList found;
    for (const char* folder : {"/etc/udev/rules.d", "/usr/lib/udev/rules.d", "/lib/udev/rules.d"}) {
        const QString rule = QStringLiteral("%1/70-prisca-lab.rules").arg(QLatin1String(folder));
        if (QFileInfo::exists(rule) && !found.contains(QFileInfo(rule).canonicalFilePath())) {
            found << QFileInfo(rule).canonicalFilePath();
        }
    }
    return found;
}

}  // namespace prisca::devices
