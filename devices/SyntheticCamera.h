#pragma once

#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"

#include <opencv2/core.hpp>

#include <cstdint>

namespace prisca::devices {

/// How the synthetic ceiling camera sees the floor.
struct SyntheticCameraSettings {
    cv::Size size{640, 480};
    double background = 18.0;  ///< mean grey level of the floor
    double noise = 3.0;        ///< per-pixel Gaussian noise, std [grey levels]
    double ledPeak =
        420.0;  ///< an LED spot's peak before the sensor saturates at 255 (IR LEDs overexpose)
    double ledSigma = 1.4;  ///< an LED spot's Gaussian radius [px]
    double blur = 0.0;      ///< extra Gaussian blur of the whole frame, sigma [px] (0: none)
    double flicker = 0.0;   ///< chance an LED is dim (below the tracker's threshold) in a frame
    int reflections = 0;    ///< stray bright spots per frame (floor glints, other lights)
};

/// Renders a car's three IR LEDs at a pose through the floor calibration (floor m -> image px),
/// with noise, blur, flicker and stray reflections, all drawn from `seed`. Pure function: the
/// same arguments give the same frame. 8-bit grey.
cv::Mat renderLeds(const PlanarPose& pose, const FloorCalibration& calibration,
                   const SyntheticCameraSettings& settings, const LedGeometry& geometry,
                   std::uint64_t seed);

/// A plausible ceiling camera over the lab floor for tests and the virtual rig: the image
/// (640 x 480) sees x in about [-0.6, 5.0] m and y in [-1.6, 2.6] m (the slide-park and its lot),
/// slightly tilted (a true perspective homography), calibrated from its corners and centre.
FloorCalibration syntheticCeilingCamera();

}  // namespace prisca::devices
