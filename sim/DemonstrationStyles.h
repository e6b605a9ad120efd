#pragma once

#include "Plant.h"
#include "PlantParameters.h"
#include "core/Demonstration.h"

#include <QString>
#include <QStringList>

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

/// The slide-car's, the acrobot's and the aircraft's styles (their scripted operators).
StyleSet slideCarStyles();
StyleSet acrobotStyles();
StyleSet aircraftStyles();

/// The family of scripted demonstrations per plant: operators differ (keyboard or stick, left or
/// right, how far and how fast), and a method is only as good as it is on demonstrations it was
/// not tuned on. Each style is a scripted operator whose hand varies with the seed. The first
/// style of a plant is its classic demonstration (PlantCatalog::demonstrate).
class DemonstrationStyles {
  public:
    /// The styles of a plant in a fixed order (empty for an unknown plant).
    static std::vector<DemonstrationStyle> of(const QString& plant);
    /// Their names.
    static QStringList names(const QString& plant);
    static bool contains(const QString& plant, const QString& style) {
        return names(plant).contains(style);
    }
    /// The first, classic style of a plant.
    static QString classic(const QString& plant);
    /// Empty when every style is one of the plant's; else "unknown <plant> style 'x' (one of:
    /// ...)" for the first that is not.
    static QString unknownStyleIn(const QString& plant, const QStringList& styles);
    /// Records the demonstration of this style with this seed's hand variation. Throws
    /// std::invalid_argument naming the known styles for an unknown plant or style.
    static core::Demonstration record(const QString& plant, const QString& style,
                                      std::uint64_t seed, const SimulationTiming& timing = {},
                                      const RecordingConditions& conditions = {});
};

}  // namespace prisca::sim
