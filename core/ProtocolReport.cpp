#include "ProtocolReport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace prisca::core {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

QString fixed(double value) {
    return formatFixed(value);
}

QString full(double value) {
    return formatFull(value);
}

// "4.21 [3.80, 4.62]", or the mean alone for a single cell.
QString withInterval(const MeanInterval& m) {
    if (m.count == 0) {
        return QStringLiteral("n/a");
    }
    if (m.count == 1) {
        return fixed(m.mean);
    }
    return QStringLiteral("%1 [%2, %3]").arg(fixed(m.mean), fixed(m.lower), fixed(m.upper));
}

// Below half the tables' last digit (0.01 cm, 0.01 deg) the limit is 0 as far as a ratio goes.
constexpr double kResolvableLimit = 0.005;

QString ratio(double value, double limit) {
    if (!std::isfinite(value) || !std::isfinite(limit) || limit < kResolvableLimit) {
        return QStringLiteral("n/a");
    }
    return QStringLiteral("%1x").arg(QString::number(value / limit, 'f', 1));
}

QJsonObject intervalJson(const MeanInterval& m) {
    return {{"meanAbsoluteError", jsonNumber(m.mean)},
            {"lower", jsonNumber(m.lower)},
            {"upper", jsonNumber(m.upper)},
            {"cells", m.count}};
}

// The spread of cells' position MAEs (non-finite ones skipped), `names` naming each.
CellSpread spreadOf(const std::vector<double>& values, const QStringList& names) {
    CellSpread out;
    std::vector<double> finite;
    int worst = -1;
    for (size_t i = 0; i < values.size(); ++i) {
        if (std::isfinite(values[i])) {
            finite.push_back(values[i]);
            if (worst < 0 || values[i] > values[static_cast<size_t>(worst)]) {
                worst = static_cast<int>(i);
            }
        }
    }
    out.cells = static_cast<int>(finite.size());
    if (finite.empty()) {
        out.mean = out.median = out.worst = kNaN;
        return out;
    }
    out.mean = mean(finite);
    std::sort(finite.begin(), finite.end());
    const size_t n = finite.size();
    out.median = n % 2 == 1 ? finite[n / 2] : 0.5 * (finite[n / 2 - 1] + finite[n / 2]);
    out.worst = finite.back();
    out.worstCell = names[worst];
    return out;
}

// "4.21 / 3.10 / 9.80 (u on day 7102)": mean / median / worst cell.
QString spreadText(const CellSpread& s) {
    if (s.cells == 0) {
        return QStringLiteral("n/a");
    }
    return QStringLiteral("%1 / %2 / %3 (%4)")
        .arg(fixed(s.mean), fixed(s.median), fixed(s.worst), s.worstCell);
}

QJsonObject spreadJson(const CellSpread& s) {
    return {{"cells", s.cells},
            {"meanCm", jsonNumber(s.mean)},
            {"medianCm", jsonNumber(s.median)},
            {"worstCm", jsonNumber(s.worst)},
            {"worstCell", s.worstCell}};
}

// One cell's position MAE [cm], by its name and its day's index in the summary.
struct CellValue {
    QString name;
    size_t day = 0;
    double cm = 0.0;
};

double meanOfFinite(const std::vector<CellValue>& cells, const std::optional<size_t>& day) {
    std::vector<double> finite;
    for (const CellValue& c : cells) {
        if ((!day || c.day == *day) && std::isfinite(c.cm)) {
            finite.push_back(c.cm);
        }
    }
    return finite.empty() ? kNaN : mean(finite);
}

