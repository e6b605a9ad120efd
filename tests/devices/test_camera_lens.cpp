// The camera's lens: distort/undistort invert each other, a calibration from generated board
// views of a wide lens recovers it, the floor calibration fitted under it maps the whole floor
// to within millimetres where the homography alone errs by decimetres, and bad files are refused.
#include "devices/CameraLens.h"
#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"
#include "devices/SyntheticCamera.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace prisca::devices;

namespace {

std::vector<CalibrationPoint> floorPoints(const FloorCalibration& truth, int nx, int ny,
                                          double pixelNoise, std::uint64_t seed) {
    return syntheticFloorMarkers(truth, nx, ny, pixelNoise, seed);
}

// The largest distance between where a calibration puts a pixel on the floor and where it is,
// over a grid reaching the image's edges and corners.
double worstFloorError(const FloorCalibration& estimate, const FloorCalibration& truth) {
    double worst = 0.0;
    for (int u = 4; u <= 636; u += 16) {
        for (int v = 4; v <= 476; v += 16) {
            const cv::Point2d px(u, v);
            worst = std::max(worst, cv::norm(estimate.toFloor(px) - truth.toFloor(px)));
        }
    }
    return worst;
}

}  // namespace

class TestCameraLens : public QObject {
    Q_OBJECT
  private slots:
    void distortAndUndistort_areInverses() {
        const CameraLens lens = *syntheticWideLensCamera().lens;
        for (int u = 0; u <= 640; u += 40) {
            for (int v = 0; v <= 480; v += 40) {
                const cv::Point2d px(u, v);
                QVERIFY2(cv::norm(lens.distort(lens.undistort(px)) - px) < 1e-6,
                         qPrintable(QStringLiteral("at (%1, %2)").arg(u).arg(v)));
            }
        }
        // Beyond the field the model folds; distort() puts such a point nowhere in the image.
        const cv::Point2d far = lens.distort(cv::Point2d(322 + 600 * 3.0, 238.5 + 600 * 3.0));
        QVERIFY(far.x < 0 || far.y < 0 || far.x > 640 || far.y > 480);
        QVERIFY2(lens.plausibilityProblem().isEmpty(), qPrintable(lens.plausibilityProblem()));
    }

    void calibration_recoversAWideLensFromGeneratedViews() {
        const CameraLens truth = *syntheticWideLensCamera(-0.3).lens;
        const BoardViewRenderer renderer(truth);
        const BoardSpec board;
        const auto poses = renderer.poses(board, 14, 7);
        QCOMPARE(static_cast<int>(poses.size()), 14);
        std::vector<QString> names;
        std::vector<cv::Mat> images;
        for (size_t i = 0; i < poses.size(); ++i) {
            names.push_back(QStringLiteral("view%1.png").arg(i));
            images.push_back(renderer.render(board, poses[i].first, poses[i].second, 2.0, i + 1));
        }
        // A view with no board is listed, not fatal.
        names.push_back(QStringLiteral("empty.png"));
        images.push_back(cv::Mat(480, 640, CV_8U, cv::Scalar(90)));
        QString error;
        const auto lens = calibrateLens(names, images, board, &error);
        QVERIFY2(lens, qPrintable(error));
        QCOMPARE(static_cast<int>(lens->views.size()), 15);
        QVERIFY(!lens->views.back().found);
        int found = 0;
        for (const LensView& v : lens->views) {
            found += v.found;
            if (v.found) {
                QVERIFY(v.errorPixels < 0.5);
            }
        }
        QVERIFY2(found >= 12, qPrintable(QString::number(found)));
        qInfo("RMS %.3f px, fx %.1f (600), k1 %.4f (-0.3), k2 %.4f (0.05)", lens->rmsPixels,
              lens->matrix(0, 0), lens->distortion[0], lens->distortion[1]);
        QVERIFY(lens->rmsPixels < 0.3);
        QVERIFY(std::abs(lens->matrix(0, 0) / 600.0 - 1.0) < 0.01);
        QVERIFY(std::abs(lens->distortion[0] + 0.3) < 0.03);
        // Where it matters: every pixel's ray (its ideal position in the camera's own
        // normalised coordinates) within a pixel's worth (1/600) of the truth's.
        const auto ray = [](const CameraLens& l, const cv::Point2d& px) {
            const cv::Point2d ideal = l.undistort(px);
            return cv::Point2d((ideal.x - l.matrix(0, 2)) / l.matrix(0, 0),
                               (ideal.y - l.matrix(1, 2)) / l.matrix(1, 1));
        };
        double worst = 0.0;
        for (int u = 0; u <= 640; u += 32) {
            for (int v = 0; v <= 480; v += 32) {
                const cv::Point2d px(u, v);
                worst = std::max(worst, cv::norm(ray(*lens, px) - ray(truth, px)) * 600.0);
            }
        }
        qInfo("worst ray error %.3f px", worst);
        QVERIFY(worst < 1.0);
        QVERIFY2(lens->plausibilityProblem().isEmpty(), qPrintable(lens->plausibilityProblem()));

        // The floor under the fitted lens: within 10 mm everywhere; the homography alone is
        // decimetres off at the edges and refused.
        const FloorCalibration truthFloor = syntheticWideLensCamera(-0.3);
        const std::vector<CalibrationPoint> points = floorPoints(truthFloor, 6, 5, 0.25, 3);
        const auto withLens = FloorCalibration::fit(points, &error, lens);
        QVERIFY2(withLens, qPrintable(error));
        const auto alone = FloorCalibration::fit(points, &error);
        QVERIFY2(alone, qPrintable(error));
        const double lensError = worstFloorError(*withLens, truthFloor);
        const double aloneError = worstFloorError(*alone, truthFloor);
        qInfo("floor: worst %.1f mm with the lens, %.1f mm by the homography alone",
              lensError * 1000.0, aloneError * 1000.0);
        QVERIFY(lensError < 0.010);
        QVERIFY(aloneError > 0.050);
        QVERIFY(withLens->accuracyProblem().isEmpty());
        QVERIFY(alone->accuracyProblem().contains("mm RMS"));
        QVERIFY(alone->accuracyProblem().contains("--camera"));
        // Fitted again from its own points under the lens: the same calibration.
        const auto again = alone->withLens(lens, &error);
        QVERIFY(again);
        QVERIFY(worstFloorError(*again, *withLens) < 1e-9);
    }

