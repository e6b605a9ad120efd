#include "sim/experiments/LearningCurveExperiment.h"

#include "core/Pegasus.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/episodes/TrialMetrics.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace prisca::sim {

namespace {

// Mean over the trial of the squared tracked error (the paper's "square of the l2-norm of the
// joint angle deviation" for the acrobot), against the time-aligned demonstration.
double meanSquaredTracking(const PlantInfo& info, const core::Demonstration& demonstration,
                           const EpisodeResult& result) {
    if (result.steps.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    double sum = 0.0;
    for (size_t k = 0; k < result.steps.size(); ++k) {
        const double e =
            trackedError(info, demonstration, result.steps[k].state, static_cast<int>(k));
        sum += e * e;
    }
    return sum / result.steps.size();
}

}  // namespace

QStringList curveMethods() {
    return MethodCatalog::curveIds();
}

bool isCurveMethod(const QString& method) {
    return curveMethods().contains(method);
}

std::vector<double> resampleCurve(const std::vector<CurvePoint>& run,
                                  const std::vector<long long>& grid) {
    std::vector<double> values(grid.size(), std::numeric_limits<double>::quiet_NaN());
    size_t next = 0;
    double current = std::numeric_limits<double>::quiet_NaN();
    for (size_t g = 0; g < grid.size(); ++g) {
        while (next < run.size() && run[next].steps <= grid[g]) {
            current = run[next].trackingError;
            ++next;
        }
        values[g] = current;
    }
    return values;
}

std::vector<MethodCurves> runLearningCurves(const LearningCurveSettings& settings,
                                            const Task& task) {
    // One set-up per method: the same trial as everywhere else (the plant at the task's
    // period, perturbation, sensor with its latency and drops, length).
    std::vector<RunSetup> setups;
    for (const QString& method : settings.methods) {
        if (!isCurveMethod(method)) {
            throw std::invalid_argument(QStringLiteral("'%1' has no learning curve (one of: %2)")
                                            .arg(method, curveMethods().join(QLatin1Char(' ')))
                                            .toStdString());
        }
        setups.emplace_back(task, method, settings.run);
    }
    const MethodTuning& profile = task.profile;
    const std::shared_ptr<const core::Demonstration>& demonstration = task.demonstration;
    const Eigen::MatrixXd& fittedB = task.fit.b;

    const int runs = settings.runs;
    const std::function<std::vector<CurvePoint>(int)> job = [&](int index) {
        const RunSetup& setup = setups[index / runs];
        const QString& method = setup.method().id;
        const std::uint64_t runSeed = mixSeed(settings.run.seed, index % runs);
        auto plant = setup.makePlant();
        const PlantInfo info = plant->info();
        std::vector<CurvePoint> curve;
        long long consumed = 0;
        if (setup.method().training == MethodSpec::Training::Pegasus) {
            // Fixed scenarios for this run; every rollout is charged to the budget.
            auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
                auto policy =
                    MethodCatalog::create(method, profile, demonstration, fittedB, &theta);
                const EpisodeSettings episode = setup.curveScenario(runSeed, scenario);
                const EpisodeResult result =
                    runEpisode(*plant, *policy, episode, settings.cancelled);
                return core::EpisodeOutcome{result.meanCost, result.stepCount};
            };
            core::PegasusParameters parameters = profile.pegasus;
            core::Pegasus pegasus(rollout,
                                  Eigen::MatrixXd::Zero(profile.features.featureCount(),
                                                        profile.features.channelCount()),
                                  parameters);
            while (consumed < settings.budgetSteps &&
                   !(settings.cancelled && settings.cancelled())) {
                const auto iteration = pegasus.iterate(settings.cancelled);
                if (!iteration) {
                    break;
                }
                // Scored like the online learners: on a fresh trial it never trained on (an
                // evaluation, so not charged to its budget).
                auto policy = MethodCatalog::create(method, profile, demonstration, fittedB,
                                                    &pegasus.theta());
                const EpisodeSettings episode =
                    setup.curveEvaluation(runSeed, static_cast<int>(curve.size()));
                const EpisodeResult evaluation =
                    runEpisode(*plant, *policy, episode, settings.cancelled);
                const double mean = meanSquaredTracking(info, *demonstration, evaluation);
                consumed = iteration->stepsConsumed;
                curve.push_back({consumed, mean});
            }
        } else {
            // Online learners carry what they learned into the next trial; the others start
            // every trial afresh (a flat curve to read the learners against).
            auto controller = setup.makeController(settings.cancelled);
            for (int trial = 0; controller && consumed < settings.budgetSteps; ++trial) {
                if (settings.cancelled && settings.cancelled()) {
                    break;
                }
                EpisodeSettings episode = setup.episode();
                setTrial(episode, runSeed, trial);
                episode.perturbation.trialIndex = trial;
                const EpisodeResult result =
                    runEpisode(*plant, *controller, episode, settings.cancelled);
                if (result.cancelled) {
                    break;
                }
                consumed += result.stepCount;
                curve.push_back({consumed, meanSquaredTracking(info, *demonstration, result)});
            }
        }
        return curve;
    };
    const auto all = runParallel<std::vector<CurvePoint>>(
        static_cast<int>(settings.methods.size()) * runs, settings.run.threads, job,
        settings.cancelled, [&](int done, int total) {
            if (settings.progress &&
                (done == total || done * 10 / total != (done - 1) * 10 / total)) {
                settings.progress(QStringLiteral("curve: %1/%2 runs").arg(done).arg(total));
            }
        });
    std::vector<MethodCurves> curves;
    for (int m = 0; m < settings.methods.size(); ++m) {
        MethodCurves method;
        method.method = settings.methods[m];
        for (int r = 0; r < runs; ++r) {
            method.runs.push_back(all[m * runs + r]);
        }
        curves.push_back(std::move(method));
    }
    return curves;
}

