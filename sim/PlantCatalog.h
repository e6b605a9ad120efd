#pragma once

#include "Plant.h"
#include "core/Demonstration.h"

#include <QStringList>

#include <cstdint>
#include <memory>

namespace prisca::sim {

/// The simulated plants by name, with their scripted demonstrators: the one place that knows
/// which plants exist, for the app, the CLI and the experiments.
class PlantCatalog {
  public:
    /// "slidecar", "acrobot", "aircraft".
    static QStringList names();
    static bool contains(const QString& name) { return names().contains(name); }
    /// A new plant with default physical parameters; throws std::invalid_argument for an
    /// unknown name (the message lists the known ones).
    static std::unique_ptr<Plant> create(const QString& name, const SimulationTiming& timing = {});
    /// The plant's description without building it.
    static PlantInfo describe(const QString& name);
    /// The scripted, human-like demonstration of the plant for this seed, in its classic style
    /// (DemonstrationStyles has the others).
    static core::Demonstration demonstrate(const QString& name, std::uint64_t seed,
                                           const SimulationTiming& timing = {});
};

}  // namespace prisca::sim
