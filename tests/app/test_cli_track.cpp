// prisca-cli track end to end: a generated video of the car's LEDs (the synthetic camera, MJPEG)
// and its floor calibration in, poses out, compared with the truth; bad inputs refused.
#include "devices/FloorCalibration.h"
#include "devices/SyntheticCamera.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "support/CliProcess.h"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cmath>

using namespace prisca::devices;

namespace {

using Result = prisca::test::CliResult;

Result cli(const QStringList& arguments, const QString& directory) {
    return prisca::test::runCli(arguments, directory);
}

PlanarPose truthAt(int frame) {
    // A car driving an arc across the floor.
    const double t = frame * 0.025;
    return {0.4 + 1.2 * t, 0.8 * std::sin(0.7 * t), 0.56 * std::cos(0.7 * t)};
}

}  // namespace

class TestCliTrack : public QObject {
    Q_OBJECT
  private slots:
    void track_recoversThePosesOfAGeneratedVideo() {
        QTemporaryDir dir;
        const FloorCalibration camera = syntheticCeilingCamera();
        QString error;
        QVERIFY(camera.save(dir.filePath("cal.json"), &error));
        const QString video = dir.filePath("car.avi");
        cv::VideoWriter writer(video.toStdString(), cv::CAP_OPENCV_MJPEG,
                               cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                               cv::Size(640, 480), true);
        QVERIFY(writer.isOpened());
        writer.set(cv::VIDEOWRITER_PROP_QUALITY, 95);
        SyntheticCameraSettings settings;
        settings.noise = 3.0;
        const int frames = 80;
        for (int k = 0; k < frames; ++k) {
            cv::Mat grey = renderLeds(truthAt(k), camera, settings, LedGeometry{}, k + 1);
            if (k == 40) {
                grey.setTo(20);  // the LEDs hidden for a frame: no pose, not a guess
            }
            cv::Mat bgr;
            cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
            writer.write(bgr);
        }
        writer.release();

        const Result r = cli({"track", "--video", video, "--calibration", dir.filePath("cal.json"),
                              "--out", "poses.csv", "--format", "json"},
                             dir.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("\"frames\": 80"), qPrintable(r.out));
        QFile csv(dir.filePath("poses.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = csv.readAll().trimmed().split('\n');
        QCOMPARE(lines[0], QByteArray("# prisca-poses 1"));
        int row = 0;
        double worst = 0.0;
        for (const QByteArray& line : lines) {
            if (line.startsWith('#') || line.startsWith("frame")) {
                continue;
            }
            const QList<QByteArray> f = line.split(',');
            QCOMPARE(f.size(), 8);
            QCOMPARE(f[0].toInt(), row);
            if (row == 40) {
                QCOMPARE(f[5], QByteArray("0"));
                QVERIFY(f[2].isEmpty());
            } else {
                QCOMPARE(f[5], QByteArray("1"));
                const PlanarPose truth = truthAt(row);
                worst = std::max(worst,
                                 std::hypot(f[2].toDouble() - truth.x, f[3].toDouble() - truth.y));
                QVERIFY(std::abs(std::remainder(f[4].toDouble() - truth.heading, 2 * M_PI)) <
                        M_PI / 180.0);
            }
            ++row;
        }
        QCOMPARE(row, frames);
        qInfo("through MJPEG: worst position error %.2f mm", worst * 1000.0);
        QVERIFY2(worst < 0.005, qPrintable(QString::number(worst)));
    }

    void track_badInputsGiveOneLineAndExitTwo() {
        QTemporaryDir dir;
        QFile bad(dir.filePath("bad.json"));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write("{\"homography\": [1]}");
        bad.close();
        Result r = cli({"track", "--video", "x.avi", "--calibration", "bad.json", "--out", "p.csv"},
                       dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("bad.json") && r.err.contains("9 numbers"), qPrintable(r.err));
        const FloorCalibration camera = syntheticCeilingCamera();
        QString error;
        QVERIFY(camera.save(dir.filePath("cal.json"), &error));
        r = cli({"track", "--video", "missing.avi", "--calibration", "cal.json", "--out", "p.csv"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("missing.avi"), qPrintable(r.err));
        QFile junk(dir.filePath("junk.avi"));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("this is not a video");
        junk.close();
        r = cli({"track", "--video", "junk.avi", "--calibration", "cal.json", "--out", "p.csv"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("junk.avi"), qPrintable(r.err));
        QVERIFY(!QFile::exists(dir.filePath("p.csv")));
        r = cli({"track", "--video", "junk.avi", "--calibration", "cal.json", "--out", "p.csv",
                 "--leds", "0.1,0;0,0.05"},
                dir.path());
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("three positions"), qPrintable(r.err));
    }

    void track_usesTheLedGeometryGiven() {
        // A car with a wider LED triangle: found with --leds, refused (no pose) without.
        QTemporaryDir dir;
        const FloorCalibration camera = syntheticCeilingCamera();
        QString error;
        QVERIFY(camera.save(dir.filePath("cal.json"), &error));
        LedGeometry wide;
        wide.leds = {cv::Point2d(0.20, 0.0), cv::Point2d(-0.10, 0.10), cv::Point2d(-0.10, -0.10)};
        cv::VideoWriter writer(dir.filePath("wide.avi").toStdString(), cv::CAP_OPENCV_MJPEG,
                               cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                               cv::Size(640, 480), true);
        QVERIFY(writer.isOpened());
        for (int k = 0; k < 10; ++k) {
            cv::Mat bgr;
            cv::cvtColor(renderLeds({1.0 + 0.02 * k, 0.3, 0.4}, camera, {}, wide, k + 1), bgr,
                         cv::COLOR_GRAY2BGR);
            writer.write(bgr);
        }
        writer.release();
        Result r = cli({"track", "--video", "wide.avi", "--calibration", "cal.json", "--out",
                        "a.csv", "--format", "json"},
                       dir.path());
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("\"withPose\": 0"), qPrintable(r.out));
        r = cli({"track", "--video", "wide.avi", "--calibration", "cal.json", "--out", "b.csv",
                 "--leds", "0.20,0;-0.10,0.10;-0.10,-0.10", "--format", "json"},
                dir.path());
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("\"withPose\": 10"), qPrintable(r.out));
    }
};

QTEST_GUILESS_MAIN(TestCliTrack)
#include "test_cli_track.moc"