namespace {

// Adds a cell's runs to each method's runs so far.
void pool(std::vector<MethodCurves>& into, const std::vector<MethodCurves>& cell) {
    if (into.empty()) {
        into = cell;
        return;
    }
    for (size_t m = 0; m < cell.size(); ++m) {
        into[m].runs.insert(into[m].runs.end(), cell[m].runs.begin(), cell[m].runs.end());
    }
}

}  // namespace

LearningCurveProtocolResult runLearningCurveProtocol(
    const LearningCurveProtocolSettings& settings, const MethodTuning& profile,
    const std::function<void(int, int, const QString&, std::uint64_t)>& cellStarted) {
    const QString& plant = profile.info.name;
    if (const QString unknown = DemonstrationStyles::unknownStyleIn(plant, settings.styles);
        !unknown.isEmpty()) {
        throw std::invalid_argument(unknown.toStdString());
    }
    if (settings.styles.isEmpty() || settings.seedSets.empty()) {
        throw std::invalid_argument("the curves need at least one style and one seed set");
    }
    LearningCurveProtocolResult result;
    result.perStyle.resize(static_cast<size_t>(settings.styles.size()));
    result.shortestDemonstration = std::numeric_limits<long long>::max();
    const int cellCount = static_cast<int>(settings.styles.size() * settings.seedSets.size());
    for (int s = 0; s < settings.styles.size() && !result.cancelled; ++s) {
        for (std::uint64_t set : settings.seedSets) {
            if (settings.curves.cancelled && settings.curves.cancelled()) {
                result.cancelled = true;
                break;
            }
            if (cellStarted) {
                cellStarted(result.cells + 1, cellCount, settings.styles[s], set);
            }
            const Task task =
                makeTask(profile,
                         std::make_shared<core::Demonstration>(DemonstrationStyles::record(
                             plant, settings.styles[s], set, {},
                             demonstrationConditions(settings.curves.run, profile,
                                                     settings.plantParameters.get(), set))),
                         settings.fit, settings.plantParameters);
            LearningCurveSettings cell = settings.curves;
            cell.run.seed = set;
            const std::vector<MethodCurves> curves = runLearningCurves(cell, task);
            if (result.cells == 0) {
                result.dt = task.demonstration->dt;
            }
            ++result.cells;
            result.shortestDemonstration =
                std::min<long long>(result.shortestDemonstration, task.demonstration->length());
            pool(result.pooled, curves);
            pool(result.perStyle[static_cast<size_t>(s)], curves);
        }
    }
    if (settings.curves.cancelled && settings.curves.cancelled()) {
        result.cancelled = true;
    }
    return result;
}

std::vector<CurveSummary> summarizeCurves(const std::vector<MethodCurves>& curves, long long unit,
                                          long long budgetSteps, double dt) {
    std::vector<long long> grid;
    for (long long s = unit; unit > 0 && s <= budgetSteps; s += unit) {
        grid.push_back(s);
    }
    std::vector<CurveSummary> out;
    for (const MethodCurves& method : curves) {
        std::vector<std::vector<double>> resampled;
        for (const auto& run : method.runs) {
            resampled.push_back(resampleCurve(run, grid));
        }
        CurveSummary summary;
        summary.method = method.method;
        summary.steps = grid;
        for (long long steps : grid) {
            summary.seconds.push_back(steps * dt);
        }
        summary.band = core::confidenceBand(resampled, 0.95);
        out.push_back(std::move(summary));
    }
    return out;
}

}  // namespace prisca::sim
