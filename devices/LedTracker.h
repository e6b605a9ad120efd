#pragma once

#include "devices/FloorCalibration.h"

#include <opencv2/core.hpp>

#include <array>
#include <optional>
#include <vector>

namespace prisca::devices {

/// Where the car's three IR LEDs sit in the car frame (x forward, y left) [m];
/// docs/architecture.md's default: front (+0.12, 0), rear-left (-0.08, +0.06), rear-right (-0.08,
/// -0.06).
struct LedGeometry {
    std::array<cv::Point2d, 3> leds = {cv::Point2d(0.12, 0.0), cv::Point2d(-0.08, 0.06),
                                       cv::Point2d(-0.08, -0.06)};
};

/// A planar pose: the car-frame origin on the floor [m] and the heading of its x axis [rad].
struct PlanarPose {
    double x = 0.0;
    double y = 0.0;
    double heading = 0.0;
};

struct TrackerSettings {
    LedGeometry geometry;
    int threshold = 180;      ///< grey level above which a pixel is lit (0..255)
    int minArea = 3;          ///< smallest credible LED blob [px]
    int maxArea = 600;        ///< largest (bigger is a reflection or the sun) [px]
    double tolerance = 0.02;  ///< largest RMS misfit of the LEDs to the triangle [m]
    int regionMargin = 80;    ///< half-size added around the last pose's LEDs once locked [px]
};

/// The result of one frame.
struct TrackResult {
    std::optional<PlanarPose> pose;  ///< empty: no credible triangle ("no pose", never a guess)
    double misfit = 0.0;             ///< RMS distance of the LEDs from the triangle [m]
    int blobs = 0;                   ///< credible blobs found
    bool usedRegion = false;         ///< searched only around the last pose
};

/// The IR-LED tracker of docs/architecture.md: threshold, connected components with area gating and
/// intensity-weighted centroids, the three blobs that best match the LED triangle (all triples,
/// all labellings, a rigid fit on the floor), the pose through the floor calibration. Once
/// locked it searches a region around the last pose first and falls back to the full frame.
/// Not thread-safe; one per camera.
class LedTracker {
  public:
    explicit LedTracker(TrackerSettings settings = {});
    /// `frame` is 8-bit grey (or BGR, converted).
    TrackResult track(const cv::Mat& frame, const FloorCalibration& calibration);
    /// Forget the lock (a new run, a jump).
    void reset() { last_.reset(); }
    const TrackerSettings& settings() const { return settings_; }

  private:
    TrackResult trackIn(const cv::Mat& grey, const cv::Rect& region,
                        const FloorCalibration& calibration);

    TrackerSettings settings_;
    std::optional<PlanarPose> last_;
};

}  // namespace prisca::devices
