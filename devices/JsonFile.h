#pragma once

#include "core/FileIo.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <optional>

namespace prisca::devices {

/// The JSON object in `json`; on failure nullopt and *error says where the JSON is broken, or
/// `notAnObject` when it is valid JSON but no object.
inline std::optional<QJsonObject> parseJsonObject(const QByteArray& json,
                                                  const QString& notAnObject, QString* error) {
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error = QStringLiteral("not valid JSON at byte %1 (%2)")
                     .arg(parseError.offset)
                     .arg(parseError.errorString());
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = notAnObject;
        return std::nullopt;
    }
    return doc.object();
}

/// Reads a JSON file of at most T::kMaxJsonBytes into a T through T::fromJson; on failure
/// nullopt and *error names the file and the problem.
template <typename T>
std::optional<T> loadJsonFile(const QString& path, QString* error) {
    core::FileError fileError;
    const std::optional<QByteArray> json =
        core::readFileBounded(path, T::kMaxJsonBytes, &fileError);
    if (!json) {
        *error = fileError.toString();
        return std::nullopt;
    }
    auto value = T::fromJson(*json, error);
    if (!value) {
        *error = core::printable(QStringLiteral("%1: %2").arg(path, *error));
    }
    return value;
}

/// Writes value.toJson() to `path` atomically; false and *error on failure.
template <typename T>
bool saveJsonFile(const T& value, const QString& path, QString* error) {
    core::FileError fileError;
    if (!core::writeFileAtomically(path, value.toJson(), &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

}  // namespace prisca::devices
