#pragma once

#include "devices/FloorCalibration.h"
#include "devices/LedTracker.h"
#include "devices/SyntheticCamera.h"

#include <QString>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include <cstdint>
#include <functional>
#include <memory>

namespace prisca::devices {

/// One camera frame with the steady-clock time it arrived.
struct CameraFrame {
    cv::Mat image;              ///< 8-bit grey or BGR
    std::int64_t steadyNs = 0;  ///< std::chrono::steady_clock, nanoseconds
    long long index = 0;        ///< 0, 1, 2, ... from the source's start
};

/// A source of frames. grab() blocks until the next frame (paced by the device, the file's
/// frame rate when `paced`, or the synthetic camera's clock). Single-threaded: CameraWorker
/// calls it from its own thread.
class CameraSource {
  public:
    virtual ~CameraSource() = default;
    /// Opens the source; on failure false and *error names the device or file and the reason.
    virtual bool open(QString* error) = 0;
    /// The next frame; false at the end of a file or on a device error (*error says which).
    virtual bool grab(CameraFrame* frame, QString* error) = 0;
    /// grab() returned false because the source came to its end (a video file played through):
    /// no fault.
    virtual bool ended() const { return false; }
    virtual double framesPerSecond() const = 0;
    virtual QString describe() const = 0;
};

/// A V4L2 camera through OpenCV (resolution, frame rate, exposure and gain as the driver
/// accepts them; what it refuses is reported, not fatal).
struct V4l2Settings {
    QString device = QStringLiteral("/dev/video0");
    int width = 640;
    int height = 480;
    double fps = 60.0;
    double exposure = -1.0;  ///< driver units; < 0 leaves the driver's automatic exposure
    double gain = -1.0;      ///< driver units; < 0 leaves it
};
std::unique_ptr<CameraSource> makeV4l2Source(const V4l2Settings& settings);

/// A video file; `paced` plays it at its frame rate, else as fast as it decodes.
std::unique_ptr<CameraSource> makeVideoFileSource(const QString& path, bool paced);

/// The synthetic camera: renders the LEDs of the car at the pose `poseAt(t)` gives for the
/// frame time t [s since open], paced at `fps`. A missing pose (the car off the floor) renders
/// an empty floor.
std::unique_ptr<CameraSource> makeSyntheticSource(
    std::function<std::optional<PlanarPose>(double)> poseAt, FloorCalibration calibration,
    SyntheticCameraSettings settings, double fps, std::uint64_t seed = 1);

/// Steady-clock now in nanoseconds.
std::int64_t steadyNowNs();

}  // namespace prisca::devices
