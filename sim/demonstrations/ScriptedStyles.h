#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace prisca::sim {

/// One way of demonstrating a plant's manoeuvre, as different operators do it.
struct DemonstrationStyle {
    QString name;         ///< command-line name, e.g. "stick-180-left"
    QString description;  ///< one line for the operator
};

/// The plant a demonstration is recorded on, beyond its operator's script. Plain data.
struct RecordingConditions {
    /// The plant's physical parameters (a plant file); null: the catalog's plant.
    const PlantParameters* parameters = nullptr;
    /// What the plant meets while recorded: none (the nominal plant) or a session day's
    /// mismatch (Perturbation::dayOf), so the demonstration is the day's car's.
    Perturbation perturbation;
};

/// One plant's styles: their list and how one is recorded (PlantCatalog holds one per plant).
struct StyleSet {
    std::vector<DemonstrationStyle> (*list)() = nullptr;
    core::Demonstration (*record)(const QString& style, std::uint64_t seed,
                                  const SimulationTiming& timing,
                                  const RecordingConditions& conditions) = nullptr;
};

/// A style of the set recorded, the style named in the demonstration's metadata ("style"): what
/// every caller records through (DemonstrationStyles by name, the catalog's classic one).
inline core::Demonstration recordInStyle(const StyleSet& styles, const QString& style,
                                         std::uint64_t seed, const SimulationTiming& timing,
                                         const RecordingConditions& conditions) {
    core::Demonstration demonstration = styles.record(style, seed, timing, conditions);
    demonstration.metadata.insert(QStringLiteral("style"), style);
    return demonstration;
}

/// The slide-car's, the acrobot's and the aircraft's styles (their scripted operators).
StyleSet slideCarStyles();
StyleSet acrobotStyles();
StyleSet aircraftStyles();

}  // namespace prisca::sim