    void tracker_undistortsTheLedsThroughTheCalibration() {
        const FloorCalibration truth = syntheticWideLensCamera(-0.3);
        LedTracker tracker;
        SyntheticCameraSettings settings;
        double worst = 0.0, worstHeading = 0.0;
        for (const PlanarPose pose : {PlanarPose{-0.2, 2.2, 0.3}, PlanarPose{4.6, -1.2, -2.0},
                                      PlanarPose{2.2, 0.5, 1.0}, PlanarPose{4.4, 2.15, 3.0}}) {
            tracker.reset();
            const TrackResult r =
                tracker.track(renderLeds(pose, truth, settings, LedGeometry{}, 5), truth);
            QVERIFY(r.pose);
            qInfo("(%.1f, %.1f): %.1f mm", pose.x, pose.y,
                  1000.0 * std::hypot(r.pose->x - pose.x, r.pose->y - pose.y));
            worst = std::max(worst, std::hypot(r.pose->x - pose.x, r.pose->y - pose.y));
            worstHeading = std::max(
                worstHeading, std::abs(std::remainder(r.pose->heading - pose.heading, 2 * M_PI)));
        }
        // Within the issue's bound (10 mm, 1 degree) at the image's corners (the last pose's
        // LEDs are some 15 px from the edges; a spot the edge cuts is off by its cut).
        QVERIFY2(worst < 0.010, qPrintable(QString::number(worst)));
        QVERIFY(worstHeading < M_PI / 180.0);
    }

    void files_roundTripAndRefuseWhatNoCameraHas() {
        QTemporaryDir dir;
        FloorCalibration floor = syntheticWideLensCamera();
        floor.points = floorPoints(floor, 3, 3, 0.0, 1);
        QString error;
        QVERIFY(floor.save(dir.filePath("cal.json"), &error));
        const auto back = FloorCalibration::load(dir.filePath("cal.json"), &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(back->lens && back->lens->sameModel(*floor.lens));
        QVERIFY(cv::norm(back->toImage({1.0, 1.0}) - floor.toImage({1.0, 1.0})) < 1e-9);

        const CameraLens lens = *floor.lens;
        QVERIFY(lens.save(dir.filePath("camera.json"), &error));
        const auto lensBack = CameraLens::load(dir.filePath("camera.json"), &error);
        QVERIFY2(lensBack && lensBack->sameModel(lens), qPrintable(error));

        CameraLens bad = lens;
        bad.rmsPixels = 3.2;
        QVERIFY(bad.plausibilityProblem().contains("3.200 px"));
        bad = lens;
        bad.matrix(0, 0) = 20.0;
        QVERIFY(bad.plausibilityProblem().contains("focal length"));
        bad = lens;
        bad.matrix(0, 2) = 900.0;
        QVERIFY(bad.plausibilityProblem().contains("principal point"));
        bad = lens;
        bad.distortion[0] = -1.5;  // folds inside the image
        QVERIFY(bad.plausibilityProblem().contains("the distortion (k1 -1.5"));
        bad = lens;
        bad.distortion[2] = 0.4;  // p1: the tangential terms fold it, the radial ones do not
        QVERIFY2(bad.plausibilityProblem().contains("the tangential distortion (p1 0.4"),
                 qPrintable(bad.plausibilityProblem()));
        bad = lens;
        bad.distortion[0] = -1.5;
        QVERIFY(!CameraLens::fromJson("[]", &error));
        QVERIFY(error.contains("not camera intrinsics"));
        QVERIFY(!CameraLens::fromJson("{\"camera_matrix\": [1, 2]}", &error));
        QVERIFY(error.contains("9 numbers"));
        QVERIFY(!CameraLens::fromJson(bad.toJson(), &error));
        QVERIFY(error.contains("folds"));
        QVERIFY(!FloorCalibration::fromJson(R"({"homography": [1,0,0,0,1,0,0,0,1], "camera": 3})",
                                            &error));
        QVERIFY(error.contains("'camera'"));
    }
};

QTEST_GUILESS_MAIN(TestCameraLens)
#include "test_camera_lens.moc"
