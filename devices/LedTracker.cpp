#include "devices/LedTracker.h"

#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace prisca::devices {

LedTracker::LedTracker(TrackerSettings settings) : settings_(settings) {
    // One thread: a frame takes a few tenths of a millisecond on its own, and OpenCV's pool would
    // wake other threads every frame (which would inherit the loop thread's real-time priority).
    cv::setNumThreads(1);
}

namespace {

// The rigid transform (rotation, translation) taking the car-frame LEDs onto the measured
// floor points in the least-squares sense (2-D Procrustes). Returns the RMS misfit.
double rigidFit(const std::array<cv::Point2d, 3>& model, const std::array<cv::Point2d, 3>& seen,
                PlanarPose* pose) {
    cv::Point2d cm(0, 0), cs(0, 0);
    for (int i = 0; i < 3; ++i) {
        cm += model[i] / 3.0;
        cs += seen[i] / 3.0;
    }
    double sxx = 0.0, sxy = 0.0;  // sum of dot and cross products of centred points
    for (int i = 0; i < 3; ++i) {
        const cv::Point2d a = model[i] - cm, b = seen[i] - cs;
        sxx += a.x * b.x + a.y * b.y;
        sxy += a.x * b.y - a.y * b.x;
    }
    const double angle = std::atan2(sxy, sxx);
    const double c = std::cos(angle), s = std::sin(angle);
    const cv::Point2d origin = cs - cv::Point2d(c * cm.x - s * cm.y, s * cm.x + c * cm.y);
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        const cv::Point2d p =
            origin + cv::Point2d(c * model[i].x - s * model[i].y, s * model[i].x + c * model[i].y);
        const cv::Point2d d = p - seen[i];
        sum += d.dot(d);
    }
    *pose = {origin.x, origin.y, angle};
    return std::sqrt(sum / 3.0);
}

}  // namespace

TrackResult LedTracker::track(const cv::Mat& frame, const FloorCalibration& calibration) {
    cv::Mat grey;
    if (frame.channels() == 3) {
        cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
    } else {
        grey = frame;
    }
    const cv::Rect whole(0, 0, grey.cols, grey.rows);
    if (last_) {
        // Around where the LEDs were: the bounding box of their image points, grown.
        std::vector<cv::Point2f> image;
        const double c = std::cos(last_->heading), s = std::sin(last_->heading);
        for (const cv::Point2d& led : settings_.geometry.leds) {
            const cv::Point2d floor(last_->x + c * led.x - s * led.y,
                                    last_->y + s * led.x + c * led.y);
            const cv::Point2d px = calibration.toImage(floor);
            image.emplace_back(static_cast<float>(px.x), static_cast<float>(px.y));
        }
        cv::Rect region = cv::boundingRect(image);
        region -= cv::Point(settings_.regionMargin, settings_.regionMargin);
        region += cv::Size(2 * settings_.regionMargin, 2 * settings_.regionMargin);
        region &= whole;
        if (region.area() > 0) {
            TrackResult local = trackIn(grey, region, calibration);
            if (local.pose) {
                local.usedRegion = true;
                last_ = local.pose;
                return local;
            }
        }
    }
    TrackResult result = trackIn(grey, whole, calibration);
    last_ = result.pose;
    return result;
}

TrackResult LedTracker::trackIn(const cv::Mat& grey, const cv::Rect& region,
                                const FloorCalibration& calibration) {
    TrackResult result;
    const cv::Mat roi = grey(region);
    cv::Mat lit, labels, stats, centroids;
    cv::threshold(roi, lit, settings_.threshold, 255, cv::THRESH_BINARY);
    const int count = cv::connectedComponentsWithStats(lit, labels, stats, centroids, 8, CV_32S);
    // Intensity-weighted centroids of the credible blobs, on the floor.
    std::vector<cv::Point2d> floor;
    for (int label = 1; label < count; ++label) {
        const int area = stats.at<int>(label, cv::CC_STAT_AREA);
        if (area < settings_.minArea || area > settings_.maxArea) {
            continue;
        }
        const cv::Rect box(
            stats.at<int>(label, cv::CC_STAT_LEFT), stats.at<int>(label, cv::CC_STAT_TOP),
            stats.at<int>(label, cv::CC_STAT_WIDTH), stats.at<int>(label, cv::CC_STAT_HEIGHT));
        double sw = 0.0, sx = 0.0, sy = 0.0;
        for (int v = box.y; v < box.y + box.height; ++v) {
            const int* l = labels.ptr<int>(v);
            const std::uint8_t* g = roi.ptr<std::uint8_t>(v);
            for (int u = box.x; u < box.x + box.width; ++u) {
                if (l[u] == label) {
                    const double w = g[u] - settings_.threshold + 1.0;
                    sw += w;
                    sx += w * u;
                    sy += w * v;
                }
            }
        }
        const cv::Point2d image(region.x + sx / sw, region.y + sy / sw);
        floor.push_back(calibration.toFloor(image));
    }
    result.blobs = static_cast<int>(floor.size());
    if (floor.size() < 3 || floor.size() > 24) {
        return result;  // fewer than three LEDs (or a frame full of light): no pose
    }
    // Every triple, every labelling: the best rigid fit to the triangle.
    static const int orders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                     {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    double best = std::numeric_limits<double>::infinity();
    PlanarPose bestPose;
    for (size_t i = 0; i < floor.size(); ++i)
        for (size_t j = i + 1; j < floor.size(); ++j)
            for (size_t k = j + 1; k < floor.size(); ++k) {
                const cv::Point2d triple[3] = {floor[i], floor[j], floor[k]};
                for (const auto& order : orders) {
                    const std::array<cv::Point2d, 3> seen = {triple[order[0]], triple[order[1]],
                                                             triple[order[2]]};
                    PlanarPose pose;
                    const double misfit = rigidFit(settings_.geometry.leds, seen, &pose);
                    if (misfit < best) {
                        best = misfit;
                        bestPose = pose;
                    }
                }
            }
    result.misfit = best;
    if (best <= settings_.tolerance) {
        result.pose = bestPose;
    }
    return result;
}

}  // namespace prisca::devices
