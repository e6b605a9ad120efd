#include "FileIo.h"

#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>

namespace prisca::core {

QString FileError::toString() const {
    QString text = path;
    if (line > 0) {
        text += QStringLiteral(":%1").arg(line);
        if (column > 0) {
            text += QStringLiteral(":%1").arg(column);
        }
    }
    if (!text.isEmpty()) {
        text += QStringLiteral(": ");
    }
    return printable(text + message);
}

QString printable(const QString& text) {
    QString out;
    out.reserve(text.size());
    for (const QChar c : text) {
        const char16_t u = c.unicode();
        if (u < 0x20 || u == 0x7f || (u >= 0x80 && u < 0xa0)) {
            out += QStringLiteral("\\x%1").arg(int(u), 2, 16, QLatin1Char('0'));
        } else {
            out += c;
        }
    }
    return out;
}

bool checkRegularFile(const QString& path, qint64 maxBytes, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return false;
    };
    if (path.isEmpty()) {
        return fail(QStringLiteral("no file name given"));
    }
    const QFileInfo info(path);
    if (!info.exists()) {
        return fail(QStringLiteral("no such file"));
    }
    if (info.isDir()) {
        return fail(QStringLiteral("is a folder, not a file"));
    }
    if (!info.isFile()) {
        return fail(
            QStringLiteral("is not a regular file (a device, FIFO or socket); save the "
                           "data to a file first"));
    }
    if (maxBytes >= 0 && info.size() > maxBytes) {
        return fail(QStringLiteral("%1 bytes, more than the %2 bytes this reader accepts")
                        .arg(info.size())
                        .arg(maxBytes));
    }
    return true;
}

std::optional<QByteArray> readFileBounded(const QString& path, qint64 maxBytes, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return std::nullopt;
    };
    // Refused before it is opened: what is not a regular file, or is too big already.
    if (!checkRegularFile(path, maxBytes, error)) {
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return fail(QStringLiteral("cannot open for reading: %1").arg(file.errorString()));
    }
    QByteArray bytes;
    constexpr qint64 kChunk = qint64(1) << 20;
    try {
        for (;;) {
            const qint64 room = maxBytes + 1 - bytes.size();  // one more tells "too big"
            if (room <= 0) {
                return fail(
                    QStringLiteral("more than the %1 bytes this reader accepts").arg(maxBytes));
            }
            const qint64 at = bytes.size();
            bytes.resize(at + std::min(kChunk, room));
            const qint64 got = file.read(bytes.data() + at, bytes.size() - at);
            if (got < 0) {
                return fail(QStringLiteral("cannot read: %1").arg(file.errorString()));
            }
            bytes.resize(at + got);
            if (got == 0) {
                break;
            }
        }
    } catch (const std::bad_alloc&) {
        return fail(QStringLiteral("not enough memory to read the file"));
    }
    return bytes;
}

void appendCsvNumber(QByteArray& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, static_cast<qsizetype>(result.ptr - buffer));
}

bool checkOutputPath(const QString& path, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return false;
    };
    if (path.isEmpty()) {
        return fail(QStringLiteral("no file name given"));
    }
    // Only a regular file is replaced: a device (/dev/null as root), a FIFO, a socket or a folder
    // is left alone.
    struct stat existing {};
    const QByteArray native = QFile::encodeName(path);
    const bool exists = ::stat(native.constData(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) {
        return fail(QStringLiteral("is a folder; give a file name"));
    }
    if (exists && !S_ISREG(existing.st_mode)) {
        return fail(
            QStringLiteral("exists and is not a regular file (a device, FIFO or socket); not "
                           "replaced"));
    }
    const QFileInfo info(path);
    const QString folder = info.absolutePath();
    if (!QFileInfo(folder).isDir()) {
        return fail(QStringLiteral("its folder %1 does not exist").arg(folder));
    }
    if (::access(QFile::encodeName(folder).constData(), W_OK) != 0) {
        return fail(QStringLiteral("its folder %1 is not writable").arg(folder));
    }
    return true;
}

bool writeFileAtomically(const QString& path, const QByteArray& bytes, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return false;
    };
    if (!checkOutputPath(path, error)) {
        return false;
    }
    // A replaced file keeps its permissions, read-only included.
    struct stat existing {};
    const bool exists = ::stat(QFile::encodeName(path).constData(), &existing) == 0;
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return fail(QStringLiteral("cannot open for writing: %1").arg(file.errorString()));
    }
    // A small write stays in the file's buffer, and commit() does not report a failed flush
    // of it (a full disk then left an empty file behind a "saved"): flush and check first.
    const qint64 written = file.write(bytes);
    if (written != bytes.size() || !file.flush()) {
        // A short write (a full disk, a file-size limit) sets no error string of its own.
        // A full disk and a file-size limit are worded one way, whichever call noticed them.
        QString reason = file.errorString();
        if (written != bytes.size() || reason.isEmpty() ||
            reason == QLatin1String("Unknown error") ||
            reason.contains(QLatin1String("No space left")) ||
            reason.contains(QLatin1String("File too large"))) {
            reason = written >= 0 && written < bytes.size()
                         ? QStringLiteral("the disk is full (%1 of %2 bytes written)")
                               .arg(written)
                               .arg(bytes.size())
                         : QStringLiteral("the disk is full");
        }
        file.cancelWriting();
        return fail(QStringLiteral("cannot write: %1; the previous file is kept").arg(reason));
    }
    if (exists && ::fchmod(file.handle(), existing.st_mode & 07777) != 0) {
        file.cancelWriting();
        return fail(QStringLiteral("cannot keep the previous file's permissions: %1")
                        .arg(QString::fromLocal8Bit(std::strerror(errno))));
    }
    if (!file.commit()) {
        return fail(QStringLiteral("cannot save: %1").arg(file.errorString()));
    }
    return true;
}

}  // namespace prisca::core
