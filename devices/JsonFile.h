#pragma once

#include "core/FileIo.h"

#include <QString>

#include <optional>

namespace prisca::devices {

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
