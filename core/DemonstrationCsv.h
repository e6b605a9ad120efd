#pragma once

#include "Demonstration.h"
#include "FileIo.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace prisca::core {

// The demonstration / run-log CSV format (docs/architecture.md "File formats"):
//
//     # prisca-demonstration 1
//     # plant: slidecar
//     # dt: 0.025
//     # states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]
//     # actions: throttle[1], steering[1]
//     t,x,y,psi,vx,vy,r,throttle,steering
//     0,0,0,0,0,0,0,0.5,0
//
// "#" lines come first; the first must be the magic "# prisca-demonstration 1". The keys plant,
// dt, states and actions (matched case-insensitively) fill the Demonstration's fields; every
// other "# key: value" line goes to Demonstration::metadata (key and value trimmed); "#" lines
// without a "key:" are free comments and are dropped. Then exactly one header row
// "t,<state names>,<action names>", then one data row per sample. Plain comma-separated values,
// '.' decimal point, no quoting, so pandas (comment='#') and MATLAB read it as is.
//
// The reader accepts a UTF-8 byte order mark, CRLF / CR / LF line endings, blank lines, "#"
// comment lines among the data rows, spaces or tabs around fields and a leading '+' on numbers.
// A list entry without "[unit]" gets unit "1". When the dt line is missing, dt is the median time
// step. All functions are pure, never throw and may be called from any thread.

/// Options for reading a demonstration CSV.
struct CsvReadOptions {
    /// Largest accepted relative deviation of each time step from dt: a step h is rejected when
    /// |h - dt| > dtTolerance * dt. Dimensionless, >= 0; infinity accepts any spacing.
    double dtTolerance = 0.05;
};

/// Parses demonstration CSV text (the bytes of a file, UTF-8).
/// @param sourceName  used as FileError::path (a file path, or e.g. "<clipboard>")
/// @param error       when non-null and parsing fails, receives the first problem found;
///                    left untouched on success
/// @return the demonstration (which passes Demonstration::validate()), or nullopt on failure
std::optional<Demonstration> parseDemonstrationCsv(const QByteArray& text,
                                                   const QString& sourceName, FileError* error,
                                                   const CsvReadOptions& options = {});

/// Reads and parses the demonstration CSV file at @p path; see parseDemonstrationCsv().
/// Also fails (with the path and the system's reason) when the file cannot be opened or read.
std::optional<Demonstration> readDemonstrationCsv(const QString& path, FileError* error,
                                                  const CsvReadOptions& options = {});

/// Checks that @p demo can be written as CSV and read back identically: it passes
/// Demonstration::validate(); names are non-empty, unique, not "t", have no surrounding
/// whitespace and contain none of , [ ] # " or control characters; units contain none of , [ ]
/// or control characters; the plant and metadata contain no line breaks; metadata keys are
/// non-empty, contain no ':' and are not one of the reserved keys plant, dt, states, actions.
/// @return an empty string when writable, else a one-line description of the first problem
QString checkDemonstrationForCsv(const Demonstration& demo);

/// Formats @p demo as CSV text (LF line endings). Numbers use the shortest representation
/// that reads back to the identical double, so a write/read round trip is bit for bit.
/// @param problem  when non-null and the demonstration is not writable, receives the reason
/// @return the text, or an empty array when checkDemonstrationForCsv() reports a problem
QByteArray formatDemonstrationCsv(const Demonstration& demo, QString* problem = nullptr);

/// The header of formatDemonstrationCsv() alone (magic line, plant, dt, names and units,
/// metadata, column row), from the demonstration's descriptive fields; its samples are not
/// used. A recording streamed to disk starts with this, then appendDemonstrationCsvRow() per
/// sample. The names must be writable (see checkDemonstrationForCsv()).
QByteArray formatDemonstrationCsvHeader(const Demonstration& demo);

/// Appends one data row (t, states..., actions...) in the format of formatDemonstrationCsv(), so
/// a recording can be streamed to disk row by row after a header written by that function.
void appendDemonstrationCsvRow(QByteArray& out, double time, const Eigen::VectorXd& state,
                               const Eigen::VectorXd& action);

/// Writes @p demo to @p path atomically (QSaveFile): on any failure an existing file at
/// @p path is left untouched and no partial file remains.
/// @param error  when non-null and writing fails, receives the path and the reason (an invalid
///               demonstration is refused before anything is written); untouched on success
/// @return true when the file was written completely
bool writeDemonstrationCsv(const Demonstration& demo, const QString& path, FileError* error);

}  // namespace prisca::core
