// prisca-cli table1: the paper's Table I (slide parking) in simulation.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/ProtocolReport.h"
#include "core/Table1Report.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/experiments/Table1Protocol.h"
#include "sim/plants/SlideCar.h"

#include <QDir>

#include <algorithm>
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

// --variants DIR: every plant file (*.json) in the folder, by name; UsageError if there is none
// or one is not a plant file of the plant.
std::vector<std::shared_ptr<const sim::PlantParameters>> variantsOption(const QString& folder,
                                                                        const QString& plant) {
    const QDir dir(folder);
    if (!dir.exists()) {
        throw UsageError(QStringLiteral("--variants: %1 is not a folder").arg(folder));
    }
    const QStringList files =
        dir.entryList({QStringLiteral("*.json")}, QDir::Files | QDir::Readable, QDir::Name);
    if (files.isEmpty()) {
        throw UsageError(QStringLiteral("--variants: no plant file (*.json) in %1").arg(folder));
    }
    std::vector<std::shared_ptr<const sim::PlantParameters>> variants;
    for (const QString& file : files) {
        QString error;
        auto parameters = sim::readPlantParameters(dir.filePath(file), plant, &error);
        if (!parameters) {
            throw UsageError(QStringLiteral("--variants: %1").arg(error));
        }
        variants.push_back(std::make_shared<const sim::PlantParameters>(std::move(*parameters)));
    }
    return variants;
}

// The trials by their place in the day, per method: mean and 95% interval over the cells.
QByteArray learningCurveCsv(const std::vector<sim::TrialCurve>& curves) {
    QByteArray csv(
        "method,trial,phase,cells,position_cm,position_lower,position_upper,orientation_deg,"
        "orientation_lower,orientation_upper\n");
    for (const sim::TrialCurve& curve : curves) {
        for (size_t i = 0; i < curve.position.size(); ++i) {
            const core::MeanInterval p = core::meanInterval(curve.position[i]);
            const core::MeanInterval o = core::meanInterval(curve.orientation[i]);
            csv +=
                QStringLiteral("%1,%2,%3,%4,%5,%6,%7,%8,%9,%10\n")
                    .arg(curve.method)
                    .arg(i + 1)
                    .arg(static_cast<int>(i) < curve.trainingTrials ? QStringLiteral("training")
                                                                    : QStringLiteral("evaluation"))
                    .arg(p.count)
                    .arg(p.mean, 0, 'g', 8)
                    .arg(p.lower, 0, 'g', 8)
                    .arg(p.upper, 0, 'g', 8)
                    .arg(o.mean, 0, 'g', 8)
                    .arg(o.lower, 0, 'g', 8)
                    .arg(o.upper, 0, 'g', 8)
                    .toUtf8();
        }
    }
    return csv;
}

