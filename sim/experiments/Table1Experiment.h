#pragma once

#include "core/Table1Report.h"

#include "core/Demonstration.h"
#include "sim/MethodCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// How Table I is produced (paper Table I, docs/architecture.md "Metrics"). Plain data.
struct Table1Settings {
    /// Methods, as MethodCatalog names them, in table order (default: every Table I method).
    QStringList methods = MethodCatalog::defaultTable1Ids();
    int trials = 20;  ///< evaluation trials per method
    /// The seed (evaluation trial i uses mixSeed(seed, i)), the levels, the training trials
    /// (their own seeds, never evaluation ones: PD (selected) scores its gain grid on them;
    /// PRISCA, PGSD and ILC learn on them in a row before evaluation, each evaluation trial then
    /// starting from what they learned and learning on) and the worker threads.
    RunSettings run;
    bool keepPaths = false;  ///< keep every trial's path (x, y, heading per step) for plots
    std::function<bool()> cancelled;               ///< polled between and within trials
    std::function<void(const QString&)> progress;  ///< progress lines (any thread)
};

/// One method's evaluation trials.
struct MethodTrials {
    QString method;
    std::vector<TrialSummary> trials;  ///< one per evaluation trial (completed ones only valid)
    std::vector<bool> completed;       ///< false where cancelled before it finished
    std::vector<std::vector<Eigen::Vector3d>> paths;  ///< (x, y, heading) per step, if kept
    /// An online learner's training trials, in the order it learned on them (empty for the
    /// others): with the evaluation trials after them, its learning curve.
    std::vector<TrialSummary> training;
};

/// Everything Table I and Fig. 7 need.
struct Table1Result {
    std::vector<MethodTrials> methods;
    Eigen::Vector3d lot =
        Eigen::Vector3d::Zero();  ///< the demonstration's final pose (x, y, heading)
    bool cancelled = false;
};

/// Runs the experiment: training phases first, then every (method, trial) pair on the thread
/// pool. The result depends only on the settings, demonstration and profile, never on the
/// thread count. The plant steps at the task's control period (RunSetup). Throws
/// std::invalid_argument for an unknown method or a plant without pose.
Table1Result runTable1(const Table1Settings& settings, const Task& task);

/// Table I's rows from a result: per method, the position [cm] and orientation [deg] error
/// summaries over the trials that finished. *finished (if given) receives their number.
std::vector<core::Table1Row> table1Rows(const Table1Result& result, int* finished = nullptr);

}  // namespace prisca::sim
