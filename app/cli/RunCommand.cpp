// prisca-cli run: PRISCA or a baseline on a simulated plant, trial after trial, with a run log.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "app/figures/PaperFigures.h"
#include "core/RunLogCsv.h"
#include "rig/TrialBundle.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/RunLogBuilder.h"
#include "sim/run/RunSetup.h"

#include <QDir>
#include <QJsonArray>

#include <cmath>
#include <optional>

namespace prisca::app::cli {

using namespace figures;

namespace {

// The training trials of PEGASUS and PD (selected) never share a seed with evaluation trials.

QJsonValue finiteOrNull(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

// A trial of at least this many control steps reports its progress every tenth of them (at
// ~40 us a step on the slide-car, a second or more).
constexpr int kLongTrialSteps = 20000;

// One trial, stepped here rather than by runEpisode (the same trial bit for bit: runEpisode is
// this stepper run to its end) so that a long one can say how far it is. Sets `reported` when it
// printed a progress line.
sim::EpisodeResult runTrial(sim::Plant& plant, core::Controller& controller,
                            const sim::EpisodeSettings& episode, const QString& label,
                            bool& reported) {
    sim::EpisodeStepper stepper(plant, controller, episode);
    const int tenth = stepper.maxSteps() >= kLongTrialSteps ? stepper.maxSteps() / 10 : 0;
    while (!stepper.finished()) {
        stepper.step();
        if (tenth > 0 && stepper.stepCount() % tenth == 0 && !stepper.finished() &&
            !stepper.runningOut()) {
            printProgress(
                QStringLiteral("%1, %2%").arg(label).arg(10 * (stepper.stepCount() / tenth)));
            reported = true;
        }
    }
    return stepper.takeResult();
}

}  // namespace

int runCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("run"),
                     QStringLiteral("Run PRISCA or a baseline on a simulated plant for one or more "
                                    "trials (learning carries over between trials) and log every "
                                    "control step."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addValue("demo", "Demonstration CSV to repeat.", "file");
    line.addValue("method", "Method: " + sim::MethodCatalog::ids().join(", ") + ".", "name");
    line.addValue("trials", "Trials in a row (warm start: PRISCA and PGSD keep learning).", "N",
                  "1");
    addRunSettingsOptions(line, "Training trials for PEGASUS and PD (selected).");
    line.addValue("mask", "Intuitive mapping B~ (default: the plant's), as for 'fit'.", "signs");
    addPlantParametersOption(line);
    addMethodParameterOptions(line);
    line.addValue("out", "Run log CSV.", "file");
    line.addValue("bundle-dir",
                  "Also save every trial as a bundle (prisca-cli replay reads it) in a new "
                  "folder under this one.",
                  "dir");
    line.addValue("compare", "Also run this method on the same trials and report it beside.",
                  "name");
    line.addValue("plot",
                  "Draw desired and actual paths (of both methods with --compare) to this "
                  ".png or .svg file (planar vehicles).",
                  "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out", "plot"});
    const QString plantName = line.required("plant");
    const QString method = line.required("method");
    if (!sim::MethodCatalog::contains(method)) {
        throw UsageError(QStringLiteral("unknown method '%1' (one of: %2)")
                             .arg(method, sim::MethodCatalog::ids().join(' ')));
    }
    const QString out = line.required("out");
    const auto parameters = plantParametersOption(line, checkedPlant(plantName));
    Task task = loadTask(plantName, line.required("demo"), line.value("mask"));
    task.plantParameters = parameters;
    sim::MethodTuning& profile = task.profile;
    applyMethodParameters(line, profile, parameters != nullptr);
    const int trials = static_cast<int>(line.integer("trials", 1, 100000));
    sim::RunSettings settings;
    readRunSettings(line, settings);
    const QString compareMethod = line.value("compare");
    if (!compareMethod.isEmpty() && !sim::MethodCatalog::contains(compareMethod)) {
        throw UsageError(QStringLiteral("--compare: unknown method '%1' (one of: %2)")
                             .arg(compareMethod, sim::MethodCatalog::ids().join(' ')));
    }

