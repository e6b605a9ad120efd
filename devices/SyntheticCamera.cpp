#include "devices/SyntheticCamera.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace prisca::devices {

namespace {

void addSpot(cv::Mat& image, const cv::Point2d& centre, double peak, double sigma) {
    const int r = static_cast<int>(std::ceil(4.0 * sigma));
    const int u0 = static_cast<int>(std::floor(centre.x)) - r;
    const int v0 = static_cast<int>(std::floor(centre.y)) - r;
    for (int v = std::max(0, v0); v <= std::min(image.rows - 1, v0 + 2 * r + 1); ++v) {
        float* row = image.ptr<float>(v);
        for (int u = std::max(0, u0); u <= std::min(image.cols - 1, u0 + 2 * r + 1); ++u) {
            const double dx = u - centre.x, dy = v - centre.y;
            row[u] +=
                static_cast<float>(peak * std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)));
        }
    }
}

}  // namespace

cv::Mat renderLeds(const PlanarPose& pose, const FloorCalibration& calibration,
                   const SyntheticCameraSettings& s, const LedGeometry& geometry,
                   std::uint64_t seed) {
    cv::RNG rng(seed ? seed : 1);
    cv::Mat image(s.size, CV_32F, cv::Scalar(s.background));
    const double c = std::cos(pose.heading), sn = std::sin(pose.heading);
    for (const cv::Point2d& led : geometry.leds) {
        const cv::Point2d floor(pose.x + c * led.x - sn * led.y, pose.y + sn * led.x + c * led.y);
        const double peak = rng.uniform(0.0, 1.0) < s.flicker ? s.ledPeak * 0.3 : s.ledPeak;
        addSpot(image, calibration.toImage(floor), peak - s.background, s.ledSigma);
    }
    for (int i = 0; i < s.reflections; ++i) {
        const cv::Point2d at(rng.uniform(0.0, double(s.size.width)),
                             rng.uniform(0.0, double(s.size.height)));
        addSpot(image, at, rng.uniform(120.0, 255.0), rng.uniform(0.8, 3.0));
    }
    if (s.blur > 0.0) {
        cv::GaussianBlur(image, image, cv::Size(0, 0), s.blur);
    }
    if (s.noise > 0.0) {
        cv::Mat noise(s.size, CV_32F);
        rng.fill(noise, cv::RNG::NORMAL, 0.0, s.noise);
        image += noise;
    }
    cv::Mat out;
    image.convertTo(out, CV_8U);  // saturates to 0..255
    return out;
}

FloorCalibration syntheticCeilingCamera() {
    // Image corners and centre -> floor points, a mild keystone as from a tilted mount; the
    // floor seen is about 5.6 m x 4.2 m, enough for the slide-park and its lot.
    const std::vector<CalibrationPoint> points = {
        {{0, 0}, {-0.60, 2.60}},    {{639, 0}, {5.00, 2.70}},   {{639, 479}, {4.95, -1.55}},
        {{0, 479}, {-0.55, -1.60}}, {{320, 240}, {2.20, 0.55}},
    };
    QString error;
    return *FloorCalibration::fit(points, &error);
}

}  // namespace prisca::devices
