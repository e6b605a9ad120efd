// prisca-cli calibrate-camera: the lens's intrinsics from chessboard views.
// prisca-cli calibrate-floor: the floor calibration from measured points, under that lens.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "core/FileIo.h"
#include "devices/CameraLens.h"
#include "devices/FloorCalibration.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace prisca::app::cli {

namespace {

devices::BoardSpec parseBoard(const CommandLine& line) {
    devices::BoardSpec board;
    const QStringList wh = line.value("board").toLower().split(QLatin1Char('x'));
    bool okW = false, okH = false;
    const int w = wh.value(0).trimmed().toInt(&okW), h = wh.value(1).trimmed().toInt(&okH);
    if (wh.size() != 2 || !okW || !okH || w < 3 || h < 3 || w > 50 || h > 50) {
        throw UsageError(QStringLiteral("--board: '%1' is not COLUMNSxROWS of inner corners, "
                                        "each from 3 to 50 (e.g. 9x6)")
                             .arg(line.value("board")));
    }
    board.innerCorners = cv::Size(w, h);
    board.squareMetres = line.number("square", 0.001, 1.0);
    board.fitK3 = line.isSet("k3");
    return board;
}

// The largest image calibrate-camera reads [bytes]: a 50-megapixel PNG is about this.
constexpr qint64 kMaxImageBytes = qint64(200) << 20;

}  // namespace

int calibrateCameraCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("calibrate-camera"),
        QStringLiteral("Fit the camera's intrinsics (focal length, principal point, lens "
                       "distortion) to views of a chessboard: every image in a folder, the board "
                       "tilted and moved over the whole image, its corners too. Views without "
                       "the board are listed, not fatal."));
    line.addValue("images", "Folder of the views (PNG, JPEG, BMP, TIFF).", "dir");
    line.addValue("board", "Inner corners of the board, columns x rows.", "CxR", "9x6");
    line.addValue("square", "Side of one square.", "m", "0.04");
    line.addFlag("k3",
                 "Fit the third radial coefficient too (very wide lenses; with boards "
                 "that do not reach the image's corners it bends the model there).");
    line.addValue("out", "Camera intrinsics JSON to write.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const devices::BoardSpec board = parseBoard(line);
    const QString folder = line.required("images");
    const QString out = line.required("out");
    const QFileInfo info(folder);
    if (!info.exists()) {
        throw UsageError(QStringLiteral("--images %1: no such folder").arg(folder));
    }
    if (!info.isDir()) {
        throw UsageError(QStringLiteral("--images %1: not a folder").arg(folder));
    }
    const QStringList files =
        QDir(folder).entryList({"*.png", "*.PNG", "*.jpg", "*.JPG", "*.jpeg", "*.JPEG", "*.bmp",
                                "*.BMP", "*.tif", "*.tiff", "*.TIF", "*.TIFF"},
                               QDir::Files, QDir::Name);
    if (files.isEmpty()) {
        throw UsageError(
            QStringLiteral("--images %1: no PNG, JPEG, BMP or TIFF image in it").arg(folder));
    }
    installInterruptHandler();
    std::vector<QString> names;
    std::vector<cv::Mat> images;
    QStringList unreadable;
    for (int i = 0; i < files.size() && !interrupted(); ++i) {
        const QString path = QDir(folder).filePath(files[i]);
        core::FileError fileError;
        cv::Mat image;
        // A regular file of a sane size only: a FIFO would block the decoder.
        if (core::checkRegularFile(path, kMaxImageBytes, &fileError)) {
            image = cv::imread(path.toStdString(), cv::IMREAD_GRAYSCALE);
        }
        if (image.empty()) {
            unreadable << files[i];
        }
        names.push_back(files[i]);
        images.push_back(image);
        printProgress(
            QStringLiteral("calibrate-camera: read %1 of %2 views").arg(i + 1).arg(files.size()));
    }
    printProgress(QString());
    if (interrupted()) {
        std::fprintf(stderr, "prisca-cli: calibrate-camera: stopped by %s; nothing written\n",
                     interruptionName().toLatin1().constData());
        return interruptedExitCode();
    }
    QString error;
    const auto lens = devices::calibrateLens(names, images, board, &error);
    if (!lens) {
        throw UsageError(QStringLiteral("--images %1: %2").arg(folder, error));
    }
    if (const QString problem = lens->plausibilityProblem(); !problem.isEmpty()) {
        throw UsageError(QStringLiteral("refused: %1").arg(problem));
    }
    const QString written = writeOutput(out, lens->toJson(), true);
    QStringList missing;
    for (const devices::LensView& v : lens->views) {
        if (!v.found) {
            missing << v.name;
        }
    }
    if (line.format() == QLatin1String("json")) {
        QJsonObject o = lens->toJsonObject();
        o.insert("out", written);
        o.insert("without_board", QJsonArray::fromStringList(missing));
        o.insert("unreadable", QJsonArray::fromStringList(unreadable));
        printJson(o);
    } else {
        QString text;
        for (const devices::LensView& v : lens->views) {
            text += v.found
                        ? QStringLiteral("  %1: %2 px\n").arg(v.name).arg(v.errorPixels, 0, 'f', 3)
                        : QStringLiteral("  %1: no board found\n").arg(v.name);
        }
        text += QStringLiteral(
                    "%1 of %2 views used; RMS reprojection error %3 px\n"
                    "fx %4, fy %5, cx %6, cy %7 px; k1 %8, k2 %9, p1 %10, p2 %11, "
                    "k3 %12\nwrote %13\n")
                    .arg(lens->views.size() - missing.size())
                    .arg(lens->views.size())
                    .arg(lens->rmsPixels, 0, 'f', 3)
                    .arg(lens->matrix(0, 0), 0, 'f', 1)
                    .arg(lens->matrix(1, 1), 0, 'f', 1)
                    .arg(lens->matrix(0, 2), 0, 'f', 1)
                    .arg(lens->matrix(1, 2), 0, 'f', 1)
                    .arg(lens->distortion[0], 0, 'g', 4)
                    .arg(lens->distortion[1], 0, 'g', 4)
                    .arg(lens->distortion[2], 0, 'g', 4)
                    .arg(lens->distortion[3], 0, 'g', 4)
                    .arg(lens->distortion[4], 0, 'g', 4)
                    .arg(written);
        printText(text);
    }
    if (!unreadable.isEmpty()) {
        std::fprintf(stderr, "prisca-cli: calibrate-camera: warning: could not read %s\n",
                     qPrintable(unreadable.join(QStringLiteral(", "))));
    }
    return 0;
}

int calibrateFloorCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("calibrate-floor"),
        QStringLiteral("Fit the floor calibration (camera image -> floor metres) to measured "
                       "points, through the lens's intrinsics when given. Refused when it fits "
                       "the points worse than the tracker tolerates."));
    line.addValue("points",
                  "CSV, one point per line: u, v (image px), x, y (floor m); '#' comments and a "
                  "header line allowed. At least 4 points, spread over the floor.",
                  "file");
    line.addValue("camera", "Camera intrinsics JSON (from calibrate-camera).", "file");
    line.addValue("out", "Floor calibration JSON to write.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString pointsPath = line.required("points");
    const QString out = line.required("out");
    std::optional<devices::CameraLens> lens;
    QString error;
    if (line.isSet("camera")) {
        lens = devices::CameraLens::load(line.value("camera"), &error);
        if (!lens) {
            throw UsageError(error);
        }
    }
    core::FileError fileError;
    const std::optional<QByteArray> text =
        core::readFileBounded(pointsPath, qint64(16) << 20, &fileError);
    if (!text) {
        throw UsageError(fileError.toString());
    }
    std::vector<devices::CalibrationPoint> points;
    const QList<QByteArray> rows = text->split('\n');
    for (int i = 0; i < rows.size(); ++i) {
        const QByteArray row = rows[i].trimmed();
        if (row.isEmpty() || row.startsWith('#')) {
            continue;
        }
        const QList<QByteArray> fields = row.split(',');
        double v[4] = {0, 0, 0, 0};
        bool ok = fields.size() == 4;
        for (int k = 0; ok && k < 4; ++k) {
            v[k] = fields[k].trimmed().toDouble(&ok);
            ok = ok && std::isfinite(v[k]);
        }
        if (!ok) {
            if (points.empty() && !row.isEmpty() &&
                !std::isdigit(static_cast<unsigned char>(row[0])) && row[0] != '-' &&
                row[0] != '+' && row[0] != '.') {
                continue;  // a header line
            }
            throw UsageError(
                core::printable(QStringLiteral("%1:%2: '%3' is not four numbers u, v, x, y")
                                    .arg(pointsPath)
                                    .arg(i + 1)
                                    .arg(QString::fromUtf8(row.left(80)))));
        }
        points.push_back({{v[0], v[1]}, {v[2], v[3]}});
    }
    const auto calibration = devices::FloorCalibration::fit(points, &error, lens);
    if (!calibration) {
        throw UsageError(QStringLiteral("%1: %2").arg(pointsPath, error));
    }
    if (const QString problem = calibration->accuracyProblem(); !problem.isEmpty()) {
        throw UsageError(QStringLiteral("refused: %1").arg(problem));
    }
    const QString written = writeOutput(out, calibration->toJson(), true);
    const std::vector<double> residuals = calibration->residuals();
    const double worst = *std::max_element(residuals.begin(), residuals.end());
    if (line.format() == QLatin1String("json")) {
        QJsonArray r;
        for (double e : residuals) {
            r.append(e);
        }
        printJson({{"points", int(points.size())},
                   {"rms_m", calibration->rmsMetres},
                   {"largest_m", worst},
                   {"residuals_m", r},
                   {"lens", bool(lens)},
                   {"out", written}});
    } else {
        printText(QStringLiteral("%1 points%2; RMS %3 mm, largest %4 mm\nwrote %5\n")
                      .arg(points.size())
                      .arg(lens ? QStringLiteral(" through the lens") : QString())
                      .arg(calibration->rmsMetres * 1000.0, 0, 'f', 2)
                      .arg(worst * 1000.0, 0, 'f', 2)
                      .arg(written));
    }
    return 0;
}

}  // namespace prisca::app::cli
