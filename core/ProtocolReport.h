#pragma once

#include "Table1Report.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace prisca::core {

/// A mean with its two-sided Student-t confidence interval over independent units (here: the
/// cells of an evaluation, each a demonstration style on a seed set).
struct MeanInterval {
    double mean = 0.0;   ///< mean of the finite values; NaN when there is none
    double lower = 0.0;  ///< mean - t s / sqrt(N); the mean itself when N == 1; NaN when N == 0
    double upper = 0.0;  ///< mean + t s / sqrt(N)
    int count = 0;       ///< N, the finite values used
};

/// Mean and interval of the finite values (non-finite ones skipped) at `level` (0.95: 95%).
MeanInterval meanInterval(const std::vector<double>& values, double level = 0.95);

/// One method's Table I row on one cell of the evaluation: a demonstration style on a seed set.
struct ProtocolCell {
    QString style;          ///< the demonstration style
    std::uint64_t seedSet;  ///< the seed set (demonstration hand and trial perturbations)
    Table1Row row;          ///< the method's trials there
};

/// How a set of cells spreads: the median and the worst of their position MAEs, and which cell
/// the worst is, so that one hard cell or day
/// shows as one.
struct CellSpread {
    int cells = 0;
    double mean = 0.0;    ///< [cm]; NaN without a finite cell
    double median = 0.0;  ///< [cm]
    double worst = 0.0;   ///< [cm]
    QString worstCell;    ///< "u on day 7102" (its style or variant, and seed set)
};

/// One day (seed set) of a method: its cells there.
struct DaySpread {
    std::uint64_t seedSet = 0;
    CellSpread position;
};

/// A method over every cell: the cells' mean absolute errors averaged with a 95% interval over
/// the cells, and per style the same over that style's seed sets; the cells' spread over all and
/// per day.
struct ProtocolRow {
    QString method;
    QString label;       ///< as tables show it (the id where empty)
    bool limit = false;  ///< the ruler (the oracle)
    const QString& shownLabel() const { return label.isEmpty() ? method : label; }
    MeanInterval position;                       ///< over the cells' position MAE [cm]
    MeanInterval orientation;                    ///< over the cells' orientation MAE [deg]
    int trials = 0;                              ///< trials that finished, over all cells
    double cpuMicrosecondsPerStep = 0.0;         ///< mean over the cells [us]
    std::vector<MeanInterval> stylePosition;     ///< per style, in ProtocolSummary::styles order
    std::vector<MeanInterval> styleOrientation;  ///< per style
    CellSpread spread;                           ///< over every cell (position)
    std::vector<DaySpread> days;                 ///< per seed set, in ProtocolSummary order
};

/// The evaluation of several methods on the same cells.
struct ProtocolSummary {
    QStringList styles;  ///< in the order given
    /// The breakdown's columns (`styles`) are plant variants, each over every style.
    bool byVariant = false;
    std::vector<std::uint64_t> seedSets;
    std::vector<ProtocolRow> rows;  ///< one per method, in the order given
    /// The row of the oracle (the limit), or -1 when it did not run.
    int oracleRow() const;
};

/// Summarises: cells[m] are method m's cells (any order). Each method's mean is the plain mean of
/// its cells' MAEs (equal weight per cell), so a style with more trials does not weigh more.
ProtocolSummary summarizeProtocol(const QStringList& methods, const QStringList& styles,
                                  const std::vector<std::uint64_t>& seedSets,
                                  const std::vector<std::vector<ProtocolCell>>& cells);

/// The summary as text: the methods' means with 95% intervals, how many times the oracle's
/// error each is (n/a where the oracle's is below 0.005, too small for a ratio), the CPU time per
/// step, a per-style breakdown, and per day (seed set) the mean, median and worst cell. Markdown
/// and LaTeX round for reading; CSV (long format: one line per method and scope, "all" or a style)
/// and JSON carry full precision. JSON rows keep Table I's keys (`method`,
/// `positionCm.meanAbsoluteError`, `orientationDeg.meanAbsoluteError`).
QString formatProtocol(const ProtocolSummary& summary, TableFormat format, const QString& caption);

}  // namespace prisca::core
