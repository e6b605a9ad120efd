#pragma once

#include "core/Statistics.h"

#include "core/Demonstration.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// Learning curves at an equal budget of simulated experience (paper Fig. 3b). Plain data.
struct LearningCurveSettings {
    QStringList methods = {"prisca", "pgsd", "pegasus"};  ///< curveMethods()
    /// Independent runs per method (run r: its trials' seeds from mixSeed(run.seed, r)).
    int runs = 20;
    long long budgetSteps = 64000;  ///< simulated control steps each run may consume
    RunSettings run;                ///< seed, perturbation and sensor levels, threads
    std::function<bool()> cancelled;
    std::function<void(const QString&)> progress;
};

/// The methods a learning curve can show: the learners (PRISCA, PGSD, ILC online, PEGASUS
/// offline) and, as flat lines to read them against, the fixed controllers and the oracle.
QStringList curveMethods();
bool isCurveMethod(const QString& method);

/// One run's curve: tracking error after each unit of experience.
struct CurvePoint {
    long long steps = 0;  ///< cumulative simulated steps consumed so far
    double trackingError =
        0.0;  ///< mean over a trial of the squared tracked error (rad^2 for the acrobot)
};

/// All curves of one method.
struct MethodCurves {
    QString method;
    std::vector<std::vector<CurvePoint>> runs;
};

/// Runs the experiment: PRISCA and PGSD learn online over consecutive trials (warm start), and
/// each trial's own tracking error is a point; PEGASUS iterates on fixed scenarios (mixSeed of the
/// run seed), and after each iteration its policy is scored on a fresh trial it never trained on,
/// as the online learners are (that evaluation is not charged to its budget). Independent of the
/// thread count.
std::vector<MethodCurves> runLearningCurves(const LearningCurveSettings& settings,
                                            const Task& task);

/// Learning curves on many demonstrations: every method on every cell, a cell being one
/// demonstration style recorded with one seed set's hand variation and run with that seed.
struct LearningCurveProtocolSettings {
    LearningCurveSettings curves;  ///< its run seed is replaced by each seed set's
    QStringList styles;            ///< demonstration styles of the profile's plant
    std::vector<std::uint64_t> seedSets;
    core::ActionMappingFitOptions fit;  ///< how B_v is fitted on each demonstration
    /// The plant's physical parameters (a plant file); null: the catalog's plant.
    std::shared_ptr<const PlantParameters> plantParameters;
};

/// What the protocol produced: every cell's runs pooled per method, and per style.
struct LearningCurveProtocolResult {
    std::vector<MethodCurves> pooled;                 ///< per method, every cell's runs
    std::vector<std::vector<MethodCurves>> perStyle;  ///< per style (settings order)
    long long shortestDemonstration = 0;  ///< [samples]: the grid unit of summarizeCurves
    double dt = 0.0;                      ///< the first cell's control period [s]
    int cells = 0;                        ///< cells that ran
    bool cancelled = false;
};

/// Runs the curves on every (style, seed set) cell in turn, each cell's Task made from the
/// profile and that cell's demonstration (makeTask). Throws std::invalid_argument for an unknown
/// style or method, or no cell.
LearningCurveProtocolResult runLearningCurveProtocol(
    const LearningCurveProtocolSettings& settings, const MethodTuning& profile,
    const std::function<void(int cell, int cells, const QString& style, std::uint64_t seed)>&
        cellStarted = {});

/// Resamples a run onto a common grid of step counts: at each grid point, the error of the most
/// recent point at or before it (NaN before the first).
std::vector<double> resampleCurve(const std::vector<CurvePoint>& run,
                                  const std::vector<long long>& grid);

/// One method's curve on a common grid: mean and 95% band over its runs (Fig. 3b).
struct CurveSummary {
    QString method;
    std::vector<long long> steps;  ///< grid of simulated steps
    std::vector<double> seconds;   ///< the same in simulated seconds
    core::ConfidenceBand band;     ///< mean, lower, upper and count per grid point
};

/// Resamples every run on a grid of one point per `unit` steps up to `budgetSteps` and
/// summarises each method over its runs.
std::vector<CurveSummary> summarizeCurves(const std::vector<MethodCurves>& curves, long long unit,
                                          long long budgetSteps, double dt);

}  // namespace prisca::sim
