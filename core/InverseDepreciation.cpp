#include "InverseDepreciation.h"

#include <cmath>
#include <stdexcept>

namespace prisca::core {

InverseDepreciation::InverseDepreciation(int horizon, double gamma, Mode mode)
    : horizon_(horizon), gamma_(gamma), mode_(mode) {
    if (horizon < 1) {
        throw std::invalid_argument("InverseDepreciation: horizon H must be >= 1");
    }
    if (!(gamma >= 0.0 && gamma <= 1.0)) {
        throw std::invalid_argument("InverseDepreciation: gamma must lie in [0, 1]");
    }
}

double InverseDepreciation::forExponent(int r) const {
    // std::pow(0, 0) == 1, so gamma = 0 gives D = H/2 at r = 0 and H afterwards, as eq. 10 reads.
    return static_cast<double>(horizon_) / (std::pow(gamma_, r) + 1.0);
}

double InverseDepreciation::at(int j, int k) const {
    const int r = mode_ == Mode::Absolute ? j : j - (k - horizon_);
    return forExponent(r);
}

}  // namespace prisca::core
