#pragma once

// PoseFilter's shared constants and its error, for its sources (PoseFilter.cpp: the filter;
// PoseFilterParameters.cpp: its parameters checked, and the ones derived from a fit or a
// demonstration).

#include <stdexcept>
#include <string>

namespace prisca::core::posefilter {

// Two times closer than this [s] are the same instant (step() computes them as k * dt, so equal
// steps give equal times; the rig's come from a nanosecond clock).
inline constexpr double kTimeTolerance = 1e-9;

// The filter's component order: x, y, psi, vx, vy, r.
inline constexpr int kHeading = 2;

inline const char* const kComponentNames[6] = {
    "x", "y", "heading", "forward velocity", "lateral velocity", "yaw rate"};

[[noreturn]] inline void fail(const std::string& message) {
    throw std::invalid_argument("PoseFilter: " + message);
}

}  // namespace prisca::core::posefilter
