#include "LearningCurveExperiment.h"

#include "MethodCatalog.h"
#include "ParallelTrials.h"
#include "PlantCatalog.h"
#include "TrialMetrics.h"
#include "core/Pegasus.h"

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

std::vector<MethodCurves> runLearningCurves(
    const LearningCurveSettings& settings, std::shared_ptr<const core::Demonstration> demonstration,
    const PlantProfile& profile, const Eigen::MatrixXd& fittedB) {
    for (const QString& method : settings.methods) {
        if (!isCurveMethod(method)) {
            throw std::invalid_argument(
                QStringLiteral("'%1' has no learning curve (one of: %2)")
                    .arg(method, curveMethods().join(QLatin1Char(' ')))
                    .toStdString());
        }
    }
    // The same trial as everywhere else (perturbation, sensor with its latency and drops,
    // length), from the profile.
    const EpisodeSettings base =
        profile.episode(*demonstration, settings.perturbation, settings.sensor);

    const int runs = settings.runs;
    const std::function<std::vector<CurvePoint>(int)> job = [&](int index) {
        const QString& method = settings.methods[index / runs];
        const std::uint64_t runSeed = mixSeed(settings.seed, index % runs);
        auto plant = PlantCatalog::create(settings.plant);
        const PlantInfo info = plant->info();
        std::vector<CurvePoint> curve;
        long long consumed = 0;
        if (MethodCatalog::get(method).training == MethodSpec::Training::Pegasus) {
            // Fixed scenarios for this run; every rollout is charged to the budget.
            auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
                auto policy = MethodCatalog::create(method, profile, demonstration, fittedB,
                                                    &theta);
                EpisodeSettings episode = base;
                episode.seed = mixSeed(runSeed, 1000 + scenario);
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
                auto policy = MethodCatalog::create(QStringLiteral("pegasus"), profile,
                                                        demonstration, fittedB, &pegasus.theta());
                EpisodeSettings episode = base;
                episode.seed = mixSeed(runSeed, 5000 + static_cast<std::uint64_t>(curve.size()));
                const EpisodeResult evaluation =
                    runEpisode(*plant, *policy, episode, settings.cancelled);
                const double mean = meanSquaredTracking(info, *demonstration, evaluation);
                consumed = iteration->stepsConsumed;
                curve.push_back({consumed, mean});
            }
        } else {
            // Online learners carry what they learned into the next trial; the others start
            // every trial afresh (a flat curve to read the learners against).
            auto controller = MethodCatalog::create(method, profile, demonstration, fittedB);
            for (int trial = 0; consumed < settings.budgetSteps; ++trial) {
                if (settings.cancelled && settings.cancelled()) {
                    break;
                }
                EpisodeSettings episode = base;
                setTrial(episode, runSeed, trial);
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
        static_cast<int>(settings.methods.size()) * runs, settings.threads, job, settings.cancelled,
        [&](int done, int total) {
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
