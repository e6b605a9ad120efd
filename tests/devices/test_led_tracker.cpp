// The floor calibration and the IR-LED tracker on generated frames: poses recovered to 5 mm and
// 1 degree through noise, blur, flicker and reflections; fewer than three LEDs refused; the
// region of interest once locked; calibration JSON round trip and bad files.
#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"
#include "devices/SyntheticCamera.h"
#include "support/FileSizeLimit.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace prisca::devices;

namespace {
double angleError(double a, double b) {
    return std::abs(std::remainder(a - b, 2 * M_PI));
}
}  // namespace

class TestLedTracker : public QObject {
    Q_OBJECT
  private slots:
    void calibration_fitsFourOrMorePointsAndReportsItsError() {
        const FloorCalibration camera = syntheticCeilingCamera();
        // Points generated through a known homography are reproduced to a micrometre.
        std::vector<CalibrationPoint> points;
        for (double x : {0.0, 1.0, 2.5, 3.0})
            for (double y : {-1.0, 0.3, 1.2}) {
                points.push_back({camera.toImage({x, y}), {x, y}});
            }
        QString error;
        const auto fit = FloorCalibration::fit(points, &error);
        QVERIFY2(fit, qPrintable(error));
        QVERIFY(fit->rmsMetres < 1e-6);
        QVERIFY(cv::norm(fit->toFloor(camera.toImage({1.7, -0.4})) - cv::Point2d(1.7, -0.4)) <
                1e-6);
        // A clicked point 2 cm off shows in the reprojection error.
        points[3].floor.x += 0.02;
        const auto off = FloorCalibration::fit(points, &error);
        QVERIFY(off->rmsMetres > 0.002 && off->rmsMetres < 0.02);
        const std::vector<double> residuals = off->residuals();
        QVERIFY(*std::max_element(residuals.begin(), residuals.end()) > 0.01);
        // Too few, or all in a line: refused with the reason.
        QVERIFY(!FloorCalibration::fit({points.begin(), points.begin() + 3}, &error));
        QVERIFY(error.contains("at least 4"));
        std::vector<CalibrationPoint> line;
        for (int i = 0; i < 5; ++i)
            line.push_back({{10.0 * i, 10.0 * i}, {0.1 * i, 0.1 * i}});
        QVERIFY(!FloorCalibration::fit(line, &error));
        QVERIFY(error.contains("one line"));
        // Four of five on one floor line, clicked half a pixel off in the image: the fit would
        // be a guess along that line; refused.
        std::vector<CalibrationPoint> fourOnALine;
        for (double x : {0.0, 1.0, 2.0, 3.0}) {
            fourOnALine.push_back({camera.toImage({x, 0.5}), {x, 0.5}});
        }
        fourOnALine.push_back({camera.toImage({1.5, 1.5}), {1.5, 1.5}});
        for (int i = 0; i < 4; ++i) {
            fourOnALine[i].image.y += (i % 2) ? 0.5 : -0.5;
        }
        QVERIFY(!FloorCalibration::fit(fourOnALine, &error));
        QVERIFY2(error.contains("do not determine"), qPrintable(error));
        // A narrow strip (4 m x 0.2 m) still determines it.
        std::vector<CalibrationPoint> strip;
        for (double x : {0.0, 1.0, 2.0, 3.0, 4.0})
            for (double y : {0.0, 0.2}) {
                strip.push_back({camera.toImage({x, y}), {x, y}});
            }
        QVERIFY2(FloorCalibration::fit(strip, &error), qPrintable(error));
        // One mistyped floor coordinate (25 for 2.5) among five good points: named, with where
        // the others put it.
        std::vector<CalibrationPoint> six;
        for (const cv::Point2d p :
             {cv::Point2d(0.0, -1.0), cv::Point2d(3.0, -1.0), cv::Point2d(2.5, 0.3),
              cv::Point2d(0.0, 1.2), cv::Point2d(3.0, 1.2), cv::Point2d(1.0, 0.3)}) {
            six.push_back({camera.toImage(p), p});
        }
        six[2].floor.x = 25.0;
        QVERIFY(!FloorCalibration::fit(six, &error));
        QVERIFY2(error.contains("calibration point 3") &&
                     error.contains("does not fit the others") &&
                     error.contains("put it at (2.500, 0.300) m"),
                 qPrintable(error));
        // A point on the floor at 1e300 m, or in the image at 1e300 px: refused by number.
        std::vector<CalibrationPoint> far = points;
        far[3].floor.x = 1e300;
        QVERIFY(!FloorCalibration::fit(far, &error));
        QVERIFY2(error.contains("calibration point 4: floor (1e+300"), qPrintable(error));
        far = points;
        far[2].image.y = -1e300;
        QVERIFY(!FloorCalibration::fit(far, &error));
        QVERIFY2(error.contains("calibration point 3: image"), qPrintable(error));
    }

