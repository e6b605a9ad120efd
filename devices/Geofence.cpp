#include "devices/Geofence.h"

#include <QJsonArray>
#include <QStringList>

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace prisca::devices {

namespace {

double cross(const cv::Point2d& o, const cv::Point2d& a, const cv::Point2d& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Whether segments ab and cd cross at a point inside both (touching ends do not count).
bool segmentsCross(const cv::Point2d& a, const cv::Point2d& b, const cv::Point2d& c,
                   const cv::Point2d& d) {
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

}  // namespace

bool Geofence::contains(const cv::Point2d& floor) const {
    if (polygon.size() < 3) {
        return true;
    }
    std::vector<cv::Point2f> contour;
    for (const cv::Point2d& p : polygon) {
        contour.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    }
    return cv::pointPolygonTest(
               contour, cv::Point2f(static_cast<float>(floor.x), static_cast<float>(floor.y)),
               false) >= 0.0;
}

QString Geofence::breach(const std::optional<PlanarPose>& pose, double speed,
                         double lostSeconds) const {
    if (maxLostSeconds > 0.0 && lostSeconds > maxLostSeconds) {
        return QStringLiteral("the track was lost for %1 s (the fence allows %2 s)")
            .arg(lostSeconds, 0, 'f', 2)
            .arg(maxLostSeconds, 0, 'f', 2);
    }
    if (!pose) {
        return {};
    }
    if (!contains({pose->x, pose->y})) {
        return QStringLiteral("the car left the fence at (%1, %2) m")
            .arg(pose->x, 0, 'f', 2)
            .arg(pose->y, 0, 'f', 2);
    }
    if (maxSpeed > 0.0 && speed > maxSpeed) {
        return QStringLiteral("the car drove at %1 m/s, over the fence's %2 m/s")
            .arg(speed, 0, 'f', 2)
            .arg(maxSpeed, 0, 'f', 2);
    }
    return {};
}

QString Geofence::problem() const {
    if (!(std::isfinite(maxSpeed) && maxSpeed >= 0.0)) {
        return QStringLiteral("the speed limit must be 0 (none) or more m/s");
    }
    if (!(std::isfinite(maxLostSeconds) && maxLostSeconds >= 0.0)) {
        return QStringLiteral("the longest lost track must be 0 (none) or more s");
    }
    if (polygon.empty()) {
        return {};
    }
    if (polygon.size() < 3) {
        return QStringLiteral("a fence needs at least 3 corners, %1 given").arg(polygon.size());
    }
    for (size_t i = 0; i < polygon.size(); ++i) {
        if (!std::isfinite(polygon[i].x) || !std::isfinite(polygon[i].y) ||
            std::abs(polygon[i].x) > 1000.0 || std::abs(polygon[i].y) > 1000.0) {
            return QStringLiteral("fence corner %1 is not a floor point within +-1000 m")
                .arg(i + 1);
        }
    }
    const size_t n = polygon.size();
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = i + 1; j < n; ++j) {
            if (segmentsCross(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) {
                return QStringLiteral(
                           "the fence's edges %1 and %2 cross: give its corners in "
                           "order around it")
                    .arg(i + 1)
                    .arg(j + 1);
            }
        }
    }
    double area = 0.0;
    for (size_t i = 0; i < n; ++i) {
        area += cross({0, 0}, polygon[i], polygon[(i + 1) % n]);
    }
    if (std::abs(area) / 2.0 < 0.01) {
        return QStringLiteral("the fence encloses %1 m^2: its corners lie (nearly) on one line")
            .arg(std::abs(area) / 2.0, 0, 'g', 2);
    }
    return {};
}

std::optional<std::vector<cv::Point2d>> Geofence::parsePolygon(const QString& text,
                                                               QString* error) {
    std::vector<cv::Point2d> points;
    QStringList corners;
    for (const QString& corner : text.split(QLatin1Char(';'))) {
        if (!corner.trimmed().isEmpty()) {
            corners << corner;
        }
    }
    for (int i = 0; i < corners.size(); ++i) {
        const QStringList xy = corners[i].split(QLatin1Char(','));
        bool okX = false, okY = false;
        const double x = xy.value(0).trimmed().toDouble(&okX);
        const double y = xy.value(1).trimmed().toDouble(&okY);
        if (xy.size() != 2 || !okX || !okY || !std::isfinite(x) || !std::isfinite(y)) {
            *error = QStringLiteral("fence corner %1 '%2' is not \"x,y\" in metres")
                         .arg(i + 1)
                         .arg(corners[i]);
            return std::nullopt;
        }
        points.emplace_back(x, y);
    }
    return points;
}

QJsonObject Geofence::toJson() const {
    QJsonArray corners;
    for (const cv::Point2d& p : polygon) {
        corners.append(QJsonArray{p.x, p.y});
    }
    return {{"polygon", corners}, {"max_speed_mps", maxSpeed}, {"max_lost_s", maxLostSeconds}};
}

std::optional<Geofence> Geofence::fromJson(const QJsonObject& object, QString* error) {
    Geofence fence;
    const QJsonArray corners = object.value("polygon").toArray();
    for (int i = 0; i < corners.size(); ++i) {
        const QJsonArray xy = corners[i].toArray();
        if (xy.size() != 2 || !xy[0].isDouble() || !xy[1].isDouble()) {
            *error =
                QStringLiteral("fence 'polygon' corner %1 must be [x, y] in metres").arg(i + 1);
            return std::nullopt;
        }
        fence.polygon.emplace_back(xy[0].toDouble(), xy[1].toDouble());
    }
    fence.maxSpeed = object.value("max_speed_mps").toDouble(0.0);
    fence.maxLostSeconds = object.value("max_lost_s").toDouble(0.0);
    if (const QString p = fence.problem(); !p.isEmpty()) {
        *error = p;
        return std::nullopt;
    }
    return fence;
}

}  // namespace prisca::devices
