#pragma once

#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"

#include <opencv2/core.hpp>

#include <cstdint>
#include <utility>
#include <vector>

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

/// A ceiling camera with a wide lens over the same floor, as the truth for lens tests: 640 x
/// 480, focal length 600 px, 4.2 m above (2.2, 0.55) m tilted 2 degrees, radial distortion
/// k1 = `k1` (barrel for k1 < 0: a point at the image's corner is seen about 20 % nearer the
/// centre than a pinhole would put it for k1 = -0.3), k2 = 0.05, a little tangential. Its floor
/// calibration is exact (no fit): toImage() is the camera's projection of a floor point.
FloorCalibration syntheticWideLensCamera(double k1 = -0.3);

/// Floor markers on an nx x ny grid over x in [-0.1, 4.5] m and y in [-1.1, 2.2] m (the floor
/// the synthetic cameras see), with their pixels through `camera` plus Gaussian noise of
/// `pixelNoise` px (a marker clicked or detected to that precision), drawn from `seed`.
std::vector<CalibrationPoint> syntheticFloorMarkers(const FloorCalibration& camera, int nx, int ny,
                                                    double pixelNoise, std::uint64_t seed);
/// The same as calibrate-floor's CSV: "u,v,x,y" per line after a comment and a header.
QByteArray floorMarkersCsv(const std::vector<CalibrationPoint>& markers);

/// Renders views of a chessboard held before a camera with a lens: the image a real camera
/// would give (distortion, anti-aliased edges, blur and noise), for lens calibration tests and
/// demonstrations. The ideal position of every pixel is computed once per lens.
class BoardViewRenderer {
  public:
    explicit BoardViewRenderer(const CameraLens& lens);
    /// The board (its first inner corner at the origin, x along the rows) at rotation `rvec`
    /// (Rodrigues) and translation `tvec` [m] in the camera frame; 8-bit grey.
    cv::Mat render(const BoardSpec& board, const cv::Vec3d& rvec, const cv::Vec3d& tvec,
                   double noise, std::uint64_t seed) const;
    /// `count` poses that show the whole board, spread over the image (its centre, edges and
    /// corners) and tilted up to about 30 degrees, drawn from `seed`.
    std::vector<std::pair<cv::Vec3d, cv::Vec3d>> poses(const BoardSpec& board, int count,
                                                       std::uint64_t seed) const;
    const CameraLens& lens() const { return lens_; }

  private:
    CameraLens lens_;
    cv::Mat idealX_, idealY_;  ///< per pixel, where the ideal pinhole camera sees it [px]
};

}  // namespace prisca::devices
