#include "sim/PlantCatalog.h"

#include "sim/demonstrations/DiffDriveDemonstrator.h"
#include "sim/plants/Acrobot.h"
#include "sim/plants/DiffDrive.h"
#include "sim/plants/PlanarAircraft.h"
#include "sim/plants/SlideCar.h"
#include "sim/tuning/DiffDriveTuning.h"
#include "sim/tuning/MethodTuning.h"

#include <QtGlobal>

#include <algorithm>
#include <stdexcept>

namespace prisca::sim {

namespace {

template <class P, class Parameters>
std::unique_ptr<Plant> make(const SimulationTiming& timing) {
    return std::make_unique<P>(Parameters{}, timing);
}

std::vector<PlantEntry> makePlantCatalog() {
    std::vector<PlantEntry> all;
    PlantEntry e;
    e.name = QStringLiteral("slidecar");
    e.displayName = QT_TRANSLATE_NOOP("PlantCatalog", "Simulated slide-car");
    e.drawing = PlantEntry::Drawing::Car;
    e.create = &make<SlideCar, SlideCarParameters>;
    e.describe = &SlideCar::describe;
    e.profile = &slideCarTuning;
    e.styles = slideCarStyles();
    all.push_back(e);

    e = PlantEntry{};
    e.name = QStringLiteral("acrobot");
    e.displayName = QT_TRANSLATE_NOOP("PlantCatalog", "Simulated acrobot");
    e.drawing = PlantEntry::Drawing::Arm;
    e.create = &make<Acrobot, AcrobotParameters>;
    e.describe = [] { return Acrobot::describe(); };
    e.profile = &acrobotTuning;
    e.styles = acrobotStyles();
    all.push_back(e);

    e = PlantEntry{};
    e.name = QStringLiteral("aircraft");
    e.displayName = QT_TRANSLATE_NOOP("PlantCatalog", "Simulated aircraft");
    e.drawing = PlantEntry::Drawing::Aircraft;
    e.create = &make<PlanarAircraft, PlanarAircraftParameters>;
    e.describe = &PlanarAircraft::describe;
    e.profile = &aircraftTuning;
    e.styles = aircraftStyles();
    all.push_back(e);

    e = PlantEntry{};
    e.name = QStringLiteral("diffdrive");
    e.displayName = QT_TRANSLATE_NOOP("PlantCatalog", "Simulated differential-drive robot");
    e.drawing = PlantEntry::Drawing::Vehicle;
    e.create = &make<DiffDrive, DiffDriveParameters>;
    e.describe = &DiffDrive::describe;
    e.profile = &diffDriveTuning;
    e.styles = diffDriveStyles();
    e.fromStick = [](const Eigen::VectorXd& stick) {  // the robot mixes a stick into its wheels
        Eigen::VectorXd wheels(2);
        wheels << std::clamp(stick[0] - stick[1], -1.0, 1.0),
            std::clamp(stick[0] + stick[1], -1.0, 1.0);
        return wheels;
    };
    all.push_back(e);
    return all;
}

}  // namespace

const std::vector<PlantEntry>& PlantCatalog::all() {
    static const std::vector<PlantEntry> catalog = makePlantCatalog();
    return catalog;
}

const PlantEntry* PlantCatalog::find(const QString& name) {
    for (const PlantEntry& e : all()) {
        if (e.name == name) {
            return &e;
        }
    }
    return nullptr;
}

const PlantEntry& PlantCatalog::get(const QString& name) {
    if (const PlantEntry* e = find(name)) {
        return *e;
    }
    throw std::invalid_argument(QStringLiteral("unknown plant '%1' (one of: %2)")
                                    .arg(name, names().join(QLatin1Char(' ')))
                                    .toStdString());
}

QStringList PlantCatalog::names() {
    QStringList names;
    for (const PlantEntry& e : all()) {
        names << e.name;
    }
    return names;
}

std::unique_ptr<Plant> PlantCatalog::create(const QString& name, const SimulationTiming& timing) {
    return get(name).create(timing);
}

std::unique_ptr<Plant> PlantCatalog::create(const PlantParameters& parameters,
                                            const SimulationTiming& timing) {
    return makePlant(parameters, timing);  // an unknown plant is named with the known ones
}

MethodTuning PlantCatalog::tuning(const PlantInfo& info) {
    const PlantEntry* entry = find(info.name);
    if (!entry || !entry->profile) {
        throw std::invalid_argument(
            QStringLiteral("no profile for plant '%1'").arg(info.name).toStdString());
    }
    return entry->profile(info);
}

PlantInfo PlantCatalog::describe(const QString& name) {
    return get(name).describe();
}

core::Demonstration PlantCatalog::demonstrate(const QString& name, std::uint64_t seed,
                                              const SimulationTiming& timing) {
    const PlantEntry& entry = get(name);  // an unknown plant is named with the known ones
    return recordInStyle(entry.styles, entry.styles.list().front().name, seed, timing, {});
}

}  // namespace prisca::sim
