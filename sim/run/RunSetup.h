#pragma once

#include "core/Controller.h"
#include "core/RunLogCsv.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/plants/Plant.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/Task.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// The settings of a run that are not a method's parameters, with the one set of defaults the
/// window, the command line, the experiments, the tuning tools and the rig share. Plain data.
struct RunSettings {
    /// Evaluation trial i uses mixSeed(seed, i); training trials have their own stream
    /// (trainingSeeds), never an evaluation seed.
    std::uint64_t seed = 1;
    double perturbation = 1.0;  ///< plant perturbation level (0 nominal, 1 realistic)
    double sensor = 1.0;        ///< sensor level (0 perfect state, 1 realistic)
    /// How the plant's parameter variation spreads over the run's trials: a lab session (the
    /// day's mismatch persists and drifts; the day is the seed) or each trial its own.
    Perturbation::Model perturbationModel = Perturbation::Model::Session;
    /// Pass the sensor's observations through the pose filter (EpisodeSettings::poseFilter;
    /// planar vehicles only). Off by default.
    bool poseFilter = false;
    /// With it: the controller sees the estimate of now (true) or of the measurement's time,
    /// compensating the latency itself (false); EpisodeSettings::poseFilterPredicts.
    bool poseFilterPredicts = true;
    /// Trials a method trains on before it is evaluated: PD (selected) scores its gain grid on
    /// them; in Table I the online learners warm up on them. PEGASUS takes its fixed scenarios
    /// from the first PegasusParameters::scenarios of them.
    int trainingTrials = 16;
    int threads = 2;  ///< worker threads for training and parallel trials
};

/// The conditions a run's scripted demonstration is recorded in: on the plant of `parameters`
/// (null: the catalog's) and, under the session model, with the day's mismatch (the day being
/// `day`, at the run's parameter level); under the trial model, the nominal plant.
RecordingConditions demonstrationConditions(const RunSettings& settings,
                                            const MethodTuning& profile,
                                            const PlantParameters* parameters, std::uint64_t day);

/// One run set up from a Task, a method and the run's settings: the plant at the task's own
/// control period (the demonstration's dt), the trials' episode settings, the method's
/// controller (trained first where it trains offline) and the run log's header. Every front end
/// and experiment builds its runs here, so none can disagree about the control period, the
/// trials' seeds or the defaults. Immutable once made; any thread may use a const RunSetup.
class RunSetup : public TrainingTrials {
  public:
    /// Throws std::invalid_argument naming the known methods for an unknown one, or for
    /// settings out of range (negative training trials, no thread, a negative level).
    RunSetup(Task task, const QString& method, const RunSettings& settings = {});

    const Task& task() const override { return task_; }
    const MethodTuning& profile() const { return task_.profile; }
    const MethodSpec& method() const { return *method_; }
    const RunSettings& settings() const { return settings_; }
    int threads() const override { return settings_.threads; }

    /// A new plant of the task's kind at the task's control period, with the task's physical
    /// parameters.
    std::unique_ptr<Plant> makePlant() const override;
    /// Every trial's settings but its seed and reset: perturbation and sensor at the run's
    /// levels, the demonstration's length plus the settle time, latency compensation.
    const EpisodeSettings& episode() const { return episode_; }
    /// Evaluation trial `trial` (0-based) of the run: seed mixSeed(seed, trial), a cold start
    /// for the first and warm starts after (setTrial). `trialsBefore`: how many trials of the
    /// day came before the first evaluation trial (the session's drift counts them).
    EpisodeSettings trial(int trial, int trialsBefore = 0) const;
    /// Training trial `trial` (0-based): its seed from trainingSeeds(), the day's trial `trial`,
    /// a cold start for the first and warm starts after.
    EpisodeSettings trainingTrial(int trial) const override;
    /// The training trials' seeds (settings.trainingTrials of them, their own stream).
    std::vector<std::uint64_t> trainingSeeds() const override;
    /// A learning curve's PEGASUS run with seed `runSeed`: its fixed scenario `scenario` (seed
    /// mixSeed(runSeed, 1000 + scenario), the day's trial `scenario`) and its evaluation after
    /// iteration `index` (seed mixSeed(runSeed, 5000 + index), the day's trial `index`), each
    /// the run's own stream; the controller is reset as episode() says.
    EpisodeSettings curveScenario(std::uint64_t runSeed, int scenario) const;
    EpisodeSettings curveEvaluation(std::uint64_t runSeed, int index) const;

    /// The method's controller, trained first on the training trials if it trains offline
    /// (PD (selected) selects its gains, PEGASUS searches its policy). Null if `cancelled`
    /// stopped the training. `progress` gets a line per training stage (any thread).
    std::unique_ptr<core::Controller> makeController(
        const std::function<bool()>& cancelled = {},
        const std::function<void(const QString&)>& progress = {}) const;
    /// The method's controller as the profile sets it up, with no training (what runs where
    /// there is no simulation to train in: the rig).
    std::unique_ptr<core::Controller> makeUntrainedController() const;

    /// The run log's header for `trials` trials of `controller` (columns, plant, method, the
    /// control period, seed, levels and where the demonstration came from).
    core::RunLog startRunLog(const core::Controller& controller, int trials,
                             const QString& demonstrationSource) const;

  private:
    Task task_;
    const MethodSpec* method_;
    RunSettings settings_;
    EpisodeSettings episode_;
};

}  // namespace prisca::sim
