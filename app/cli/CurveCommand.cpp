// prisca-cli curve: learning curves at an equal budget of simulated experience (paper Fig. 3b),
// on one demonstration or on every (style, seed set) cell.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Statistics.h"
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/experiments/LearningCurveExperiment.h"
#include "sim/experiments/Table1Protocol.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prisca::app::cli {

using namespace figures;

namespace {

// Where the runs ended: the mean over runs of each run's last trial (NaN if none ran), whatever
// the lengths of the cells' demonstrations.
double finalMean(const sim::MethodCurves& method) {
    std::vector<double> last;
    for (const auto& run : method.runs) {
        if (!run.empty()) {
            last.push_back(run.back().trackingError);
        }
    }
    return core::mean(last);
}

}  // namespace

int curveCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("curve"),
        QStringLiteral("Learning curves: tracking error against simulated experience, mean and "
                       "95% band over runs (learners learn trial after trial; fixed controllers "
                       "and the oracle give flat lines to read them against)."));
    line.addValue("plant", "Plant (default acrobot).", "name", "acrobot");
    line.addValue("demo", "Demonstration CSV (default: the scripted one, see --demo-seed).",
                  "file");
    line.addValue("demo-seed", "Seed of the scripted demonstration.", "N", "1");
    line.addValue("styles",
                  "Run on these demonstration styles (comma-separated, or 'all') x seed sets; "
                  "the bands pool the runs of every cell, and the final errors are broken down "
                  "per style.",
                  "list");
    line.addValue("seed-sets", "With --styles: how many seed sets, --seed, --seed + 1, ...", "N",
                  "1");
    line.addValue("methods", "Comma-separated methods.", "list", "prisca,pgsd,pegasus");
    line.addValue("runs", "Independent runs per method (and cell).", "N", "20");
    line.addValue("budget", "Simulated control steps each run may consume.", "steps", "64000");
    addRunSettingsOptions(line, QString());  // the curves train nothing before they start
    addPlantParametersOption(line);
    line.addValue("out", "CSV of the curves: method, steps, time, mean, lower, upper, runs.",
                  "file");
    line.addValue("plot", "Also draw the curves (Fig. 3b) to this .png or .svg file.", "file");
    addMethodParameterOptions(line);
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out", "plot"});
    const QString out = line.required("out");
    sim::LearningCurveSettings settings;
    settings.methods = line.value("methods").split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString& method : settings.methods) {
        if (!sim::isCurveMethod(method)) {
            throw UsageError(QStringLiteral("--methods: '%1' has no learning curve (one of: %2)")
                                 .arg(method, sim::curveMethods().join(QLatin1Char(' '))));
        }
    }
    if (settings.methods.isEmpty()) {
        throw UsageError(QStringLiteral("--methods: no method given"));
    }
    settings.runs = static_cast<int>(line.integer("runs", 1, 100000));
    settings.budgetSteps = line.integer("budget", 1, 1LL << 40);
    readRunSettings(line, settings.run, false);
    const std::uint64_t seed = settings.run.seed;
    installInterruptHandler();
    settings.cancelled = [] { return interrupted(); };

    // Every cell's runs, pooled per method; and per style for the breakdown.
    QStringList styles;
    sim::LearningCurveProtocolResult result;
    QString plant;
    if (line.isSet("styles")) {
        if (line.isSet("demo") || line.isSet("demo-seed")) {
            throw UsageError(
                QStringLiteral("--styles records its own demonstrations; it does not "
                               "take --demo or --demo-seed"));
        }
        plant = checkedPlant(line.value("plant"));
        styles = stylesOption(line, plant);
        sim::LearningCurveProtocolSettings protocol;
        protocol.curves = settings;
        protocol.styles = styles;
        protocol.seedSets =
            sim::consecutiveSeedSets(seed, static_cast<int>(line.integer("seed-sets", 1, 10000)));
        protocol.plantParameters = plantParametersOption(line, plant);
        sim::MethodTuning profile = sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant));
        applyMethodParameters(line, profile, protocol.plantParameters != nullptr);
        int cellNow = 0, cellsAll = 0;
        QString cellStyle;
        std::uint64_t cellSeed = 0;
        protocol.curves.progress = [&](const QString& text) {
            printProgress(QStringLiteral("cell %1/%2 (%3, seed set %4): %5")
                              .arg(cellNow)
                              .arg(cellsAll)
                              .arg(cellStyle)
                              .arg(cellSeed)
                              .arg(text));
        };
        result = sim::runLearningCurveProtocol(
            protocol, profile,
            [&](int cell, int cells, const QString& style, std::uint64_t cellSeedSet) {
                cellNow = cell;
                cellsAll = cells;
                cellStyle = style;
                cellSeed = cellSeedSet;
            });
    } else {
        if (line.isSet("seed-sets")) {
            throw UsageError(QStringLiteral("--seed-sets goes with --styles"));
        }
        const QString plantName = checkedPlant(line.value("plant"));
        // Recorded on the plant's car, as the window records its own (the protocol, --styles,
        // records each cell on its day's car).
        Task task = taskFromOptions(line, plantName);
        applyMethodParameters(line, task.profile, task.plantParameters != nullptr);
        plant = task.plant;
        settings.progress = [](const QString& text) { printProgress(text); };
        result.pooled = sim::runLearningCurves(settings, task);
        result.shortestDemonstration = task.demonstration->length();
        result.dt = task.demonstration->dt;
        result.cells = 1;
    }
    printProgress(QString());
    const std::vector<sim::MethodCurves>& pooled = result.pooled;
    const std::vector<std::vector<sim::MethodCurves>>& perStyle = result.perStyle;
    const long long unit = result.shortestDemonstration;
    const double dt = result.dt;

    // A common grid: one point per (shortest) demonstration length of experience.
    const std::vector<sim::CurveSummary> summaries =
        sim::summarizeCurves(pooled, unit, settings.budgetSteps, dt);
    QByteArray csv("method,steps,time_s,mean,lower,upper,runs\n");
    QJsonArray summary;
    QString text;
    std::vector<QString> plotted;
    std::vector<std::vector<double>> plottedSeconds;
    std::vector<core::ConfidenceBand> plottedBands;
    for (size_t i = 0; i < summaries.size(); ++i) {
        const sim::MethodCurves& method = pooled[i];
        const std::vector<long long>& grid = summaries[i].steps;
        const core::ConfidenceBand& band = summaries[i].band;
        plotted.push_back(method.method);
        plottedBands.push_back(band);
        plottedSeconds.push_back(summaries[i].seconds);
        for (size_t g = 0; g < grid.size(); ++g) {
            if (band.count[g] == 0) {
                continue;
            }
            csv += QStringLiteral("%1,%2,%3,%4,%5,%6,%7\n")
                       .arg(method.method)
                       .arg(grid[g])
                       .arg(grid[g] * dt)
                       .arg(band.mean[g], 0, 'g', 10)
                       .arg(band.lower[g], 0, 'g', 10)
                       .arg(band.upper[g], 0, 'g', 10)
                       .arg(band.count[g])
                       .toUtf8();
        }
        const double final = finalMean(method);
        QJsonObject entry{{"method", method.method},
                          {"finalMean", std::isfinite(final) ? QJsonValue(final) : QJsonValue()},
                          {"runs", static_cast<int>(method.runs.size())}};
        text += QStringLiteral(
                    "%1: tracking error of the last trial within %2 steps: %3 (mean "
                    "of %4 runs)\n")
                    .arg(method.method, -8)
                    .arg(settings.budgetSteps)
                    .arg(final, 0, 'g', 4)
                    .arg(method.runs.size());
        if (!styles.isEmpty()) {
            QJsonArray byStyle;
            for (int s = 0; s < styles.size(); ++s) {
                if (perStyle[s].empty()) {
                    continue;
                }
                const double styleFinal = finalMean(perStyle[s][i]);
                byStyle.append(
                    QJsonObject{{"style", styles[s]},
                                {"finalMean", std::isfinite(styleFinal) ? QJsonValue(styleFinal)
                                                                        : QJsonValue()}});
                text +=
                    QStringLiteral("    %1: %2\n").arg(styles[s], -22).arg(styleFinal, 0, 'g', 4);
            }
            entry.insert(QStringLiteral("styles"), byStyle);
        }
        summary.append(entry);
    }
    // Interrupted: what finished goes to NAME.partial, and a complete previous file stays.
    const bool complete = !interrupted();
    const QString written = writeOutput(out, csv, complete);
    if (line.isSet("plot")) {
        const QString yLabel = sim::PlantCatalog::describe(plant).pose
                                   ? QStringLiteral("mean squared position error [m\u00b2]")
                                   : QStringLiteral("mean squared joint-angle error [rad\u00b2]");
        saveFigureOutput(learningCurveFigure(plotted, plottedSeconds, plottedBands, yLabel),
                         line.value("plot"), complete);
    }
    if (line.format() == QLatin1String("json")) {
        printJson({{"plant", plant},
                   {"budgetSteps", static_cast<double>(settings.budgetSteps)},
                   {"cells", result.cells},
                   {"methods", summary},
                   {"out", written}});
    } else {
        printText(text + QStringLiteral("wrote %1\n").arg(written));
    }
    if (!complete) {
        std::fprintf(stderr,
                     "prisca-cli: curve: stopped by %s; kept the runs that finished in %s (the "
                     "previous --out file is left as it was)\n",
                     interruptionName().toLatin1().constData(), qPrintable(written));
        return interruptedExitCode();
    }
    return 0;
}

}  // namespace prisca::app::cli