// The planner's cells (all of them, or one day's) against the laws' (see LawComparison).
LawComparison compareWithLaws(const std::vector<std::vector<CellValue>>& values, size_t planner,
                              const std::vector<size_t>& laws, const std::vector<ProtocolRow>& rows,
                              const std::optional<size_t>& day) {
    LawComparison out;
    out.bestLawMean = out.ratioOfMeans = out.worstRatio = kNaN;
    for (size_t law : laws) {
        const double m = meanOfFinite(values[law], day);
        if (std::isfinite(m) && !(m >= out.bestLawMean)) {
            out.bestLawMean = m;
            out.bestLaw = rows[law].shownLabel();
        }
    }
    const double plannerMean = meanOfFinite(values[planner], day);
    if (std::isfinite(plannerMean) && out.bestLawMean > 0.0) {
        out.ratioOfMeans = plannerMean / out.bestLawMean;
    }
    for (const CellValue& cell : values[planner]) {
        if ((day && cell.day != *day) || !std::isfinite(cell.cm)) {
            continue;
        }
        double best = std::numeric_limits<double>::infinity();
        for (size_t law : laws) {
            for (const CellValue& other : values[law]) {
                if (other.name == cell.name && std::isfinite(other.cm)) {
                    best = std::min(best, other.cm);
                }
            }
        }
        if (!std::isfinite(best)) {
            continue;
        }
        ++out.cells;
        if (cell.cm > kCellToleranceOverBestLaw * best) {
            ++out.cellsOver;
        }
        const double ratio = best > 0.0      ? cell.cm / best
                             : cell.cm > 0.0 ? std::numeric_limits<double>::infinity()
                                             : 1.0;
        if (!(ratio <= out.worstRatio)) {
            out.worstRatio = ratio;
            out.worstRatioCell = cell.name;
        }
    }
    return out;
}

// "0.29x PD+LSD; 0 of 10 cells over 1.5x; worst 1.21x (x11 fast on day 8300)".
QString lawComparisonText(const LawComparison& c) {
    if (c.cells == 0) {
        return QStringLiteral("n/a");
    }
    return QStringLiteral("%1x %2; %3 of %4 cells over %5x; worst %6x (%7)")
        .arg(QString::number(c.ratioOfMeans, 'f', 2), c.bestLaw)
        .arg(c.cellsOver)
        .arg(c.cells)
        .arg(QString::number(kCellToleranceOverBestLaw, 'f', 1),
             QString::number(c.worstRatio, 'f', 2), c.worstRatioCell);
}

QJsonObject lawComparisonJson(const LawComparison& c) {
    return {{"cells", c.cells},
            {"bestLaw", c.bestLaw},
            {"bestLawMeanCm", jsonNumber(c.bestLawMean)},
            {"ratioOfMeans", jsonNumber(c.ratioOfMeans)},
            {"tolerance", kCellToleranceOverBestLaw},
            {"cellsOver", c.cellsOver},
            {"worstRatio", jsonNumber(c.worstRatio)},
            {"worstRatioCell", c.worstRatioCell}};
}

QString escapeLatex(QString text) {
    return text.replace(QLatin1Char('%'), QStringLiteral("\\%"))
        .replace(QLatin1Char('_'), QStringLiteral("\\_"));
}

}  // namespace

MeanInterval meanInterval(const std::vector<double>& values, double level) {
    if (!(level > 0.0 && level < 1.0)) {
        throw std::invalid_argument("meanInterval: level must be in (0, 1)");
    }
    MeanInterval out;
    std::vector<double> finite;
    for (double v : values) {
        if (std::isfinite(v)) {
            finite.push_back(v);
        }
    }
    out.count = static_cast<int>(finite.size());
    if (finite.empty()) {
        out.mean = out.lower = out.upper = kNaN;
        return out;
    }
    out.mean = mean(finite);
    if (finite.size() == 1) {
        out.lower = out.upper = out.mean;
        return out;
    }
    const double halfWidth = studentTQuantile(0.5 + 0.5 * level, out.count - 1) *
                             std::sqrt(sampleVariance(finite) / out.count);
    out.lower = out.mean - halfWidth;
    out.upper = out.mean + halfWidth;
    return out;
}

int ProtocolSummary::oracleRow() const {
    for (size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].limit) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

