#pragma once

#include "sim/experiments/LearningCurveExperiment.h"
#include "sim/experiments/Table1Experiment.h"

#include <QDateTime>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

namespace prisca::app {

/// What a result on the Experiments panel is about: the settings it was run with (not the spin
/// boxes' values now) and when it finished.
struct ExperimentRecord {
    bool curves = false;     ///< learning curves (else Table I)
    QString plant;           ///< the target's plant id
    bool poseTarget = true;  ///< a vehicle (positions) rather than joint angles
    int count = 0;           ///< trials (Table I) or runs (curves) per method asked for
    int seed = 0;
    long long budget = 0;   ///< learning curves: simulated steps per run
    QString demonstration;  ///< the demonstration's description
    QDateTime finished;     ///< when the result came back (local time)
};

/// The last result of the Experiments panel, kept on disk so that it is shown again after a
/// restart (AppLocalData/experiments/last.dat). One of table1 or curves is set.
struct KeptExperiment {
    ExperimentRecord record;
    std::shared_ptr<const sim::Table1Result> table1;
    std::shared_ptr<const std::vector<sim::CurveSummary>> curves;
    bool curvesCancelled = false;
};

/// Writes `kept` to `path` in one step (an older file is replaced whole or kept). Table I's
/// paths are kept for the methods the parking figure draws; the others' are left out. False
/// with *error naming the file on failure.
bool saveKeptExperiment(const QString& path, const KeptExperiment& kept, QString* error);

/// Reads what saveKeptExperiment wrote. nullopt with *error for a missing, truncated, foreign or
/// inconsistent file (a file of a newer version included).
std::optional<KeptExperiment> loadKeptExperiment(const QString& path, QString* error);

/// Where the window keeps its last experiment.
QString keptExperimentPath();

}  // namespace prisca::app
