// Camera sources on their worker thread: the synthetic camera paced at its frame rate with
// increasing timestamps, a video file to its end, a missing device reported; the consumer sees
// every frame on the camera thread.
#include "devices/CameraWorker.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include <chrono>

#include <thread>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <atomic>
#include <mutex>
#include <vector>

using namespace prisca::devices;

namespace {

// A camera's failed() and finished() as seen on the test's thread. They are emitted on the camera
// thread; a QSignalSpy would record them there (a direct connection), and its wait() counts only
// the signals after it is entered, so one emitted before the test reaches wait() (a missing
// device fails at once) is missed and the wait runs to its bound. Queued to a receiver on this
// thread instead, they are recorded by this thread's event loop, which QTRY_ runs: none is lost,
// and no list is shared between threads.
struct CameraEnd {
    QObject receiver;  // lives on the test's thread
    QStringList failures;
    QStringList ends;  // the source came to its end: no failure
    int finished = 0;
    explicit CameraEnd(Camera* camera) {
        QObject::connect(camera, &Camera::failed, &receiver,
                         [this](const QString& message) { failures << message; });
        QObject::connect(camera, &Camera::ended, &receiver,
                         [this](const QString& message) { ends << message; });
        QObject::connect(camera, &Camera::finished, &receiver, [this] { ++finished; });
    }
};

}  // namespace

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
        QTRY_VERIFY_WITH_TIMEOUT(shown.size() >= 6, 20000);  // the frames' count, not a time
        camera.stop();
        QTRY_VERIFY(!camera.isRunning());
        std::lock_guard<std::mutex> lock(mutex);
        QVERIFY(stamps.size() >= 6);
        // Each frame stamped with its exposure time on the 40 fps clock: consecutive frames
        // 25 ms apart, or a whole number of periods where a late reader dropped frames.
        for (size_t i = 1; i < stamps.size(); ++i) {
            QVERIFY(indices[i] > indices[i - 1]);
            const double periods = (stamps[i] - stamps[0]) / 25e6;
            QVERIFY2(std::abs(periods - (indices[i] - indices[0])) < 1e-3,
                     qPrintable(QStringLiteral("frame %1: %2 periods").arg(i).arg(periods)));
        }
        QVERIFY(offMainThread.load());
        // The screen gets a thinned copy (10 per second here).
        QVERIFY2(shown.size() >= 6 && shown.size() <= 12,
                 qPrintable(QString::number(shown.size())));
        const CameraFrame f = shown.last().at(0).value<CameraFrame>();
        QCOMPARE(f.image.size(), cv::Size(640, 480));
    }

    void synthetic_slowReaderDropsFramesInsteadOfFallingBehind() {
        Camera camera;
        std::mutex mutex;
        std::vector<long long> indices;
        std::vector<std::int64_t> received;
        camera.setConsumer([&](const CameraFrame& f) {
            {
                std::lock_guard<std::mutex> lock(mutex);
                indices.push_back(f.index);
                received.push_back(steadyNowNs());
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(60));  // 2.4 frame periods
        });
        camera.start(makeSyntheticSource(
            [](double t) {
                return PlanarPose{1.0 + t, 0.0, 0.0};
            },
            syntheticCeilingCamera(), {}, 40.0));
        QTRY_VERIFY_WITH_TIMEOUT(
            [&] {
                std::lock_guard<std::mutex> lock(mutex);
                return indices.size() >= 10;
            }(),
            20000);
        camera.stop();
        QTRY_VERIFY(!camera.isRunning());
        std::lock_guard<std::mutex> lock(mutex);
        // The scene's time (index / fps) keeps up with the clock the reader sees: frames were
        // dropped, not queued up ever later.
        const double sceneSeconds = (indices.back() - indices.front()) / 40.0;
        const double wallSeconds = (received.back() - received.front()) * 1e-9;
        QVERIFY2(
            std::abs(sceneSeconds - wallSeconds) < 0.06,
            qPrintable(QStringLiteral("scene %1 s, wall %2 s").arg(sceneSeconds).arg(wallSeconds)));
        QVERIFY(indices.back() - indices.front() > static_cast<long long>(indices.size()));
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
        CameraEnd end(&camera);
        camera.start(makeVideoFileSource(path, false));
        QTRY_COMPARE_WITH_TIMEOUT(end.finished, 1, 30000);  // 0.6 s of video; the bound ends a hang
        QCOMPARE(count.load(), 25);
        // Its end is no failure: said as the end, once.
        QCOMPARE(end.failures.size(), 0);
        QCOMPARE(end.ends.size(), 1);
        QVERIFY(end.ends.first().contains("end of the video"));
    }

    void missingDevice_isReportedByName() {
        Camera camera;
        CameraEnd end(&camera);
        V4l2Settings settings;
        settings.device = QStringLiteral("/dev/video-none");
        camera.start(makeV4l2Source(settings));
        QTRY_COMPARE_WITH_TIMEOUT(end.finished, 1, 30000);  // the bound only ends a hang
        QCOMPARE(end.failures.size(), 1);
        QVERIFY(end.failures.first().contains("/dev/video-none"));
        QVERIFY(!camera.isRunning());
    }
};

QTEST_GUILESS_MAIN(TestCamera)
#include "test_camera.moc"
