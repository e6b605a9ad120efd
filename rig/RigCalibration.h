#pragma once

#include "devices/CameraLens.h"
#include "devices/FloorCalibration.h"
#include "devices/Geofence.h"

#include <QCoreApplication>
#include <QString>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace prisca::rig {

class RigSession;

/// What one step of the rig's set-up did: `ok` when it took effect; `message` is what to tell
/// the operator either way (what was fitted, or why nothing was).
struct SetupStep {
    bool ok = false;
    QString message;
};

/// The set-up a lab does once per rig, as one workflow the front ends command and show: the
/// floor calibration from image points of known floor position, the lens (camera intrinsics)
/// from chessboard views, and the fence. It keeps what is in progress (the points clicked, the
/// board views captured, the fence's corners) and puts every result in the session it serves:
/// a floor fit or a new lens refits the session's calibration, each change of the fence its
/// geofence. A front end keeps no set-up state of its own; it shows the messages and the
/// summaries and stores what it wants to remember between runs (fencePolygonText()).
/// QtCore only; lives on the session's thread.
class RigCalibration {
    Q_DECLARE_TR_FUNCTIONS(prisca::rig::RigCalibration)
  public:
    explicit RigCalibration(RigSession& session);

    // The floor.
    /// Starts a new set of clicked points (the session's calibration stays until they fit).
    void beginFloorPoints();
    /// One point: where the camera sees it [px] and where it is on the floor [m]. From four
    /// points on, the points are fitted (under the lens, if there is one) and the fit becomes
    /// the session's calibration.
    SetupStep addFloorPoint(const cv::Point2d& image, const cv::Point2d& floor);
    int floorPointsClicked() const { return static_cast<int>(clicked_.size()); }
    /// "x, y" in metres as an operator types it; nullopt and *error says what is wrong.
    static std::optional<cv::Point2d> parseFloorPoint(const QString& text, QString* error);
    SetupStep loadFloor(const QString& path);
    SetupStep saveFloor(const QString& path) const;
    /// The session's calibration in a line: points and reprojection error.
    QString floorSummary() const;
    /// Empty, or why the floor calibration cannot be trusted with this camera: a real camera
    /// (a device or a video) with the virtual rig's calibration still in place.
    QString floorProblem(bool virtualCamera) const;

    // The lens.
    /// Finds the chessboard in `frame` (the newest camera image) and keeps its corners.
    SetupStep captureBoardView(const cv::Mat& frame);
    int boardViewsCaptured() const { return static_cast<int>(boardViews_.size()); }
    /// Every corner of every view captured [px], to draw over the image.
    std::vector<cv::Point2f> capturedCorners() const;
    /// Fits the lens to the views captured (refused if a real camera could not have it); the
    /// floor's points are fitted again under it. The views are used up.
    SetupStep fitLens();
    SetupStep loadLens(const QString& path);
    bool saveLens(const QString& path, QString* error) const;
    const std::optional<devices::CameraLens>& lens() const { return lens_; }
    /// The lens in a line, and the views captured towards the next fit.
    QString lensSummary() const;

    // The fence (floor metres). Each change is in force at once, in a trial under way too.
    void addFenceCorner(const cv::Point2d& floor);
    /// A corner where the camera sees `image` [px], through the session's calibration.
    void addFenceCornerAt(const cv::Point2d& image);
    void setFenceCorners(const std::vector<cv::Point2d>& corners);
    void clearFence();
    /// [m/s] and [s]; 0: no limit.
    void setFenceLimits(double maxSpeed, double maxLostSeconds);
    const std::vector<cv::Point2d>& fenceCorners() const { return fenceCorners_; }
    /// What the fence is now (in force, not yet, or what is wrong with it).
    QString fenceSummary() const;
    /// The corners as "x,y;x,y;..." (devices::Geofence::parsePolygon reads it back).
    QString fencePolygonText() const;

  private:
    void applyFence();
    /// The fence the corners and limits make (corners that do not make one left out) and,
    /// in *summary, what it is.
    devices::Geofence fenceInForce(QString* summary) const;
    /// The session's calibration fitted again under the lens (its points, four or more).
    void refitFloorUnderLens();

    RigSession& session_;
    std::vector<devices::CalibrationPoint> clicked_;
    std::vector<std::vector<cv::Point2f>> boardViews_;
    cv::Size boardImageSize_;
    std::optional<devices::CameraLens> lens_;
    std::vector<cv::Point2d> fenceCorners_;
    double fenceMaxSpeed_ = 0.0;
    double fenceMaxLostSeconds_ = 0.0;
};

}  // namespace prisca::rig
