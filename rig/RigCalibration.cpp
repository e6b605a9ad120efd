#include "rig/RigCalibration.h"

#include "devices/SyntheticCamera.h"
#include "rig/RigSession.h"

#include <QStringList>

namespace prisca::rig {

RigCalibration::RigCalibration(RigSession& session) : session_(session) {}

void RigCalibration::beginFloorPoints() {
    clicked_.clear();
}

SetupStep RigCalibration::addFloorPoint(const cv::Point2d& image, const cv::Point2d& floor) {
    clicked_.push_back({image, floor});
    if (clicked_.size() < 4) {
        return {false, tr("%1 point(s) clicked; at least 4 are needed.").arg(clicked_.size())};
    }
    QString error;
    const auto fit = devices::FloorCalibration::fit(clicked_, &error, lens_);
    if (!fit) {
        return {false, error};
    }
    session_.setCalibration(*fit);
    return {true, floorSummary()};
}

std::optional<cv::Point2d> RigCalibration::parseFloorPoint(const QString& text, QString* error) {
    const QStringList parts = text.split(QLatin1Char(','));
    bool okX = false;
    bool okY = false;
    const double x = parts.value(0).trimmed().toDouble(&okX);
    const double y = parts.value(1).trimmed().toDouble(&okY);
    if (parts.size() != 2 || !okX || !okY) {
        if (error) {
            *error = tr("'%1' is not two numbers \"x, y\" in metres.").arg(text);
        }
        return std::nullopt;
    }
    return cv::Point2d(x, y);
}

SetupStep RigCalibration::loadFloor(const QString& path) {
    QString error;
    if (!session_.loadCalibration(path, &error)) {
        return {false, tr("The calibration could not be read.\n\n%1").arg(error)};
    }
    return {true, floorSummary()};
}

SetupStep RigCalibration::saveFloor(const QString& path) const {
    QString error;
    if (!session_.saveCalibration(path, &error)) {
        return {false, error};
    }
    return {true, floorSummary()};
}

QString RigCalibration::floorSummary() const {
    const devices::FloorCalibration& calibration = session_.calibration();
    return tr("Floor calibration: %1 points, reprojection error %2 cm")
        .arg(calibration.points.size())
        .arg(calibration.rmsMetres * 100.0, 0, 'f', 2);
}

QString RigCalibration::floorProblem(bool virtualCamera) const {
    // The rig starts with the synthetic camera's calibration: right for the virtual rig, wrong
    // for any real camera until the operator calibrates it or opens its calibration.
    if (virtualCamera ||
        session_.calibration().toJson() != devices::syntheticCeilingCamera().toJson()) {
        return {};
    }
    return tr(
        "The floor calibration is the virtual rig's, not this camera's: calibrate this "
        "camera (Calibrate, then click four or more floor points) or open its "
        "calibration before driving or a trial.");
}

SetupStep RigCalibration::captureBoardView(const cv::Mat& frame) {
    if (frame.empty()) {
        return {false, tr("Lens: no camera image to capture a board view from.")};
    }
    std::vector<cv::Point2f> corners = devices::findBoardCorners(frame, devices::BoardSpec{});
    if (corners.empty()) {
        return {false, tr("Lens: no whole 9 x 6 board in this view (%1 captured). Hold the "
                          "board so all of it is seen, still, and try again.")
                           .arg(boardViews_.size())};
    }
    boardViews_.push_back(std::move(corners));
    boardImageSize_ = frame.size();
    return {true, lensSummary()};
}

std::vector<cv::Point2f> RigCalibration::capturedCorners() const {
    std::vector<cv::Point2f> all;
    for (const auto& view : boardViews_) {
        all.insert(all.end(), view.begin(), view.end());
    }
    return all;
}

SetupStep RigCalibration::fitLens() {
    QString error;
    auto lens = devices::calibrateLensFromCorners(boardViews_, devices::BoardSpec{},
                                                  boardImageSize_, &error);
    if (lens) {
        if (const QString problem = lens->plausibilityProblem(); !problem.isEmpty()) {
            error = tr("refused: %1").arg(problem);
            lens.reset();
        }
    }
    if (!lens) {
        return {false, tr("Lens: %1").arg(error)};
    }
    lens_ = std::move(lens);
    boardViews_.clear();
    refitFloorUnderLens();
    return {true, lensSummary()};
}

SetupStep RigCalibration::loadLens(const QString& path) {
    QString error;
    auto lens = devices::CameraLens::load(path, &error);
    if (!lens) {
        return {false, error};
    }
    lens_ = std::move(lens);
    refitFloorUnderLens();
    return {true, lensSummary()};
}

bool RigCalibration::saveLens(const QString& path, QString* error) const {
    if (!lens_) {
        if (error) {
            *error = tr("No lens has been fitted or opened.");
        }
        return false;
    }
    return lens_->save(path, error);
}

void RigCalibration::refitFloorUnderLens() {
    if (session_.calibration().points.size() < 4) {
        return;
    }
    QString ignored;  // points that fitted before fit under a plausible lens; else kept as was
    if (const auto refit = session_.calibration().withLens(lens_, &ignored)) {
        session_.setCalibration(*refit);
    }
}

QString RigCalibration::lensSummary() const {
    QString text;
    if (lens_) {
        text = tr("Lens: fx %1 px, k1 %2, k2 %3; RMS %4 px.")
                   .arg(lens_->matrix(0, 0), 0, 'f', 1)
                   .arg(lens_->distortion[0], 0, 'f', 3)
                   .arg(lens_->distortion[1], 0, 'f', 3)
                   .arg(lens_->rmsPixels, 0, 'f', 3);
    } else {
        text = tr("Lens: none (the floor calibration is a homography alone).");
    }
    if (!boardViews_.empty()) {
        text += QLatin1Char(' ') +
                tr("%1 board view(s) captured (at least %2; move the board over the whole "
                   "image, its corners too).")
                    .arg(boardViews_.size())
                    .arg(devices::kMinLensViews);
    }
    return text;
}

void RigCalibration::addFenceCorner(const cv::Point2d& floor) {
    fenceCorners_.push_back(floor);
    applyFence();
}

void RigCalibration::addFenceCornerAt(const cv::Point2d& image) {
    addFenceCorner(session_.calibration().toFloor(image));
}

void RigCalibration::setFenceCorners(const std::vector<cv::Point2d>& corners) {
    fenceCorners_ = corners;
    applyFence();
}

void RigCalibration::clearFence() {
    fenceCorners_.clear();
    applyFence();
}

void RigCalibration::setFenceLimits(double maxSpeed, double maxLostSeconds) {
    fenceMaxSpeed_ = maxSpeed;
    fenceMaxLostSeconds_ = maxLostSeconds;
    applyFence();
}

QString RigCalibration::fencePolygonText() const {
    QStringList corners;
    for (const cv::Point2d& p : fenceCorners_) {
        corners << QStringLiteral("%1,%2").arg(p.x, 0, 'g', 10).arg(p.y, 0, 'g', 10);
    }
    return corners.join(QLatin1Char(';'));
}

void RigCalibration::applyFence() {
    QString ignored;
    session_.setGeofence(fenceInForce(&ignored));
}

QString RigCalibration::fenceSummary() const {
    QString summary;  // in the language now
    fenceInForce(&summary);
    return summary;
}

devices::Geofence RigCalibration::fenceInForce(QString* summary) const {
    devices::Geofence fence;
    fence.polygon = fenceCorners_;
    fence.maxSpeed = fenceMaxSpeed_;
    fence.maxLostSeconds = fenceMaxLostSeconds_;
    QString problem = fence.problem();
    if (fence.polygon.size() < 3) {
        problem.clear();
        fence.polygon.clear();  // not a fence yet: the limits alone
    }
    if (!problem.isEmpty()) {
        *summary = tr("Fence: %1").arg(problem);
        fence.polygon.clear();
    } else if (fenceCorners_.size() >= 3) {
        *summary = tr("Fence: %1 corners; a car outside it ends the trial in failsafe.")
                       .arg(fenceCorners_.size());
    } else {
        *summary =
            tr("Fence: none (%1 corner(s) clicked; 3 or more make one).").arg(fenceCorners_.size());
    }
    return fence;
}

}  // namespace prisca::rig
