// prisca-cli table1: the paper's Table I (slide parking) in simulation.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Table1Report.h"
#include "sim/ControllerFactory.h"
#include "sim/PlantCatalog.h"
#include "sim/Table1Experiment.h"

#include <QDir>

#include <cmath>

namespace prisca::app::cli {

using namespace figures;

int table1Command(const QStringList& arguments) {
    CommandLine line(QStringLiteral("table1"),
                     QStringLiteral("Slide parking, N trials per method: final position and "
                                    "orientation errors as in the paper's Table I."));
    line.addValue("plant", "Planar vehicle (default slidecar).", "name", "slidecar");
    line.addValue("demo", "Demonstration CSV (default: the scripted one, see --demo-seed).",
                  "file");
    line.addValue("demo-seed", "Seed of the scripted demonstration when --demo is not given.", "N",
                  "1");
    line.addValue("trials", "Evaluation trials per method.", "N", "20");
    line.addValue("training-trials", "Training trials for PD (selected), PRISCA and PGSD.", "N",
                  "16");
    line.addValue("seed", "Seed of the evaluation trials.", "N", "1");
    line.addValue("jobs", "Worker threads.", "N", "2");
    line.addValue("perturbation", "Plant perturbation level (0 nominal, 1 realistic).", "level",
                  "1");
    line.addValue("sensor", "Sensor noise level (0 perfect, 1 realistic).", "level", "1");
    line.addValue("methods", "Comma-separated methods (default: the paper's rows and PGSD).",
                  "list");
    line.addValue("H", "PRISCA horizon H [steps].", "steps");
    line.addValue("gamma", "PRISCA gamma in [0, 1].", "gamma");
    line.addValue("beta", "PRISCA beta > 0.", "beta");
    line.addValue("out", "Write the table here instead of standard output.", "file");
    line.addValue("plot",
                  "Also draw Fig. 7 (paths and end postures of playback, PD and PRISCA) "
                  "to this .png or .svg file.",
                  "file");
    line.addFormat({"md", "csv", "latex", "json"});
    if (!line.parse(arguments)) {
        return 0;
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
        const QString scratch = QDir::temp().filePath(
            QStringLiteral("prisca-table1-demo-%1.csv").arg(QCoreApplication::applicationPid()));
        writeDemonstration(
            sim::PlantCatalog::demonstrate(
                plant, static_cast<std::uint64_t>(line.integer("demo-seed", 0, 1LL << 62))),
            scratch);
        task = loadTask(plant, scratch, QString());
        QFile::remove(scratch);
    }
    if (!task.profile.info.pose) {
        throw UsageError(
            QStringLiteral("Table I is for planar vehicles; '%1' has no pose").arg(task.plant));
    }
    sim::Table1Settings settings;
    settings.plant = task.plant;
    if (line.isSet("methods")) {
        settings.methods = line.value("methods").split(QLatin1Char(','), Qt::SkipEmptyParts);
        for (const QString& method : settings.methods) {
            if (!sim::ControllerFactory::isMethod(method) || method == QLatin1String("pegasus")) {
                throw UsageError(
                    QStringLiteral("--methods: '%1' is not a Table I method").arg(method));
            }
        }
    }
    settings.trials = static_cast<int>(line.integer("trials", 1, 100000));
    settings.trainingTrials = static_cast<int>(line.integer("training-trials", 0, 100000));
    settings.seed = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    settings.threads = static_cast<int>(line.integer("jobs", 1, 256));
    settings.perturbation = line.number("perturbation", 0.0, 10.0);
    settings.sensor = line.number("sensor", 0.0, 10.0);
    if (line.isSet("H")) {
        task.profile.prisca.horizon = static_cast<int>(line.integer("H", 1, 1000));
    }
    if (line.isSet("gamma")) {
        task.profile.prisca.gamma = line.number("gamma", 0.0, 1.0);
    }
    if (line.isSet("beta")) {
        task.profile.prisca.stepSize.beta = line.number("beta", 1e-9, 1e12);
    }
    const auto format = core::parseTableFormat(line.format());

    settings.keepPaths = line.isSet("plot");
    installInterruptHandler();
    settings.cancelled = [] { return interrupted(); };
    settings.progress = [](const QString& text) { printProgress(text); };
    const sim::Table1Result result =
        sim::runTable1(settings, task.demonstration, task.profile, task.fit.b);
    printProgress(QString());

    int finished = 0;
    const std::vector<core::Table1Row> rows = sim::table1Rows(result, &finished);
    QString caption = QStringLiteral(
                          "Slide parking in simulation (%1): %2 trials per method, seed %3, "
                          "%4 training trials, perturbation %5, sensor %6")
                          .arg(task.plant)
                          .arg(settings.trials)
                          .arg(settings.seed)
                          .arg(settings.trainingTrials)
                          .arg(settings.perturbation)
                          .arg(settings.sensor);
    if (result.cancelled) {
        caption += QStringLiteral(" (interrupted: %1 of %2 trials finished)")
                       .arg(finished)
                       .arg(settings.trials * static_cast<int>(settings.methods.size()));
    }
    const QString table = core::formatTable1(rows, *format, caption);
    if (line.isSet("out")) {
        core::FileError error;
        if (!core::writeFileAtomically(line.value("out"), table.toUtf8(), &error)) {
            throw UsageError(error.toString());
        }
    } else {
        printText(table);
    }
    if (line.isSet("plot")) {
        saveFigureOrThrow(parkingFigure(result, 0.40, 0.20), line.value("plot"));
    }
    if (result.cancelled) {
        std::fprintf(stderr, "prisca-cli: table1: interrupted; kept the %d trials that finished\n",
                     finished);
        return kExitInterrupted;
    }
    return 0;
}

}  // namespace prisca::app::cli
