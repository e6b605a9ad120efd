#pragma once

#include "sim/tuning/MethodTuning.h"

namespace prisca::sim {

/// The differential-drive robot's profile: its sign model, sensor and every method's settings.
MethodTuning diffDriveTuning(const PlantInfo& info);

}  // namespace prisca::sim
