#include "Table1Report.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>
#include <limits>

namespace prisca::core {

QString formatFixed(double value) {
    return std::isfinite(value) ? QString::number(value, 'f', 2) : QStringLiteral("n/a");
}

QString formatFull(double value) {
    return std::isfinite(value) ? QString::number(value, 'g', 17) : QString();
}

QJsonValue jsonNumber(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

namespace {

QString fixed(double value) {
    return formatFixed(value);
}

QString full(double value) {
    return formatFull(value);
}

// A spread needs two trials: from one it is not zero, it is unknown.
double spread(const ErrorSummary& s, double value) {
    return s.count >= 2 ? value : std::numeric_limits<double>::quiet_NaN();
}

// "MAE ± std", or the MAE alone when there is no spread to show.
QString plusMinus(const ErrorSummary& s, const QString& pm) {
    if (s.count < 2 || !std::isfinite(s.standardDeviation)) {
        return formatFixed(s.meanAbsoluteError);
    }
    return QStringLiteral("%1%2%3").arg(formatFixed(s.meanAbsoluteError), pm,
                                        formatFixed(s.standardDeviation));
}

// The label as a table shows it: "PD+H (partial: 1 of 20 trials)" for a partial row.
QString labelOf(const Table1Row& r) {
    return r.partial() ? QStringLiteral("%1 (partial: %2 of %3 trials)")
                             .arg(r.shownLabel())
                             .arg(r.position.count)
                             .arg(r.plannedTrials)
                       : r.shownLabel();
}

QJsonObject summaryJson(const ErrorSummary& s) {
    return {{"meanAbsoluteError", jsonNumber(s.meanAbsoluteError)},
            {"standardDeviation", jsonNumber(spread(s, s.standardDeviation))},
            {"variance", jsonNumber(spread(s, s.variance))},
            {"minimum", jsonNumber(s.minimum)},
            {"maximum", jsonNumber(s.maximum)},
            {"count", s.count},
            {"failed", s.nonFinite}};
}

}  // namespace

QString formatCpuMicroseconds(double microseconds) {
    if (!std::isfinite(microseconds)) {
        return QStringLiteral("n/a");
    }
    return microseconds >= 100.0 ? QString::number(microseconds, 'f', 0)
                                 : QString::number(microseconds, 'g', 3);
}

std::optional<TableFormat> parseTableFormat(const QString& text) {
    if (text == QLatin1String("md"))
        return TableFormat::Markdown;
    if (text == QLatin1String("csv"))
        return TableFormat::Csv;
    if (text == QLatin1String("latex"))
        return TableFormat::Latex;
    if (text == QLatin1String("json"))
        return TableFormat::Json;
    return std::nullopt;
}

QString formatTable1(const std::vector<Table1Row>& rows, TableFormat format,
                     const QString& caption) {
    QString out;
    switch (format) {
        case TableFormat::Markdown:
            out += caption + QStringLiteral("\n\n");
            out += QStringLiteral(
                "| method | trials | position MAE ± std [cm] | position variance [cm²] "
                "| orientation MAE ± std [deg] | orientation variance [deg²] "
                "| CPU [µs/step] |\n");
            out += QStringLiteral("| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n");
            for (const Table1Row& r : rows) {
                out += QStringLiteral("| %1 | %2 | %3 | %4 | %5 | %6 | %7 |\n")
                           .arg(labelOf(r))
                           .arg(r.position.count)
                           .arg(plusMinus(r.position, QStringLiteral(" ± ")),
                                fixed(spread(r.position, r.position.variance)),
                                plusMinus(r.orientation, QStringLiteral(" ± ")),
                                fixed(spread(r.orientation, r.orientation.variance)),
                                formatCpuMicroseconds(r.cpuMicrosecondsPerStep));
            }
            break;
        case TableFormat::Csv:
            out += QStringLiteral(
                "method,label,trials,position_mae_cm,position_std_cm,position_var_cm2,"
                "orientation_mae_deg,orientation_std_deg,orientation_var_deg2,cpu_us_per_step,"
                "trials_planned,partial\n");
            for (const Table1Row& r : rows) {
                out += QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9,%10,%11,%12\n")
                           .arg(r.method, r.shownLabel())
                           .arg(r.position.count)
                           .arg(full(r.position.meanAbsoluteError),
                                full(spread(r.position, r.position.standardDeviation)),
                                full(spread(r.position, r.position.variance)),
                                full(r.orientation.meanAbsoluteError),
                                full(spread(r.orientation, r.orientation.standardDeviation)),
                                full(spread(r.orientation, r.orientation.variance)),
                                full(r.cpuMicrosecondsPerStep))
                           .arg(r.plannedTrials > 0 ? r.plannedTrials : r.position.count)
                           .arg(r.partial() ? QStringLiteral("true") : QStringLiteral("false"));
            }
            break;
        case TableFormat::Latex: {
            QString escapedCaption = caption;
            escapedCaption.replace(QLatin1Char('%'), QStringLiteral("\\%"))
                .replace(QLatin1Char('_'), QStringLiteral("\\_"));
            out += QStringLiteral("\\begin{table}[t]\n\\centering\n\\caption{%1}\n")
                       .arg(escapedCaption);
            out += QStringLiteral("\\begin{tabular}{lrrrrrr}\n\\hline\n");
            out += QStringLiteral(
                " & & \\multicolumn{2}{c}{Position} & \\multicolumn{2}{c}{Orientation} & "
                "\\\\\n");
            out += QStringLiteral(
                "Method & $N$ & MAE [cm] & Var. [cm$^2$] & MAE [$^\\circ$] & Var. [$^{\\circ 2}$] "
                "& CPU [$\\mu$s/step] \\\\\n\\hline\n");
            for (const Table1Row& r : rows) {
                out += QStringLiteral("%1 & %2 & $%3$ & %4 & $%5$ & %6 & %7 \\\\\n")
                           .arg(labelOf(r))
                           .arg(r.position.count)
                           .arg(plusMinus(r.position, QStringLiteral(" \\pm ")),
                                fixed(spread(r.position, r.position.variance)),
                                plusMinus(r.orientation, QStringLiteral(" \\pm ")),
                                fixed(spread(r.orientation, r.orientation.variance)),
                                formatCpuMicroseconds(r.cpuMicrosecondsPerStep));
            }
            out += QStringLiteral("\\hline\n\\end{tabular}\n\\end{table}\n");
            break;
        }
        case TableFormat::Json: {
            QJsonArray array;
            for (const Table1Row& r : rows) {
                array.append(QJsonObject{
                    {"method", r.method},
                    {"label", r.shownLabel()},
                    {"trials", r.position.count},
                    {"plannedTrials", r.plannedTrials > 0 ? r.plannedTrials : r.position.count},
                    {"partial", r.partial()},
                    {"positionCm", summaryJson(r.position)},
                    {"orientationDeg", summaryJson(r.orientation)},
                    {"cpuMicrosecondsPerStep", jsonNumber(r.cpuMicrosecondsPerStep)}});
            }
            out =
                QString::fromUtf8(QJsonDocument(QJsonObject{{"caption", caption}, {"rows", array}})
                                      .toJson(QJsonDocument::Indented));
            break;
        }
    }
    return out;
}

}  // namespace prisca::core