ProtocolSummary summarizeProtocol(const QStringList& methods, const QStringList& styles,
                                  const std::vector<std::uint64_t>& seedSets,
                                  const std::vector<std::vector<ProtocolCell>>& cells) {
    if (cells.size() != static_cast<size_t>(methods.size())) {
        throw std::invalid_argument("summarizeProtocol: one list of cells per method");
    }
    ProtocolSummary summary;
    summary.styles = styles;
    summary.seedSets = seedSets;
    std::vector<std::vector<CellValue>> values(cells.size());
    for (int m = 0; m < methods.size(); ++m) {
        ProtocolRow row;
        row.method = methods[m];
        std::vector<double> position, orientation, cpu;
        std::vector<std::vector<double>> stylePosition(styles.size()),
            styleOrientation(styles.size());
        QStringList names;
        std::vector<std::vector<double>> dayPosition(seedSets.size());
        std::vector<QStringList> dayNames(seedSets.size());
        for (const ProtocolCell& cell : cells[m]) {
            row.label = cell.row.label;
            row.limit = cell.row.limit;
            row.plansThroughModel = cell.row.plansThroughModel;
            position.push_back(cell.row.position.meanAbsoluteError);
            orientation.push_back(cell.row.orientation.meanAbsoluteError);
            cpu.push_back(cell.row.cpuMicrosecondsPerStep);
            row.trials += cell.row.position.count;
            const int s = static_cast<int>(styles.indexOf(cell.style));
            if (s < 0) {
                throw std::invalid_argument(
                    QStringLiteral("summarizeProtocol: cell of unknown style '%1'")
                        .arg(cell.style)
                        .toStdString());
            }
            stylePosition[s].push_back(cell.row.position.meanAbsoluteError);
            styleOrientation[s].push_back(cell.row.orientation.meanAbsoluteError);
            const QString name = QStringLiteral("%1 on day %2")
                                     .arg(cell.demonstration.isEmpty()
                                              ? cell.style
                                              : cell.style + QLatin1Char(' ') + cell.demonstration)
                                     .arg(cell.seedSet);
            names.append(name);
            const auto day = std::find(seedSets.begin(), seedSets.end(), cell.seedSet);
            if (day == seedSets.end()) {
                throw std::invalid_argument(
                    QStringLiteral("summarizeProtocol: cell of unknown seed set %1")
                        .arg(cell.seedSet)
                        .toStdString());
            }
            const size_t d = static_cast<size_t>(day - seedSets.begin());
            dayPosition[d].push_back(cell.row.position.meanAbsoluteError);
            dayNames[d].append(name);
            values[static_cast<size_t>(m)].push_back(
                {name, d, cell.row.position.meanAbsoluteError});
        }
        row.spread = spreadOf(position, names);
        for (size_t d = 0; d < seedSets.size(); ++d) {
            row.days.push_back({seedSets[d], spreadOf(dayPosition[d], dayNames[d])});
        }
        row.position = meanInterval(position);
        row.orientation = meanInterval(orientation);
        row.cpuMicrosecondsPerStep = mean(cpu);
        for (int s = 0; s < styles.size(); ++s) {
            row.stylePosition.push_back(meanInterval(stylePosition[s]));
            row.styleOrientation.push_back(meanInterval(styleOrientation[s]));
        }
        summary.rows.push_back(std::move(row));
    }
    std::vector<size_t> laws;
    for (size_t m = 0; m < summary.rows.size(); ++m) {
        if (!summary.rows[m].limit && !summary.rows[m].plansThroughModel) {
            laws.push_back(m);
        }
    }
    for (size_t m = 0; m < summary.rows.size() && !laws.empty(); ++m) {
        ProtocolRow& row = summary.rows[m];
        if (!row.plansThroughModel) {
            continue;
        }
        row.againstLaws = compareWithLaws(values, m, laws, summary.rows, std::nullopt);
        for (size_t d = 0; d < row.days.size(); ++d) {
            row.days[d].againstLaws = compareWithLaws(values, m, laws, summary.rows, d);
        }
    }
    return summary;
}

