// prisca-cli table1: the paper's Table I (slide parking) in simulation.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Table1Report.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/SlideCar.h"
#include "sim/Table1Experiment.h"
#include "sim/Table1Protocol.h"


#include <cmath>
#include <cstdio>

namespace prisca::app::cli {

using namespace figures;

namespace {

QStringList checkedMethods(const CommandLine& line, const QStringList& defaults) {
    if (!line.isSet("methods")) {
        return defaults;
    }
    const QStringList methods = line.value("methods").split(QLatin1Char(','), Qt::SkipEmptyParts);
    if (methods.isEmpty()) {
        throw UsageError(QStringLiteral("--methods: no method given"));
    }
    for (const QString& method : methods) {
        const sim::MethodSpec* spec = sim::MethodCatalog::find(method);
        if (!spec || !spec->inTable1) {
            throw UsageError(QStringLiteral("--methods: '%1' is not a Table I method (one of: %2)")
                                 .arg(method, sim::MethodCatalog::table1Ids().join(' ')));
        }
    }
    return methods;
}

// The table to --out (atomically; an interrupted table to NAME.partial, so a complete previous
// table stays) or to standard output. Returns where it went ("" for stdout).
QString writeTable(const CommandLine& line, const QString& table, bool complete) {
    if (line.isSet("out")) {
        return writeOutput(line.value("out"), table.toUtf8(), complete);
    }
    printText(table);
    return QString();
}

// After an interruption: what was kept and where.
int reportInterrupted(const QString& kept, const QString& written) {
    std::fprintf(stderr, "prisca-cli: table1: stopped by %s; kept %s%s\n",
                 interruptionName().toLatin1().constData(), kept.toLocal8Bit().constData(),
                 written.isEmpty()
                     ? ""
                     : qPrintable(QStringLiteral(" in %1 (the previous --out file is left as "
                                                 "it was)")
                                      .arg(written)));
    return interruptedExitCode();
}

// table1 --styles: every method on every (style, seed set) cell.
int table1ProtocolCommand(const CommandLine& line) {
    if (line.isSet("demo") || line.isSet("demo-seed")) {
        throw UsageError(QStringLiteral(
            "--styles records its own demonstrations; it does not take --demo or --demo-seed"));
    }
    if (line.isSet("plot")) {
        throw UsageError(
            QStringLiteral("--plot draws one demonstration's trials; not with "
                           "--styles"));
    }
    const QString plant = checkedPlant(line.value("plant"));
    sim::MethodTuning profile = sim::MethodTuning::forPlant(sim::PlantCatalog::describe(plant));
    if (!profile.info.pose) {
        throw UsageError(
            QStringLiteral("Table I is for planar vehicles; '%1' has no pose").arg(plant));
    }
    sim::Table1ProtocolSettings settings;
    settings.styles = stylesOption(line, plant);
    settings.table.methods = checkedMethods(line, settings.table.methods);
    const int seedSets = static_cast<int>(line.integer("seed-sets", 1, 10000));
    const auto first = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    settings.seedSets = sim::consecutiveSeedSets(first, seedSets);
    settings.table.trials = static_cast<int>(line.integer("trials", 1, 100000));
    readRunSettings(line, settings.table.run);
    applyMethodParameters(line, profile);
    const auto format = core::parseTableFormat(line.format());
    installInterruptHandler();
    settings.table.cancelled = [] { return interrupted(); };
    settings.table.progress = [](const QString& text) { printProgress(text); };
    const sim::Table1ProtocolResult result = sim::runTable1Protocol(settings, profile);
    printProgress(QString());

    QString caption = QStringLiteral(
                          "Slide parking in simulation (%1) on %2 styles x %3 seed sets (%4..%5): "
                          "%6 trials per method and cell, %7 training trials, perturbation %8, "
                          "sensor %9; means and 95% intervals over the cells")
                          .arg(plant)
                          .arg(settings.styles.size())
                          .arg(seedSets)
                          .arg(first)
                          .arg(first + seedSets - 1)
                          .arg(settings.table.trials)
                          .arg(settings.table.run.trainingTrials)
                          .arg(settings.table.run.perturbation)
                          .arg(settings.table.run.sensor);
    if (settings.table.run.poseFilter) {
        caption += settings.table.run.poseFilterPredicts ? QStringLiteral("; pose filter on")
                                                         : QStringLiteral("; pose filter lagged");
    }
    if (result.cancelled) {
        caption += QStringLiteral(" (interrupted: only the cells that finished)");
    }
    const QString written =
        writeTable(line, core::formatProtocol(result.summary, *format, caption), !result.cancelled);
    if (result.cancelled) {
        return reportInterrupted(
            QStringLiteral("the cells that finished (%1 trials)").arg(result.finishedTrials),
            written);
    }
    return 0;
}

}  // namespace

int table1Command(const QStringList& arguments) {
    CommandLine line(QStringLiteral("table1"),
                     QStringLiteral("Slide parking, N trials per method: final position and "
                                    "orientation errors as in the paper's Table I."));
    line.addValue("plant", "Planar vehicle (default slidecar).", "name", "slidecar");
    line.addValue("demo", "Demonstration CSV (default: the scripted one, see --demo-seed).",
                  "file");
    line.addValue("demo-seed", "Seed of the scripted demonstration when --demo is not given.", "N",
                  "1");
    line.addValue("styles",
                  "Evaluate on these demonstration styles (comma-separated, or 'all'), each "
                  "recorded and run on every seed set; reports each method's mean and 95% "
                  "interval over the cells and a per-style breakdown.",
                  "list");
    line.addValue("seed-sets",
                  "With --styles: how many seed sets, --seed, --seed + 1, ... (each gives the "
                  "demonstration's hand variation and the trials' perturbations).",
                  "N", "1");
    line.addValue("trials", "Evaluation trials per method.", "N", "20");
    addRunSettingsOptions(line,
                          "Training trials: PD (selected) selects its gains on them, the learners "
                          "(PRISCA, PGSD, ILC) learn on them before evaluation.");
    line.addValue("methods",
                  "Comma-separated methods (default: the paper's rows, LQR, PGSD, ILC and the "
                  "oracle, the limit).",
                  "list");
    addMethodParameterOptions(line);
    line.addValue("out", "Write the table here instead of standard output.", "file");
    line.addValue("plot",
                  "Also draw Fig. 7 (paths and end postures of playback, PD and PRISCA) "
                  "to this .png or .svg file.",
                  "file");
    line.addFormat({"md", "csv", "latex", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    if (line.isSet("styles")) {
        return table1ProtocolCommand(line);
    }
    if (line.isSet("seed-sets")) {
        throw UsageError(QStringLiteral("--seed-sets goes with --styles"));
    }
    Task task =
        line.isSet("demo") ? loadTask(line.value("plant"), line.value("demo"), QString()) : Task{};
    if (!line.isSet("demo")) {
        const QString plant = line.value("plant");
        if (!sim::PlantCatalog::contains(plant)) {
            throw UsageError(QStringLiteral("unknown plant '%1' (one of: %2)")
                                 .arg(plant, sim::PlantCatalog::names().join(' ')));
        }
        // The scripted demonstration goes through the same checks as a file would.
        const auto seed = static_cast<std::uint64_t>(line.integer("demo-seed", 0, 1LL << 62));
        task = scriptedTaskFor(
            plant, sim::PlantCatalog::demonstrate(plant, seed),
            QStringLiteral("%1 scripted demonstration seed %2").arg(plant).arg(seed));
    }
    if (!task.profile.info.pose) {
        throw UsageError(
            QStringLiteral("Table I is for planar vehicles; '%1' has no pose").arg(task.plant));
    }
    sim::Table1Settings settings;
    settings.methods = checkedMethods(line, settings.methods);
    settings.trials = static_cast<int>(line.integer("trials", 1, 100000));
    readRunSettings(line, settings.run);
    applyMethodParameters(line, task.profile);
    const auto format = core::parseTableFormat(line.format());

    settings.keepPaths = line.isSet("plot");
    installInterruptHandler();
    settings.cancelled = [] { return interrupted(); };
    settings.progress = [](const QString& text) { printProgress(text); };
    const sim::Table1Result result = sim::runTable1(settings, task);
    printProgress(QString());

    int finished = 0;
    const std::vector<core::Table1Row> rows = sim::table1Rows(result, &finished);
    QString caption = QStringLiteral(
                          "Slide parking in simulation (%1): %2 trials per method, seed %3, "
                          "%4 training trials, perturbation %5, sensor %6")
                          .arg(task.plant)
                          .arg(settings.trials)
                          .arg(settings.run.seed)
                          .arg(settings.run.trainingTrials)
                          .arg(settings.run.perturbation)
                          .arg(settings.run.sensor);
    if (settings.run.poseFilter) {
        caption += settings.run.poseFilterPredicts ? QStringLiteral(", pose filter on")
                                                   : QStringLiteral(", pose filter lagged");
    }
    if (result.cancelled) {
        caption += QStringLiteral(" (interrupted: %1 of %2 trials finished)")
                       .arg(finished)
                       .arg(settings.trials * static_cast<int>(settings.methods.size()));
    }
    const QString written =
        writeTable(line, core::formatTable1(rows, *format, caption), !result.cancelled);
    if (line.isSet("plot")) {
        const sim::SlideCarParameters car;  // the car's own outline
        saveFigureOutput(parkingFigure(result, car.length, car.width), line.value("plot"),
                         !result.cancelled);
    }
    if (result.cancelled) {
        return reportInterrupted(QStringLiteral("the %1 trials that finished").arg(finished),
                                 written);
    }
    return 0;
}

}  // namespace prisca::app::cli
