#include "devices/FloorCalibration.h"

#include "core/FileIo.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <opencv2/calib3d.hpp>

#include <cmath>

namespace prisca::devices {

namespace {

cv::Point2d apply(const cv::Matx33d& h, const cv::Point2d& p) {
    const cv::Vec3d q = h * cv::Vec3d(p.x, p.y, 1.0);
    return {q[0] / q[2], q[1] / q[2]};
}

}  // namespace

std::optional<FloorCalibration> FloorCalibration::fit(const std::vector<CalibrationPoint>& points,
                                                      QString* error) {
    if (points.size() < 4) {
        *error = QStringLiteral("a floor calibration needs at least 4 points, %1 given")
                     .arg(points.size());
        return std::nullopt;
    }
    std::vector<cv::Point2d> image, floor;
    for (const CalibrationPoint& p : points) {
        if (!std::isfinite(p.image.x) || !std::isfinite(p.image.y) || !std::isfinite(p.floor.x) ||
            !std::isfinite(p.floor.y)) {
            *error = QStringLiteral("a calibration point is not a finite number");
            return std::nullopt;
        }
        image.push_back(p.image);
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
    if (degenerate(image) || degenerate(floor)) {
        *error =
            QStringLiteral("the calibration points lie on one line; spread them over the floor");
        return std::nullopt;
    }
    const cv::Mat h = cv::findHomography(image, floor, 0);
    if (h.empty()) {
        *error = QStringLiteral("no homography fits these points");
        return std::nullopt;
    }
    FloorCalibration c;
    c.imageToFloor = cv::Matx33d(h.ptr<double>());
    c.points = points;
    double sum = 0.0;
    for (double r : c.residuals()) {
        sum += r * r;
    }
    c.rmsMetres = std::sqrt(sum / points.size());
    return c;
}

cv::Point2d FloorCalibration::toFloor(const cv::Point2d& image) const {
    return apply(imageToFloor, image);
}

cv::Point2d FloorCalibration::toImage(const cv::Point2d& floor) const {
    return apply(imageToFloor.inv(), floor);
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
    return QJsonDocument(QJsonObject{{"homography", h}, {"points", pts}, {"rms_m", rmsMetres}})
        .toJson(QJsonDocument::Indented);
}

std::optional<FloorCalibration> FloorCalibration::fromJson(const QByteArray& json, QString* error) {
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        *error = QStringLiteral("not valid JSON at byte %1 (%2)")
                     .arg(parseError.offset)
                     .arg(parseError.errorString());
        return std::nullopt;
    }
    const QJsonObject root = doc.object();
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
    if (std::abs(cv::determinant(c.imageToFloor)) < 1e-300) {
        *error = QStringLiteral("'homography' is singular");
        return std::nullopt;
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
        c.points.push_back(
            {{im[0].toDouble(), im[1].toDouble()}, {fl[0].toDouble(), fl[1].toDouble()}});
    }
    c.rmsMetres = root.value("rms_m").toDouble(0.0);
    return c;
}

std::optional<FloorCalibration> FloorCalibration::load(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    auto c = fromJson(file.readAll(), error);
    if (!c) {
        *error = QStringLiteral("%1: %2").arg(path, *error);
    }
    return c;
}

bool FloorCalibration::save(const QString& path, QString* error) const {
    core::FileError fileError;
    if (!core::writeFileAtomically(path, toJson(), &fileError)) {
        *error = fileError.toString();
        return false;
    }
    return true;
}

}  // namespace prisca::devices
