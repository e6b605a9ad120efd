// prisca-cli lemma41: the H-gamma grid of Lemma 4.1 / Fig. 2 (where Var(D) < 1).
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Lemma41.h"

#include <QJsonArray>

#include <limits>

namespace prisca::app::cli {

using namespace figures;

namespace {

// The grid evaluates gamma-steps x max-h x (max-h + 1) terms of D (core::lemma41Terms), 16 to
// 28 ns each on one core of the lab's 2-core machine (more for large H, whose powers of gamma
// underflow), and writes a CSV row (~0.4 us) per cell. At most kMaxTerms keeps the largest
// accepted grids under a minute there: 39 s for --max-h 10000 --gamma-steps 14, 26 s for
// --max-h 386 --gamma-steps 10001, both with --plot.
constexpr long long kMaxTerms = 1'500'000'000;
// tau' = 2H terms per cell: the cost grows with the square of the largest horizon.
constexpr int kMaxHorizon = 10000;
// A gamma step of 1e-4: ten grid points to a pixel of the 1000-pixel-wide figure already.
constexpr int kMaxGammaSteps = 10001;
// A grid of this many terms (a few seconds) or more reports its progress every tenth.
constexpr long long kProgressTerms = 100'000'000;

// An integer option in [minimum, maximum]; a value past the maximum is refused saying why.
int boundedInteger(const CommandLine& line, const QString& name, int minimum, int maximum,
                   const QString& why) {
    const long long value = line.integer(name, std::numeric_limits<long long>::min(),
                                         std::numeric_limits<long long>::max());
    if (value < minimum || value > maximum) {
        throw UsageError(QStringLiteral("--%1 must lie in [%2, %3], got %4%5")
                             .arg(name)
                             .arg(minimum)
                             .arg(maximum)
                             .arg(value)
                             .arg(value > maximum ? QStringLiteral(": ") + why : QString()));
    }
    return static_cast<int>(value);
}

}  // namespace

int lemma41Command(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("lemma41"),
        QStringLiteral("The grid of Lemma 4.1 (Fig. 2): Var(D) of the inverse depreciation "
                       "D_i = H/(gamma^i + 1) over tau' = 2H steps, and where it is below 1."));
    line.addValue("max-h", "Largest horizon H, 1..10000.", "N", "50");
    line.addValue("gamma-steps",
                  "Grid points of gamma in [0, 1], 2..10001, and at most 1.5e9 / (H (H + 1)) "
                  "for the largest H (the grid's cost).",
                  "N", "101");
    line.addValue("out", "CSV: H, gamma, variance, satisfied.", "file");
    line.addValue("plot", "Also draw the grid (Fig. 2) to this .png or .svg file.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out", "plot"});
    const QString out = line.required("out");
    const int maxH = boundedInteger(
        line, "max-h", 1, kMaxHorizon,
        QStringLiteral("the grid's time grows with the square of the largest horizon"));
    const int steps = boundedInteger(
        line, "gamma-steps", 2, kMaxGammaSteps,
        QStringLiteral("a gamma step of 1e-4 is ten grid points to a pixel of the figure"));
    if (core::lemma41Terms(maxH, steps) > kMaxTerms) {
        const long long most = kMaxTerms / (static_cast<long long>(maxH) * (maxH + 1));
        throw UsageError(
            QStringLiteral("--gamma-steps must lie in [2, %1] with --max-h %2, got %3: the grid "
                           "evaluates gamma-steps x max-h x (max-h + 1) terms of D, at most %4 "
                           "(under a minute); lower --gamma-steps or --max-h")
                .arg(most)
                .arg(maxH)
                .arg(steps)
                .arg(kMaxTerms));
    }
    int tenthsShown = 0;
    const std::vector<core::Lemma41Cell> grid =
        core::lemma41Grid(maxH, steps, [&](long long done, long long total) {
            const int tenths = static_cast<int>(10 * done / total);
            if (total >= kProgressTerms && tenths > tenthsShown) {
                tenthsShown = tenths;
                printProgress(QStringLiteral("lemma41: %1% of the grid").arg(10 * tenths));
            }
        });
    if (tenthsShown > 0) {
        printProgress(QString());
    }
    QByteArray csv("H,gamma,variance,satisfied\n");
    for (const core::Lemma41Cell& cell : grid) {
        csv += QStringLiteral("%1,%2,%3,%4\n")
                   .arg(cell.horizon)
                   .arg(cell.gamma, 0, 'g', 10)
                   .arg(cell.variance, 0, 'g', 10)
                   .arg(cell.satisfied ? 1 : 0)
                   .toUtf8();
    }
    core::FileError error;
    if (!core::writeFileAtomically(out, csv, &error)) {
        throw UsageError(error.toString());
    }
    // Per H, the smallest gamma from which the inequality holds all the way to 1.
    QJsonArray thresholds;
    QString text;
    for (int H = 1; H <= maxH; ++H) {
        double from = 1.0;
        for (int g = steps - 1; g >= 0; --g) {
            const core::Lemma41Cell& cell = grid[(H - 1) * steps + g];
            if (!cell.satisfied) {
                break;
            }
            from = cell.gamma;
        }
        thresholds.append(QJsonObject{{"H", H}, {"satisfiedFromGamma", from}});
        if (H == 1 || H % 5 == 0) {
            text += QStringLiteral("H = %1: Var(D) < 1 for gamma >= %2\n")
                        .arg(H, 2)
                        .arg(from, 0, 'f', 2);
        }
    }
    if (line.isSet("plot")) {
        saveFigureOrThrow(lemma41Figure(grid, maxH, steps), line.value("plot"));
    }
    const int satisfied = core::lemma41SatisfiedCount(grid);
    if (line.format() == QLatin1String("json")) {
        printJson({{"cells", static_cast<int>(grid.size())},
                   {"satisfied", satisfied},
                   {"thresholds", thresholds},
                   {"out", out}});
    } else {
        printText(text + QStringLiteral("%1 of %2 cells satisfy Var(D) < 1; wrote %3\n")
                             .arg(satisfied)
                             .arg(grid.size())
                             .arg(out));
    }
    return 0;
}

}  // namespace prisca::app::cli
