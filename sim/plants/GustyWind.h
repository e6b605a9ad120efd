#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <random>

namespace prisca::sim {

/// The statistics of a horizontal gusty wind field. Plain data; SI units.
struct GustyWindParameters {
    double meanSpeed = 0.0;  ///< speed of the steady wind [m/s], >= 0
    /// Direction the steady wind blows TOWARDS [rad], counter-clockwise from world x (this is the
    /// air's velocity vector, not the meteorological "from" direction: 0 pushes along +x).
    double meanDirection = 0.0;
    double gustRms = 0.0;  ///< standard deviation of the gust on each world axis [m/s], >= 0
    /// Correlation time of the gusts [s], > 0: the autocorrelation falls to 1/e after this time.
    /// A Dryden turbulence scale L seen at airspeed V gives about L / V (30 m at 15 m/s: 2 s).
    double gustTimeConstant = 2.0;
};

/// A seeded gusty wind in the horizontal plane: a steady wind plus gusts, each world axis an
/// independent first-order Gauss-Markov process (low-pass filtered white noise, the one-pole
/// "Dryden-like" model) with stationary standard deviation gustRms and correlation time
/// gustTimeConstant. The process is advanced with its exact discretisation,
///     g(t + dt) = a g(t) + gustRms sqrt(1 - a^2) w,   a = exp(-dt / tau),   w ~ N(0, 1),
/// so its statistics (rms, autocorrelation exp(-|lag| / tau)) do not depend on the step size.
/// The gust starts in its stationary distribution. The wind is uniform in space (no spatial
/// gradients). Deterministic for a seed (std::mt19937_64 seeded with mixSeed(seed, 0)). Plain
/// class, no Qt; single-threaded like a Plant.
class GustyWind {
  public:
    /// Throws std::invalid_argument for a negative speed or rms, or a time constant <= 0.
    explicit GustyWind(GustyWindParameters parameters = {}, std::uint64_t seed = 0);

    /// Restarts the field at time 0 with a fresh gust drawn from this seed's stream.
    void reset(std::uint64_t seed);
    /// Advances the field by dt [s], >= 0 (exact discretisation; any step size).
    void advance(double dt);

    /// The air's velocity over the ground now, steady wind plus gust [m/s], world frame.
    Eigen::Vector2d velocity() const { return mean_ + gust_; }
    /// The steady part [m/s], world frame.
    Eigen::Vector2d mean() const { return mean_; }
    /// The gust part [m/s], world frame.
    Eigen::Vector2d gust() const { return gust_; }
    /// Time since the last reset [s].
    double time() const { return time_; }
    /// True when there is neither a steady wind nor gusts (the velocity stays zero).
    bool calm() const { return parameters_.meanSpeed == 0.0 && parameters_.gustRms == 0.0; }
    const GustyWindParameters& parameters() const { return parameters_; }

  private:
    GustyWindParameters parameters_;
    Eigen::Vector2d mean_ = Eigen::Vector2d::Zero();
    Eigen::Vector2d gust_ = Eigen::Vector2d::Zero();
    double time_ = 0.0;
    std::mt19937_64 random_;
    std::normal_distribution<double> normal_{0.0, 1.0};
};

}  // namespace prisca::sim
