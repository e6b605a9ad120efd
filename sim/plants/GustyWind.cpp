#include "sim/plants/GustyWind.h"

#include "sim/plants/Plant.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::sim {

GustyWind::GustyWind(GustyWindParameters parameters, std::uint64_t seed) : parameters_(parameters) {
    const GustyWindParameters& p = parameters_;
    // Written as negated comparisons so that NaN is rejected too.
    if (!(p.meanSpeed >= 0.0) || !(p.gustRms >= 0.0) || !(p.gustTimeConstant > 0.0) ||
        !std::isfinite(p.meanSpeed) || !std::isfinite(p.gustRms) ||
        !std::isfinite(p.meanDirection) || !std::isfinite(p.gustTimeConstant)) {
        throw std::invalid_argument(
            "GustyWind: speed and rms must be finite and >= 0, the time constant > 0");
    }
    reset(seed);
}

void GustyWind::reset(std::uint64_t seed) {
    random_.seed(mixSeed(seed, 0));
    // Drop a cached second normal deviate so the stream depends on the seed alone.
    normal_.reset();
    time_ = 0.0;
    mean_ = parameters_.meanSpeed * Eigen::Vector2d(std::cos(parameters_.meanDirection),
                                                    std::sin(parameters_.meanDirection));
    // Stationary start: no warm-up transient in which the gusts would be weaker than configured.
    gust_.x() = parameters_.gustRms * normal_(random_);
    gust_.y() = parameters_.gustRms * normal_(random_);
}

void GustyWind::advance(double dt) {
    if (!(dt >= 0.0)) {
        throw std::invalid_argument("GustyWind::advance: dt must be >= 0");
    }
    time_ += dt;
    const double a = std::exp(-dt / parameters_.gustTimeConstant);
    // The exact one-step transition of the Ornstein-Uhlenbeck process: keeps the variance at
    // gustRms^2 for any dt, unlike an Euler step whose variance grows with dt.
    const double drive = parameters_.gustRms * std::sqrt(std::max(0.0, 1.0 - a * a));
    // Both deviates are always drawn so the stream's position does not depend on the parameters.
    const double wx = normal_(random_);
    const double wy = normal_(random_);
    gust_.x() = a * gust_.x() + drive * wx;
    gust_.y() = a * gust_.y() + drive * wy;
}

}  // namespace prisca::sim
