#pragma once

#include "core/ActionMapping.h"
#include "core/ProtocolReport.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/tuning/MethodTuning.h"

#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace prisca::sim {

/// Table I on many demonstrations (docs/architecture.md "Evaluation"): every method on every cell,
/// a cell being one demonstration style recorded with one seed set's hand variation and run on that
/// seed set's trials. Plain data.
struct Table1ProtocolSettings {
    /// Methods, trials, training trials, perturbation, sensor, threads, cancellation and
    /// progress; its run seed is replaced by each seed set's.
    Table1Settings table;
    QStringList styles;                   ///< demonstration styles of the profile's plant
    std::vector<std::uint64_t> seedSets;  ///< each: the demonstration's hand and the trials' seed
    core::ActionMappingFitOptions fit;    ///< how B_v is fitted on each demonstration
    /// The plant's physical parameters (a plant file); null: the catalog's plant. Its
    /// demonstrations are recorded on it, and its trials run on it.
    std::shared_ptr<const PlantParameters> plantParameters;
    /// The new-car protocol: these plants (plant files) in turn, each on every style and seed
    /// set, instead of plantParameters; the breakdown is then per variant (its file's base
    /// name), over its styles and seed sets.
    std::vector<std::shared_ptr<const PlantParameters>> variants;
};

/// One method's trials by their place in the day: its training trials (online learners only)
/// then its evaluation trials, each index with one value per finished cell.
struct TrialCurve {
    QString method;
    int trainingTrials = 0;                        ///< how many of the indices are training trials
    std::vector<std::vector<double>> position;     ///< per trial index, per cell [cm]
    std::vector<std::vector<double>> orientation;  ///< per trial index, per cell [deg]
};

/// What the protocol produced.
struct Table1ProtocolResult {
    core::ProtocolSummary summary;  ///< per method over the cells, and per style
    std::vector<std::vector<core::ProtocolCell>> cells;  ///< per method, per finished cell
    bool cancelled = false;
    int finishedTrials = 0;          ///< over all methods and cells
    std::vector<TrialCurve> curves;  ///< per method, its trials by index over the cells
};

/// A variant's name: its plant file's base name ("heavy" for variants/heavy.json), or
/// "catalog" for the catalog's plant.
QString variantName(const PlantParameters* parameters);

/// The seed sets first, first + 1, ..., first + count - 1.
std::vector<std::uint64_t> consecutiveSeedSets(std::uint64_t first, int count);

/// Runs Table I on every (style, seed set) cell in turn (each cell's trials in parallel), each
/// cell's Task made from the profile and that cell's demonstration (makeTask: checked, fitted).
/// Deterministic for the settings whatever the thread count. Throws std::invalid_argument for an
/// unknown style or method (as runTable1 does).
Table1ProtocolResult runTable1Protocol(const Table1ProtocolSettings& settings,
                                       const MethodTuning& profile);

}  // namespace prisca::sim
