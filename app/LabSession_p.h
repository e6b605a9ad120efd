#pragma once

// LabSession's private part, shared by its sources (LabSession.cpp: the task, the model, the
// method; LabSessionFile.cpp: the session file).

#include "core/Demonstration.h"
#include "sim/DemonstrationStyles.h"
#include "sim/plants/PlantParameters.h"

#include <QString>

#include <cstdint>
#include <memory>

namespace prisca::app::session {

// The scripted operator's demonstration, recorded on the session's car.
inline std::shared_ptr<const core::Demonstration> scripted(const QString& plant,
                                                           const QString& style, std::uint64_t seed,
                                                           const sim::PlantParameters* parameters) {
    sim::RecordingConditions conditions;
    conditions.parameters = parameters;
    return std::make_shared<core::Demonstration>(
        sim::DemonstrationStyles::record(plant, style, seed, {}, conditions));
}

}  // namespace prisca::app::session
