// prisca-cli lemma41: the H-gamma grid of Lemma 4.1 / Fig. 2 (where Var(D) < 1).
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Lemma41.h"

#include <QJsonArray>

namespace prisca::app::cli {

using namespace figures;

int lemma41Command(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("lemma41"),
        QStringLiteral("The grid of Lemma 4.1 (Fig. 2): Var(D) of the inverse depreciation "
                       "D_i = H/(gamma^i + 1) over tau' = 2H steps, and where it is below 1."));
    line.addValue("max-h", "Largest horizon H.", "N", "50");
    line.addValue("gamma-steps", "Grid points of gamma in [0, 1].", "N", "101");
    line.addValue("out", "CSV: H, gamma, variance, satisfied.", "file");
    line.addValue("plot", "Also draw the grid (Fig. 2) to this .png or .svg file.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString out = line.required("out");
    const int maxH = static_cast<int>(line.integer("max-h", 1, 10000));
    const int steps = static_cast<int>(line.integer("gamma-steps", 2, 100000));
    const std::vector<core::Lemma41Cell> grid = core::lemma41Grid(maxH, steps);
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
