#pragma once

#include <QByteArray>
#include <QString>

namespace prisca::core {

/// Where and why a file could not be read or written.
struct FileError {
    QString path;  ///< file path, or the source name given for in-memory text
    int line = 0;  ///< 1-based line number of the problem; 0 when not applicable
    /// 1-based field number in the header or a data row (1 is the time column t), or entry
    /// number in a "states:" / "actions:" list; 0 when not applicable.
    int column = 0;
    QString message;  ///< one line; names the offending column and quotes the offending text

    /// "path:line:column: message", leaving out the parts that are empty or zero.
    QString toString() const;
};

/// Appends the shortest text that reads back to exactly the same double (locale independent,
/// unlike printf). Any thread.
void appendCsvNumber(QByteArray& out, double value);

/// Writes bytes to path atomically: a temporary file renamed over the target only when
/// complete, so a crash or a full disk never leaves a half-written file or damages the old one.
/// On failure returns false and fills *error (if given) naming the path. Any thread.
bool writeFileAtomically(const QString& path, const QByteArray& bytes, FileError* error);

}  // namespace prisca::core