    void calibration_jsonRoundTripAndBadFiles() {
        const FloorCalibration camera = syntheticCeilingCamera();
        QString error;
        const auto back = FloorCalibration::fromJson(camera.toJson(), &error);
        QVERIFY2(back, qPrintable(error));
        for (int i = 0; i < 9; ++i)
            QCOMPARE(back->imageToFloor.val[i], camera.imageToFloor.val[i]);
        QCOMPARE(back->points.size(), camera.points.size());
        QCOMPARE(back->rmsMetres, camera.rmsMetres);
        QVERIFY(!FloorCalibration::fromJson("{\"homography\": [1, 2, 3]}", &error));
        QVERIFY(error.contains("9 numbers"));
        QVERIFY(!FloorCalibration::fromJson("{\"homography\": [0,0,0,0,0,0,0,0,0]}", &error));
        QVERIFY2(error.contains("all zeros"), qPrintable(error));
        QVERIFY(!FloorCalibration::fromJson("{\"homography\": [0.01,0.02,0,0.02,0.04,0,0,0,1]}",
                                            &error));
        QVERIFY2(error.contains("singular"), qPrintable(error));
        // Finite but meaningless: 1e300 m per pixel, a horizon across the image, a negative rms,
        // points that are not numbers.
        QVERIFY(!FloorCalibration::fromJson("{\"homography\": [1e5,0,0,0,1e5,0,0,0,1]}", &error));
        QVERIFY2(error.contains("beyond"), qPrintable(error));
        QVERIFY(
            !FloorCalibration::fromJson("{\"homography\": [1e300,0,0,0,1e300,0,0,0,1]}", &error));
        QVERIFY2(error.contains("'homography'"), qPrintable(error));
        QVERIFY(
            !FloorCalibration::fromJson("{\"homography\": [0.01,0,0,0,0.01,0,0,0.01,-1]}", &error));
        QVERIFY2(error.contains("horizon"), qPrintable(error));
        QVERIFY(!FloorCalibration::fromJson(
            "{\"homography\": [0.01,0,0,0,0.01,0,0,0,1], \"rms_m\": -1}", &error));
        QVERIFY2(error.contains("rms_m"), qPrintable(error));
        QVERIFY(!FloorCalibration::fromJson(
            "{\"homography\": [0.01,0,0,0,0.01,0,0,0,1], \"points\": [{\"image\": [1e308, 0], "
            "\"floor\": [0, 0]}]}",
            &error));  // the image the homography must map reaches 1e308 px
        QVERIFY2(error.contains("beyond"), qPrintable(error));
        QVERIFY(!FloorCalibration::fromJson("nonsense", &error));
        QVERIFY(error.contains("not valid JSON"));
        // Valid JSON that is not an object: said so, not "invalid JSON (no error occurred)".
        QVERIFY(!FloorCalibration::fromJson("[]", &error));
        QVERIFY2(error.contains("valid JSON, but not a floor calibration"), qPrintable(error));
        // An offset of 1e12 m maps the image far away; that is what is said, not "singular".
        QVERIFY(
            !FloorCalibration::fromJson("{\"homography\": [0.01,0,1e12,0,0.01,0,0,0,1]}", &error));
        QVERIFY2(error.contains("beyond") && !error.contains("singular"), qPrintable(error));
        QTemporaryDir dir;
        QVERIFY(camera.save(dir.filePath("cal.json"), &error));
        QVERIFY(FloorCalibration::load(dir.filePath("cal.json"), &error));
        QVERIFY(!FloorCalibration::load(dir.filePath("missing.json"), &error));
        QVERIFY(error.contains("missing.json"));
        QVERIFY(!FloorCalibration::load(QStringLiteral("/dev/zero"), &error));  // never ends
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
        {
            const FileSizeLimit full(64);  // a full disk: refused, the saved file kept
            QVERIFY(full.active());
            QVERIFY(!camera.save(dir.filePath("cal.json"), &error));
            QVERIFY2(error.contains("cal.json"), qPrintable(error));
        }
        QVERIFY(FloorCalibration::load(dir.filePath("cal.json"), &error));
    }

