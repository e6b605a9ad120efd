// A wide lens end to end through the CLI: generated chessboard views -> calibrate-camera,
// measured floor points -> calibrate-floor, a video of the car's LEDs over the whole floor ->
// track --camera; poses against the truth. The homography alone is refused with its figure.
// Bad inputs exit 2 naming what and where.
#include "devices/FloorCalibration.h"
#include "devices/SyntheticCamera.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "support/CliProcess.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>

using namespace prisca::devices;

namespace {

using Result = prisca::test::CliResult;

Result cli(const QStringList& arguments, const QString& directory) {
    return prisca::test::runCli(arguments, directory);
}

// Poses over the whole floor the camera sees: a grid whose outer poses' LEDs come within
// about 15 px of the image's edges, headings turning.
std::vector<PlanarPose> floorPoses(const FloorCalibration& truth) {
    std::vector<PlanarPose> poses;
    for (int i = 0; i <= 8; ++i) {
        for (int j = 0; j <= 6; ++j) {
            const PlanarPose p{-0.15 + 4.5 * i / 8.0, -1.05 + 3.15 * j / 6.0, 0.9 * (i + 2 * j)};
            const cv::Point2d px = truth.toImage({p.x, p.y});
            if (px.x > 20 && px.y > 20 && px.x < 620 && px.y < 460) {
                poses.push_back(p);
            }
        }
    }
    return poses;
}

}  // namespace

