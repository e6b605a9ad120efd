#pragma once

#include "core/Controller.h"
#include "core/PdController.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/plants/Plant.h"
#include "sim/run/Task.h"

#include <Eigen/Core>

#include <QString>

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// What an offline training runs on: the run's task, its training trials and a fresh plant for
/// each job. RunSetup is one (training is part of making a run's controller); any thread may use
/// a const one.
class TrainingTrials {
  public:
    virtual ~TrainingTrials() = default;
    virtual const Task& task() const = 0;
    /// The training trials' seeds; trainingTrial(i) is the trial of the i-th.
    virtual std::vector<std::uint64_t> trainingSeeds() const = 0;
    virtual EpisodeSettings trainingTrial(int trial) const = 0;
    virtual std::unique_ptr<Plant> makePlant() const = 0;
    /// Worker threads a training may use.
    virtual int threads() const = 0;
};

/// What a training polls and reports.
struct TrainingHooks {
    std::function<bool()> cancelled;               ///< polled between and within episodes
    std::function<void(const QString&)> progress;  ///< one line per stage (any thread)
};

/// PD (selected): a grid search over common scales of the profile's Kp and Kd (each scale
/// multiplies every channel's gain), scored by the mean plus the standard deviation of
/// tuningScore() over the setup's training trials. Returns the profile's PD parameters with the
/// best gains.
core::PdParameters selectPdGains(const TrainingTrials& setup, const TrainingHooks& hooks = {},
                                 const std::vector<double>& kpScales = {0.25, 0.5, 1, 2, 4},
                                 const std::vector<double>& kdScales = {0, 0.5, 1, 2});

/// What PEGASUS learned and what it cost.
struct PegasusTraining {
    Eigen::MatrixXd theta;         ///< final policy parameters (p x m)
    std::vector<double> costs;     ///< J(theta) at each iteration (mean episode cost)
    std::vector<long long> steps;  ///< cumulative simulated steps after each iteration
};

/// PEGASUS on fixed scenarios (the first profile.pegasus.scenarios training trials: each fixes
/// the start, the perturbation and every noise stream) with the frozen linear policy of the
/// "pegasus" method, `iterations` gradient steps.
PegasusTraining trainPegasus(const TrainingTrials& setup, int iterations,
                             const TrainingHooks& hooks = {});

/// The training seeds of a run or experiment with seed `seed`: their own stream, never its
/// evaluation seeds (mixSeed(seed, i)).
std::vector<std::uint64_t> trainingSeeds(std::uint64_t seed, int count);

}  // namespace prisca::sim
