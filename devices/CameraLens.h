#pragma once

#include <QByteArray>
#include <QJsonObject>
#include <QString>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace prisca::devices {

/// A chessboard's inner corners (columns x rows, OpenCV's pattern size) and its square's side.
struct BoardSpec {
    cv::Size innerCorners{9, 6};
    double squareMetres = 0.04;
    /// Whether the fit frees k3 too. Off by default: k1 and k2 describe a lens up to a wide
    /// one, and a free k3 fitted on boards that cannot reach the image's corners (their quiet
    /// zone keeps the corners a few squares in) bends the model wildly just beyond them (25 px
    /// there, measured on generated views of a k1 = -0.3 lens; under 1 px with k3 fixed).
    bool fitK3 = false;
};

/// One view given to the lens calibration: its name (the file) and whether the board was found
/// in it; if so its RMS reprojection error after the fit [px].
struct LensView {
    QString name;
    bool found = false;
    double errorPixels = 0.0;
};

/// A camera's intrinsics: the pinhole matrix and OpenCV's distortion (k1, k2, p1, p2, k3) for
/// the image size they were fitted at. undistort() maps a pixel of the real image to where an
/// ideal pinhole camera with the same matrix would see it; distort() is its inverse. JSON:
/// {"camera_matrix": [9, row-major], "distortion": [k1, k2, p1, p2, k3], "image_size": [w, h],
///  "rms_px": ..., "views": [{"name", "found", "error_px"}]}.
struct CameraLens {
    cv::Matx33d matrix = cv::Matx33d::eye();
    cv::Vec<double, 5> distortion{0, 0, 0, 0, 0};
    cv::Size imageSize{640, 480};
    double rmsPixels = 0.0;  ///< the fit's RMS reprojection error over every corner [px]
    std::vector<LensView> views;

    cv::Point2d undistort(const cv::Point2d& pixel) const;
    /// Where the real image shows what the ideal camera sees at `ideal`. A point beyond the
    /// radius at which the distortion folds back (outside the lens's field) maps far outside
    /// the image, never back into it.
    cv::Point2d distort(const cv::Point2d& ideal) const;

    /// Empty when these intrinsics are ones a real camera can have and the fit is good enough
    /// to track with; else what is wrong, with the figure.
    QString plausibilityProblem() const;
    /// The largest RMS reprojection error accepted [px]: a corner found to a fraction of a
    /// pixel fits a good lens model to well below it; more is a wrong board size, a blurred
    /// view or a model that does not fit.
    static constexpr double kMaxRmsPixels = 1.0;

    bool sameModel(const CameraLens& other) const;

    QJsonObject toJsonObject() const;
    static std::optional<CameraLens> fromJsonObject(const QJsonObject& object, QString* error);
    QByteArray toJson() const;
    static std::optional<CameraLens> fromJson(const QByteArray& json, QString* error);
    static constexpr qint64 kMaxJsonBytes = qint64(1) << 20;
    static std::optional<CameraLens> load(const QString& path, QString* error);
    bool save(const QString& path, QString* error) const;
};

/// Finds the board's inner corners in an 8-bit grey or BGR image (findChessboardCorners, then
/// cornerSubPix); empty if the board is not all in view.
std::vector<cv::Point2f> findBoardCorners(const cv::Mat& image, const BoardSpec& board);

/// Fits the intrinsics to the views (calibrateCamera). Views without the board are listed in
/// the result, not fatal; fewer than kMinLensViews with it is an error. All views must have one
/// size. On failure nullopt and *error says why.
constexpr int kMinLensViews = 4;
std::optional<CameraLens> calibrateLens(const std::vector<QString>& names,
                                        const std::vector<cv::Mat>& images, const BoardSpec& board,
                                        QString* error);

/// Same, from corners already found (one vector per view that showed the board).
std::optional<CameraLens> calibrateLensFromCorners(
    const std::vector<std::vector<cv::Point2f>>& corners, const BoardSpec& board,
    cv::Size imageSize, QString* error);

}  // namespace prisca::devices
