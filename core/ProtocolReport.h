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
    /// The demonstration style where `style` names a plant variant (empty otherwise): a cell is
    /// a variant, a demonstration style and a seed set.
    QString demonstration;
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

/// A cell may be this many times the best feedback law on that cell before a planner counts as
/// worse there (its fallback did not hold).
constexpr double kCellToleranceOverBestLaw = 1.5;

/// A planner (a row that plans through a model) against the feedback laws (the rows that are
/// neither a planner nor the limit), over a set of cells: the ratio of its mean to the mean of
/// the law that parks best over those cells, and cell by cell against whichever law parked best
/// on that cell.
struct LawComparison {
    int cells = 0;              ///< cells where the planner and at least one law are finite
    QString bestLaw;            ///< the law with the lowest mean over the cells (its label)
    double bestLawMean = 0.0;   ///< [cm]; NaN without a law
    double ratioOfMeans = 0.0;  ///< the planner's mean / bestLawMean; NaN without a law
    int cellsOver = 0;          ///< cells worse than kCellToleranceOverBestLaw x that cell's best
    double worstRatio = 0.0;    ///< the largest ratio to a cell's best law; NaN without a cell
    QString worstRatioCell;     ///< its cell
};

/// One day (seed set) of a method: its cells there.
struct DaySpread {
    std::uint64_t seedSet = 0;
    CellSpread position;
    LawComparison againstLaws;  ///< for a planner: the day's cells against the laws
};

/// A method over every cell: the cells' mean absolute errors averaged with a 95% interval over
/// the cells, and per style the same over that style's seed sets; the cells' spread over all and
/// per day.
struct ProtocolRow {
    QString method;
    QString label;                   ///< as tables show it (the id where empty)
    bool limit = false;              ///< the ruler (the oracle)
    bool plansThroughModel = false;  ///< a planner: read against the feedback laws
    const QString& shownLabel() const { return label.isEmpty() ? method : label; }
    MeanInterval position;                       ///< over the cells' position MAE [cm]
    MeanInterval orientation;                    ///< over the cells' orientation MAE [deg]
    int trials = 0;                              ///< trials that finished, over all cells
    double cpuMicrosecondsPerStep = 0.0;         ///< mean over the cells [us]
    std::vector<MeanInterval> stylePosition;     ///< per style, in ProtocolSummary::styles order
    std::vector<MeanInterval> styleOrientation;  ///< per style
    CellSpread spread;                           ///< over every cell (position)
    std::vector<DaySpread> days;                 ///< per seed set, in ProtocolSummary order
    /// For a planner (with at least one law among the rows): its cells against the laws'.
    LawComparison againstLaws;
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

/// Summarises: cells[m] are method m's cells (any order; a cell is matched across methods by its
/// style, demonstration and seed set). Each method's mean is the plain mean of its cells' MAEs
/// (equal weight per cell), so a style with more trials does not weigh more. A planner's row is
/// compared with the feedback laws' over all cells and per day.
ProtocolSummary summarizeProtocol(const QStringList& methods, const QStringList& styles,
                                  const std::vector<std::uint64_t>& seedSets,
                                  const std::vector<std::vector<ProtocolCell>>& cells);

/// The summary as text: the methods' means with 95% intervals, how many times the oracle's
/// error each is (n/a where the oracle's is below 0.005, too small for a ratio), the CPU time per
/// step, a per-style breakdown, per day (seed set) the mean, median and worst cell, and for a
/// planner its comparison with the best feedback law (Markdown and JSON: `againstLaws`). Markdown
/// and LaTeX round for reading; CSV (long format: one line per method and scope, "all" or a style)
/// and JSON carry full precision. JSON rows keep Table I's keys (`method`,
/// `positionCm.meanAbsoluteError`, `orientationDeg.meanAbsoluteError`).
QString formatProtocol(const ProtocolSummary& summary, TableFormat format, const QString& caption);

}  // namespace prisca::core