    void tracker_recoversPosesTo5MillimetresAnd1Degree() {
        const FloorCalibration camera = syntheticCeilingCamera();
        SyntheticCameraSettings s;
        s.noise = 4.0;
        s.blur = 0.6;
        std::mt19937 random(3);
        std::uniform_real_distribution<double> x(0.2, 2.8), y(-1.1, 1.1), psi(-M_PI, M_PI);
        double worstPosition = 0.0, worstHeading = 0.0;
        for (int i = 0; i < 200; ++i) {
            LedTracker tracker;  // full frame each time
            const PlanarPose truth{x(random), y(random), psi(random)};
            const TrackResult r =
                tracker.track(renderLeds(truth, camera, s, LedGeometry{}, i + 1), camera);
            QVERIFY2(r.pose, qPrintable(QStringLiteral("frame %1: %2 blobs").arg(i).arg(r.blobs)));
            worstPosition =
                std::max(worstPosition, std::hypot(r.pose->x - truth.x, r.pose->y - truth.y));
            worstHeading = std::max(worstHeading, angleError(r.pose->heading, truth.heading));
        }
        qInfo("200 frames: worst position error %.2f mm, worst heading error %.3f deg",
              worstPosition * 1000.0, worstHeading * 180.0 / M_PI);
        QVERIFY2(worstPosition < 0.005, qPrintable(QString::number(worstPosition)));
        QVERIFY2(worstHeading < M_PI / 180.0,
                 qPrintable(QString::number(worstHeading * 180 / M_PI)));
    }

    void tracker_picksTheTriangleAmongReflections() {
        const FloorCalibration camera = syntheticCeilingCamera();
        SyntheticCameraSettings s;
        s.reflections = 4;
        int found = 0;
        for (int i = 0; i < 100; ++i) {
            LedTracker tracker;
            const PlanarPose truth{1.0 + 0.01 * i, 0.2, 0.03 * i};
            const TrackResult r =
                tracker.track(renderLeds(truth, camera, s, LedGeometry{}, 100 + i), camera);
            if (r.pose) {
                ++found;
                // Never a wrong pose: the right triangle or none.
                QVERIFY(std::hypot(r.pose->x - truth.x, r.pose->y - truth.y) < 0.005);
            }
        }
        QVERIFY2(found >= 95, qPrintable(QString::number(found)));
    }

    void tracker_refusesFramesWithFewerThanThreeLeds() {
        const FloorCalibration camera = syntheticCeilingCamera();
        SyntheticCameraSettings s;
        s.flicker = 1.0;  // every LED dim
        LedTracker tracker;
        TrackResult r = tracker.track(renderLeds({1, 0, 0}, camera, s, LedGeometry{}, 7), camera);
        QVERIFY(!r.pose);
        QCOMPARE(r.blobs, 0);
        // Two LEDs: still no pose (the third is outside the image).
        s.flicker = 0.0;
        r = tracker.track(renderLeds({5.02, 0.0, 0.0}, camera, s, LedGeometry{}, 8), camera);
        QVERIFY(r.blobs < 3);
        QVERIFY(!r.pose);
        // A frame of noise alone: no pose.
        cv::Mat noise(480, 640, CV_8U);
        cv::randu(noise, 0, 120);
        QVERIFY(!tracker.track(noise, camera).pose);
    }

    void tracker_searchesAroundTheLastPoseOnceLocked() {
        const FloorCalibration camera = syntheticCeilingCamera();
        LedTracker tracker;
        SyntheticCameraSettings s;
        TrackResult r =
            tracker.track(renderLeds({1.0, 0.0, 0.0}, camera, s, LedGeometry{}, 1), camera);
        QVERIFY(r.pose && !r.usedRegion);
        r = tracker.track(renderLeds({1.05, 0.01, 0.1}, camera, s, LedGeometry{}, 2), camera);
        QVERIFY(r.pose && r.usedRegion);
        QVERIFY(std::abs(r.pose->x - 1.05) < 0.005);
        // A jump beyond the region: found again on the full frame.
        r = tracker.track(renderLeds({2.5, -0.8, 2.0}, camera, s, LedGeometry{}, 3), camera);
        QVERIFY(r.pose && !r.usedRegion);
        QVERIFY(std::abs(r.pose->x - 2.5) < 0.005);
    }
};

QTEST_GUILESS_MAIN(TestLedTracker)
#include "test_led_tracker.moc"
