#pragma once

#include "devices/CameraLens.h"

#include <QByteArray>
#include <QString>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace prisca::devices {

/// One clicked point: where it is in the image [px] and on the floor [m].
struct CalibrationPoint {
    cv::Point2d image;
    cv::Point2d floor;
};

/// The floor calibration: the homography from image pixels to floor metres, fitted to four or
/// more points the operator clicked, and how well it fits them. JSON as docs/architecture.md gives
/// it:
/// {"homography": [h00..h22 row-major, image px -> floor m], "points": [...], "rms_m": ...,
///  "camera": {the lens, CameraLens's JSON; absent: none}}.
/// With a lens the homography maps the ideal (undistorted) image to the floor, and toFloor()
/// and toImage() take the lens's distortion off and put it back; the points keep the pixels as
/// clicked in the real image, so the calibration can be fitted again under another lens.
struct FloorCalibration {
    cv::Matx33d imageToFloor = cv::Matx33d::eye();
    std::vector<CalibrationPoint> points;
    std::optional<CameraLens> lens;
    double rmsMetres = 0.0;  ///< RMS distance between each point's floor position and its
                             ///< image point mapped to the floor [m]

    /// Fits the homography to the points (least squares over all of them). Needs four or more
    /// points within kMaxFloorMetres and kMaxImagePixels that determine it (four with no three
    /// on one line). On failure returns nullopt and *error says
    /// why.
    static std::optional<FloorCalibration> fit(const std::vector<CalibrationPoint>& points,
                                               QString* error,
                                               const std::optional<CameraLens>& lens = {});
    /// The same points fitted again under `lens` (none: the homography alone).
    std::optional<FloorCalibration> withLens(const std::optional<CameraLens>& lens,
                                             QString* error) const {
        return fit(points, error, lens);
    }
    /// The largest RMS residual a calibration to track with may have [m]: the tracker's own
    /// tolerance for the LED triangle's misfit (20 mm); a floor mapped worse than that breaks
    /// the triangle.
    static constexpr double kMaxRmsMetres = 0.02;
    /// Empty when the fit is good enough to track with; else the figure (RMS, the worst point)
    /// and what to do.
    QString accuracyProblem() const;

    /// How far from the origin a floor point may lie [m]; a lab floor is tens of metres, so 1 km
    /// is only a corrupt file.
    static constexpr double kMaxFloorMetres = 1000.0;
    /// How far from the origin an image point may lie [px]: larger than any sensor.
    static constexpr double kMaxImagePixels = 100000.0;
    /// Empty when imageToFloor is a homography a ceiling camera can have: finite, not singular,
    /// the image (a 640 x 480 frame and the points' extent) on one side of the
    /// horizon and mapped within kMaxFloorMetres; else what is wrong, for a message.
    QString homographyProblem() const;

    cv::Point2d toFloor(const cv::Point2d& image) const;
    cv::Point2d toImage(const cv::Point2d& floor) const;
    /// Per point, the distance between its floor position and its image point mapped [m].
    std::vector<double> residuals() const;

    QByteArray toJson() const;
    /// Reads the JSON; on failure nullopt and *error names the key and the problem.
    static std::optional<FloorCalibration> fromJson(const QByteArray& json, QString* error);
    /// The largest calibration file load() reads (a few hundred points take a few KB).
    static constexpr qint64 kMaxJsonBytes = qint64(1) << 20;
    /// Reads a file; errors name the file.
    static std::optional<FloorCalibration> load(const QString& path, QString* error);
    bool save(const QString& path, QString* error) const;
};

}  // namespace prisca::devices
