#pragma once

#include "core/Controller.h"
#include "core/RunLogCsv.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/plants/Plant.h"

namespace prisca::sim {

/// The run log's columns for a plant and a controller, the same whoever writes it (the CLI's
/// `run --out`, the window's "Export run log"): trial, t, the true state, the observation,
/// ref_index, the error e_* (a vehicle's lon / lat / heading in the desired pose's frame), u_*,
/// ustar_*, cost, and theta_<i>_<control> for a controller that learns.
core::RunLog startRunLog(const PlantInfo& info, const QString& method, double dt,
                         const core::Controller& controller);

/// Appends a finished trial's steps (recorded with EpisodeSettings::recordSteps).
void appendRunLogTrial(core::RunLog& log, int trial, const EpisodeResult& result, double dt);

}  // namespace prisca::sim
