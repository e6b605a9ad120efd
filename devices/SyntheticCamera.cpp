#include "devices/SyntheticCamera.h"

#include <opencv2/calib3d.hpp>
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

namespace prisca::devices {

FloorCalibration syntheticWideLensCamera(double k1) {
    CameraLens lens;
    lens.matrix = cv::Matx33d(600.0, 0.0, 322.0, 0.0, 600.0, 238.5, 0.0, 0.0, 1.0);
    lens.distortion = cv::Vec<double, 5>(k1, 0.05, 0.0004, -0.0003, 0.0);
    lens.imageSize = cv::Size(640, 480);
    // The camera's axes in floor coordinates: x along the floor's x, y along its -y, z down;
    // then tilted 2 degrees about its own x axis (a mount that is not quite level).
    const double tilt = 2.0 * M_PI / 180.0;
    const cv::Matx33d level(1, 0, 0, 0, -1, 0, 0, 0, -1);
    const cv::Matx33d tilted(1, 0, 0, 0, std::cos(tilt), -std::sin(tilt), 0, std::sin(tilt),
                             std::cos(tilt));
    const cv::Matx33d rotation = tilted * level;  // floor -> camera
    const cv::Vec3d centre(2.2, 0.55, 4.2);
    const cv::Vec3d t = -(rotation * centre);
    // Floor (x, y, 0) -> ideal pixel: K [r1 r2 t].
    const cv::Matx33d floorToCamera(rotation(0, 0), rotation(0, 1), t[0], rotation(1, 0),
                                    rotation(1, 1), t[1], rotation(2, 0), rotation(2, 1), t[2]);
    FloorCalibration c;
    c.imageToFloor = (lens.matrix * floorToCamera).inv();
    c.lens = lens;
    return c;
}

BoardViewRenderer::BoardViewRenderer(const CameraLens& lens) : lens_(lens) {
    const cv::Size size = lens.imageSize;
    std::vector<cv::Point2d> pixels;
    pixels.reserve(static_cast<size_t>(size.area()));
    for (int v = 0; v < size.height; ++v) {
        for (int u = 0; u < size.width; ++u) {
            pixels.emplace_back(u, v);
        }
    }
    std::vector<cv::Point2d> ideal;
    cv::undistortPoints(
        pixels, ideal, cv::Mat(lens.matrix), cv::Mat(lens.distortion), cv::noArray(),
        cv::Mat(lens.matrix),
        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-10));
    idealX_.create(size, CV_64F);
    idealY_.create(size, CV_64F);
    for (int v = 0; v < size.height; ++v) {
        for (int u = 0; u < size.width; ++u) {
            const cv::Point2d& p = ideal[static_cast<size_t>(v) * size.width + u];
            idealX_.at<double>(v, u) = p.x;
            idealY_.at<double>(v, u) = p.y;
        }
    }
}

cv::Mat BoardViewRenderer::render(const BoardSpec& board, const cv::Vec3d& rvec,
                                  const cv::Vec3d& tvec, double noise, std::uint64_t seed) const {
    cv::Matx33d r;
    cv::Rodrigues(rvec, r);
    const cv::Matx33d boardToIdeal =
        lens_.matrix * cv::Matx33d(r(0, 0), r(0, 1), tvec[0], r(1, 0), r(1, 1), tvec[1], r(2, 0),
                                   r(2, 1), tvec[2]);
    const cv::Matx33d idealToBoard = boardToIdeal.inv();
    const double s = board.squareMetres;
    const int cols = board.innerCorners.width, rows = board.innerCorners.height;
    // The squares run from -s to cols * s and -s to rows * s; a white border one square wide
    // around them (the quiet zone a board is printed with); beyond it a grey wall.
    const auto shade = [&](double bx, double by) -> float {
        if (bx < -2 * s || by < -2 * s || bx > (cols + 1) * s || by > (rows + 1) * s) {
            return 90.0f;
        }
        if (bx < -s || by < -s || bx > cols * s || by > rows * s) {
            return 215.0f;
        }
        const long ix = static_cast<long>(std::floor(bx / s)),
                   iy = static_cast<long>(std::floor(by / s));
        return ((ix + iy) & 1) ? 215.0f : 25.0f;
    };
    const cv::Size size = lens_.imageSize;
    cv::Mat image(size, CV_32F);
    constexpr int kSub = 4;  // 4 x 4 samples per pixel: anti-aliased edges
    for (int v = 0; v < size.height; ++v) {
        for (int u = 0; u < size.width; ++u) {
            // The ideal position varies smoothly: sub-pixel samples by its local derivative.
            const int u1 = std::min(u + 1, size.width - 1), v1 = std::min(v + 1, size.height - 1);
            const int u0 = u1 - 1, v0 = v1 - 1;
            const double x = idealX_.at<double>(v, u), y = idealY_.at<double>(v, u);
            const double dxdu = idealX_.at<double>(v, u1) - idealX_.at<double>(v, u0);
            const double dydu = idealY_.at<double>(v, u1) - idealY_.at<double>(v, u0);
            const double dxdv = idealX_.at<double>(v1, u) - idealX_.at<double>(v0, u);
            const double dydv = idealY_.at<double>(v1, u) - idealY_.at<double>(v0, u);
            double sum = 0.0;
            for (int i = 0; i < kSub; ++i) {
                for (int j = 0; j < kSub; ++j) {
                    const double du = (i + 0.5) / kSub - 0.5, dv = (j + 0.5) / kSub - 0.5;
                    const cv::Vec3d q = idealToBoard * cv::Vec3d(x + dxdu * du + dxdv * dv,
                                                                 y + dydu * du + dydv * dv, 1.0);
                    sum += q[2] > 0.0 || q[2] < 0.0 ? shade(q[0] / q[2], q[1] / q[2]) : 90.0f;
                }
            }
            image.at<float>(v, u) = static_cast<float>(sum / (kSub * kSub));
        }
    }
    cv::GaussianBlur(image, image, cv::Size(0, 0), 0.6);
    if (noise > 0.0) {
        cv::RNG rng(seed ? seed : 1);
        cv::Mat n(size, CV_32F);
        rng.fill(n, cv::RNG::NORMAL, 0.0, noise);
        image += n;
    }
    cv::Mat out;
    image.convertTo(out, CV_8U);
    return out;
}

