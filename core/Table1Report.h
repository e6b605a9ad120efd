#pragma once

#include "Statistics.h"

#include <QJsonValue>
#include <QString>

#include <limits>
#include <optional>
#include <vector>

namespace prisca::core {

/// One row of the paper's Table I: a method's final position and orientation errors over its
/// trials, as mean absolute error +- standard deviation and variance.
struct Table1Row {
    QString method;            ///< command-line name, e.g. "pd-h"
    ErrorSummary position;     ///< |p_end - p_lot| [cm]
    ErrorSummary orientation;  ///< |wrap(psi_end - psi_lot)| [deg]
    /// The controller's mean CPU time per control step [us]; NaN when not measured.
    double cpuMicrosecondsPerStep = std::numeric_limits<double>::quiet_NaN();
    QString label;       ///< as tables show it, e.g. "PD+H" (the method's id where empty)
    bool limit = false;  ///< the ruler every row is read against (the oracle)
    /// Trials asked for (0: as many as it has); a row with fewer (a cancelled batch) is partial.
    int plannedTrials = 0;
    /// label, or the id where there is none.
    const QString& shownLabel() const { return label.isEmpty() ? method : label; }
    /// Fewer trials than asked for: every format marks it.
    bool partial() const { return plannedTrials > 0 && position.count < plannedTrials; }
    /// Plans through an identified model (mpc): protocols read it per cell against the best
    /// feedback law, the rows that are neither this nor the limit.
    bool plansThroughModel = false;
};

/// Output formats of Table I.
enum class TableFormat { Markdown, Csv, Latex, Json };

/// "md", "csv", "latex" or "json".
std::optional<TableFormat> parseTableFormat(const QString& text);
/// The table as text. Markdown and LaTeX show "MAE +- std" and the variance for position (cm,
/// cm^2) and orientation (deg, deg^2) with two decimals, the trial count and the CPU time per
/// control step; CSV and JSON carry full precision. `caption` describes the experiment (seed,
/// trials, perturbation). A row of one trial has no spread (shown "n/a", empty in CSV, null in
/// JSON); a partial row (Table1Row::partial) says so in every format, with the trials it has
/// of those asked for.
QString formatTable1(const std::vector<Table1Row>& rows, TableFormat format,
                     const QString& caption);
/// A CPU time per step for a table: three significant digits, "n/a" when not measured.
QString formatCpuMicroseconds(double microseconds);
/// A number for reading: two decimals, "n/a" when not finite.
QString formatFixed(double value);
/// A number for machines: full precision, empty when not finite.
QString formatFull(double value);
/// A number for JSON: null when not finite.
QJsonValue jsonNumber(double value);

}  // namespace prisca::core