class TestCliCalibrate : public QObject {
    Q_OBJECT
  private slots:
    void wideLens_calibrateCameraThenFloorThenTrack() {
        QTemporaryDir dir;
        const FloorCalibration truth = syntheticWideLensCamera(-0.3);
        const BoardViewRenderer renderer(*truth.lens);
        const BoardSpec board;  // 9 x 6 inner corners, 40 mm squares
        QVERIFY(QDir(dir.path()).mkdir("views"));
        const auto poses = renderer.poses(board, 14, 11);
        for (size_t i = 0; i < poses.size(); ++i) {
            const cv::Mat view =
                renderer.render(board, poses[i].first, poses[i].second, 2.0, i + 1);
            QVERIFY(cv::imwrite(
                dir.filePath(QStringLiteral("views/view%1.png").arg(i, 2, 10, QLatin1Char('0')))
                    .toStdString(),
                view));
        }
        // A view of the room with no board: listed, not fatal.
        QVERIFY(cv::imwrite(dir.filePath("views/wall.png").toStdString(),
                            cv::Mat(480, 640, CV_8U, cv::Scalar(90))));

        Result r = cli({"calibrate-camera", "--images", "views", "--board", "9x6", "--square",
                        "0.04", "--out", "camera.json", "--format", "json"},
                       dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject lens = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY2(lens.value("rms_px").toDouble() < 0.3, qPrintable(r.out));
        QCOMPARE(lens.value("without_board").toArray().size(), 1);
        QCOMPARE(lens.value("without_board").toArray().at(0).toString(), QString("wall.png"));
        r = cli({"calibrate-camera", "--images", "views", "--out", "camera2.json"}, dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("wall.png: no board found") && r.out.contains("RMS"),
                 qPrintable(r.out));

        // Floor markers on a 6 x 5 grid, their pixels measured to a quarter of a pixel.
        const QByteArray csv = floorMarkersCsv(syntheticFloorMarkers(truth, 6, 5, 0.25, 5));
        QFile points(dir.filePath("floor.csv"));
        QVERIFY(points.open(QIODevice::WriteOnly));
        points.write(csv);
        points.close();
        // The homography alone: refused, with its figure and what to do.
        r = cli({"calibrate-floor", "--points", "floor.csv", "--out", "plain.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("mm RMS") && r.err.contains("--camera"), qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("plain.json")));
        r = cli({"calibrate-floor", "--points", "floor.csv", "--camera", "camera.json", "--out",
                 "calibration.json", "--format", "json"},
                dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject floorFit = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QVERIFY2(floorFit.value("largest_m").toDouble() < 0.010, qPrintable(r.out));

        // The car over the whole floor, seen through the lens.
        const std::vector<PlanarPose> truthPoses = floorPoses(truth);
        QVERIFY(truthPoses.size() >= 40);
        cv::VideoWriter writer(dir.filePath("car.avi").toStdString(), cv::CAP_OPENCV_MJPEG,
                               cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                               cv::Size(640, 480), true);
        QVERIFY(writer.isOpened());
        writer.set(cv::VIDEOWRITER_PROP_QUALITY, 95);
        for (size_t k = 0; k < truthPoses.size(); ++k) {
            cv::Mat bgr;
            cv::cvtColor(renderLeds(truthPoses[k], truth, {}, LedGeometry{}, k + 1), bgr,
                         cv::COLOR_GRAY2BGR);
            writer.write(bgr);
        }
        writer.release();
        // The homography alone, for comparison (its fit written by hand: the CLI refuses it).
        std::vector<CalibrationPoint> plainPoints;
        QString error;
        const auto plain = FloorCalibration::fit(
            FloorCalibration::load(dir.filePath("calibration.json"), &error)->points, &error);
        QVERIFY(plain && plain->save(dir.filePath("plain.json"), &error));

        // Per file: the worst position and heading error over the frames with a pose, and the
        // frames without one.
        struct Worst {
            double position = 0.0, heading = 0.0;
            int lost = 0, rows = 0;
        };
        const auto worstOf = [&](const QString& file) {
            Worst w;
            QFile f(dir.filePath(file));
            if (!f.open(QIODevice::ReadOnly)) {
                w.lost = -1;
                return w;
            }
            for (const QByteArray& line : f.readAll().trimmed().split('\n')) {
                if (line.startsWith('#') || line.startsWith("frame")) {
                    continue;
                }
                const QList<QByteArray> c = line.split(',');
                if (w.rows >= static_cast<int>(truthPoses.size())) {
                    w.lost = -1;
                    return w;
                }
                const PlanarPose& t = truthPoses[w.rows++];
                if (c[5] != "1") {
                    ++w.lost;
                    continue;
                }
                w.position =
                    std::max(w.position, std::hypot(c[2].toDouble() - t.x, c[3].toDouble() - t.y));
                w.heading = std::max(
                    w.heading, std::abs(std::remainder(c[4].toDouble() - t.heading, 2 * M_PI)));
            }
            return w;
        };
        r = cli({"track", "--video", "car.avi", "--calibration", "calibration.json", "--out",
                 "poses.csv"},
                dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Worst lensed = worstOf("poses.csv");
        // The same through --camera on the plain calibration (fitted again from its points).
        r = cli({"track", "--video", "car.avi", "--calibration", "plain.json", "--camera",
                 "camera.json", "--out", "poses2.csv"},
                dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const Worst refitted = worstOf("poses2.csv");
        r = cli(
            {"track", "--video", "car.avi", "--calibration", "plain.json", "--out", "poses3.csv"},
            dir.path());
        QVERIFY2(r.err.contains("warning") && r.err.contains("--camera"), qPrintable(r.err));
        const Worst plainWorst = worstOf("poses3.csv");
        qInfo(
            "%zu poses over the floor, worst: %.1f mm, %.2f deg through the lens "
            "(%.1f mm, %.2f deg by --camera); the homography alone %.1f mm, %.2f deg, "
            "%d frames without a pose (the LED triangle bent past the tracker's tolerance)",
            truthPoses.size(), lensed.position * 1000.0, lensed.heading * 180.0 / M_PI,
            refitted.position * 1000.0, refitted.heading * 180.0 / M_PI,
            plainWorst.position * 1000.0, plainWorst.heading * 180.0 / M_PI, plainWorst.lost);
        const int frames = static_cast<int>(truthPoses.size());
        QCOMPARE(lensed.rows, frames);
        QCOMPARE(lensed.lost, 0);
        QVERIFY(lensed.position < 0.010 && lensed.heading < M_PI / 180.0);
        QCOMPARE(refitted.rows, frames);
        QCOMPARE(refitted.lost, 0);
        QVERIFY(refitted.position < 0.010 && refitted.heading < M_PI / 180.0);
        QCOMPARE(plainWorst.rows, frames);
        QVERIFY(plainWorst.position > 0.050);
    }

    void badInputs_exitTwoNamingWhatAndWhere() {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("empty"));
        Result r = cli({"calibrate-camera", "--images", "nowhere", "--out", "c.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("nowhere") && r.err.contains("no such folder"), qPrintable(r.err));
        r = cli({"calibrate-camera", "--images", "empty", "--out", "c.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no PNG"), qPrintable(r.err));
        r = cli({"calibrate-camera", "--images", "empty", "--board", "9by6", "--out", "c.json"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--board") && r.err.contains("9by6"), qPrintable(r.err));
        // Views without a board: not enough to fit, said with the count.
        QVERIFY(cv::imwrite(dir.filePath("empty/a.png").toStdString(),
                            cv::Mat(480, 640, CV_8U, cv::Scalar(90))));
        QFile junk(dir.filePath("empty/b.png"));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("not an image");
        junk.close();
        r = cli({"calibrate-camera", "--images", "empty", "--out", "c.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("found in 0 view"), qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("c.json")));

        QFile csv(dir.filePath("floor.csv"));
        QVERIFY(csv.open(QIODevice::WriteOnly));
        csv.write("u,v,x,y\n0,0,0,0\n100,0,1,0\n100,oops,1,1\n");
        csv.close();
        r = cli({"calibrate-floor", "--points", "floor.csv", "--out", "f.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("floor.csv:4") && r.err.contains("oops"), qPrintable(r.err));
        QVERIFY(csv.open(QIODevice::WriteOnly | QIODevice::Truncate));
        csv.write("0,0,0,0\n100,0,1,0\n");
        csv.close();
        r = cli({"calibrate-floor", "--points", "floor.csv", "--out", "f.json"}, dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("at least 4 points"), qPrintable(r.err));
        QFile cam(dir.filePath("camera.json"));
        QVERIFY(cam.open(QIODevice::WriteOnly));
        cam.write(
            "{\"camera_matrix\": [1,0,0,0,1,0,0,0,1], \"distortion\": [0,0,0,0,0], "
            "\"image_size\": [640, 480]}");
        cam.close();
        r = cli({"calibrate-floor", "--points", "floor.csv", "--camera", "camera.json", "--out",
                 "f.json"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("camera.json") && r.err.contains("focal length"),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliCalibrate)
#include "test_cli_calibrate.moc"
