#pragma once

#include "devices/LedTracker.h"

#include <QJsonObject>
#include <QString>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace prisca::devices {

/// Where a trial on the rig may go, and how: a polygon on the floor [m], a speed limit [m/s]
/// and the longest the track may be lost [s]. Any one breached ends the trial in failsafe
/// (RigLoop). Each part is off when empty or 0. JSON: {"polygon": [[x, y], ...],
/// "max_speed_mps": ..., "max_lost_s": ...}.
struct Geofence {
    std::vector<cv::Point2d> polygon;  ///< floor [m], in order around it; < 3 points: none
    double maxSpeed = 0.0;             ///< [m/s]; 0: no limit
    double maxLostSeconds = 0.0;       ///< [s]; 0: no limit

    bool enabled() const { return polygon.size() >= 3 || maxSpeed > 0.0 || maxLostSeconds > 0.0; }
    /// Whether a floor point is inside the polygon (on its edge counts as inside); true when
    /// there is no polygon.
    bool contains(const cv::Point2d& floor) const;
    /// Why a frame breaches the fence, or empty: the pose outside the polygon, the speed over
    /// the limit, or the track lost for longer than allowed (`lostSeconds`, 0 while tracked).
    QString breach(const std::optional<PlanarPose>& pose, double speed, double lostSeconds) const;
    /// Empty when the fence is usable; else what is wrong (a self-crossing or degenerate
    /// polygon, a non-finite vertex, a negative limit).
    QString problem() const;

    /// "x,y;x,y;x,y..." [m]; on failure nullopt and *error names the vertex.
    static std::optional<std::vector<cv::Point2d>> parsePolygon(const QString& text,
                                                                QString* error);
    QJsonObject toJson() const;
    static std::optional<Geofence> fromJson(const QJsonObject& object, QString* error);
};

}  // namespace prisca::devices
