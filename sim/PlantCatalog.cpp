#include "PlantCatalog.h"

#include "Acrobot.h"
#include "DemonstrationStyles.h"
#include "PlanarAircraft.h"
#include "SlideCar.h"

#include <stdexcept>

namespace prisca::sim {

namespace {

[[noreturn]] void unknown(const QString& name) {
    throw std::invalid_argument(QStringLiteral("unknown plant '%1' (one of: %2)")
                                    .arg(name, PlantCatalog::names().join(QLatin1Char(' ')))
                                    .toStdString());
}

}  // namespace

QStringList PlantCatalog::names() {
    return {QStringLiteral("slidecar"), QStringLiteral("acrobot"), QStringLiteral("aircraft")};
}

std::unique_ptr<Plant> PlantCatalog::create(const QString& name, const SimulationTiming& timing) {
    if (name == QLatin1String("slidecar")) {
        return std::make_unique<SlideCar>(SlideCarParameters{}, timing);
    }
    if (name == QLatin1String("acrobot")) {
        return std::make_unique<Acrobot>(AcrobotParameters{}, timing);
    }
    if (name == QLatin1String("aircraft")) {
        return std::make_unique<PlanarAircraft>(PlanarAircraftParameters{}, timing);
    }
    unknown(name);
}

PlantInfo PlantCatalog::describe(const QString& name) {
    if (name == QLatin1String("slidecar")) {
        return SlideCar::describe();
    }
    if (name == QLatin1String("acrobot")) {
        return Acrobot::describe();
    }
    if (name == QLatin1String("aircraft")) {
        return PlanarAircraft::describe();
    }
    unknown(name);
}

core::Demonstration PlantCatalog::demonstrate(const QString& name, std::uint64_t seed,
                                              const SimulationTiming& timing) {
    if (!contains(name)) {
        unknown(name);
    }
    return DemonstrationStyles::record(name, DemonstrationStyles::classic(name), seed, timing);
}

}  // namespace prisca::sim
