#pragma once
// Shapes of a scripted operator's stick motions, shared by the demonstrators.

#include <algorithm>
#include <cmath>

namespace prisca::sim {

/// 0 -> 1 over [start, start + duration] [s] with zero slope at both ends, like a hand moving
/// a stick from one position to another.
inline double smoothStep(double t, double start, double duration) {
    const double x = std::clamp((t - start) / std::max(duration, 1e-9), 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

/// The window's keyboard driving (DrivingInput): a held key pushes its control towards +-1 at 2
/// per second; released (key 0), the control returns to 0 at 3 per second.
inline double keyRamp(double current, int key, double dt) {
    constexpr double kUp = 2.0, kBack = 3.0;
    if (key != 0) {
        return std::clamp(current + key * kUp * dt, -1.0, 1.0);
    }
    const double back = kBack * dt;
    return std::abs(current) <= back ? 0.0 : current - std::copysign(back, current);
}

/// Which key an operator holds to bring a ramped control towards what they want: the one in
/// the wanted direction while short of it, none once past (it returns to neutral by itself).
inline int keyFor(double wanted, double current) {
    constexpr double kDeadband = 0.05;
    if (std::abs(wanted) >= 1.0 - kDeadband) {
        return wanted > 0.0 ? 1 : -1;  // full: the key is simply held down
    }
    if (wanted > kDeadband) {
        return current < wanted - kDeadband ? 1 : 0;
    }
    if (wanted < -kDeadband) {
        return current > wanted + kDeadband ? -1 : 0;
    }
    return 0;
}

}  // namespace prisca::sim
