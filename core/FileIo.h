#pragma once

#include <QByteArray>
#include <QString>

#include <optional>

namespace prisca::core {

/// Where and why a file could not be read or written.
struct FileError {
    QString path;  ///< file path, or the source name given for in-memory text
    int line = 0;  ///< 1-based line number of the problem; 0 when not applicable
    /// 1-based field number in the header or a data row (1 is the time column t), or entry
    /// number in a "states:" / "actions:" list; 0 when not applicable.
    int column = 0;
    QString message;  ///< one line; names the offending column and quotes the offending text

    /// "path:line:column: message", leaving out the parts that are empty or zero; control
    /// characters escaped (printable()).
    QString toString() const;
};

/// The text with every control character (C0, DEL, C1; NUL included) written as \xNN, so a
/// message quoting hostile input stays one line, is not cut short by a NUL and sends no escape
/// sequence to a terminal. Any thread.
QString printable(const QString& text);

/// Whether path is an existing regular file of at most maxBytes (< 0: any size), decided from
/// its metadata without opening it (a FIFO would block). On failure *error (if given) says why.
bool checkRegularFile(const QString& path, qint64 maxBytes, FileError* error);

/// Reads a whole regular file of at most maxBytes (its size checked before reading). Devices,
/// FIFOs, sockets and folders are refused before they are opened (a FIFO would block, /dev/zero
/// never ends), and the size is capped while reading, not taken from stat, so a file growing under
/// the reader cannot exhaust memory either. On failure nullopt with *error (if given) naming the
/// path. Any thread.
std::optional<QByteArray> readFileBounded(const QString& path, qint64 maxBytes, FileError* error);

/// Appends the shortest text that reads back to exactly the same double (locale independent,
/// unlike printf). Any thread.
void appendCsvNumber(QByteArray& out, double value);

/// Writes bytes to path atomically: a temporary file renamed over the target only when
/// complete and flushed, so a crash or a full disk never leaves a half-written file or damages
/// the old one. Only a regular file (or none) at path is replaced, keeping its permissions; a
/// device, FIFO, socket or folder there is refused.
/// On failure returns false and fills *error (if given) naming the path. Any thread.
bool writeFileAtomically(const QString& path, const QByteArray& bytes, FileError* error);
/// What writeFileAtomically() would refuse before writing a byte: no name, a folder, something
/// that is not a regular file (a device, FIFO or socket), a folder that is not there or not
/// writable. For commands that compute for long before they write: checked first.
bool checkOutputPath(const QString& path, FileError* error);

}  // namespace prisca::core
