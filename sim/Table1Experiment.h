#pragma once

#include "core/Table1Report.h"

#include "EpisodeRunner.h"
#include "MethodCatalog.h"
#include "PlantProfile.h"
#include "TrialMetrics.h"
#include "core/Demonstration.h"

#include <Eigen/Core>

#include <functional>
#include <memory>
#include <vector>

namespace prisca::sim {

/// How Table I is produced (paper Table I, DESIGN.md "Metrics"). Plain data.
struct Table1Settings {
    QString plant = QStringLiteral("slidecar");  ///< a planar vehicle
    /// Methods, as MethodCatalog names them, in table order (default: every Table I method).
    QStringList methods = MethodCatalog::table1Ids();
    int trials = 20;         ///< evaluation trials per method
    std::uint64_t seed = 1;  ///< evaluation trial i uses mixSeed(seed, i)
    /// Training trials (their own seeds, never evaluation ones): PD (selected) scores its gain
    /// grid on them; PRISCA and PGSD learn on them in a row before evaluation (each evaluation
    /// trial then starts from what they learned and keeps learning online).
    int trainingTrials = 16;
    double perturbation = 1.0;  ///< plant perturbation level
    double sensor = 1.0;        ///< sensor noise level (0: perfect state)
    int threads = 2;            ///< worker threads
    bool keepPaths = false;     ///< keep every trial's path (x, y, heading per step) for plots
    std::function<bool()> cancelled;               ///< polled between and within trials
    std::function<void(const QString&)> progress;  ///< progress lines (any thread)
};

/// One method's evaluation trials.
struct MethodTrials {
    QString method;
    std::vector<TrialSummary> trials;  ///< one per evaluation trial (completed ones only valid)
    std::vector<bool> completed;       ///< false where cancelled before it finished
    std::vector<std::vector<Eigen::Vector3d>> paths;  ///< (x, y, heading) per step, if kept
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
/// thread count. Throws std::invalid_argument for an unknown method or a plant without pose.
Table1Result runTable1(const Table1Settings& settings,
                       std::shared_ptr<const core::Demonstration> demonstration,
                       const PlantProfile& profile, const Eigen::MatrixXd& fittedB);

/// Table I's rows from a result: per method, the position [cm] and orientation [deg] error
/// summaries over the trials that finished. *finished (if given) receives their number.
std::vector<core::Table1Row> table1Rows(const Table1Result& result, int* finished = nullptr);

}  // namespace prisca::sim
