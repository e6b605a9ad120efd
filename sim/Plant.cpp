#include "Plant.h"

#include <cmath>

namespace prisca::sim {

core::DeviationModel PlantInfo::deviationModel() const {
    core::DeviationModel model;
    model.dimension = stateDimension();
    model.angleIndices = angleIndices;
    model.pose = pose;
    model.bodyVelocity = bodyVelocity;
    return model;
}

double PlantInfo::stateBound(int component) const {
    const QString unit = stateUnits.value(component);
    return unit.endsWith(QLatin1String("/s")) ? 1e3 : 1e4;
}

QString PlantInfo::stateProblem(const Eigen::VectorXd& state) const {
    if (state.size() != stateDimension()) {
        return QStringLiteral("the %1 state needs %2 values (%3), got %4")
            .arg(name)
            .arg(stateDimension())
            .arg(stateNames.join(QStringLiteral(", ")))
            .arg(state.size());
    }
    for (int i = 0; i < state.size(); ++i) {
        const double bound = stateBound(i);
        if (!std::isfinite(state[i])) {
            return QStringLiteral("%1 = %2 is not a finite number").arg(stateNames[i]).arg(state[i]);
        }
        if (std::abs(state[i]) > bound) {
            return QStringLiteral("%1 = %2 %3 is outside [%4, %5] %3")
                .arg(stateNames[i])
                .arg(state[i])
                .arg(stateUnits.value(i))
                .arg(-bound)
                .arg(bound);
        }
    }
    return QString();
}

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

}  // namespace prisca::sim
