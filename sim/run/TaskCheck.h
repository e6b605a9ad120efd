#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"

namespace prisca::sim {

/// The fewest samples a demonstration may have to be fitted and repeated.
constexpr int kMinimumDemonstrationSamples = 4;

/// Checks that a demonstration belongs to a plant before anything uses it, for the window and
/// the CLI alike: its plant tag (if any) names this plant, its state and action columns are the
/// plant's by name and number, and it has at least kMinimumDemonstrationSamples samples. Throws
/// std::invalid_argument saying which of these fails and what was expected.
void checkDemonstrationFor(const core::Demonstration& demonstration, const PlantInfo& plant);

}  // namespace prisca::sim
