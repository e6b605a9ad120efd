#pragma once

#include "MethodTuning.h"
#include "Table1Experiment.h"
#include "core/ActionMapping.h"
#include "core/ProtocolReport.h"

#include <QStringList>

#include <cstdint>
#include <vector>

namespace prisca::sim {

/// Table I on many demonstrations (docs/architecture.md "Evaluation"): every method on every cell, a cell
/// being one demonstration style recorded with one seed set's hand variation and run on that
/// seed set's trials. Plain data.
struct Table1ProtocolSettings {
    /// Methods, trials, training trials, perturbation, sensor, threads, cancellation and
    /// progress; its run seed is replaced by each seed set's.
    Table1Settings table;
    QStringList styles;                   ///< demonstration styles of the profile's plant
    std::vector<std::uint64_t> seedSets;  ///< each: the demonstration's hand and the trials' seed
    core::ActionMappingFitOptions fit;    ///< how B_v is fitted on each demonstration
};

/// What the protocol produced.
struct Table1ProtocolResult {
    core::ProtocolSummary summary;  ///< per method over the cells, and per style
    std::vector<std::vector<core::ProtocolCell>> cells;  ///< per method, per finished cell
    bool cancelled = false;
    int finishedTrials = 0;  ///< over all methods and cells
};

/// The seed sets first, first + 1, ..., first + count - 1.
std::vector<std::uint64_t> consecutiveSeedSets(std::uint64_t first, int count);

/// Runs Table I on every (style, seed set) cell in turn (each cell's trials in parallel), each
/// cell's Task made from the profile and that cell's demonstration (makeTask: checked, fitted). Deterministic for the
/// settings whatever the thread count. Throws std::invalid_argument for an unknown style or
/// method (as runTable1 does).
Table1ProtocolResult runTable1Protocol(const Table1ProtocolSettings& settings,
                                       const MethodTuning& profile);

}  // namespace prisca::sim
