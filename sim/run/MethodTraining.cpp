#include "sim/run/MethodTraining.h"

#include "core/Pegasus.h"
#include "core/PriscaController.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/episodes/TrialMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prisca::sim {

core::PdParameters selectPdGains(const TrainingTrials& setup, const TrainingHooks& hooks,
                                 const std::vector<double>& kpScales,
                                 const std::vector<double>& kdScales) {
    struct Candidate {
        double kp, kd;
    };
    std::vector<Candidate> grid;
    for (double kp : kpScales) {
        for (double kd : kdScales) {
            grid.push_back({kp, kd});
        }
    }
    const std::vector<std::uint64_t> seedList = setup.trainingSeeds();
    const int seeds = static_cast<int>(seedList.size());
    if (seeds == 0) {
        return setup.task().profile.pd;
    }
    const Task& task = setup.task();
    // One job per (candidate, seed) so both cores stay busy on small grids.
    const std::function<double(int)> job = [&](int index) {
        const Candidate& c = grid[index / seeds];
        MethodTuning profile = task.profile;
        profile.pd.kp *= c.kp;
        profile.pd.kd *= c.kd;
        auto plant = setup.makePlant();
        auto controller =
            MethodCatalog::create(QStringLiteral("pd"), profile, task.demonstration, task.fit.b);
        EpisodeSettings episode = setup.trainingTrial(index % seeds);
        episode.resetMode = core::ResetMode::Cold;
        episode.recordSteps = false;
        const EpisodeResult result = runEpisode(*plant, *controller, episode, hooks.cancelled);
        return tuningScore(plant->info(),
                           summarizeTrial(plant->info(), *task.demonstration, result));
    };
    const std::vector<double> scores = runParallel<double>(
        static_cast<int>(grid.size()) * seeds, setup.threads(), job, hooks.cancelled,
        [&](int done, int total) {
            // About ten lines in all, however large the grid.
            if (hooks.progress && (done == total || done * 10 / total != (done - 1) * 10 / total)) {
                hooks.progress(QStringLiteral("pd-selected: grid %1/%2").arg(done).arg(total));
            }
        });
    // Risk-averse: mean + standard deviation over the training trials, so gains that are good
    // on most trials but break on some are not chosen.
    double best = std::numeric_limits<double>::infinity();
    Candidate chosen{1.0, 1.0};
    for (size_t g = 0; g < grid.size(); ++g) {
        std::vector<double> trialScores(scores.begin() + g * seeds,
                                        scores.begin() + (g + 1) * seeds);
        double mean = 0.0;
        for (double v : trialScores) {
            mean += v / seeds;
        }
        double spread = 0.0;
        for (double v : trialScores) {
            spread += (v - mean) * (v - mean);
        }
        const double score = mean + (seeds > 1 ? std::sqrt(spread / (seeds - 1)) : 0.0);
        if (score < best) {
            best = score;
            chosen = grid[g];
        }
    }
    core::PdParameters gains = task.profile.pd;
    gains.kp *= chosen.kp;
    gains.kd *= chosen.kd;
    return gains;
}

PegasusTraining trainPegasus(const TrainingTrials& setup, int iterations,
                             const TrainingHooks& hooks) {
    const Task& task = setup.task();
    std::vector<std::uint64_t> seeds = setup.trainingSeeds();
    if (static_cast<int>(seeds.size()) > task.profile.pegasus.scenarios) {
        seeds.resize(static_cast<size_t>(std::max(1, task.profile.pegasus.scenarios)));
    }
    const int scenarios = static_cast<int>(seeds.size());
    PegasusTraining training;
    if (scenarios == 0) {
        training.theta = Eigen::MatrixXd::Zero(task.profile.features.featureCount(),
                                               task.profile.features.channelCount());
        return training;
    }
    auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
        auto plant = setup.makePlant();
        auto policy = MethodCatalog::create(QStringLiteral("pegasus"), task.profile,
                                            task.demonstration, task.fit.b, &theta);
        EpisodeSettings episode = setup.trainingTrial(scenario);
        episode.resetMode = core::ResetMode::Cold;
        episode.recordSteps = false;
        const EpisodeResult result = runEpisode(*plant, *policy, episode, hooks.cancelled);
        return core::EpisodeOutcome{result.meanCost, result.stepCount};
    };
    core::PegasusParameters parameters = task.profile.pegasus;
    parameters.scenarios = scenarios;
    const Eigen::MatrixXd start = Eigen::MatrixXd::Zero(task.profile.features.featureCount(),
                                                        task.profile.features.channelCount());
    core::Pegasus pegasus(rollout, start, parameters);
    for (int i = 0; i < iterations; ++i) {
        const auto iteration = pegasus.iterate(hooks.cancelled);
        if (!iteration) {
            break;
        }
        training.costs.push_back(iteration->cost);
        training.steps.push_back(iteration->stepsConsumed);
        if (hooks.progress) {
            hooks.progress(QStringLiteral("pegasus: iteration %1/%2, cost %3")
                               .arg(i + 1)
                               .arg(iterations)
                               .arg(iteration->cost, 0, 'g', 4));
        }
    }
    training.theta = pegasus.theta();
    return training;
}

std::vector<std::uint64_t> trainingSeeds(std::uint64_t seed, int count) {
    constexpr std::uint64_t kTrainingStream = 0x7EA1;
    std::vector<std::uint64_t> seeds;
    for (int i = 0; i < count; ++i) {
        seeds.push_back(mixSeed(seed ^ kTrainingStream, i));
    }
    return seeds;
}

}  // namespace prisca::sim
