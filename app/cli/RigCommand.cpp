// prisca-cli rig --virtual: the whole rig chain with no hardware, headless.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "core/DeviationModel.h"
#include "devices/ProcessFailsafe.h"
#include "rig/RigSession.h"
#include "sim/MethodCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonObject>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <vector>

namespace prisca::app::cli {

namespace {

// A command within two pulse microseconds of centre (of +-512) counts as neutral: the
// protocols' channel steps are finer (CRSF about 0.6 us).
constexpr double kNeutralSlack = 2.0 / 512.0;

// Waits until `done` holds, the user interrupts (unless `untilInterrupted` is false: the
// closing wait must see the link closed), or the camera fails; returns `done()`.
using Wait =
    std::function<bool(const std::function<bool()>& done, int timeoutMs, bool untilInterrupted)>;

void declareRigOptions(CommandLine& line) {
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
    line.addFlag("measure-latency",
                 "First measure the loop's latency (throttle steps with the car at rest, the "
                 "response timed in the camera); the trials then compensate it.");
    line.addValue("latency-steps", "Steps the latency measurement times.", "N", "5");
    line.addValue("loop-latency",
                  "The loop's latency for the controllers to compensate (a measured value; "
                  "default: the profile's assumption).",
                  "ms");
    line.addValue("inject-camera-delay",
                  "The virtual camera shows the car this much later (to check the measurement).",
                  "ms", "0");
    line.addValue("bundle-dir",
                  "Save every trial as a bundle (poses, commands, the camera's frames) in a new "
                  "folder under this one (prisca-cli replay reads it).",
                  "dir");
    line.addValue("bundle-fps", "Frame rate of the bundles' video (0: none).", "1/s", "10");
    line.addValue("fence",
                  "A fence on the floor, its corners in order: \"x,y;x,y;x,y...\" [m]. A car "
                  "outside it ends the trial in failsafe.",
                  "polygon");
    line.addValue("max-speed", "A speed over this ends the trial in failsafe (0: no limit).", "m/s",
                  "0");
    line.addValue("max-lost", "A track lost for longer ends the trial in failsafe (0: no limit).",
                  "s", "0");
    addPlantParametersOption(line);
    addMethodParameterOptions(line);
    addVerboseOption(line);
    line.addFormat({"text", "json"});
}

// The method named by --method, if the rig may run it (its own rule, the pre-trial check's,
// said before any device is opened).
const sim::MethodSpec& rigMethod(const QString& method) {
    const sim::MethodSpec* spec = sim::MethodCatalog::find(method);
    if (!spec) {
        throw UsageError(QStringLiteral("unknown method '%1' (one of: %2)")
                             .arg(method, sim::MethodCatalog::ids().join(' ')));
    }
    if (const QString problem =
            rig::methodRigProblem(spec->simulationOnly, spec->trainsOffline(), spec->label);
        !problem.isEmpty()) {
        throw UsageError(QStringLiteral("--method %1: %2").arg(method, problem));
    }
    return *spec;
}

devices::Geofence fenceOption(const CommandLine& line) {
    devices::Geofence fence;
    if (line.isSet("fence")) {
        QString fenceError;
        const auto polygon = devices::Geofence::parsePolygon(line.value("fence"), &fenceError);
        if (!polygon) {
            throw UsageError(QStringLiteral("--fence: %1").arg(fenceError));
        }
        if (polygon->empty()) {
            // An unset shell variable, most likely: a trial must not run unfenced by accident.
            throw UsageError(QStringLiteral("--fence '%1' gives no corner: give at least 3 as "
                                            "\"x,y;x,y;x,y\" in metres, or leave --fence out for "
                                            "no fence")
                                 .arg(line.value("fence")));
        }
        fence.polygon = *polygon;
    }
    fence.maxSpeed = line.number("max-speed", 0.0, 100.0);
    fence.maxLostSeconds = line.number("max-lost", 0.0, 3600.0);
    if (const QString problem = fence.problem(); !problem.isEmpty()) {
        throw UsageError(QStringLiteral("--fence: %1").arg(problem));
    }
    return fence;
}

// --measure-latency: the loop's latency measured; what it found (empty when interrupted).
QJsonObject measureLoopLatency(rig::RigSession& rig, const Wait& waitFor, int probeSteps,
                               double cameraDelay, bool text) {
    std::optional<rig::LatencyMeasurement> measured;
    // Delivered on this thread (the session emits on the camera's), and not after the return.
    QObject receiver;
    QObject::connect(&rig, &rig::RigSession::latencyMeasured, &receiver,
                     [&measured](const rig::LatencyMeasurement& m) { measured = m; });
    devices::LatencyProbeSettings probe;
    probe.steps = probeSteps;
    // A camera delayed on purpose answers that much later: the step waits for it.
    probe.giveUpAfter += cameraDelay;
    QString error;
    if (!rig.measureLatency(probe, &error)) {
        throw UsageError(QStringLiteral("the latency measurement could not start: %1").arg(error));
    }
    printProgress(QStringLiteral("rig: measuring the loop's latency (%1 steps)").arg(probeSteps));
    waitFor([&] { return measured.has_value(); }, 20000 * probeSteps, true);
    printProgress(QString());
    if (!measured) {
        rig.cancelLatencyMeasurement();
        if (!interrupted()) {
            throw UsageError(QStringLiteral("the latency measurement did not finish"));
        }
        return {};
    }
    if (!measured->error.isEmpty()) {
        throw UsageError(QStringLiteral("the latency measurement failed: %1").arg(measured->error));
    }
    // (The session compensates what it measured from now on.)
    QJsonArray steps;
    QStringList stepText;
    for (double s : measured->stepsSeconds) {
        steps.append(s * 1000.0);
        stepText << QString::number(s * 1000.0, 'f', 1);
    }
    if (text) {
        printText(QStringLiteral("loop latency (command -> response seen): median %1 ms, "
                                 "from %2 to %3 ms, std %4 ms over %5 steps (%6 ms); "
                                 "the trials compensate %1 ms\n")
                      .arg(measured->median * 1000.0, 0, 'f', 1)
                      .arg(measured->min * 1000.0, 0, 'f', 1)
                      .arg(measured->max * 1000.0, 0, 'f', 1)
                      .arg(measured->spread * 1000.0, 0, 'f', 1)
                      .arg(measured->stepsSeconds.size())
                      .arg(stepText.join(", ")));
    }
    return {{"medianMs", measured->median * 1000.0},
            {"minMs", measured->min * 1000.0},
            {"maxMs", measured->max * 1000.0},
            {"spreadMs", measured->spread * 1000.0},
            {"stepsMs", steps}};
}

// The pre-trial check the window's strip shows, printed; no trial starts on a failed one.
QJsonArray checkBeforeTrials(const rig::PreTrialCheck& check, bool text) {
    QJsonArray checkJson;
    QStringList checkText;
    for (const rig::PreTrialItem& item : check.items) {
        checkJson.append(QJsonObject{{"item", item.key},
                                     {"ok", item.ok},
                                     {"blocking", item.blocking},
                                     {"detail", item.detail}});
        checkText << QStringLiteral("  %1 %2: %3")
                         .arg(item.ok         ? QStringLiteral("ok  ")
                              : item.blocking ? QStringLiteral("FAIL")
                                              : QStringLiteral("note"),
                              item.label, item.detail);
    }
    if (!check.ready()) {
        std::fprintf(stderr, "prisca-cli: rig: pre-trial check:\n%s\n",
                     qPrintable(checkText.join(QLatin1Char('\n'))));
        throw UsageError(QStringLiteral("not ready for a trial (%1): %2")
                             .arg(check.missingLabels(), check.missingDetails()));
    }
    if (text) {
        printText(
            QStringLiteral("pre-trial check: ready\n%1\n").arg(checkText.join(QLatin1Char('\n'))));
    }
    return checkJson;
}

// One trial's report: its JSON row, and its lines when the format is text.
QJsonObject reportTrial(const rig::RigTrialResult& trial, int number, long long decoded,
                        const QString& method, bool text) {
    // Frame-to-command latency: the median, the 99th percentile (nearest rank) and the worst.
    std::vector<double> latency = trial.loopLatencyMs;
    std::sort(latency.begin(), latency.end());
    const auto percentile = [&latency](double p) {
        if (latency.empty()) {
            return -1.0;
        }
        const auto rank = static_cast<size_t>(std::ceil(p / 100.0 * latency.size()));
        return latency[std::clamp<size_t>(rank, 1, latency.size()) - 1];
    };
    const double medianLatency = percentile(50.0);
    const double p99Latency = percentile(99.0);
    const double worstLatency = latency.empty() ? -1.0 : latency.back();
    QJsonObject row{{"trial", number},
                    {"seconds", trial.seconds},
                    {"stopped", trial.stopped},
                    {"failsafe", trial.fault},
                    {"failsafeReason", trial.reason},
                    {"frames", static_cast<double>(trial.frames)},
                    {"framesWithPose", static_cast<double>(trial.framesWithPose)},
                    {"linkFramesDecoded", static_cast<double>(decoded)},
                    {"medianFrameToCommandMs", medianLatency},
                    {"p99FrameToCommandMs", p99Latency},
                    {"worstFrameToCommandMs", worstLatency}};
    row.insert("runOutSeconds", trial.runOutSeconds);
    if (trial.parked) {
        row.insert("finalPositionErrorCm", trial.parked->position * 100.0);
        row.insert("finalHeadingErrorDeg", trial.parked->heading * 180.0 / core::kPi);
    }
    if (!trial.controllerNote.isEmpty()) {
        row.insert("controllerNote", trial.controllerNote);
    }
    if (text) {
        const QString where = trial.parked
                                  ? QStringLiteral("parked %1 cm and %2 deg from the lot")
                                        .arg(trial.parked->position * 100.0, 0, 'f', 1)
                                        .arg(trial.parked->heading * 180.0 / core::kPi, 0, 'f', 1)
                                  : QStringLiteral("no pose seen");
        const QString ending =
            trial.stopped ? (trial.reason.isEmpty()
                                 ? QStringLiteral(" (stopped early)")
                                 : QStringLiteral(" (stopped early: %1)").arg(trial.reason))
            : trial.fault ? QStringLiteral(" (failsafe: %1)").arg(trial.reason)
                          : QString();
        const QString ranOut = trial.runOutSeconds > 0.0
                                   ? QStringLiteral(" after running out %1 s in neutral")
                                         .arg(trial.runOutSeconds, 0, 'f', 1)
                                   : QString();
        printText(QStringLiteral("trial %1: %2%3; %4 of %5 frames with a pose; %6 link "
                                 "frames decoded; frame -> command median %7 ms, p99 %8 ms, "
                                 "worst %9 ms\n")
                      .arg(number)
                      .arg(where + ranOut, ending)
                      .arg(trial.framesWithPose)
                      .arg(trial.frames)
                      .arg(decoded)
                      .arg(medianLatency, 0, 'f', 2)
                      .arg(p99Latency, 0, 'f', 2)
                      .arg(worstLatency, 0, 'f', 2));
        if (!trial.controllerNote.isEmpty()) {
            printText(QStringLiteral("  %1: %2\n").arg(method, trial.controllerNote));
        }
    }
    return row;
}

// Each trial's bundle answer counted, the saved folders kept, a failed one warned of.
void watchBundles(rig::RigSession& rig, QObject* receiver, QStringList* bundles, int* answers) {
    QObject::connect(&rig, &rig::RigSession::bundleSaved, receiver,
                     [bundles, answers](const QString& folder, const QString& error) {
                         ++*answers;
                         if (!error.isEmpty()) {
                             std::fprintf(stderr, "prisca-cli: rig: warning: bundle %s: %s\n",
                                          qPrintable(folder), qPrintable(error));
                         } else {
                             *bundles << folder;
                         }
                     });
}

// Starts a trial and waits for its end (`last` set by the session's trialFinished), with
// progress each second of wall-clock time (the trial itself runs on frame time); a trial that
// does not end (interrupted, the camera failed, no frames) is ended now.
void runTrial(rig::RigSession& rig, const Wait& waitFor, const rig::TrialRequest& request,
              const QString& which, double seconds,
              const std::optional<rig::RigTrialResult>& last) {
    QString error;
    if (!rig.startTrial(request, &error)) {
        throw UsageError(QStringLiteral("trial %1 could not start: %2")
                             .arg(which.section(QLatin1Char('/'), 0, 0), error));
    }
    QElapsedTimer sinceStart;
    sinceStart.start();
    int shownSecond = 0;
    waitFor(
        [&] {
            if (const int second = static_cast<int>(sinceStart.elapsed() / 1000);
                second > shownSecond && !last) {
                shownSecond = second;
                printProgress(second <= seconds
                                  ? QStringLiteral("rig: trial %1: %2 of %3 s")
                                        .arg(which)
                                        .arg(second)
                                        .arg(seconds, 0, 'f', 1)
                                  // A car still moving at the end runs out in neutral.
                                  : QStringLiteral("rig: trial %1: %2 s, past its %3 s: "
                                                   "ending, or running out in neutral")
                                        .arg(which)
                                        .arg(second)
                                        .arg(seconds, 0, 'f', 1));
            }
            return last.has_value();
        },
        static_cast<int>((seconds + 30.0) * 1000), true);
    if (!last) {
        rig.stopTrial();
        // A trial that ended on the camera's thread just before is reported on this one.
        waitFor([&] { return last.has_value(); }, 2000, false);
    }
    if (!last) {
        throw UsageError(QStringLiteral("trial %1 ended without a result")
                             .arg(which.section(QLatin1Char('/'), 0, 0)));
    }
}

// The link closed (its last frame failsafe), and what the car's receiver holds after it: into
// `heldJson`, and as a line when the format is text.
bool closeLink(rig::RigSession& rig, const Wait& waitFor, QJsonArray* heldJson, bool text) {
    rig.stopCamera();
    rig.disconnectLink();
    const bool closed = waitFor([&] { return !rig.linkStatus().connected; }, 5000, false);
    const Eigen::VectorXd held = rig.virtualReceivedCommand().value_or(Eigen::VectorXd());
    const bool neutral = closed && held.size() > 0 && held.cwiseAbs().maxCoeff() <= kNeutralSlack;
    if (interrupted()) {
        // On stderr: stdout may be the pipe whose closing (SIGPIPE) stopped the command.
        std::fprintf(stderr, "prisca-cli: rig: stopped by %s; the link %s\n",
                     interruptionName().toLatin1().constData(),
                     neutral ? "ended in failsafe (the car's receiver holds neutral)"
                             : "closed, but the car's receiver does NOT hold neutral");
    }
    QStringList values;
    for (double u : held) {
        heldJson->append(u);
        values << QString::asprintf("%+.3f", u);
    }
    if (text) {
        printText(QStringLiteral("link closed; the car's receiver holds [%1]: %2\n")
                      .arg(values.join(", "), neutral ? QStringLiteral("neutral (failsafe)")
                                                      : QStringLiteral("NOT neutral")));
    }
    return neutral;
}

}  // namespace

int rigCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("rig"),
        QStringLiteral(
            "Trials on the rig. With --virtual, the real rig's chain with no hardware: a "
            "simulated car driven through a pseudo-terminal by the transmitter link, "
            "the synthetic ceiling camera, the LED tracker, the state estimator and the "
            "controller, in real time."));
    declareRigOptions(line);
    if (!line.parse(arguments)) {
        return 0;
    }
    applyVerbosity(line);
    if (!line.isSet("virtual")) {
        throw UsageError(QStringLiteral(
            "rig drives the virtual rig only (give --virtual); the real rig runs in the window"));
    }
    const bool text = line.format() == QLatin1String("text");
    const QString method = line.value("method");
    const sim::MethodSpec& spec = rigMethod(method);
    // The scripted operator drives the same car as the trials.
    Task task = taskFromOptions(line, QStringLiteral("slidecar"));
    const std::shared_ptr<const sim::PlantParameters> parameters = task.plantParameters;
    applyMethodParameters(line, task.profile, parameters != nullptr);
    const devices::Geofence fence = fenceOption(line);
    const int trials = static_cast<int>(line.integer("trials", 0, 1000));
    const auto seed = static_cast<std::uint64_t>(line.integer("seed", 0, 1LL << 62));
    // The run as the simulation sets it up: the rig's loop takes its controller, settle time,
    // lost-track distance and latency compensation from here.
    const auto setup = std::make_shared<const sim::RunSetup>(task, method);

    // The window's rig session, headless: the virtual car seen by the synthetic camera at the
    // demonstration's control rate, the link on the car's pseudo-terminal.
    const core::Demonstration& demo = *task.demonstration;
    rig::RigSession rig;
    rig.setGeofence(fence);
    if (line.isSet("bundle-dir")) {
        rig.setBundles(line.value("bundle-dir"), line.number("bundle-fps", 0.0, 200.0));
    }
    QStringList bundles;
    int bundleAnswers = 0;  // one per trial, saved or not: a failed bundle is not waited for
    // The session's signals come from the camera's thread: delivered here, on this one.
    QObject receiver;
    watchBundles(rig, &receiver, &bundles, &bundleAnswers);
    rig::CameraRequest camera;
    camera.virtualFps = 1.0 / demo.dt;  // one frame per control step
    camera.virtualPerturbation = line.number("perturbation", 0.0, 10.0);
    camera.virtualPlant = parameters;
    camera.virtualCameraDelay = line.number("inject-camera-delay", 0.0, 2000.0) / 1000.0;
    if (line.isSet("loop-latency")) {
        rig.setLoopLatency(line.number("loop-latency", 0.0, 1000.0) / 1000.0);
    }
    const int probeSteps = static_cast<int>(line.integer("latency-steps", 2, 50));
    QString error;
    if (!rig.startCamera(camera, &error)) {
        throw UsageError(QStringLiteral("the virtual rig could not start: %1").arg(error));
    }
    devices::LinkSettings link;
    link.port = rig.virtualPort();
    link.failsafe = rig.channels().failsafe();
    link.sendOnCommand = true;  // a camera frame's command goes out at once
    rig.connectLink(link);
    installInterruptHandler();
    QString cameraError;
    QObject::connect(&rig, &rig::RigSession::cameraFailed, &receiver,
                     [&cameraError](const QString& message) { cameraError = message; });
    const Wait waitFor = [&cameraError](const std::function<bool()>& done, int timeoutMs,
                                        bool untilInterrupted) {
        QEventLoop loop;
        QTimer poll;
        QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
            if (done() || (untilInterrupted && interrupted()) || !cameraError.isEmpty()) {
                loop.quit();
            }
        });
        poll.start(10);
        QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
        loop.exec();
        return done();
    };
    if (!waitFor([&] { return rig.linkStatus().connected && rig.lastPose().has_value(); }, 10000,
                 true)) {
        throw UsageError(QStringLiteral("the virtual rig could not start: %1")
                             .arg(!cameraError.isEmpty() ? cameraError
                                  : !rig.linkStatus().connected
                                      ? QStringLiteral("the link did not connect")
                                      : QStringLiteral("the camera saw no car")));
    }
    const QJsonObject latencyJson =
        line.isSet("measure-latency") && !interrupted()
            ? measureLoopLatency(rig, waitFor, probeSteps, camera.virtualCameraDelay, text)
            : QJsonObject();
    const QJsonArray checkJson = checkBeforeTrials(rig.preTrialCheck(task, spec), text);
    const double seconds = demo.length() * demo.dt + task.profile.settleTime;
    QJsonArray rows;
    std::optional<rig::RigTrialResult> last;
    QObject::connect(&rig, &rig::RigSession::trialFinished, &receiver,
                     [&last](const rig::RigTrialResult& result) { last = result; });
    for (int t = 0; t < trials && !interrupted(); ++t) {
        printProgress(QStringLiteral("rig: trial %1/%2 (%3 s)")
                          .arg(t + 1)
                          .arg(trials)
                          .arg(seconds, 0, 'f', 1));
        rig::TrialRequest request;
        request.setup = setup;
        request.virtualSeed = sim::mixSeed(seed, t);
        last.reset();
        const long long decodedBefore = rig.virtualFramesDecoded();
        runTrial(rig, waitFor, request, QStringLiteral("%1/%2").arg(t + 1).arg(trials), seconds,
                 last);
        if (line.isSet("bundle-dir")) {  // the bundle's last lines and result on disk
            waitFor([&] { return bundleAnswers > t; }, 10000, false);
        }
        if (!cameraError.isEmpty()) {
            throw UsageError(QStringLiteral("the camera failed: %1").arg(cameraError));
        }
        rows.append(
            reportTrial(*last, t + 1, rig.virtualFramesDecoded() - decodedBefore, method, text));
        if (devices::processfailsafe::held()) {
            break;  // stopped and continued: no trial starts by itself
        }
    }
    // The link's last frame is failsafe; once it has closed, what the car's receiver holds is
    // what the car was left with (an interrupt included).
    QJsonArray heldJson;
    const bool neutral = closeLink(rig, waitFor, &heldJson, text);
    if (!text) {
        printJson(QJsonObject{{"plant", QStringLiteral("slidecar")},
                              {"method", method},
                              {"seed", static_cast<double>(seed)},
                              {"preTrialCheck", checkJson},
                              {"trials", rows},
                              {"latency", latencyJson},
                              {"receiverLastCommand", heldJson},
                              {"receiverNeutral", neutral},
                              {"bundles", QJsonArray::fromStringList(bundles)}});
    }
    if (!interrupted() && devices::processfailsafe::held()) {
        throw UsageError(
            QStringLiteral("the process was stopped and continued, so the link held "
                           "failsafe and no further trial started; start the rig "
                           "again to drive"));
    }
    return interrupted() ? interruptedExitCode() : 0;
}

}  // namespace prisca::app::cli
