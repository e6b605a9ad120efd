// Camera sources on their worker thread: the synthetic camera paced at its frame rate with
// increasing timestamps, a video file to its end, a missing device reported; the consumer sees
// every frame on the camera thread.
#include "devices/CameraWorker.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <atomic>
#include <mutex>
#include <vector>

using namespace prisca::devices;

class TestCamera : public QObject {
    Q_OBJECT
  private slots:
    void synthetic_isPacedAndTimestampedOnItsOwnThread() {
        Camera camera;
        std::mutex mutex;
        std::vector<std::int64_t> stamps;
        std::vector<long long> indices;
        std::atomic<bool> offMainThread{true};
        QThread* main = QThread::currentThread();
        camera.setConsumer([&](const CameraFrame& f) {
            std::lock_guard<std::mutex> lock(mutex);
            stamps.push_back(f.steadyNs);
            indices.push_back(f.index);
            if (QThread::currentThread() == main)
                offMainThread = false;
        });
        QSignalSpy shown(&camera, &Camera::frameReady);
        const FloorCalibration floor = syntheticCeilingCamera();
        camera.start(makeSyntheticSource(
                         [](double t) {
                             return PlanarPose{1.0 + t, 0.0, 0.0};
                         },
                         floor, {}, 40.0),
                     10.0);
        QTest::qWait(1000);
        camera.stop();
        QTRY_VERIFY(!camera.isRunning());
        std::lock_guard<std::mutex> lock(mutex);
        // 40 frames a second, give or take scheduling.
        QVERIFY2(stamps.size() >= 34 && stamps.size() <= 44,
                 qPrintable(QString::number(stamps.size())));
        for (size_t i = 1; i < stamps.size(); ++i) {
            QVERIFY(stamps[i] > stamps[i - 1]);
            QCOMPARE(indices[i], indices[i - 1] + 1);
        }
        QVERIFY(offMainThread.load());
        // The screen gets a thinned copy (10 per second here).
        QVERIFY2(shown.size() >= 6 && shown.size() <= 12,
                 qPrintable(QString::number(shown.size())));
        const CameraFrame f = shown.last().at(0).value<CameraFrame>();
        QCOMPARE(f.image.size(), cv::Size(640, 480));
    }

    void videoFile_runsToItsEndThenFinishes() {
        QTemporaryDir dir;
        const QString path = dir.filePath("clip.avi");
        cv::VideoWriter writer(path.toStdString(), cv::CAP_OPENCV_MJPEG,
                               cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 40.0,
                               cv::Size(640, 480), true);
        QVERIFY(writer.isOpened());
        for (int k = 0; k < 25; ++k) {
            writer.write(cv::Mat(480, 640, CV_8UC3, cv::Scalar(k, k, k)));
        }
        writer.release();
        Camera camera;
        std::atomic<int> count{0};
        camera.setConsumer([&](const CameraFrame&) { ++count; });
        QSignalSpy finished(&camera, &Camera::finished);
        QSignalSpy failed(&camera, &Camera::failed);
        camera.start(makeVideoFileSource(path, false));
        QVERIFY(finished.wait(5000));
        QCOMPARE(count.load(), 25);
        QCOMPARE(failed.size(), 1);  // "end of the video"
        QVERIFY(failed.first().at(0).toString().contains("end of the video"));
    }

    void missingDevice_isReportedByName() {
        Camera camera;
        QSignalSpy failed(&camera, &Camera::failed);
        V4l2Settings settings;
        settings.device = QStringLiteral("/dev/video-none");
        camera.start(makeV4l2Source(settings));
        QVERIFY(failed.wait(3000));
        QVERIFY(failed.first().at(0).toString().contains("/dev/video-none"));
        QTRY_VERIFY(!camera.isRunning());
    }
};

QTEST_GUILESS_MAIN(TestCamera)
#include "test_camera.moc"
