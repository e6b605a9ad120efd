#include "devices/CameraLens.h"

#include "core/FileIo.h"
#include "devices/JsonFile.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace prisca::devices {

namespace {

// The radial factor 1 + k1 r^2 + k2 r^4 + k3 r^6 and whether r is inside the radius where
// r * factor still grows with r (beyond it the model folds the outside of the field back in).
bool radialInField(const cv::Vec<double, 5>& d, double r2) {
    return 1.0 + 3.0 * d[0] * r2 + 5.0 * d[1] * r2 * r2 + 7.0 * d[4] * r2 * r2 * r2 > 0.0;
}

}  // namespace

cv::Point2d CameraLens::undistort(const cv::Point2d& pixel) const {
    const std::vector<cv::Point2d> in{pixel};
    std::vector<cv::Point2d> out;
    // The default five iterations leave a wide lens's corners pixels off; these converge to
    // well below a thousandth of a pixel.
    cv::undistortPoints(
        in, out, cv::Mat(matrix), cv::Mat(distortion), cv::noArray(), cv::Mat(matrix),
        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
    return out.front();
}

cv::Point2d CameraLens::distort(const cv::Point2d& ideal) const {
    const double fx = matrix(0, 0), fy = matrix(1, 1), cx = matrix(0, 2), cy = matrix(1, 2);
    const double x = (ideal.x - cx) / fx, y = (ideal.y - cy) / fy;
    const double r2 = x * x + y * y;
    const cv::Vec<double, 5>& d = distortion;
    if (!radialInField(d, r2)) {
        return {-1e6, -1e6};  // outside the lens's field: nowhere in the image
    }
    const double radial = 1.0 + d[0] * r2 + d[1] * r2 * r2 + d[4] * r2 * r2 * r2;
    const double xd = x * radial + 2.0 * d[2] * x * y + d[3] * (r2 + 2.0 * x * x);
    const double yd = y * radial + d[2] * (r2 + 2.0 * y * y) + 2.0 * d[3] * x * y;
    return {fx * xd + cx, fy * yd + cy};
}

QString CameraLens::plausibilityProblem() const {
    for (double v : matrix.val) {
        if (!std::isfinite(v)) {
            return QStringLiteral("the camera matrix has an entry that is not a finite number");
        }
    }
    for (double v : distortion.val) {
        if (!std::isfinite(v)) {
            return QStringLiteral("a distortion coefficient is not a finite number");
        }
    }
    if (imageSize.width < 16 || imageSize.height < 16 || imageSize.width > 100000 ||
        imageSize.height > 100000) {
        return QStringLiteral("image size %1 x %2 px is not a camera's")
            .arg(imageSize.width)
            .arg(imageSize.height);
    }
    const double fx = matrix(0, 0), fy = matrix(1, 1);
    // A focal length from a tenth of the width (a fisheye's, beyond this model) to 20 widths
    // (a telephoto, useless over a floor).
    const double w = imageSize.width;
    if (!(fx > 0.1 * w && fx < 20.0 * w && fy > 0.1 * w && fy < 20.0 * w)) {
        return QStringLiteral(
                   "focal length fx %1, fy %2 px is not plausible for a %3 px wide "
                   "image (from %4 to %5 px)")
            .arg(fx, 0, 'f', 1)
            .arg(fy, 0, 'f', 1)
            .arg(imageSize.width)
            .arg(0.1 * w, 0, 'f', 0)
            .arg(20.0 * w, 0, 'f', 0);
    }
    if (!(std::abs(fx / fy - 1.0) < 0.2)) {
        return QStringLiteral("fx / fy = %1: pixels that far from square are a wrong fit")
            .arg(fx / fy, 0, 'f', 3);
    }
    const double cx = matrix(0, 2), cy = matrix(1, 2);
    if (!(cx > 0.0 && cx < imageSize.width && cy > 0.0 && cy < imageSize.height)) {
        return QStringLiteral("the principal point (%1, %2) px lies outside the %3 x %4 image")
            .arg(cx, 0, 'f', 1)
            .arg(cy, 0, 'f', 1)
            .arg(imageSize.width)
            .arg(imageSize.height);
    }
    if (matrix(0, 1) != 0.0 || matrix(1, 0) != 0.0 || matrix(2, 0) != 0.0 || matrix(2, 1) != 0.0 ||
        matrix(2, 2) != 1.0) {
        return QStringLiteral("the camera matrix must be [fx 0 cx; 0 fy cy; 0 0 1]");
    }
    // The model must not fold inside the image: at the corner farthest from the principal
    // point (in ideal coordinates, found by undistorting it) the map still grows and turns
    // back into the corner.
    const auto foldsAtACorner = [&](const CameraLens& lens) {
        for (const cv::Point2d corner :
             {cv::Point2d(0, 0), cv::Point2d(w, 0), cv::Point2d(0, imageSize.height),
              cv::Point2d(w, imageSize.height)}) {
            const cv::Point2d ideal = lens.undistort(corner);
            const double x = (ideal.x - cx) / fx, y = (ideal.y - cy) / fy;
            if (!std::isfinite(x) || !std::isfinite(y) ||
                !radialInField(lens.distortion, x * x + y * y) ||
                cv::norm(lens.distort(ideal) - corner) > 0.05) {
                return true;
            }
        }
        return false;
    };
    if (foldsAtACorner(*this)) {
        // Which terms fold it: the radial ones alone, or the tangential ones with them.
        CameraLens radialOnly = *this;
        radialOnly.distortion[2] = radialOnly.distortion[3] = 0.0;
        if (!foldsAtACorner(radialOnly)) {
            return QStringLiteral(
                       "the tangential distortion (p1 %1, p2 %2) folds the image back on itself at "
                       "its "
                       "corners (the radial terms alone do not): a lens this model cannot "
                       "describe, or "
                       "a fit without views near the corners")
                .arg(distortion[2], 0, 'g', 3)
                .arg(distortion[3], 0, 'g', 3);
        }
        return QStringLiteral(
                   "the distortion (k1 %1, k2 %2, k3 %3) folds the image back on itself at its "
                   "corners: a lens this model cannot describe, or a fit without views near the "
                   "corners")
            .arg(distortion[0], 0, 'g', 3)
            .arg(distortion[1], 0, 'g', 3)
            .arg(distortion[4], 0, 'g', 3);
    }
    if (!(rmsPixels >= 0.0 && rmsPixels <= kMaxRmsPixels)) {
        return QStringLiteral(
                   "the fit's RMS reprojection error is %1 px, above the %2 px a "
                   "board found to a fraction of a pixel gives (wrong --board or "
                   "--square? blurred views?)")
            .arg(rmsPixels, 0, 'f', 3)
            .arg(kMaxRmsPixels, 0, 'f', 1);
    }
    return {};
}

bool CameraLens::sameModel(const CameraLens& other) const {
    return matrix == other.matrix && distortion == other.distortion && imageSize == other.imageSize;
}

QJsonObject CameraLens::toJsonObject() const {
    QJsonArray k, d, vs;
    for (double v : matrix.val) {
        k.append(v);
    }
    for (double v : distortion.val) {
        d.append(v);
    }
    for (const LensView& v : views) {
        QJsonObject o{{"name", v.name}, {"found", v.found}};
        if (v.found) {
            o.insert("error_px", v.errorPixels);
        }
        vs.append(o);
    }
    return {{"camera_matrix", k},
            {"distortion", d},
            {"image_size", QJsonArray{imageSize.width, imageSize.height}},
            {"rms_px", rmsPixels},
            {"views", vs}};
}

std::optional<CameraLens> CameraLens::fromJsonObject(const QJsonObject& root, QString* error) {
    CameraLens lens;
    const QJsonArray k = root.value("camera_matrix").toArray();
    if (k.size() != 9) {
        *error = QStringLiteral("'camera_matrix' must be a list of 9 numbers (row-major)");
        return std::nullopt;
    }
    for (int i = 0; i < 9; ++i) {
        if (!k[i].isDouble()) {
            *error = QStringLiteral("'camera_matrix' entry %1 is not a number").arg(i + 1);
            return std::nullopt;
        }
        lens.matrix.val[i] = k[i].toDouble();
    }
    const QJsonArray d = root.value("distortion").toArray();
    if (d.size() != 5) {
        *error = QStringLiteral("'distortion' must be a list of 5 numbers (k1, k2, p1, p2, k3)");
        return std::nullopt;
    }
    for (int i = 0; i < 5; ++i) {
        if (!d[i].isDouble()) {
            *error = QStringLiteral("'distortion' entry %1 is not a number").arg(i + 1);
            return std::nullopt;
        }
        lens.distortion[i] = d[i].toDouble();
    }
    const QJsonArray size = root.value("image_size").toArray();
    if (size.size() != 2 || !size[0].isDouble() || !size[1].isDouble()) {
        *error = QStringLiteral("'image_size' must be [width, height] in pixels");
        return std::nullopt;
    }
    const double width = size[0].toDouble(), height = size[1].toDouble();
    if (!(width >= 16 && width <= 100000 && height >= 16 && height <= 100000)) {
        *error = QStringLiteral("'image_size' %1 x %2 must be from 16 to 100000 px each")
                     .arg(width)
                     .arg(height);
        return std::nullopt;
    }
    lens.imageSize = cv::Size(static_cast<int>(width), static_cast<int>(height));
    const QJsonValue rms = root.value("rms_px");
    if (!rms.isUndefined()) {
        if (!rms.isDouble() || !(rms.toDouble() >= 0.0)) {
            *error = QStringLiteral("'rms_px' must be a number of pixels, 0 or more");
            return std::nullopt;
        }
        lens.rmsPixels = rms.toDouble();
    }
    for (const QJsonValue& v : root.value("views").toArray()) {
        const QJsonObject o = v.toObject();
        lens.views.push_back({o.value("name").toString(), o.value("found").toBool(),
                              o.value("error_px").toDouble()});
    }
    if (const QString problem = lens.plausibilityProblem(); !problem.isEmpty()) {
        *error = problem;
        return std::nullopt;
    }
    return lens;
}

QByteArray CameraLens::toJson() const {
    return QJsonDocument(toJsonObject()).toJson(QJsonDocument::Indented);
}

std::optional<CameraLens> CameraLens::fromJson(const QByteArray& json, QString* error) {
    const auto root = parseJsonObject(
        json,
        QStringLiteral("valid JSON, but not camera intrinsics: it must be an object such as "
                       "{\"camera_matrix\": [9 numbers], \"distortion\": [5 numbers], "
                       "\"image_size\": [w, h]}"),
        error);
    return root ? fromJsonObject(*root, error) : std::nullopt;
}

std::optional<CameraLens> CameraLens::load(const QString& path, QString* error) {
    return loadJsonFile<CameraLens>(path, error);
}

bool CameraLens::save(const QString& path, QString* error) const {
    return saveJsonFile(*this, path, error);
}

std::vector<cv::Point2f> findBoardCorners(const cv::Mat& image, const BoardSpec& board) {
    cv::Mat grey;
    if (image.channels() == 3) {
        cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    } else if (image.channels() == 4) {
        cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
    } else {
        grey = image;
    }
    if (grey.depth() != CV_8U) {
        return {};
    }
    std::vector<cv::Point2f> corners;
    // FAST_CHECK rejects a view with no board at once (the full search takes seconds there).
    const bool found = cv::findChessboardCorners(
        grey, board.innerCorners, corners,
        cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
    if (!found) {
        return {};
    }
    cv::cornerSubPix(grey, corners, cv::Size(5, 5), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 40, 0.001));
    return corners;
}

std::optional<CameraLens> calibrateLensFromCorners(
    const std::vector<std::vector<cv::Point2f>>& corners, const BoardSpec& board,
    cv::Size imageSize, QString* error) {
    if (static_cast<int>(corners.size()) < kMinLensViews) {
        *error = QStringLiteral(
                     "the board was found in %1 view(s); a lens calibration needs at "
                     "least %2, tilted and spread over the image, its corners too")
                     .arg(corners.size())
                     .arg(kMinLensViews);
        return std::nullopt;
    }
    if (!(board.squareMetres > 0.0) || board.innerCorners.width < 2 ||
        board.innerCorners.height < 2) {
        *error = QStringLiteral("the board needs at least 2 x 2 inner corners and a square > 0");
        return std::nullopt;
    }
    std::vector<cv::Point3f> model;
    for (int r = 0; r < board.innerCorners.height; ++r) {
        for (int c = 0; c < board.innerCorners.width; ++c) {
            model.emplace_back(static_cast<float>(c * board.squareMetres),
                               static_cast<float>(r * board.squareMetres), 0.0f);
        }
    }
    const std::vector<std::vector<cv::Point3f>> objects(corners.size(), model);
    cv::Mat k = cv::Mat::eye(3, 3, CV_64F), d = cv::Mat::zeros(5, 1, CV_64F);
    std::vector<cv::Mat> rvecs, tvecs;
    double rms = 0.0;
    try {
        rms = cv::calibrateCamera(
            objects, corners, imageSize, k, d, rvecs, tvecs, board.fitK3 ? 0 : cv::CALIB_FIX_K3,
            cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
    } catch (const cv::Exception& e) {
        *error = QStringLiteral("the lens fit failed: %1").arg(QString::fromStdString(e.msg));
        return std::nullopt;
    }
    CameraLens lens;
    lens.matrix = cv::Matx33d(k.ptr<double>());
    for (int i = 0; i < 5; ++i) {
        lens.distortion[i] = d.at<double>(i);
    }
    lens.imageSize = imageSize;
    lens.rmsPixels = rms;
    for (size_t v = 0; v < corners.size(); ++v) {
        std::vector<cv::Point2f> projected;
        cv::projectPoints(model, rvecs[v], tvecs[v], k, d, projected);
        double sum = 0.0;
        for (size_t i = 0; i < projected.size(); ++i) {
            const cv::Point2f e = projected[i] - corners[v][i];
            sum += e.x * e.x + e.y * e.y;
        }
        lens.views.push_back({QString(), true, std::sqrt(sum / projected.size())});
    }
    return lens;
}

std::optional<CameraLens> calibrateLens(const std::vector<QString>& names,
                                        const std::vector<cv::Mat>& images, const BoardSpec& board,
                                        QString* error) {
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<LensView> views;
    cv::Size size;
    for (size_t i = 0; i < images.size(); ++i) {
        const QString name = i < names.size() ? names[i] : QStringLiteral("view %1").arg(i + 1);
        if (images[i].empty()) {
            views.push_back({name, false, 0.0});
            continue;
        }
        if (size.empty()) {
            size = images[i].size();
        } else if (images[i].size() != size) {
            *error = QStringLiteral(
                         "%1 is %2 x %3 px, the views before it %4 x %5: every view "
                         "must come from the one camera at one resolution")
                         .arg(name)
                         .arg(images[i].cols)
                         .arg(images[i].rows)
                         .arg(size.width)
                         .arg(size.height);
            return std::nullopt;
        }
        std::vector<cv::Point2f> found = findBoardCorners(images[i], board);
        views.push_back({name, !found.empty(), 0.0});
        if (!found.empty()) {
            corners.push_back(std::move(found));
        }
    }
    auto lens = calibrateLensFromCorners(corners, board, size, error);
    if (!lens) {
        return std::nullopt;
    }
    // Put each fitted view's error beside its name, the views without a board in between.
    size_t fitted = 0;
    for (LensView& v : views) {
        if (v.found) {
            v.errorPixels = lens->views[fitted++].errorPixels;
        }
    }
    lens->views = std::move(views);
    return lens;
}

}  // namespace prisca::devices
