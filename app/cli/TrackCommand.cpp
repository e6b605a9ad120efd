// prisca-cli track: the car's pose in every frame of a video of its IR LEDs.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "core/FileIo.h"
#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"

#include <QFileInfo>
#include <QJsonObject>

#include <opencv2/videoio.hpp>

#include <cmath>

namespace prisca::app::cli {

int trackCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("track"),
                     QStringLiteral("Track the car's three IR LEDs in a video and write its pose "
                                    "per frame (x, y in floor metres, heading in radians); frames "
                                    "without three credible LEDs have no pose."));
    line.addValue("video", "Video file of the ceiling camera.", "file");
    line.addValue("calibration", "Floor calibration JSON (image px -> floor m).", "file");
    line.addValue("out", "CSV: frame, t, x, y, psi, found, misfit_m, blobs.", "file");
    line.addValue("threshold", "Grey level above which a pixel is lit.", "0..255", "180");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString videoPath = line.required("video");
    const QString out = line.required("out");
    QString error;
    const auto calibration = devices::FloorCalibration::load(line.required("calibration"), &error);
    if (!calibration) {
        throw UsageError(error);
    }
    if (!QFileInfo::exists(videoPath)) {
        throw UsageError(QStringLiteral("%1: no such file").arg(videoPath));
    }
    cv::VideoCapture video(videoPath.toStdString());
    if (!video.isOpened()) {
        throw UsageError(QStringLiteral("%1: not a video this build can read").arg(videoPath));
    }
    double fps = video.get(cv::CAP_PROP_FPS);
    if (!(fps > 0.0 && std::isfinite(fps))) {
        fps = 40.0;
    }
    devices::TrackerSettings settings;
    settings.threshold = static_cast<int>(line.integer("threshold", 0, 255));
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
        core::appendCsvNumber(row, r.misfit);
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
    core::FileError fileError;
    if (!core::writeFileAtomically(out, csv, &fileError)) {
        throw UsageError(fileError.toString());
    }
    if (line.format() == QLatin1String("json")) {
        printJson({{"frames", frames}, {"withPose", found}, {"out", out}});
    } else {
        printText(QStringLiteral("%1 frames, %2 with a pose; wrote %3\n")
                      .arg(frames)
                      .arg(found)
                      .arg(out));
    }
    return interrupted() ? kExitInterrupted : 0;
}

}  // namespace prisca::app::cli
