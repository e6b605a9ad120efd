#pragma once

#include "EpisodeRunner.h"
#include "PlantProfile.h"
#include "core/Controller.h"
#include "core/Demonstration.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// What the offline-tuned methods train on: the plant, the demonstration, and the training
/// trials (seeds that are never the evaluation seeds).
struct TrainingSetup {
    QString plant;         ///< plant name (PlantCatalog)
    PlantProfile profile;  ///< features, limits, defaults
    std::shared_ptr<const core::Demonstration> demonstration;
    Eigen::MatrixXd fittedB;                       ///< B for PRISCA-style policies
    EpisodeSettings episode;                       ///< duration, perturbation, sensor
    std::vector<std::uint64_t> seeds;              ///< training trials
    int threads = 1;                               ///< worker threads
    std::function<bool()> cancelled;               ///< polled between episodes
    std::function<void(const QString&)> progress;  ///< one line per stage (any thread)
};

/// PD (selected): a grid search over common scales of the profile's Kp and Kd (each scale
/// multiplies every channel's gain), scored by the mean plus the standard deviation of
/// tuningScore() over the training seeds.
/// Returns the profile's PD parameters with the best gains.
core::PdParameters selectPdGains(const TrainingSetup& setup,
                                 const std::vector<double>& kpScales = {0.25, 0.5, 1, 2, 4},
                                 const std::vector<double>& kdScales = {0, 0.5, 1, 2});

/// What PEGASUS learned and what it cost.
struct PegasusTraining {
    Eigen::MatrixXd theta;         ///< final policy parameters (p x m)
    std::vector<double> costs;     ///< J(theta) at each iteration (mean episode cost)
    std::vector<long long> steps;  ///< cumulative simulated steps after each iteration
};

/// PEGASUS on fixed scenarios (the training seeds: each fixes the start, the perturbation and
/// every noise stream) with the frozen linear policy of the "pegasus" method.
PegasusTraining trainPegasus(const TrainingSetup& setup, int iterations);

/// The training seeds of a run or experiment with seed `seed`: their own stream, never its
/// evaluation seeds (mixSeed(seed, i)).
std::vector<std::uint64_t> trainingSeeds(std::uint64_t seed, int count);

/// Whether `method` trains offline before it runs (PD (selected), PEGASUS).
bool trainsOffline(const QString& method);

/// `method`'s controller for setup.profile, trained first on setup's seeds if it trains offline
/// (PD (selected) selects its gains, PEGASUS takes `pegasusIterations` gradient steps). Returns
/// null if setup.cancelled stopped the training. Throws std::invalid_argument as
/// MethodCatalog::create does.
std::unique_ptr<core::Controller> createTrained(const QString& method, const TrainingSetup& setup,
                                                int pegasusIterations);

}  // namespace prisca::sim
