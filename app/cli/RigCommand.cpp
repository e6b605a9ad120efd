// prisca-cli rig --virtual: the whole rig chain with no hardware, headless.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "core/DeviationModel.h"
#include "rigsim/VirtualRig.h"
#include "sim/EpisodeRunner.h"
#include "sim/MethodCatalog.h"
#include "sim/TrialMetrics.h"

#include <QJsonArray>
#include <QJsonObject>

#include <algorithm>
#include <cmath>

namespace prisca::app::cli {

int rigCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("rig"),
        QStringLiteral(
            "Trials on the rig. With --virtual, the real rig's chain with no hardware: a "
            "simulated car driven through a pseudo-terminal by the transmitter link, "
            "the synthetic ceiling camera, the LED tracker, the state estimator and the "
            "controller, in real time."));
    line.addFlag("virtual", "The virtual rig (the only rig this command drives).");
    line.addValue("demo", "Demonstration CSV (default: the scripted one, see --demo-seed).",
                  "file");
    line.addValue("demo-seed", "Seed of the scripted demonstration.", "N", "1");
    line.addValue("method", "Method: " + sim::MethodCatalog::ids().join(", ") + ".", "name",
                  "prisca");
    line.addValue("trials", "Trials in a row (each lasts the demonstration plus its settling).",
                  "N", "3");
    line.addValue("seed", "Seed of the trials (the car's start, friction, gains).", "N", "1");
    line.addValue("perturbation", "The simulated car's perturbation level.", "level", "1");
    addPriscaDefaultsOption(line);
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    if (!line.isSet("virtual")) {
        throw UsageError(QStringLiteral(
            "rig drives the virtual rig only (give --virtual); the real rig runs in the window"));
    }
    const QString method = line.value("method");
    const sim::MethodSpec* spec = sim::MethodCatalog::find(method);
    if (!spec) {
        throw UsageError(QStringLiteral("unknown method '%1' (one of: %2)")
                             .arg(method, sim::MethodCatalog::ids().join(' ')));
    }
    if (spec->simulationOnly || spec->trainsOffline()) {
        throw UsageError(QStringLiteral("%1 cannot run on a rig (%2)")
                             .arg(method, spec->simulationOnly
                                              ? QStringLiteral("it plans on the simulator itself")
                                              : QStringLiteral("it trains offline first")));
    }
    Task task =
        loadOrDemonstrate(QStringLiteral("slidecar"), line.value("demo"),
                          static_cast<std::uint64_t>(line.integer("demo-seed", 0, 1LL << 62)));
    applyPriscaDefaults(line, task.profile);
    const int trials = static_cast<int>(line.integer("trials", 1, 1000));
    const auto seed = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));

    rigsim::VirtualRigSettings settings;
    settings.perturbation = line.number("perturbation", 0.0, 10.0);
    settings.lostTrackDistance = task.profile.lostTrackDistance;
    settings.cameraFps = 1.0 / task.demonstration->dt;  // one frame per control step
    rigsim::VirtualRig rig(
        settings, sim::MethodCatalog::create(method, task.profile, task.demonstration, task.fit.b));
    QString error;
    if (!rig.open(&error)) {
        throw UsageError(QStringLiteral("the virtual rig could not start: %1").arg(error));
    }
    installInterruptHandler();
    const core::Demonstration& demo = *task.demonstration;
    const double seconds = demo.length() * demo.dt + task.profile.settleTime;
    QJsonArray rows;
    for (int t = 0; t < trials && !interrupted(); ++t) {
        printProgress(QStringLiteral("rig: trial %1/%2 (%3 s)")
                          .arg(t + 1)
                          .arg(trials)
                          .arg(seconds, 0, 'f', 1));
        const rigsim::VirtualRig::Trial trial = rig.runTrial(
            seconds, sim::resetForTrial(t), sim::mixSeed(seed, t), [] { return interrupted(); });
        const sim::ParkingError parked = sim::parkingError(
            task.profile.info, demo, trial.finalPose.x, trial.finalPose.y, trial.finalPose.heading);
        const double miss = parked.position;
        const double heading = parked.heading;
        std::vector<double> latency = trial.latencyMs;
        std::sort(latency.begin(), latency.end());
        const double medianLatency = latency.empty() ? -1.0 : latency[latency.size() / 2];
        rows.append(QJsonObject{{"trial", t + 1},
                                {"finalPositionErrorCm", miss * 100.0},
                                {"finalHeadingErrorDeg", heading * 180.0 / core::kPi},
                                {"frames", trial.frames},
                                {"framesWithPose", trial.framesWithPose},
                                {"linkFramesDecoded", static_cast<double>(trial.linkFramesDecoded)},
                                {"medianFrameToBytesMs", medianLatency}});
        if (line.format() == QLatin1String("text")) {
            printText(QStringLiteral("trial %1: parked %2 cm and %3 deg from the lot; %4 of %5 "
                                     "frames with a pose; %6 link frames decoded; frame -> bytes "
                                     "median %7 ms\n")
                          .arg(t + 1)
                          .arg(miss * 100.0, 0, 'f', 1)
                          .arg(heading * 180.0 / core::kPi, 0, 'f', 1)
                          .arg(trial.framesWithPose)
                          .arg(trial.frames)
                          .arg(trial.linkFramesDecoded)
                          .arg(medianLatency, 0, 'f', 2));
        }
    }
    if (line.format() == QLatin1String("json")) {
        printJson(QJsonObject{{"plant", QStringLiteral("slidecar")},
                              {"method", method},
                              {"seed", static_cast<double>(seed)},
                              {"trials", rows}});
    }
    return interrupted() ? kExitInterrupted : 0;
}

}  // namespace prisca::app::cli
