#include "Plant.h"

namespace prisca::sim {

core::DeviationModel PlantInfo::deviationModel() const {
    core::DeviationModel model;
    model.dimension = stateDimension();
    model.angleIndices = angleIndices;
    model.pose = pose;
    model.bodyVelocity = bodyVelocity;
    return model;
}

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

}  // namespace prisca::sim
