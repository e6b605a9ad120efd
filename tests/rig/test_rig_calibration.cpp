// The rig's set-up workflow without a window: floor points fitted into the session's
// calibration, a lens from generated chessboard views refitting the floor under it, the fence
// put in force (or refused) in the session, and every refusal saying why.
#include "devices/SyntheticCamera.h"
#include "rig/RigCalibration.h"
#include "rig/RigSession.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace prisca;
using rig::RigCalibration;

class TestRigCalibration : public QObject {
    Q_OBJECT
  private slots:
    void floorPoints_fitFromFourIntoTheSession() {
        rig::RigSession session;
        RigCalibration setup(session);
        const devices::FloorCalibration truth = devices::syntheticCeilingCamera();
        const auto markers = devices::syntheticFloorMarkers(truth, 3, 2, 0.0, 1);
        const QByteArray before = session.calibration().toJson();
        setup.beginFloorPoints();
        for (int i = 0; i < 3; ++i) {
            const rig::SetupStep step = setup.addFloorPoint(markers[i].image, markers[i].floor);
            QVERIFY(!step.ok);
            QVERIFY2(step.message.contains(QStringLiteral("at least 4")), qPrintable(step.message));
            QCOMPARE(session.calibration().toJson(), before);  // nothing fitted yet
        }
        for (int i = 3; i < 6; ++i) {
            const rig::SetupStep step = setup.addFloorPoint(markers[i].image, markers[i].floor);
            QVERIFY2(step.ok, qPrintable(step.message));
        }
        QCOMPARE(static_cast<int>(session.calibration().points.size()), 6);
        QVERIFY(session.calibration().rmsMetres < 0.005);
        const cv::Point2d floor = session.calibration().toFloor(truth.toImage({2.0, 0.5}));
        QVERIFY(cv::norm(floor - cv::Point2d(2.0, 0.5)) < 0.01);
        QVERIFY(setup.floorSummary().contains(QStringLiteral("6 points")));
        // The synthetic camera's calibration gone: no warning for a real camera any more.
        QVERIFY(setup.floorProblem(false).isEmpty());

        setup.beginFloorPoints();
        QCOMPARE(setup.floorPointsClicked(), 0);
    }

    void floorProblem_theVirtualRigsCalibrationOnARealCamera() {
        rig::RigSession session;
        const RigCalibration setup(session);
        QVERIFY(setup.floorProblem(true).isEmpty());
        QVERIFY(setup.floorProblem(false).contains(QStringLiteral("virtual rig's")));
    }

    void parseFloorPoint_twoNumbersOrWhatIsWrong() {
        QString error;
        const auto p = RigCalibration::parseFloorPoint(QStringLiteral(" 1.5, -0.2 "), &error);
        QVERIFY(p);
        QCOMPARE(p->x, 1.5);
        QCOMPARE(p->y, -0.2);
        for (const QString& bad : {QStringLiteral("1.5"), QStringLiteral("1.5, a"),
                                   QStringLiteral("1, 2, 3"), QString()}) {
            error.clear();
            QVERIFY(!RigCalibration::parseFloorPoint(bad, &error));
            QVERIFY2(error.contains(QStringLiteral("not two numbers")), qPrintable(error));
        }
    }

