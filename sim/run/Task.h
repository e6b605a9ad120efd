#pragma once

#include "core/ActionMapping.h"
#include "core/Demonstration.h"
#include "sim/plants/PlantParameters.h"
#include "sim/tuning/MethodTuning.h"

#include <memory>

namespace prisca::sim {

/// A demonstration checked against its plant, with the plant's profile and the fitted B: what
/// every run, experiment and the window's session start from.
struct Task {
    QString plant;            ///< plant name
    MethodTuning profile;     ///< profile (mapping possibly the operator's own)
    SimulationTiming timing;  ///< control period = the demonstration's dt
    std::shared_ptr<const core::Demonstration> demonstration;  ///< S*, U*
    core::ActionMappingFit fit;                                ///< B_v, B and diagnostics
    /// The plant's physical parameters where they are not the catalog's (a plant file); null:
    /// the catalog's plant.
    std::shared_ptr<const PlantParameters> plantParameters;
};

/// The one way a task is made, for the window and the CLI alike: the demonstration is checked
/// against the profile's plant (checkDemonstrationFor) and fitted with the profile's B~ and
/// `options`. Throws std::invalid_argument saying what does not fit; nothing is half-made.
Task makeTask(const MethodTuning& profile, std::shared_ptr<const core::Demonstration> demonstration,
              const core::ActionMappingFitOptions& options = {},
              std::shared_ptr<const PlantParameters> plantParameters = nullptr);

}  // namespace prisca::sim
