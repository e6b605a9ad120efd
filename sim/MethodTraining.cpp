#include "MethodTraining.h"

#include "MethodCatalog.h"
#include "ParallelTrials.h"
#include "PlantCatalog.h"
#include "TrialMetrics.h"
#include "core/Pegasus.h"
#include "core/PriscaController.h"

#include <cmath>
#include <limits>

namespace prisca::sim {

core::PdParameters selectPdGains(const TrainingSetup& setup, const std::vector<double>& kpScales,
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
    const int seeds = static_cast<int>(setup.seeds.size());
    // One job per (candidate, seed) so both cores stay busy on small grids.
    const std::function<double(int)> job = [&](int index) {
        const Candidate& c = grid[index / seeds];
        PlantProfile profile = setup.profile;
        profile.pd.kp *= c.kp;
        profile.pd.kd *= c.kd;
        auto plant = PlantCatalog::create(setup.plant);
        auto controller = MethodCatalog::create(QStringLiteral("pd"), profile,
                                                    setup.demonstration, setup.fittedB);
        EpisodeSettings episode = setup.episode;
        episode.seed = setup.seeds[index % seeds];
        const EpisodeResult result = runEpisode(*plant, *controller, episode, setup.cancelled);
        return tuningScore(plant->info(),
                           summarizeTrial(plant->info(), *setup.demonstration, result));
    };
    const std::vector<double> scores = runParallel<double>(
        static_cast<int>(grid.size()) * seeds, setup.threads, job, setup.cancelled,
        [&](int done, int total) {
            // About ten lines in all, however large the grid.
            if (setup.progress && (done == total || done * 10 / total != (done - 1) * 10 / total)) {
                setup.progress(QStringLiteral("pd-selected: grid %1/%2").arg(done).arg(total));
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
    core::PdParameters gains = setup.profile.pd;
    gains.kp *= chosen.kp;
    gains.kd *= chosen.kd;
    return gains;
}

PegasusTraining trainPegasus(const TrainingSetup& setup, int iterations) {
    const int scenarios = static_cast<int>(setup.seeds.size());
    auto rollout = [&](const Eigen::MatrixXd& theta, int scenario) {
        auto plant = PlantCatalog::create(setup.plant);
        auto policy = MethodCatalog::create(QStringLiteral("pegasus"), setup.profile,
                                                setup.demonstration, setup.fittedB, &theta);
        EpisodeSettings episode = setup.episode;
        episode.seed = setup.seeds[scenario];
        episode.recordSteps = false;
        const EpisodeResult result = runEpisode(*plant, *policy, episode, setup.cancelled);
        return core::EpisodeOutcome{result.meanCost, result.stepCount};
    };
    core::PegasusParameters parameters = setup.profile.pegasus;
    parameters.scenarios = scenarios;
    const Eigen::MatrixXd start = Eigen::MatrixXd::Zero(setup.profile.features.featureCount(),
                                                        setup.profile.features.channelCount());
    core::Pegasus pegasus(rollout, start, parameters);
    PegasusTraining training;
    for (int i = 0; i < iterations; ++i) {
        const auto iteration = pegasus.iterate(setup.cancelled);
        if (!iteration) {
            break;
        }
        training.costs.push_back(iteration->cost);
        training.steps.push_back(iteration->stepsConsumed);
        if (setup.progress) {
            setup.progress(QStringLiteral("pegasus: iteration %1/%2, cost %3")
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

bool trainsOffline(const QString& method) {
    return MethodCatalog::get(method).trainsOffline();
}

std::unique_ptr<core::Controller> createTrained(const QString& method, const TrainingSetup& setup,
                                                int pegasusIterations) {
    PlantProfile profile = setup.profile;
    Eigen::MatrixXd pegasusTheta;
    if (trainsOffline(method)) {
        TrainingSetup training = setup;
        training.episode.recordSteps = false;
        switch (MethodCatalog::get(method).training) {
            case MethodSpec::Training::Pegasus:
                pegasusTheta = trainPegasus(training, pegasusIterations).theta;
                break;
            case MethodSpec::Training::SelectPdGains:
                profile.pd = selectPdGains(training);
                break;
            case MethodSpec::Training::None:
                break;
        }
        if (setup.cancelled && setup.cancelled()) {
            return nullptr;
        }
    }
    return MethodCatalog::create(method, profile, setup.demonstration, setup.fittedB,
                                     pegasusTheta.size() ? &pegasusTheta : nullptr);
}

}  // namespace prisca::sim