QString formatProtocol(const ProtocolSummary& summary, TableFormat format, const QString& caption) {
    const int oracle = summary.oracleRow();
    const double limitPosition = oracle >= 0 ? summary.rows[oracle].position.mean : kNaN;
    const double limitOrientation = oracle >= 0 ? summary.rows[oracle].orientation.mean : kNaN;
    QString out;
    switch (format) {
        case TableFormat::Markdown: {
            out += caption + QStringLiteral("\n\n");
            out += QStringLiteral(
                "| method | cells | trials | position MAE [cm] (95% interval) | x limit "
                "| orientation MAE [deg] (95% interval) | x limit | CPU [µs/step] |\n");
            out += QStringLiteral("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
            for (const ProtocolRow& r : summary.rows) {
                out += QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 | %7 | %8 |\n")
                           .arg(r.shownLabel())
                           .arg(r.position.count)
                           .arg(r.trials)
                           .arg(withInterval(r.position), ratio(r.position.mean, limitPosition),
                                withInterval(r.orientation),
                                ratio(r.orientation.mean, limitOrientation),
                                formatCpuMicroseconds(r.cpuMicrosecondsPerStep));
            }
            out +=
                QStringLiteral(
                    "\nPer %1, position MAE [cm] / orientation MAE [deg] "
                    "(mean over seed sets):\n\n| method |")
                    .arg(summary.byVariant ? QStringLiteral("variant") : QStringLiteral("style"));
            QString rule = QStringLiteral("| --- |");
            for (const QString& style : summary.styles) {
                out += QStringLiteral(" %1 |").arg(style);
                rule += QStringLiteral(" ---: |");
            }
            out += QLatin1Char('\n') + rule + QLatin1Char('\n');
            for (const ProtocolRow& r : summary.rows) {
                out += QStringLiteral("| %1 |").arg(r.shownLabel());
                for (int s = 0; s < summary.styles.size(); ++s) {
                    out +=
                        QStringLiteral(" %1 / %2 |")
                            .arg(fixed(r.stylePosition[s].mean), fixed(r.styleOrientation[s].mean));
                }
                out += QLatin1Char('\n');
            }
            out += QStringLiteral(
                "\nPer day (seed set), position MAE [cm] over the day's cells: mean / median / "
                "worst (its cell):\n\n| method | all |");
            // A column per day (seed set) after "all", and the header's rule.
            auto dayColumns = [&](const QString& alignment) {
                QString dayRule = QStringLiteral("| --- | %1 |").arg(alignment);
                for (std::uint64_t set : summary.seedSets) {
                    out += QStringLiteral(" %1 |").arg(set);
                    dayRule += QStringLiteral(" %1 |").arg(alignment);
                }
                out += QLatin1Char('\n') + dayRule + QLatin1Char('\n');
            };
            dayColumns(QStringLiteral("---:"));
            for (const ProtocolRow& r : summary.rows) {
                out += QStringLiteral("| %1 | %2 |").arg(r.shownLabel(), spreadText(r.spread));
                for (const DaySpread& day : r.days) {
                    out += QStringLiteral(" %1 |").arg(spreadText(day.position));
                }
                out += QLatin1Char('\n');
            }
            const bool planners =
                std::any_of(summary.rows.begin(), summary.rows.end(),
                            [](const ProtocolRow& r) { return r.againstLaws.cells > 0; });
            if (planners) {
                out += QStringLiteral(
                           "\nPlanners against the feedback laws (every row but the planners and "
                           "the limit): the ratio of means to the law that parks best over the "
                           "cells, the cells worse than %1x the best law on that cell, the worst "
                           "ratio (its cell):\n\n| method | all |")
                           .arg(QString::number(kCellToleranceOverBestLaw, 'f', 1));
                dayColumns(QStringLiteral("---"));
                for (const ProtocolRow& r : summary.rows) {
                    if (r.againstLaws.cells == 0) {
                        continue;
                    }
                    out += QStringLiteral("| %1 | %2 |")
                               .arg(r.shownLabel(), lawComparisonText(r.againstLaws));
                    for (const DaySpread& day : r.days) {
                        out += QStringLiteral(" %1 |").arg(lawComparisonText(day.againstLaws));
                    }
                    out += QLatin1Char('\n');
                }
            }
            break;
        }
        case TableFormat::Csv: {
            out += QStringLiteral(
                "scope,method,label,cells,position_mae_cm,position_lower_cm,position_upper_cm,"
                "orientation_mae_deg,orientation_lower_deg,orientation_upper_deg,trials,"
                "cpu_us_per_step,position_median_cm,position_worst_cm,worst_cell\n");
            auto line = [&](const QString& scope, const ProtocolRow& r, const MeanInterval& p,
                            const MeanInterval& o, const QString& trials, const QString& cpu,
                            const CellSpread* spread) {
                out += QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9,%10,%11,%12,%13,%14,%15\n")
                           .arg(scope, r.method, r.shownLabel())
                           .arg(p.count)
                           .arg(full(p.mean), full(p.lower), full(p.upper), full(o.mean),
                                full(o.lower), full(o.upper), trials, cpu)
                           .arg(spread ? full(spread->median) : QString(),
                                spread ? full(spread->worst) : QString(),
                                spread ? spread->worstCell : QString());
            };
            for (const ProtocolRow& r : summary.rows) {
                line(QStringLiteral("all"), r, r.position, r.orientation, QString::number(r.trials),
                     full(r.cpuMicrosecondsPerStep), &r.spread);
            }
            for (int s = 0; s < summary.styles.size(); ++s) {
                for (const ProtocolRow& r : summary.rows) {
                    line(summary.styles[s], r, r.stylePosition[s], r.styleOrientation[s], QString(),
                         QString(), nullptr);
                }
            }
            for (size_t d = 0; d < summary.seedSets.size(); ++d) {
                for (const ProtocolRow& r : summary.rows) {
                    // A day's mean without its interval: the day's cells are not independent
                    // units of the day's hand and perturbations.
                    MeanInterval p;
                    p.count = r.days[d].position.cells;
                    p.mean = r.days[d].position.mean;
                    p.lower = p.upper = kNaN;
                    MeanInterval o;
                    o.mean = o.lower = o.upper = kNaN;
                    line(QStringLiteral("day %1").arg(summary.seedSets[d]), r, p, o, QString(),
                         QString(), &r.days[d].position);
                }
            }
            break;
        }
        case TableFormat::Latex: {
            out += QStringLiteral("\\begin{table}[t]\n\\centering\n\\caption{%1}\n")
                       .arg(escapeLatex(caption));
            out += QStringLiteral("\\begin{tabular}{lrrrrrr}\n\\hline\n");
            out += QStringLiteral(
                "Method & Cells & Position MAE [cm] & $\\times$ limit & Orientation MAE "
                "[$^\\circ$] & $\\times$ limit & CPU [$\\mu$s/step] \\\\\n\\hline\n");
            for (const ProtocolRow& r : summary.rows) {
                out += QStringLiteral("%1 & %2 & %3 & %4 & %5 & %6 & %7 \\\\\n")
                           .arg(r.shownLabel())
                           .arg(r.position.count)
                           .arg(withInterval(r.position), ratio(r.position.mean, limitPosition),
                                withInterval(r.orientation),
                                ratio(r.orientation.mean, limitOrientation),
                                formatCpuMicroseconds(r.cpuMicrosecondsPerStep));
            }
            out += QStringLiteral("\\hline\n\\end{tabular}\n\n");
            out += QStringLiteral("\\begin{tabular}{l%1}\n\\hline\nMethod")
                       .arg(QString(summary.styles.size(), QLatin1Char('r')));
            for (const QString& style : summary.styles) {
                out += QStringLiteral(" & %1").arg(escapeLatex(style));
            }
            out += QStringLiteral(" \\\\\n\\hline\n");
            for (const ProtocolRow& r : summary.rows) {
                out += r.shownLabel();
                for (int s = 0; s < summary.styles.size(); ++s) {
                    out +=
                        QStringLiteral(" & %1 / %2")
                            .arg(fixed(r.stylePosition[s].mean), fixed(r.styleOrientation[s].mean));
                }
                out += QStringLiteral(" \\\\\n");
            }
            out += QStringLiteral("\\hline\n\\end{tabular}\n\n");
            // Per day: mean / median / worst cell's position MAE [cm].
            out += QStringLiteral("\\begin{tabular}{lr%1}\n\\hline\nMethod & all")
                       .arg(QString(static_cast<int>(summary.seedSets.size()), QLatin1Char('r')));
            for (std::uint64_t set : summary.seedSets) {
                out += QStringLiteral(" & %1").arg(set);
            }
            out += QStringLiteral(" \\\\\n\\hline\n");
            const auto latexSpread = [](const CellSpread& c) {
                return c.cells == 0 ? QStringLiteral("n/a")
                                    : QStringLiteral("%1 / %2 / %3")
                                          .arg(fixed(c.mean), fixed(c.median), fixed(c.worst));
            };
            for (const ProtocolRow& r : summary.rows) {
                out += r.shownLabel() + QStringLiteral(" & ") + latexSpread(r.spread);
                for (const DaySpread& day : r.days) {
                    out += QStringLiteral(" & ") + latexSpread(day.position);
                }
                out += QStringLiteral(" \\\\\n");
            }
            out += QStringLiteral("\\hline\n\\end{tabular}\n\\end{table}\n");
            break;
        }
        case TableFormat::Json: {
            QJsonArray rows;
            for (const ProtocolRow& r : summary.rows) {
                QJsonArray days;
                for (const DaySpread& day : r.days) {
                    QJsonObject o = spreadJson(day.position);
                    o.insert("seedSet", static_cast<double>(day.seedSet));
                    if (r.plansThroughModel) {
                        o.insert("againstLaws", lawComparisonJson(day.againstLaws));
                    }
                    days.append(o);
                }
                QJsonArray styles;
                for (int s = 0; s < summary.styles.size(); ++s) {
                    styles.append(
                        QJsonObject{{"style", summary.styles[s]},
                                    {"positionCm", intervalJson(r.stylePosition[s])},
                                    {"orientationDeg", intervalJson(r.styleOrientation[s])}});
                }
                QJsonObject row{
                    {"method", r.method},
                    {"label", r.shownLabel()},
                    {"trials", r.trials},
                    {"positionCm", intervalJson(r.position)},
                    {"orientationDeg", intervalJson(r.orientation)},
                    {"positionTimesLimit",
                     jsonNumber(limitPosition >= kResolvableLimit ? r.position.mean / limitPosition
                                                                  : kNaN)},
                    {"orientationTimesLimit", jsonNumber(limitOrientation >= kResolvableLimit
                                                             ? r.orientation.mean / limitOrientation
                                                             : kNaN)},
                    {"cpuMicrosecondsPerStep", jsonNumber(r.cpuMicrosecondsPerStep)},
                    {"styles", styles},
                    {"cellSpread", spreadJson(r.spread)},
                    {"days", days}};
                if (r.plansThroughModel) {
                    row.insert("againstLaws", lawComparisonJson(r.againstLaws));
                }
                rows.append(row);
            }
            QJsonArray styles, seedSets;
            for (const QString& style : summary.styles) {
                styles.append(style);
            }
            for (std::uint64_t set : summary.seedSets) {
                seedSets.append(static_cast<double>(set));
            }
            out = QString::fromUtf8(QJsonDocument(QJsonObject{{"caption", caption},
                                                              {"styles", styles},
                                                              {"seedSets", seedSets},
                                                              {"rows", rows}})
                                        .toJson(QJsonDocument::Indented));
            break;
        }
    }
    return out;
}

}  // namespace prisca::core
