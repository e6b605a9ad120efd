#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <deque>
#include <random>

namespace prisca::sim {

/// What the controller sees of the true state: a camera-like sensor with Gaussian noise, a fixed
/// latency and occasional dropped samples (the last good sample is held). Seeded; no wall clock.
struct MeasurementParameters {
    Eigen::VectorXd noise;         ///< std of additive noise per state component (empty: none)
    int loopLatencySteps = 0;      ///< delay of the observation [control steps]
    double dropProbability = 0.0;  ///< chance a sample is lost and the previous one repeats
};

/// Applies MeasurementParameters step by step. One instance per trial.
class MeasurementModel {
  public:
    MeasurementModel(MeasurementParameters parameters, std::uint64_t seed);

    /// Starts a trial: the delay line is filled with the initial true state.
    void reset(const Eigen::VectorXd& initialState);
    /// The observation for this control step, given the current true state.
    Eigen::VectorXd observe(const Eigen::VectorXd& trueState);
    /// Whether the last observe() repeated an old sample because of a drop.
    bool lastDropped() const { return lastDropped_; }
    const MeasurementParameters& parameters() const { return parameters_; }

  private:
    MeasurementParameters parameters_;
    std::mt19937_64 random_;
    std::deque<Eigen::VectorXd> delayLine_;
    Eigen::VectorXd lastObservation_;
    bool lastDropped_ = false;
};

}  // namespace prisca::sim