std::vector<std::pair<cv::Vec3d, cv::Vec3d>> BoardViewRenderer::poses(const BoardSpec& board,
                                                                      int count,
                                                                      std::uint64_t seed) const {
    cv::RNG rng(seed ? seed : 1);
    const cv::Size size = lens_.imageSize;
    const double s = board.squareMetres;
    const int cols = board.innerCorners.width, rows = board.innerCorners.height;
    const cv::Vec3d middle((cols - 1) * s / 2.0, (rows - 1) * s / 2.0, 0.0);
    const std::vector<cv::Vec3d> outline = {{-2 * s, -2 * s, 0},
                                            {(cols + 1) * s, -2 * s, 0},
                                            {-2 * s, (rows + 1) * s, 0},
                                            {(cols + 1) * s, (rows + 1) * s, 0}};
    const cv::Matx33d kInv = lens_.matrix.inv();
    std::vector<std::pair<cv::Vec3d, cv::Vec3d>> out;
    for (int n = 0; n < count; ++n) {
        // The first nine on a 3 x 3 grid reaching into the corners, the rest anywhere.
        double fu, fv;
        if (n < 9) {
            fu = 0.5 * (n % 3);
            fv = 0.5 * (n / 3);
        } else {
            fu = rng.uniform(0.1, 0.9);
            fv = rng.uniform(0.1, 0.9);
        }
        const double distance = rng.uniform(0.6, 0.95);
        const double ax = rng.uniform(-0.5, 0.5), ay = rng.uniform(-0.5, 0.5),
                     az = rng.uniform(-0.25, 0.25);
        cv::Matx33d rx, ry, rz;
        cv::Rodrigues(cv::Vec3d(ax, 0, 0), rx);
        cv::Rodrigues(cv::Vec3d(0, ay, 0), ry);
        cv::Rodrigues(cv::Vec3d(0, 0, az), rz);
        const cv::Matx33d r = rz * ry * rx;
        // Pull the board toward the image's centre until all of it (its border too) is in view.
        for (double shrink = 1.0; shrink > 0.05; shrink *= 0.85) {
            const cv::Point2d target((0.5 + (fu - 0.5) * shrink) * size.width,
                                     (0.5 + (fv - 0.5) * shrink) * size.height);
            const cv::Point2d ideal = lens_.undistort(target);
            const cv::Vec3d ray = kInv * cv::Vec3d(ideal.x, ideal.y, 1.0);
            const cv::Vec3d t = ray * (distance / ray[2]) - r * middle;
            bool inside = true;
            for (const cv::Vec3d& corner : outline) {
                const cv::Vec3d c = r * corner + t;
                if (c[2] <= 0.05) {
                    inside = false;
                    break;
                }
                const cv::Vec3d p = lens_.matrix * (c * (1.0 / c[2]));
                const cv::Point2d seen = lens_.distort({p[0], p[1]});
                inside = inside && seen.x > 6 && seen.y > 6 && seen.x < size.width - 7 &&
                         seen.y < size.height - 7;
            }
            if (inside) {
                cv::Vec3d rvec;
                cv::Rodrigues(r, rvec);
                out.emplace_back(rvec, t);
                break;
            }
        }
    }
    return out;
}

std::vector<CalibrationPoint> syntheticFloorMarkers(const FloorCalibration& camera, int nx, int ny,
                                                    double pixelNoise, std::uint64_t seed) {
    cv::RNG rng(seed ? seed : 1);
    std::vector<CalibrationPoint> points;
    for (int i = 0; i < nx; ++i) {
        for (int j = 0; j < ny; ++j) {
            const cv::Point2d floor(-0.1 + 4.6 * i / std::max(1, nx - 1),
                                    -1.1 + 3.3 * j / std::max(1, ny - 1));
            const cv::Point2d px = camera.toImage(floor) +
                                   cv::Point2d(rng.gaussian(pixelNoise), rng.gaussian(pixelNoise));
            points.push_back({px, floor});
        }
    }
    return points;
}

QByteArray floorMarkersCsv(const std::vector<CalibrationPoint>& markers) {
    QByteArray csv = "# u, v [px], x, y [m]\nu,v,x,y\n";
    for (const CalibrationPoint& p : markers) {
        csv += QByteArray::number(p.image.x, 'f', 3) + ',' + QByteArray::number(p.image.y, 'f', 3) +
               ',' + QByteArray::number(p.floor.x) + ',' + QByteArray::number(p.floor.y) + '\n';
    }
    return csv;
}

}  // namespace prisca::devices