// The trials by their place in the day as a figure: per method the mean position and
// orientation error over the cells with its 95% band, the training trials left of the dashed
// line and the evaluation trials right of it.
plot::Figure learningCurvePlot(const std::vector<sim::TrialCurve>& curves) {
    plot::Figure figure;
    figure.title = QStringLiteral(
        "Each trial of the day, mean over the cells (95% band): training trials, then evaluation");
    figure.columns = 2;
    int training = 0;
    for (const sim::TrialCurve& curve : curves) {
        training = std::max(training, curve.trainingTrials);
    }
    for (int panel = 0; panel < 2; ++panel) {
        plot::Axes axes;
        axes.title = panel == 0 ? QStringLiteral("Final position error")
                                : QStringLiteral("Final orientation error");
        axes.xLabel = QStringLiteral("trial of the day");
        axes.yLabel = panel == 0 ? QStringLiteral("error [cm]") : QStringLiteral("error [deg]");
        double top = 0.0;
        for (size_t m = 0; m < curves.size(); ++m) {
            const sim::TrialCurve& curve = curves[m];
            const auto& values = panel == 0 ? curve.position : curve.orientation;
            const QString label = sim::MethodCatalog::get(curve.method).label;
            plot::Line line;
            line.label = label;
            line.color = plot::paletteColor(static_cast<int>(m));
            line.markers = true;
            plot::Band band;
            band.label = label;
            // A method that does not learn has evaluation trials only: placed after the
            // training trials, where the learners' evaluation trials are.
            const int offset = training - curve.trainingTrials;
            for (size_t i = 0; i < values.size(); ++i) {
                const core::MeanInterval mi = core::meanInterval(values[i]);
                if (mi.count == 0) {
                    continue;
                }
                const double x = static_cast<double>(offset + static_cast<int>(i) + 1);
                line.points.emplace_back(x, mi.mean);
                band.x.push_back(x);
                band.lower.push_back(mi.lower);
                band.upper.push_back(mi.upper);
                top = std::max(top, mi.upper);
            }
            axes.bands.push_back(band);
            axes.lines.push_back(line);
        }
        if (training > 0) {
            plot::Line boundary;
            boundary.points = {QPointF(training + 0.5, 0.0), QPointF(training + 0.5, top)};
            boundary.color = Qt::darkGray;
            boundary.style = Qt::DashLine;
            axes.lines.push_back(boundary);
        }
        figure.panels.push_back(axes);
    }
    return figure;
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
    sim::MethodTuning profile = sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant));
    if (!profile.info.pose) {
        throw UsageError(
            QStringLiteral("Table I is for planar vehicles; '%1' has no pose").arg(plant));
    }
    sim::Table1ProtocolSettings settings;
    settings.plantParameters = plantParametersOption(line, plant);
    if (line.isSet("variants")) {
        if (settings.plantParameters) {
            throw UsageError(QStringLiteral("give --plant-params or --variants, not both"));
        }
        settings.variants = variantsOption(line.value("variants"), plant);
    }
    settings.styles = stylesOption(line, plant);
    settings.table.methods = checkedMethods(line, settings.table.methods);
    const int seedSets = static_cast<int>(line.integer("seed-sets", 1, 10000));
    const auto first = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    settings.seedSets = sim::consecutiveSeedSets(first, seedSets);
    settings.table.trials = static_cast<int>(line.integer("trials", 1, 100000));
    readRunSettings(line, settings.table.run);
    applyMethodParameters(line, profile,
                          settings.plantParameters != nullptr || !settings.variants.empty());
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
    caption += QStringLiteral(", %1 perturbation model")
                   .arg(sim::perturbationModelName(settings.table.run.perturbationModel));
    if (!settings.variants.empty()) {
        caption += QStringLiteral(", %1 plant variants from %2 (the breakdown is per variant)")
                       .arg(settings.variants.size())
                       .arg(line.value("variants"));
    } else if (settings.plantParameters) {
        caption += QStringLiteral(", plant file %1").arg(settings.plantParameters->source);
    }
    if (settings.table.run.poseFilter) {
        caption += settings.table.run.poseFilterPredicts ? QStringLiteral("; pose filter on")
                                                         : QStringLiteral("; pose filter lagged");
    }
    if (result.cancelled) {
        caption += QStringLiteral(" (interrupted: only the cells that finished)");
    }
    if (line.isSet("learning-out")) {
        writeOutput(line.value("learning-out"), learningCurveCsv(result.curves), !result.cancelled);
    }
    if (line.isSet("learning-plot")) {
        saveFigureOutput(learningCurvePlot(result.curves), line.value("learning-plot"),
                         !result.cancelled);
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
    line.addValue("variants",
                  "With --styles: the new-car protocol, every plant file (*.json) in this folder "
                  "in turn on every style and seed set; the breakdown is per variant.",
                  "folder");
    line.addValue("learning-out",
                  "With --styles: write each method's trials by their place in the day (training "
                  "trials first, then evaluation) as CSV: mean and 95% interval over the cells.",
                  "file");
    line.addValue("learning-plot",
                  "With --styles: draw the same (the trials by their place in the day, per "
                  "method) to this .png or .svg file.",
                  "file");
    line.addValue("trials", "Evaluation trials per method.", "N", "20");
    addRunSettingsOptions(line,
                          "Training trials: PD (selected) selects its gains on them, the learners "
                          "(PRISCA, PGSD, ILC) learn on them before evaluation.");
    line.addValue("methods",
                  "Comma-separated methods (default: the paper's rows, LQR, PGSD, ILC and the "
                  "oracle, the limit).",
                  "list");
    addPlantParametersOption(line);
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
    checkOutputs(line, {"out", "plot", "learning-out", "learning-plot"});
    if (line.isSet("styles")) {
        return table1ProtocolCommand(line);
    }
    for (const char* option : {"seed-sets", "variants", "learning-out", "learning-plot"}) {
        if (line.isSet(QLatin1String(option))) {
            throw UsageError(QStringLiteral("--%1 goes with --styles").arg(QLatin1String(option)));
        }
    }
    sim::Table1Settings settings;
    readRunSettings(line, settings.run);
    const QString plantName = checkedPlant(line.value("plant"));
    // The scripted demonstration (checked as a file would be) is recorded on the plant's car, as
    // the window records its own; the protocol (--styles) records each cell on its day's car.
    Task task = taskFromOptions(line, plantName);
    if (!task.profile.info.pose) {
        throw UsageError(
            QStringLiteral("Table I is for planar vehicles; '%1' has no pose").arg(task.plant));
    }
    settings.methods = checkedMethods(line, settings.methods);
    settings.trials = static_cast<int>(line.integer("trials", 1, 100000));
    applyMethodParameters(line, task.profile, task.plantParameters != nullptr);
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
