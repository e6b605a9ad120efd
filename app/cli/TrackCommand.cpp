// prisca-cli track: the car's pose in every frame of a video of its IR LEDs.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "core/FileIo.h"
#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"

#include <QFileInfo>
#include <QJsonObject>

#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>
#include <cstdio>

namespace prisca::app::cli {

int trackCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("track"),
                     QStringLiteral("Track the car's three IR LEDs in a video and write its pose "
                                    "per frame (x, y in floor metres, heading in radians); frames "
                                    "without three credible LEDs have no pose."));
    line.addValue("video", "Video file of the ceiling camera.", "file");
    line.addValue("calibration", "Floor calibration JSON (image px -> floor m).", "file");
    line.addValue("camera",
                  "Camera intrinsics JSON (calibrate-camera): the LEDs are undistorted through "
                  "it, the floor calibration fitted again under it from its own points.",
                  "file");
    line.addValue("out", "CSV: frame, t, x, y, psi, found, misfit_m, blobs.", "file");
    line.addValue("threshold", "Grey level above which a pixel is lit.", "0..255", "180");
    line.addValue("leds",
                  "LED positions in the car frame [m], front first: \"x,y;x,y;x,y\" (x forward, "
                  "y left; default the car's LED triangle 0.12,0;-0.08,0.06;-0.08,-0.06).",
                  "x,y;x,y;x,y");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString videoPath = line.required("video");
    const QString out = line.required("out");
    devices::TrackerSettings settings;
    settings.threshold = static_cast<int>(line.integer("threshold", 0, 255));
    if (line.isSet("leds")) {
        const QStringList leds = line.value("leds").split(QLatin1Char(';'));
        if (leds.size() != 3) {
            throw UsageError(QStringLiteral("--leds: three positions \"x,y;x,y;x,y\" are needed, "
                                            "%1 given")
                                 .arg(leds.size()));
        }
        for (int i = 0; i < 3; ++i) {
            const QStringList xy = leds[i].split(QLatin1Char(','));
            bool okX = false, okY = false;
            const double x = xy.value(0).trimmed().toDouble(&okX);
            const double y = xy.value(1).trimmed().toDouble(&okY);
            if (xy.size() != 2 || !okX || !okY || !std::isfinite(x) || !std::isfinite(y)) {
                throw UsageError(QStringLiteral("--leds: LED %1 '%2' is not \"x,y\" in metres")
                                     .arg(i + 1)
                                     .arg(leds[i]));
            }
            settings.geometry.leds[i] = cv::Point2d(x, y);
        }
    }
    QString error;
    auto calibration = devices::FloorCalibration::load(line.required("calibration"), &error);
    if (!calibration) {
        throw UsageError(error);
    }
    if (line.isSet("camera")) {
        const auto lens = devices::CameraLens::load(line.value("camera"), &error);
        if (!lens) {
            throw UsageError(error);
        }
        if (!calibration->lens || !calibration->lens->sameModel(*lens)) {
            if (calibration->points.size() < 4) {
                throw UsageError(QStringLiteral("--camera: %1 keeps no points to fit again "
                                                "under the lens; run calibrate-floor --camera")
                                     .arg(line.value("calibration")));
            }
            calibration = calibration->withLens(lens, &error);
            if (!calibration) {
                throw UsageError(QStringLiteral("--camera: %1").arg(error));
            }
        }
    }
    if (const QString problem = calibration->accuracyProblem(); !problem.isEmpty()) {
        std::fprintf(stderr, "prisca-cli: track: warning: %s\n", qPrintable(problem));
    }
    // A video file only: a FIFO or a device would block the decoder in its open.
    core::FileError videoError;
    if (!core::checkRegularFile(videoPath, -1, &videoError)) {
        throw UsageError(videoError.toString());
    }
    // OpenCV's own log lines (backends it tries and drops) would break the one-line error rule.
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    cv::VideoCapture video(videoPath.toStdString());
    if (!video.isOpened()) {
        throw UsageError(QStringLiteral("%1: not a video this build can read").arg(videoPath));
    }
    double fps = video.get(cv::CAP_PROP_FPS);
    if (!(fps > 0.0 && std::isfinite(fps))) {
        fps = 40.0;
    }
    devices::LedTracker tracker(settings);
    installInterruptHandler();
    QByteArray csv = "# prisca-poses 1\n# video: " + videoPath.toUtf8() +
                     "\n# x, y [m], psi [rad]; empty where no pose\n"
                     "frame,t,x,y,psi,found,misfit_m,blobs\n";
    cv::Mat frame;
    int frames = 0, found = 0;
    while (!interrupted() && video.read(frame) && !frame.empty()) {
        const devices::TrackResult r = tracker.track(frame, *calibration);
        QByteArray row = QByteArray::number(frames) + ',';
        core::appendCsvNumber(row, frames / fps);
        row += ',';
        if (r.pose) {
            core::appendCsvNumber(row, r.pose->x);
            row += ',';
            core::appendCsvNumber(row, r.pose->y);
            row += ',';
            core::appendCsvNumber(row, r.pose->heading);
            row += ",1,";
            ++found;
        } else {
            row += ",,,0,";
        }
        if (std::isfinite(r.misfit)) {  // no misfit without three blobs: left empty
            core::appendCsvNumber(row, r.misfit);
        }
        row += ',' + QByteArray::number(r.blobs) + '\n';
        csv += row;
        ++frames;
        if (frames % 200 == 0) {
            printProgress(QStringLiteral("track: %1 frames").arg(frames));
        }
    }
    printProgress(QString());
    if (frames == 0) {
        throw UsageError(QStringLiteral("%1: no frame could be read").arg(videoPath));
    }
    // Interrupted: the frames tracked go to NAME.partial, and a complete previous file stays.
    const bool complete = !interrupted();
    const QString written = writeOutput(out, csv, complete);
    if (found == 0) {
        std::fprintf(stderr,
                     "prisca-cli: track: warning: none of the %d frames gave a pose; check "
                     "--threshold, --leds and the calibration\n",
                     frames);
    }
    if (line.format() == QLatin1String("json")) {
        printJson({{"frames", frames}, {"withPose", found}, {"out", written}});
    } else {
        printText(QStringLiteral("%1 frames, %2 with a pose; wrote %3\n")
                      .arg(frames)
                      .arg(found)
                      .arg(written));
    }
    if (!complete) {
        std::fprintf(stderr, "prisca-cli: track: stopped by %s; kept %d frames in %s\n",
                     interruptionName().toLatin1().constData(), frames, qPrintable(written));
        return interruptedExitCode();
    }
    return 0;
}

}  // namespace prisca::app::cli
