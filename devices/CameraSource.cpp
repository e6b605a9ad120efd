#include "devices/CameraSource.h"

#include <QFileInfo>
#include <QLoggingCategory>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

Q_LOGGING_CATEGORY(lcCamera, "prisca.devices.camera")

namespace prisca::devices {

std::int64_t steadyNowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

namespace {

// Sleeps until frame `index` is due at `fps` after `startNs`.
void paceTo(std::int64_t startNs, long long index, double fps) {
    const std::int64_t due = startNs + static_cast<std::int64_t>(index * 1e9 / fps);
    const std::int64_t wait = due - steadyNowNs();
    if (wait > 0) {
        std::this_thread::sleep_for(std::chrono::nanoseconds(wait));
    }
}

class V4l2Source : public CameraSource {
  public:
    explicit V4l2Source(V4l2Settings s) : s_(std::move(s)) {}
    bool open(QString* error) override {
        if (!QFileInfo::exists(s_.device)) {
            *error = QStringLiteral("%1: no such camera device").arg(s_.device);
            return false;
        }
        if (!capture_.open(s_.device.toStdString(), cv::CAP_V4L2)) {
            *error = QStringLiteral("%1: the camera could not be opened").arg(s_.device);
            return false;
        }
        const auto request = [&](int property, double value, const char* name) {
            if (!capture_.set(property, value)) {
                qCInfo(lcCamera) << s_.device << "refused" << name << value;
            }
        };
        request(cv::CAP_PROP_FRAME_WIDTH, s_.width, "width");
        request(cv::CAP_PROP_FRAME_HEIGHT, s_.height, "height");
        request(cv::CAP_PROP_FPS, s_.fps, "frame rate");
        if (s_.exposure >= 0.0) {
            request(cv::CAP_PROP_AUTO_EXPOSURE, 1, "manual exposure");  // V4L2: 1 = manual
            request(cv::CAP_PROP_EXPOSURE, s_.exposure, "exposure");
        }
        if (s_.gain >= 0.0) {
            request(cv::CAP_PROP_GAIN, s_.gain, "gain");
        }
        return true;
    }
    bool grab(CameraFrame* frame, QString* error) override {
        if (!capture_.read(frame->image) || frame->image.empty()) {
            *error = QStringLiteral("%1: no frame (unplugged?)").arg(s_.device);
            return false;
        }
        frame->steadyNs = steadyNowNs();
        frame->index = index_++;
        return true;
    }
    double framesPerSecond() const override {
        const double f = capture_.get(cv::CAP_PROP_FPS);
        return f > 0 ? f : s_.fps;
    }
    QString describe() const override { return s_.device; }

  private:
    V4l2Settings s_;
    cv::VideoCapture capture_;
    long long index_ = 0;
};

class VideoFileSource : public CameraSource {
  public:
    VideoFileSource(QString path, bool paced) : path_(std::move(path)), paced_(paced) {}
    bool open(QString* error) override {
        if (!QFileInfo::exists(path_)) {
            *error = QStringLiteral("%1: no such file").arg(path_);
            return false;
        }
        if (!capture_.open(path_.toStdString())) {
            *error = QStringLiteral("%1: not a video this build can read").arg(path_);
            return false;
        }
        fps_ = capture_.get(cv::CAP_PROP_FPS);
        if (!(fps_ > 0.0)) {
            fps_ = 40.0;
        }
        startNs_ = steadyNowNs();
        return true;
    }
    bool grab(CameraFrame* frame, QString* error) override {
        if (paced_) {
            paceTo(startNs_, index_, fps_);
        }
        if (!capture_.read(frame->image) || frame->image.empty()) {
            *error = QStringLiteral("%1: end of the video").arg(path_);
            ended_ = true;
            return false;
        }
        frame->steadyNs = steadyNowNs();
        frame->index = index_++;
        return true;
    }
    double framesPerSecond() const override { return fps_; }
    QString describe() const override { return path_; }
    bool ended() const override { return ended_; }

  private:
    QString path_;
    bool paced_;
    bool ended_ = false;
    cv::VideoCapture capture_;
    double fps_ = 40.0;
    std::int64_t startNs_ = 0;
    long long index_ = 0;
};

class SyntheticSource : public CameraSource {
  public:
    SyntheticSource(std::function<std::optional<PlanarPose>(double)> poseAt,
                    FloorCalibration calibration, SyntheticCameraSettings settings, double fps,
                    std::uint64_t seed)
        : poseAt_(std::move(poseAt)),
          calibration_(std::move(calibration)),
          settings_(settings),
          fps_(fps),
          seed_(seed) {}
    bool open(QString*) override {
        startNs_ = steadyNowNs();
        return true;
    }
    bool grab(CameraFrame* frame, QString*) override {
        // As a real camera under a late reader: the frames whose time has passed are gone
        // (dropped), and the one delivered is the one due now, so the scene's time keeps up
        // with the clock instead of falling further behind on a loaded machine.
        const long long due =
            static_cast<long long>(std::floor((steadyNowNs() - startNs_) * 1e-9 * fps_));
        index_ = std::max(index_, due);
        paceTo(startNs_, index_, fps_);
        const std::optional<PlanarPose> pose = poseAt_(index_ / fps_);
        if (pose) {
            frame->image = renderLeds(*pose, calibration_, settings_, LedGeometry{},
                                      seed_ * 1000003ULL + index_);
        } else {
            SyntheticCameraSettings empty = settings_;
            empty.flicker = 1.0;  // no LED lit: nothing to see
            frame->image = renderLeds({100, 100, 0}, calibration_, empty, LedGeometry{}, seed_);
        }
        // Stamped with its exposure time, as a camera driver stamps its buffers.
        frame->steadyNs = startNs_ + static_cast<std::int64_t>(index_ * 1e9 / fps_);
        frame->index = index_++;
        return true;
    }
    double framesPerSecond() const override { return fps_; }
    QString describe() const override { return QStringLiteral("synthetic camera"); }

  private:
    std::function<std::optional<PlanarPose>(double)> poseAt_;
    FloorCalibration calibration_;
    SyntheticCameraSettings settings_;
    double fps_;
    std::uint64_t seed_;
    std::int64_t startNs_ = 0;
    long long index_ = 0;
};

}  // namespace

std::unique_ptr<CameraSource> makeV4l2Source(const V4l2Settings& settings) {
    return std::make_unique<V4l2Source>(settings);
}

std::unique_ptr<CameraSource> makeVideoFileSource(const QString& path, bool paced) {
    return std::make_unique<VideoFileSource>(path, paced);
}

std::unique_ptr<CameraSource> makeSyntheticSource(
    std::function<std::optional<PlanarPose>(double)> poseAt, FloorCalibration calibration,
    SyntheticCameraSettings settings, double fps, std::uint64_t seed) {
    return std::make_unique<SyntheticSource>(std::move(poseAt), std::move(calibration), settings,
                                             fps, seed);
}

}  // namespace prisca::devices
