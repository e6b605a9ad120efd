#pragma once

#include "PlantProfile.h"

namespace prisca::sim {

/// The differential-drive robot's profile: its sign model, sensor and every method's settings.
PlantProfile diffDriveProfile(const PlantInfo& info);

}  // namespace prisca::sim
