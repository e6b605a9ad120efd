#include "FileIo.h"

#include <QSaveFile>

#include <charconv>

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
    return text + message;
}

void appendCsvNumber(QByteArray& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, static_cast<qsizetype>(result.ptr - buffer));
}

bool writeFileAtomically(const QString& path, const QByteArray& bytes, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return false;
    };
    if (path.isEmpty()) {
        return fail(QStringLiteral("no file name given"));
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        return fail(QStringLiteral("cannot open for writing: %1").arg(file.errorString()));
    }
    if (file.write(bytes) != bytes.size()) {
        const QString reason = file.errorString();
        file.cancelWriting();
        return fail(QStringLiteral("cannot write: %1").arg(reason));
    }
    if (!file.commit()) {
        return fail(QStringLiteral("cannot save: %1").arg(file.errorString()));
    }
    return true;
}

}  // namespace prisca::core
