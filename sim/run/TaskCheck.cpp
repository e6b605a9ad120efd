#include "sim/run/TaskCheck.h"

#include <stdexcept>

namespace prisca::sim {

void checkDemonstrationFor(const core::Demonstration& demonstration, const PlantInfo& plant) {
    if (!demonstration.plant.isEmpty() && demonstration.plant != plant.name) {
        throw std::invalid_argument(QStringLiteral("it was recorded on '%1', not '%2'")
                                        .arg(demonstration.plant, plant.name)
                                        .toStdString());
    }
    if (demonstration.stateNames != plant.stateNames ||
        demonstration.actionNames != plant.actionNames) {
        throw std::invalid_argument(
            QStringLiteral("it has states (%1) and actions (%2); the %3 has (%4) and (%5)")
                .arg(demonstration.stateNames.join(QStringLiteral(", ")),
                     demonstration.actionNames.join(QStringLiteral(", ")), plant.name,
                     plant.stateNames.join(QStringLiteral(", ")),
                     plant.actionNames.join(QStringLiteral(", ")))
                .toStdString());
    }
    if (demonstration.length() < kMinimumDemonstrationSamples) {
        throw std::invalid_argument(QStringLiteral("it has %1 samples; at least %2 are needed")
                                        .arg(demonstration.length())
                                        .arg(kMinimumDemonstrationSamples)
                                        .toStdString());
    }
}

}  // namespace prisca::sim
