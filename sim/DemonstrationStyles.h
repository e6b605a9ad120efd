#pragma once

#include "core/Demonstration.h"
#include "sim/demonstrations/ScriptedStyles.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <vector>

namespace prisca::sim {

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
