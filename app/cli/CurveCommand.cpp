// prisca-cli curve: learning curves at an equal budget of simulated experience (paper Fig. 3b).
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/FileIo.h"
#include "core/Statistics.h"
#include "sim/LearningCurveExperiment.h"

#include <QJsonArray>

#include <cmath>

namespace prisca::app::cli {

using namespace figures;

int curveCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("curve"),
        QStringLiteral("Learning curves: tracking error against simulated experience for "
                       "PRISCA, PGSD and PEGASUS, mean and 95% band over runs."));
    line.addValue("plant", "Plant (default acrobot).", "name", "acrobot");
    line.addValue("demo", "Demonstration CSV (default: the scripted one, see --demo-seed).",
                  "file");
    line.addValue("demo-seed", "Seed of the scripted demonstration.", "N", "1");
    line.addValue("methods", "Comma-separated learners.", "list", "prisca,pgsd,pegasus");
    line.addValue("runs", "Independent runs per method.", "N", "20");
    line.addValue("budget", "Simulated control steps each run may consume.", "steps", "64000");
    line.addValue("seed", "Seed of the runs.", "N", "1");
    line.addValue("jobs", "Worker threads.", "N", "2");
    line.addValue("perturbation", "Plant perturbation level.", "level", "1");
    line.addValue("sensor", "Sensor noise level.", "level", "1");
    line.addValue("out", "CSV of the curves: method, steps, time, mean, lower, upper, runs.",
                  "file");
    line.addValue("plot", "Also draw the curves (Fig. 3b) to this .png or .svg file.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString out = line.required("out");
    Task task =
        loadOrDemonstrate(line.value("plant"), line.value("demo"),
                          static_cast<std::uint64_t>(line.integer("demo-seed", 0, 1LL << 62)));
    sim::LearningCurveSettings settings;
    settings.plant = task.plant;
    settings.methods = line.value("methods").split(QLatin1Char(','), Qt::SkipEmptyParts);
    for (const QString& method : settings.methods) {
        if (method != QLatin1String("prisca") && method != QLatin1String("pgsd") &&
            method != QLatin1String("pegasus")) {
            throw UsageError(
                QStringLiteral("--methods: '%1' is not a learner (prisca, pgsd, pegasus)")
                    .arg(method));
        }
    }
    settings.runs = static_cast<int>(line.integer("runs", 1, 100000));
    settings.budgetSteps = line.integer("budget", 1, 1LL << 40);
    settings.seed = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    settings.threads = static_cast<int>(line.integer("jobs", 1, 256));
    settings.perturbation = line.number("perturbation", 0.0, 10.0);
    settings.sensor = line.number("sensor", 0.0, 10.0);
    installInterruptHandler();
    settings.cancelled = [] { return interrupted(); };
    settings.progress = [](const QString& text) { printProgress(text); };
    const auto curves =
        sim::runLearningCurves(settings, task.demonstration, task.profile, task.fit.b);
    printProgress(QString());

    // A common grid: one point per demonstration length of experience.
    const double dt = task.demonstration->dt;
    const std::vector<sim::CurveSummary> summaries =
        sim::summarizeCurves(curves, task.demonstration->length(), settings.budgetSteps, dt);
    QByteArray csv("method,steps,time_s,mean,lower,upper,runs\n");
    QJsonArray summary;
    QString text;
    std::vector<QString> plotted;
    std::vector<std::vector<double>> plottedSeconds;
    std::vector<core::ConfidenceBand> plottedBands;
    for (size_t i = 0; i < summaries.size(); ++i) {
        const sim::MethodCurves& method = curves[i];
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
        // The last grid point every run reached.
        double final = std::numeric_limits<double>::quiet_NaN();
        for (size_t g = grid.size(); g-- > 0;) {
            if (band.count[g] > 0) {
                final = band.mean[g];
                break;
            }
        }
        summary.append(
            QJsonObject{{"method", method.method},
                        {"finalMean", std::isfinite(final) ? QJsonValue(final) : QJsonValue()},
                        {"runs", static_cast<int>(method.runs.size())}});
        text += QStringLiteral("%1: tracking error after %2 steps: %3 (mean of %4 runs)\n")
                    .arg(method.method, -8)
                    .arg(settings.budgetSteps)
                    .arg(final, 0, 'g', 4)
                    .arg(method.runs.size());
    }
    core::FileError error;
    if (!core::writeFileAtomically(out, csv, &error)) {
        throw UsageError(error.toString());
    }
    if (line.isSet("plot")) {
        const QString yLabel = task.profile.info.pose
                                   ? QStringLiteral("mean squared position error [m\u00b2]")
                                   : QStringLiteral("mean squared joint-angle error [rad\u00b2]");
        saveFigureOrThrow(learningCurveFigure(plotted, plottedSeconds, plottedBands, yLabel),
                          line.value("plot"));
    }
    if (line.format() == QLatin1String("json")) {
        printJson({{"plant", task.plant},
                   {"budgetSteps", static_cast<double>(settings.budgetSteps)},
                   {"methods", summary},
                   {"out", out}});
    } else {
        printText(text + QStringLiteral("wrote %1\n").arg(out));
    }
    return interrupted() ? kExitInterrupted : 0;
}

}  // namespace prisca::app::cli