    void floorFiles_loadSaveAndABadFileSaysWhy() {
        QTemporaryDir dir;
        rig::RigSession session;
        RigCalibration setup(session);
        const QString path = dir.filePath(QStringLiteral("floor.json"));
        QVERIFY(setup.saveFloor(path).ok);
        const QString bad = dir.filePath(QStringLiteral("bad.json"));
        QFile file(bad);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{not json");
        file.close();
        const rig::SetupStep refused = setup.loadFloor(bad);
        QVERIFY(!refused.ok);
        QVERIFY2(refused.message.contains(QStringLiteral("could not be read")),
                 qPrintable(refused.message));
        QVERIFY(setup.loadFloor(path).ok);
    }

    void lens_fromBoardViews_refitsTheFloorUnderIt() {
        rig::RigSession session;
        RigCalibration setup(session);
        const devices::FloorCalibration truth = devices::syntheticWideLensCamera(-0.3);
        // The floor clicked through the lens before it is known: a homography alone, bent.
        for (const auto& m : devices::syntheticFloorMarkers(truth, 5, 4, 0.0, 3)) {
            setup.addFloorPoint(m.image, m.floor);
        }
        const double homographyAlone = session.calibration().rmsMetres;
        QVERIFY2(homographyAlone > 0.01, qPrintable(QString::number(homographyAlone)));

        QVERIFY(!setup.captureBoardView(cv::Mat()).ok);
        const rig::SetupStep blank =
            setup.captureBoardView(cv::Mat(480, 640, CV_8U, cv::Scalar(90)));
        QVERIFY(!blank.ok);
        QVERIFY2(blank.message.contains(QStringLiteral("no whole 9 x 6 board")),
                 qPrintable(blank.message));
        const rig::SetupStep tooFew = setup.fitLens();
        QVERIFY(!tooFew.ok);
        QVERIFY(tooFew.message.startsWith(QStringLiteral("Lens: ")));

        const devices::BoardViewRenderer renderer(*truth.lens);
        const devices::BoardSpec board;
        const auto poses = renderer.poses(board, 10, 7);
        for (size_t i = 0; i < poses.size(); ++i) {
            const rig::SetupStep step = setup.captureBoardView(
                renderer.render(board, poses[i].first, poses[i].second, 2.0, i + 1));
            QVERIFY2(step.ok, qPrintable(step.message));
        }
        QCOMPARE(setup.boardViewsCaptured(), 10);
        QCOMPARE(static_cast<int>(setup.capturedCorners().size()), 10 * 9 * 6);
        const rig::SetupStep fitted = setup.fitLens();
        QVERIFY2(fitted.ok, qPrintable(fitted.message));
        QVERIFY(setup.lens());
        QCOMPARE(setup.boardViewsCaptured(), 0);  // the views are used up
        QVERIFY(std::abs(setup.lens()->distortion[0] + 0.3) < 0.05);
        // The same clicked points, fitted again under the lens, now fit.
        QVERIFY(session.calibration().lens);
        QVERIFY2(session.calibration().rmsMetres < homographyAlone / 5.0,
                 qPrintable(QStringLiteral("%1 -> %2")
                                .arg(homographyAlone)
                                .arg(session.calibration().rmsMetres)));

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("camera.json"));
        QString error;
        QVERIFY2(setup.saveLens(path, &error), qPrintable(error));
        rig::RigSession other;
        RigCalibration again(other);
        QVERIFY(!again.saveLens(dir.filePath(QStringLiteral("none.json")), &error));
        QVERIFY(again.loadLens(path).ok);
        QVERIFY(again.lens()->sameModel(*setup.lens()));
        QVERIFY(!again.loadLens(dir.filePath(QStringLiteral("missing.json"))).ok);
    }

    void fence_inForceFromThreeCornersAndABadOneRefused() {
        rig::RigSession session;
        RigCalibration setup(session);
        setup.setFenceLimits(2.5, 0.4);
        QCOMPARE(session.geofence().maxSpeed, 2.5);
        QCOMPARE(session.geofence().maxLostSeconds, 0.4);
        setup.addFenceCorner({-1.0, -1.0});
        setup.addFenceCorner({4.0, -1.0});
        QVERIFY(session.geofence().polygon.empty());  // two corners make no fence
        QVERIFY(setup.fenceSummary().contains(QStringLiteral("none (2 corner(s)")));
        setup.addFenceCorner({4.0, 2.0});
        QCOMPARE(static_cast<int>(session.geofence().polygon.size()), 3);
        QVERIFY(setup.fenceSummary().contains(QStringLiteral("3 corners")));
        // A corner that makes the polygon cross itself: said, and no polygon in force.
        setup.setFenceCorners({{0.0, 0.0}, {2.0, 2.0}, {2.0, 0.0}, {0.0, 2.0}});
        QVERIFY(session.geofence().polygon.empty());
        QCOMPARE(session.geofence().maxSpeed, 2.5);  // the limits stay
        QVERIFY(setup.fenceSummary().startsWith(QStringLiteral("Fence: ")));
        QVERIFY2(setup.fenceSummary().contains(QStringLiteral("cross")),
                 qPrintable(setup.fenceSummary()));
        // The corners round-trip through their text (what the window remembers).
        setup.setFenceCorners({{-0.5, -1.25}, {4.5, -1.25}, {4.5, 2.0}});
        QString error;
        const auto parsed = devices::Geofence::parsePolygon(setup.fencePolygonText(), &error);
        QVERIFY2(parsed, qPrintable(error));
        QCOMPARE(*parsed, setup.fenceCorners());
        // A click on the image: through the session's calibration.
        const cv::Point2d image = session.calibration().toImage({1.0, 0.5});
        setup.addFenceCornerAt(image);
        QVERIFY(cv::norm(setup.fenceCorners().back() - cv::Point2d(1.0, 0.5)) < 1e-6);
        setup.clearFence();
        QVERIFY(session.geofence().polygon.empty());
        QVERIFY(setup.fenceCorners().empty());
    }
};

QTEST_GUILESS_MAIN(TestRigCalibration)
#include "test_rig_calibration.moc"
