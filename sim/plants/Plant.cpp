#include "sim/plants/Plant.h"

#include <algorithm>
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
            return QStringLiteral("%1 = %2 is not a finite number")
                .arg(stateNames[i])
                .arg(state[i]);
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

QString perturbationModelName(Perturbation::Model model) {
    return model == Perturbation::Model::Session ? QStringLiteral("session")
                                                 : QStringLiteral("trial");
}

std::optional<Perturbation::Model> perturbationModelFromName(const QString& name) {
    if (name == QLatin1String("session")) {
        return Perturbation::Model::Session;
    }
    if (name == QLatin1String("trial")) {
        return Perturbation::Model::Trial;
    }
    return std::nullopt;
}

SessionDay::SessionDay(const Perturbation& perturbation)
    : state_(mixSeed(perturbation.day, 0x5E55)),
      trialIndex_(std::max(0, perturbation.trialIndex)) {}

double SessionDay::normal() {
    // Box-Muller on two splitmix64 draws: a fixed, library-independent sequence per day.
    state_ = mixSeed(state_, 1);
    const double u1 = (static_cast<double>(state_ >> 11) + 0.5) * 0x1.0p-53;
    state_ = mixSeed(state_, 2);
    const double u2 = (static_cast<double>(state_ >> 11) + 0.5) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

double SessionDay::drift(double perTrial) const {
    return std::min(0.5, std::max(0.0, perTrial) * trialIndex_);
}

}  // namespace prisca::sim
