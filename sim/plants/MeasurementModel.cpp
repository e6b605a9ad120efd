#include "sim/plants/MeasurementModel.h"

#include <stdexcept>

namespace prisca::sim {

MeasurementModel::MeasurementModel(MeasurementParameters parameters, std::uint64_t seed)
    : parameters_(std::move(parameters)), random_(seed) {
    if (parameters_.loopLatencySteps < 0 || parameters_.dropProbability < 0.0 ||
        parameters_.dropProbability >= 1.0 ||
        (parameters_.noise.size() && (parameters_.noise.array() < 0).any())) {
        throw std::invalid_argument(
            "MeasurementModel: latency >= 0, 0 <= drop probability < 1 and noise >= 0 needed");
    }
}

void MeasurementModel::reset(const Eigen::VectorXd& initialState) {
    delayLine_.assign(parameters_.loopLatencySteps, initialState);
    lastObservation_ = initialState;
    lastDropped_ = false;
}

Eigen::VectorXd MeasurementModel::observe(const Eigen::VectorXd& trueState) {
    if (lastObservation_.size() == 0) {
        reset(trueState);
    }
    delayLine_.push_back(trueState);
    Eigen::VectorXd delayed = delayLine_.front();
    delayLine_.pop_front();
    // Every random number is drawn every step, dropped or not, so one trial's stream does not
    // depend on how many samples happened to drop.
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const bool drop = uniform(random_) < parameters_.dropProbability;
    if (parameters_.noise.size() == delayed.size()) {
        std::normal_distribution<double> normal(0.0, 1.0);
        for (Eigen::Index i = 0; i < delayed.size(); ++i) {
            delayed[i] += parameters_.noise[i] * normal(random_);
        }
    }
    lastDropped_ = drop;
    if (!drop) {
        lastObservation_ = delayed;
    }
    return lastObservation_;
}

}  // namespace prisca::sim