    // Offline-tuned methods train first, on their own seeds.
    const auto build = [&](const sim::RunSetup& setup) {
        auto controller =
            setup.makeController({}, [](const QString& text) { printProgress(text); });
        if (setup.method().trainsOffline()) {
            printProgress(QString());
        }
        return controller;
    };
    const sim::RunSetup setup(task, method, settings);
    const core::Demonstration& demo = *setup.task().demonstration;
    auto plant = setup.makePlant();
    auto controller = build(setup);
    std::optional<sim::RunSetup> compareSetup;
    std::unique_ptr<core::Controller> comparison;
    if (!compareMethod.isEmpty()) {
        compareSetup.emplace(task, compareMethod, settings);
        comparison = build(*compareSetup);
    }
    const sim::PlantInfo& info = plant->info();
    const std::uint64_t seed = settings.seed;

    core::RunLog log = setup.startRunLog(*controller, trials, line.value("demo"));

    QJsonArray trialsJson;
    QJsonArray compareJson;
    QString text;
    std::vector<std::vector<QPointF>> paths, comparePaths;
    std::vector<double> rms, compareRms, pathRms, comparePathRms;
    const auto pathOf = [&](const sim::EpisodeResult& result) {
        std::vector<QPointF> path;
        if (info.pose) {
            for (const sim::StepRecord& step : result.steps) {
                path.emplace_back(step.state[info.pose->x], step.state[info.pose->y]);
            }
        }
        return path;
    };
    bool reported = false;  // a progress line is open on stderr
    QString bundleFailure;  // the first bundle that could not be written (no more are tried)
    for (int trial = 0; trial < trials; ++trial) {
        const sim::EpisodeSettings episode = setup.trial(trial);
        const QString trialLabel = QStringLiteral("run: trial %1/%2").arg(trial + 1).arg(trials);
        if (comparison) {
            // The same trial (seed, perturbation, sensor noise) for the other method.
            const sim::EpisodeResult other =
                runTrial(*plant, *comparison, episode,
                         trialLabel + QStringLiteral(" (%1)").arg(compareMethod), reported);
            const sim::TrialSummary otherSummary = sim::summarizeTrial(info, demo, other);
            compareRms.push_back(otherSummary.trackingRms);
            comparePathRms.push_back(otherSummary.pathRms);
            comparePaths.push_back(pathOf(other));
            QJsonObject otherJson{{"trial", trial}, {"trackingRms", otherSummary.trackingRms}};
            if (info.pose) {  // a plant with no pose has no position to speak of: no null
                otherJson.insert("finalPositionErrorCm",
                                 finiteOrNull(otherSummary.finalPositionError * 100.0));
                otherJson.insert("pathRms", finiteOrNull(otherSummary.pathRms));
            }
            compareJson.append(otherJson);
            text += info.pose ? QStringLiteral("trial %1 (%2): tracking RMS %3 m, path RMS %4 m\n")
                                    .arg(trial)
                                    .arg(compareMethod)
                                    .arg(otherSummary.trackingRms, 0, 'f', 3)
                                    .arg(otherSummary.pathRms, 0, 'f', 3)
                              : QStringLiteral("trial %1 (%2): tracking RMS %3\n")
                                    .arg(trial)
                                    .arg(compareMethod)
                                    .arg(otherSummary.trackingRms, 0, 'f', 4);
        }
        const sim::EpisodeResult result =
            runTrial(*plant, *controller, episode, trialLabel, reported);
        sim::appendRunLogTrial(log, trial, result, demo.dt);
        const sim::TrialSummary summary = sim::summarizeTrial(info, demo, result);
        if (line.isSet("bundle-dir") && bundleFailure.isEmpty()) {
            const QString folder =
                QDir(line.value("bundle-dir"))
                    .filePath(QStringLiteral("%1-trial-%2").arg(method).arg(trial));
            QString bundleError;
            if (!rig::writeSimulationBundle(
                    folder,
                    {{"method", method}, {"trial", trial}, {"seed", static_cast<double>(seed)}},
                    info, demo, result, summary, &bundleError)) {
                // The run goes on and its log is written: a bundle costs no trial's record.
                bundleFailure =
                    QStringLiteral("--bundle-dir: trial %1: %2").arg(trial).arg(bundleError);
            }
        }
        rms.push_back(summary.trackingRms);
        pathRms.push_back(summary.pathRms);
        paths.push_back(pathOf(result));
        QJsonObject trialJson{{"trial", trial},
                              {"duration", summary.duration},
                              {"trackingRms", summary.trackingRms},
                              {"meanCost", summary.meanCost},
                              {"cpuMicrosecondsPerStep", summary.controllerMicrosecondsPerStep},
                              {"runOutSeconds", result.runOutSeconds}};
        if (!result.controllerNote.isEmpty()) {
            trialJson.insert("controllerNote", result.controllerNote);
        }
        if (info.pose) {
            trialJson.insert("finalPositionErrorCm",
                             finiteOrNull(summary.finalPositionError * 100.0));
            trialJson.insert("finalHeadingErrorDeg",
                             finiteOrNull(summary.finalHeadingError * 180.0 / M_PI));
            trialJson.insert("pathRms", finiteOrNull(summary.pathRms));
        }
        trialsJson.append(trialJson);
        if (info.pose) {
            text += QStringLiteral(
                        "trial %1: final position error %2 cm, heading error %3 deg, "
                        "tracking RMS %4 m, path RMS %5 m, controller %6 us/step\n")
                        .arg(trial)
                        .arg(summary.finalPositionError * 100.0, 0, 'f', 1)
                        .arg(summary.finalHeadingError * 180.0 / M_PI, 0, 'f', 1)
                        .arg(summary.trackingRms, 0, 'f', 3)
                        .arg(summary.pathRms, 0, 'f', 3)
                        .arg(core::formatCpuMicroseconds(summary.controllerMicrosecondsPerStep));
        } else {
            text += QStringLiteral(
                        "trial %1: tracking RMS %2 rad, mean cost %3, controller %4 us/step\n")
                        .arg(trial)
                        .arg(summary.trackingRms, 0, 'f', 4)
                        .arg(summary.meanCost, 0, 'g', 4)
                        .arg(core::formatCpuMicroseconds(summary.controllerMicrosecondsPerStep));
        }
        if (result.runOutSeconds > 0.0) {
            text += QStringLiteral(
                        "  still moving at its end: ran out %1 s in neutral, scored "
                        "where it rests\n")
                        .arg(result.runOutSeconds, 0, 'f', 1);
        }
        if (!result.controllerNote.isEmpty()) {
            text += QStringLiteral("  %1: %2\n").arg(method, result.controllerNote);
        }
        if (trials > 1) {
            printProgress(trialLabel);
            reported = true;
        }
    }
    if (reported) {
        printProgress(QString());
    }
    core::FileError error;
    if (!core::writeRunLogCsv(log, out, &error)) {
        throw UsageError(bundleFailure.isEmpty()
                             ? error.toString()
                             : error.toString() + QStringLiteral("; ") + bundleFailure);
    }
    if (!bundleFailure.isEmpty()) {
        throw UsageError(QStringLiteral("%1 (no bundle was written after it; the run log %2 "
                                        "holds every trial)")
                             .arg(bundleFailure, out));
    }
    // A trial whose error is not a number has no result to report (the plant's state left the
    // numbers, e.g. on a demonstration no real car could drive): say so, and exit 2.
    for (size_t trial = 0; trial < rms.size(); ++trial) {
        const bool finite =
            std::isfinite(rms[trial]) && (!comparison || std::isfinite(compareRms[trial]));
        if (!finite) {
            throw UsageError(QStringLiteral("trial %1 diverged: its tracking error is not a "
                                            "number (the run log %2 keeps every step)")
                                 .arg(trial)
                                 .arg(out));
        }
    }
    if (line.isSet("plot")) {
        if (!info.pose) {
            throw UsageError(
                QStringLiteral("--plot draws planar paths; '%1' has none").arg(task.plant));
        }
        std::vector<QPointF> desired;
        for (int k = 0; k < demo.length(); ++k) {
            desired.emplace_back(demo.states(k, info.pose->x), demo.states(k, info.pose->y));
        }
        std::vector<TrajectoryPanel> panels{{method, paths, rms, pathRms}};
        if (comparison) {
            panels.insert(panels.begin(),
                          TrajectoryPanel{compareMethod, comparePaths, compareRms, comparePathRms});
        }
        saveFigureOrThrow(trajectoryFigure(desired, panels), line.value("plot"));
    }
    if (line.format() == QLatin1String("json")) {
        QJsonObject summary{{"plant", task.plant},
                            {"method", method},
                            {"seed", static_cast<double>(seed)},
                            {"trials", trialsJson},
                            {"out", out}};
        if (comparison) {
            summary.insert("compare",
                           QJsonObject{{"method", compareMethod}, {"trials", compareJson}});
        }
        printJson(summary);
    } else {
        printText(text + QStringLiteral("wrote %1\n").arg(out));
    }
    return 0;
}

}  // namespace prisca::app::cli
