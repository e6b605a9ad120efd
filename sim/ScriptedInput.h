#pragma once
// Shapes of a scripted operator's stick motions, shared by the demonstrators.

#include <algorithm>

namespace prisca::sim {

/// 0 -> 1 over [start, start + duration] [s] with zero slope at both ends, like a hand moving
/// a stick from one position to another.
inline double smoothStep(double t, double start, double duration) {
    const double x = std::clamp((t - start) / std::max(duration, 1e-9), 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

}  // namespace prisca::sim
