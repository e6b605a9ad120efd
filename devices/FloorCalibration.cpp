#include "devices/FloorCalibration.h"

#include "core/FileIo.h"
#include "devices/JsonFile.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <opencv2/calib3d.hpp>

#include <algorithm>
#include <cmath>

namespace prisca::devices {

namespace {

cv::Point2d apply(const cv::Matx33d& h, const cv::Point2d& p) {
    const cv::Vec3d q = h * cv::Vec3d(p.x, p.y, 1.0);
    return {q[0] / q[2], q[1] / q[2]};
}

}  // namespace

namespace {

// Whether the points determine a homography: the direct linear system (on points normalised to
// mean 0 and mean distance sqrt(2), which makes its conditioning scale free) has a one-
// dimensional null space, i.e. its eighth singular value is clearly above zero and above the
// ninth. Four points in
// general position give that; points on one line, or all but one on a line, do not.
bool determined(const std::vector<cv::Point2d>& image, const std::vector<cv::Point2d>& floor) {
    const auto normalised = [](const std::vector<cv::Point2d>& q) {
        cv::Point2d mean(0.0, 0.0);
        for (const cv::Point2d& p : q) {
            mean += p;
        }
        mean *= 1.0 / static_cast<double>(q.size());
        double spread = 0.0;
        for (const cv::Point2d& p : q) {
            spread += cv::norm(p - mean);
        }
        spread /= static_cast<double>(q.size());
        const double scale = spread > 0.0 ? std::sqrt(2.0) / spread : 1.0;
        std::vector<cv::Point2d> out;
        for (const cv::Point2d& p : q) {
            out.push_back((p - mean) * scale);
        }
        return out;
    };
    const std::vector<cv::Point2d> a = normalised(image), b = normalised(floor);
    const int n = static_cast<int>(a.size());
    cv::Mat system(2 * n, 9, CV_64F);
    for (int i = 0; i < n; ++i) {
        const double x = a[i].x, y = a[i].y, u = b[i].x, v = b[i].y;
        const double rows[2][9] = {{-x, -y, -1, 0, 0, 0, u * x, u * y, u},
                                   {0, 0, 0, -x, -y, -1, v * x, v * y, v}};
        for (int r = 0; r < 2; ++r) {
            for (int c = 0; c < 9; ++c) {
                system.at<double>(2 * i + r, c) = rows[r][c];
            }
        }
    }
    cv::Mat singular;
    cv::SVD::compute(system, singular, cv::SVD::NO_UV);
    if (singular.rows < 8) {
        return false;
    }
    // Determined: the eighth above 0.5 % of the first, and clearly above the ninth. A 4 x 3 grid
    // of points gives about 30 %, a 20:1 strip 3 %; four of five on a line clicked half a
    // pixel off give 0.15 % (what is left there is only the clicking noise).
    const double eighth = singular.at<double>(7);
    const double ninth = singular.rows > 8 ? singular.at<double>(8) : 0.0;
    return eighth > 5e-3 * singular.at<double>(0) && eighth > 10.0 * ninth;
}

}  // namespace

std::optional<FloorCalibration> FloorCalibration::fit(const std::vector<CalibrationPoint>& points,
                                                      QString* error,
                                                      const std::optional<CameraLens>& lens) {
    if (points.size() < 4) {
        *error = QStringLiteral("a floor calibration needs at least 4 points, %1 given")
                     .arg(points.size());
        return std::nullopt;
    }
    std::vector<cv::Point2d> image, floor;
    for (size_t i = 0; i < points.size(); ++i) {
        const CalibrationPoint& p = points[i];
        if (!std::isfinite(p.image.x) || !std::isfinite(p.image.y) || !std::isfinite(p.floor.x) ||
            !std::isfinite(p.floor.y)) {
            *error = QStringLiteral("calibration point %1 is not a finite number").arg(i + 1);
            return std::nullopt;
        }
        if (std::abs(p.floor.x) > kMaxFloorMetres || std::abs(p.floor.y) > kMaxFloorMetres) {
            *error = QStringLiteral(
                         "calibration point %1: floor (%2, %3) m is beyond the +-%4 m "
                         "a floor can span")
                         .arg(i + 1)
                         .arg(p.floor.x, 0, 'g', 4)
                         .arg(p.floor.y, 0, 'g', 4)
                         .arg(kMaxFloorMetres);
            return std::nullopt;
        }
        if (std::abs(p.image.x) > kMaxImagePixels || std::abs(p.image.y) > kMaxImagePixels) {
            *error = QStringLiteral(
                         "calibration point %1: image (%2, %3) px is beyond the +-%4 "
                         "px of any camera frame")
                         .arg(i + 1)
                         .arg(p.image.x, 0, 'g', 4)
                         .arg(p.image.y, 0, 'g', 4)
                         .arg(kMaxImagePixels);
            return std::nullopt;
        }
        image.push_back(lens ? lens->undistort(p.image) : p.image);
        floor.push_back(p.floor);
    }
    // Three of the points on one line (in the image or on the floor) leave it undetermined.
    const auto degenerate = [](const std::vector<cv::Point2d>& q) {
        double best = 0.0;
        for (size_t i = 0; i < q.size(); ++i)
            for (size_t j = i + 1; j < q.size(); ++j)
                for (size_t k = j + 1; k < q.size(); ++k) {
                    const cv::Point2d a = q[j] - q[i], b = q[k] - q[i];
                    const double scale = std::max(1e-12, cv::norm(a) * cv::norm(b));
                    best = std::max(best, std::abs(a.x * b.y - a.y * b.x) / scale);
                }
        return best < 1e-3;  // every triple (nearly) collinear
    };
    // One mistyped coordinate among good points makes the set look undetermined or folded:
    // when all the others agree on a homography that puts this one far off, it is named.
    const auto mistyped = [&]() -> QString {
        if (image.size() < 5) {
            return {};
        }
        int culprit = -1;
        cv::Point2d where;
        double othersRms = 0.0;
        for (size_t i = 0; i < image.size(); ++i) {
            std::vector<cv::Point2d> restImage, restFloor;
            for (size_t j = 0; j < image.size(); ++j) {
                if (j != i) {
                    restImage.push_back(image[j]);
                    restFloor.push_back(floor[j]);
                }
            }
            if (degenerate(restImage) || degenerate(restFloor) ||
                !determined(restImage, restFloor)) {
                continue;
            }
            const cv::Mat h = cv::findHomography(restImage, restFloor, 0);
            if (h.empty()) {
                continue;
            }
            const cv::Matx33d m(h.ptr<double>());
            const auto map = [&m](const cv::Point2d& p) {
                const cv::Vec3d q = m * cv::Vec3d(p.x, p.y, 1.0);
                return cv::Point2d(q[0] / q[2], q[1] / q[2]);
            };
            double sum = 0.0;
            for (size_t j = 0; j < restImage.size(); ++j) {
                const double r = cv::norm(map(restImage[j]) - restFloor[j]);
                sum += r * r;
            }
            const double rms = std::sqrt(sum / restImage.size());
            const cv::Point2d mapped = map(image[i]);
            const double off = cv::norm(mapped - floor[i]);
            if (rms < 0.02 && std::isfinite(off) && off > 0.1 && off > 20.0 * rms) {
                if (culprit >= 0) {
                    return {};  // two could be: say nothing that may be wrong
                }
                culprit = static_cast<int>(i);
                where = mapped;
                othersRms = rms;
            }
        }
        if (culprit < 0) {
            return {};
        }
        const CalibrationPoint& p = points[static_cast<size_t>(culprit)];
        return QStringLiteral(
                   "calibration point %1 (image (%2, %3) px, floor (%4, %5) m) does not "
                   "fit the others: they agree within %6 mm and put it at (%7, %8) m. "
                   "A mistyped coordinate?")
            .arg(culprit + 1)
            .arg(p.image.x, 0, 'g', 6)
            .arg(p.image.y, 0, 'g', 6)
            .arg(p.floor.x, 0, 'g', 6)
            .arg(p.floor.y, 0, 'g', 6)
            .arg(othersRms * 1000.0, 0, 'f', 1)
            .arg(where.x, 0, 'f', 3)
            .arg(where.y, 0, 'f', 3);
    };
    const auto refuse = [&](const QString& why) {
        const QString named = mistyped();
        *error = named.isEmpty() ? why : named;
        return std::nullopt;
    };
    if (degenerate(image) || degenerate(floor)) {
        return refuse(
            QStringLiteral("the calibration points lie on one line; spread them over the floor"));
    }
    if (!determined(image, floor)) {
        return refuse(QStringLiteral(
            "the calibration points do not determine the homography: it needs four of them "
            "with no three on one line (on the floor and in the image); spread them over the "
            "floor"));
    }
    const cv::Mat h = cv::findHomography(image, floor, 0);
    if (h.empty()) {
        return refuse(QStringLiteral("no homography fits these points"));
    }
    FloorCalibration c;
    c.imageToFloor = cv::Matx33d(h.ptr<double>());
    c.points = points;
    c.lens = lens;
    double sum = 0.0;
    for (double r : c.residuals()) {
        sum += r * r;
    }
    c.rmsMetres = std::sqrt(sum / points.size());
    if (const QString problem = c.homographyProblem(); !problem.isEmpty()) {
        return refuse(QStringLiteral("the homography these points give %1").arg(problem));
    }
    return c;
}

QString FloorCalibration::homographyProblem() const {
    double largest = 0.0;
    for (double v : imageToFloor.val) {
        if (!std::isfinite(v)) {
            return QStringLiteral("has an entry that is not a finite number");
        }
        largest = std::max(largest, std::abs(v));
    }
    if (largest == 0.0) {
        return QStringLiteral("is all zeros");
    }
    // Scale-free: a homography is defined up to a factor, so judge it with its largest entry 1.
    const cv::Matx33d h = imageToFloor * (1.0 / largest);
    // The image it must map: a VGA frame and the calibration points' extent.
    double u0 = 0.0, v0 = 0.0, u1 = 640.0, v1 = 480.0;
    for (const CalibrationPoint& p : points) {
        u0 = std::min(u0, p.image.x);
        u1 = std::max(u1, p.image.x);
        v0 = std::min(v0, p.image.y);
        v1 = std::max(v1, p.image.y);
    }
    double sign = 0.0;
    if (lens) {
        u1 = std::max(u1, double(lens->imageSize.width));
        v1 = std::max(v1, double(lens->imageSize.height));
    }
    for (const cv::Point2d corner :
         {cv::Point2d(u0, v0), cv::Point2d(u1, v0), cv::Point2d(u0, v1), cv::Point2d(u1, v1)}) {
        const cv::Point2d ideal = lens ? lens->undistort(corner) : corner;
        const cv::Vec3d q = h * cv::Vec3d(ideal.x, ideal.y, 1.0);
        if (sign == 0.0) {
            sign = q[2] > 0.0 ? 1.0 : -1.0;
        }
        if (!(q[2] * sign > 0.0)) {
            return QStringLiteral(
                "puts the horizon inside the image (a ceiling camera sees "
                "only floor)");
        }
        const double x = q[0] / q[2], y = q[1] / q[2];
        if (!(std::abs(x) <= kMaxFloorMetres && std::abs(y) <= kMaxFloorMetres)) {
            return QStringLiteral(
                       "maps image point (%1, %2) px to (%3, %4) m, beyond the "
                       "+-%5 m a floor can span")
                .arg(corner.x)
                .arg(corner.y)
                .arg(x, 0, 'g', 3)
                .arg(y, 0, 'g', 3)
                .arg(kMaxFloorMetres);
        }
    }
    // Only now: a huge offset (the image mapped kilometres away) also makes the scaled
    // determinant tiny, and is the clearer message above.
    if (std::abs(cv::determinant(h)) < 1e-12) {
        return QStringLiteral("is singular (it folds the image onto a line)");
    }
    return {};
}

cv::Point2d FloorCalibration::toFloor(const cv::Point2d& image) const {
    return apply(imageToFloor, lens ? lens->undistort(image) : image);
}

cv::Point2d FloorCalibration::toImage(const cv::Point2d& floor) const {
    const cv::Point2d ideal = apply(imageToFloor.inv(), floor);
    return lens ? lens->distort(ideal) : ideal;
}

QString FloorCalibration::accuracyProblem() const {
    if (rmsMetres <= kMaxRmsMetres) {
        return {};
    }
    const std::vector<double> r = residuals();
    const auto worst = std::max_element(r.begin(), r.end());
    return QStringLiteral(
               "the floor calibration fits its points to %1 mm RMS (point %2 is %3 mm "
               "off), more than the %4 mm the tracker tolerates; %5")
        .arg(rmsMetres * 1000.0, 0, 'f', 1)
        .arg(worst - r.begin() + 1)
        .arg(*worst * 1000.0, 0, 'f', 1)
        .arg(kMaxRmsMetres * 1000.0, 0, 'f', 0)
        .arg(lens ? QStringLiteral("check the points (a mistyped coordinate, a swapped pair)")
                  : QStringLiteral("a wide lens's distortion? calibrate the camera and give "
                                   "its intrinsics (--camera)"));
}

std::vector<double> FloorCalibration::residuals() const {
    std::vector<double> r;
    for (const CalibrationPoint& p : points) {
        r.push_back(cv::norm(toFloor(p.image) - p.floor));
    }
    return r;
}

QByteArray FloorCalibration::toJson() const {
    QJsonArray h;
    for (int i = 0; i < 9; ++i) {
        h.append(imageToFloor.val[i]);
    }
    QJsonArray pts;
    for (const CalibrationPoint& p : points) {
        pts.append(QJsonObject{{"image", QJsonArray{p.image.x, p.image.y}},
                               {"floor", QJsonArray{p.floor.x, p.floor.y}}});
    }
    QJsonObject root{{"homography", h}, {"points", pts}, {"rms_m", rmsMetres}};
    if (lens) {
        root.insert("camera", lens->toJsonObject());
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::optional<FloorCalibration> FloorCalibration::fromJson(const QByteArray& json, QString* error) {
    const auto parsed = parseJsonObject(
        json,
        QStringLiteral("valid JSON, but not a floor calibration: it must be an object such as "
                       "{\"homography\": [9 numbers], \"points\": [...]}"),
        error);
    if (!parsed) {
        return std::nullopt;
    }
    const QJsonObject& root = *parsed;
    const QJsonArray h = root.value("homography").toArray();
    if (h.size() != 9) {
        *error = QStringLiteral(
            "'homography' must be a list of 9 numbers (row-major, image px -> "
            "floor m)");
        return std::nullopt;
    }
    FloorCalibration c;
    for (int i = 0; i < 9; ++i) {
        if (!h[i].isDouble() || !std::isfinite(h[i].toDouble())) {
            *error = QStringLiteral("'homography' entry %1 is not a number").arg(i + 1);
            return std::nullopt;
        }
        c.imageToFloor.val[i] = h[i].toDouble();
    }
    const QJsonArray pts = root.value("points").toArray();
    for (int i = 0; i < pts.size(); ++i) {
        const QJsonArray im = pts[i].toObject().value("image").toArray();
        const QJsonArray fl = pts[i].toObject().value("floor").toArray();
        if (im.size() != 2 || fl.size() != 2) {
            *error =
                QStringLiteral("'points' entry %1 needs \"image\": [u, v] and \"floor\": [x, y]")
                    .arg(i + 1);
            return std::nullopt;
        }
        const CalibrationPoint p{{im[0].toDouble(), im[1].toDouble()},
                                 {fl[0].toDouble(), fl[1].toDouble()}};
        if (!std::isfinite(p.image.x) || !std::isfinite(p.image.y) || !std::isfinite(p.floor.x) ||
            !std::isfinite(p.floor.y)) {
            *error = QStringLiteral("'points' entry %1 is not four finite numbers").arg(i + 1);
            return std::nullopt;
        }
        c.points.push_back(p);
    }
    const QJsonValue rms = root.value("rms_m");
    if (!rms.isUndefined()) {
        if (!rms.isDouble() || !(rms.toDouble() >= 0.0 && rms.toDouble() <= kMaxFloorMetres)) {
            *error =
                QStringLiteral("'rms_m' must be a distance from 0 to %1 m").arg(kMaxFloorMetres);
            return std::nullopt;
        }
        c.rmsMetres = rms.toDouble();
    }
    if (root.contains("camera")) {
        if (!root.value("camera").isObject()) {
            *error = QStringLiteral("'camera' must be an object (the camera's intrinsics)");
            return std::nullopt;
        }
        QString lensError;
        c.lens = CameraLens::fromJsonObject(root.value("camera").toObject(), &lensError);
        if (!c.lens) {
            *error = QStringLiteral("'camera': %1").arg(lensError);
            return std::nullopt;
        }
    }
    if (const QString problem = c.homographyProblem(); !problem.isEmpty()) {
        *error = QStringLiteral("'homography' %1").arg(problem);
        return std::nullopt;
    }
    return c;
}

std::optional<FloorCalibration> FloorCalibration::load(const QString& path, QString* error) {
    return loadJsonFile<FloorCalibration>(path, error);
}

bool FloorCalibration::save(const QString& path, QString* error) const {
    return saveJsonFile(*this, path, error);
}

}  // namespace prisca::devices
