#pragma once

#include "core/Demonstration.h"
#include "sim/demonstrations/ScriptedStyles.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"

#include <QStringList>

#include <cstdint>
#include <memory>
#include <vector>

namespace prisca::sim {

struct MethodTuning;

/// One plant: everything the window, the CLI and the experiments need to know of it. Adding a
/// plant is one entry in PlantCatalog.cpp plus the plant's own files (its model, demonstrator,
/// styles and profile).
struct PlantEntry {
    /// How the arena draws the plant.
    enum class Drawing {
        Car,       ///< a car from above, the parking lot at the demonstration's end
        Arm,       ///< a two-link arm from the side (joint angles 0 and 1)
        Aircraft,  ///< an aircraft from above, its path
        Vehicle    ///< any other planar vehicle: an oriented marker on its path
    };
    QString name;  ///< as the command line and files spell it, e.g. "slidecar"
    const char* displayName =
        "";  ///< for the window (translated there), e.g. "Simulated slide-car"
    Drawing drawing = Drawing::Vehicle;
    std::unique_ptr<Plant> (*create)(const SimulationTiming& timing) = nullptr;
    PlantInfo (*describe)() = nullptr;
    MethodTuning (*profile)(const PlantInfo& info) = nullptr;  ///< its tuned methods' settings
    StyleSet styles;  ///< its demonstration styles; the first is its classic one
    /// How an operator's two stick axes (forward, left; each in [-1, 1]) become its actions when
    /// recording in the window; null: one axis per action, in order.
    Eigen::VectorXd (*fromStick)(const Eigen::VectorXd& stick) = nullptr;
};

/// The simulated plants: the one place that knows which plants exist, for the app, the CLI and
/// the experiments.
class PlantCatalog {
  public:
    /// Every entry, in the order every list shows them.
    static const std::vector<PlantEntry>& all();
    /// The entry of a name, or null.
    static const PlantEntry* find(const QString& name);
    /// The entry of a name; std::invalid_argument naming the known plants if there is none.
    static const PlantEntry& get(const QString& name);
    /// "slidecar", "acrobot", "aircraft", ...
    static QStringList names();
    static bool contains(const QString& name) { return find(name) != nullptr; }
    /// A new plant with default physical parameters; throws std::invalid_argument for an
    /// unknown name (the message lists the known ones).
    static std::unique_ptr<Plant> create(const QString& name, const SimulationTiming& timing = {});
    /// A new plant with these physical parameters (defaultPlantParameters: the catalog's plant;
    /// makePlant, which the layers below the catalog call).
    static std::unique_ptr<Plant> create(const PlantParameters& parameters,
                                         const SimulationTiming& timing = {});
    /// The tuned methods' settings for a plant by its info: its entry's profile with every
    /// method parameter's per-plant default (MethodCatalog); std::invalid_argument for an unknown
    /// plant.
    static MethodTuning tuning(const PlantInfo& info);
    /// The plant's description without building it.
    static PlantInfo describe(const QString& name);
    /// The scripted, human-like demonstration of the plant for this seed, in its classic style
    /// (DemonstrationStyles has the others).
    static core::Demonstration demonstrate(const QString& name, std::uint64_t seed,
                                           const SimulationTiming& timing = {});
};

}  // namespace prisca::sim
