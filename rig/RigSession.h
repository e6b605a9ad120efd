#pragma once

#include "core/Controller.h"
#include "core/Demonstration.h"
#include "devices/CameraSource.h"
#include "devices/CameraWorker.h"
#include "devices/ChannelMap.h"
#include "devices/FloorCalibration.h"
#include "devices/Geofence.h"
#include "devices/LatencyProbe.h"
#include "devices/TransmitterLink.h"
#include "rig/PreTrialCheck.h"
#include "rig/TrialBundle.h"
#include "sim/MethodCatalog.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"
#include "sim/run/RunSetup.h"

#include <QJsonObject>
#include <QMetaType>
#include <QObject>
#include <QString>
#include <QThread>

#include <Eigen/Core>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace prisca::rigsim {
class VirtualCar;
}

namespace prisca::devices {
class RigLoop;
}

namespace prisca::rig {

/// Where the rig's frames come from.
struct CameraRequest {
    enum class Source { Virtual, Device, Video };
    Source source = Source::Virtual;
    devices::V4l2Settings device;  ///< Source::Device
    QString videoPath;             ///< Source::Video (played at its own frame rate)
    /// Source::Virtual: the synthetic camera's frame rate [1/s] (the demonstration's control
    /// rate, one frame per control step).
    double virtualFps = 0.0;
    double virtualPerturbation = 1.0;  ///< the virtual car's (start offsets, friction, gains)
    /// The virtual car's physical parameters (a plant file); null: the catalog's slide-car.
    std::shared_ptr<const sim::PlantParameters> virtualPlant;
    /// Source::Virtual: the camera shows the car as it was this long ago [s] (an injected
    /// camera latency, for what measures it).
    double virtualCameraDelay = 0.0;
};

/// A measurement of the loop's latency (RigSession::measureLatency).
struct LatencyMeasurement {
    std::vector<double> stepsSeconds;  ///< each step's command-to-response latency [s]
    double median = -1.0, min = -1.0, max = -1.0, spread = 0.0;  ///< [s]; spread: std
    QString error;  ///< why it failed (then no figures)
};

/// One trial on the rig.
struct TrialRequest {
    /// The run, set up as in simulation (sim::RunSetup): its method (a new method gets a new
    /// loop, its controller made untrained), the target (a planar vehicle), the demonstration
    /// (its length and its lot), the settle time after it, the lost-track failsafe distance and
    /// the latency the controller compensates.
    std::shared_ptr<const sim::RunSetup> setup;
    /// The virtual car's seed for this trial (its start, friction, gains); 0: the trial number.
    std::uint64_t virtualSeed = 0;
    /// The operator's session (the window's), kept in the trial's bundle; empty: none.
    QJsonObject session;
};

/// How a trial on the rig ended.
struct RigTrialResult {
    int trial = 0;         ///< 1, 2, ... since the loop was built
    bool stopped = false;  ///< ended early by Stop or E-STOP
    bool fault = false;    ///< ended in failsafe: the fence, the lost-track guard, a fault
    QString reason;        ///< why, when `fault`
    double seconds = 0.0;  ///< its length by the camera's frame clock [s]
    /// Of those, run out in neutral after its time, the car still moving [s] (the controller no
    /// longer asked; the car scored where it came to rest or where the limit left it).
    double runOutSeconds = 0.0;
    long long frames = 0;  ///< frames it saw
    long long framesWithPose = 0;
    /// Per frame with a pose: from the frame's arrival to its command handed to the link [ms].
    std::vector<double> loopLatencyMs;
    /// Where the car stopped relative to the demonstration's end; empty: no pose was seen.
    std::optional<sim::ParkingError> parked;
    QString controllerNote;  ///< the controller's word on the trial (Controller::trialNote)
};

/// A trial's result in one sentence for the operator: where it parked, how it ended, and the
/// controller's word on it.
QString trialSentence(const RigTrialResult& result);

/// A demonstration recorded by driving on the rig.
struct RigRecording {
    QString path;  ///< the file on disk (kept even when unusable)
    /// The take on one uniform step (the frames' median interval); null: nothing usable.
    std::shared_ptr<core::Demonstration> demonstration;
    QString error;  ///< why there is none, or why the file could not be rewritten
};

/// The rig as one object: camera, tracker, closed loop, transmitter link and recorder, with
/// time taken from the frames' timestamps. The camera and the link each run on their own
/// thread; the closed loop steps on the camera's thread (no queue between frame and command);
/// the recorder writes on the session's own worker thread, so no disk write ever happens under a
/// lock another thread waits on. Commands are called on the owner's (the window's) thread;
/// results come back as signals. Knows nothing of widgets: the Rig panel shows and commands it.
class RigSession : public QObject {
    Q_OBJECT
  public:
    explicit RigSession(QObject* parent = nullptr);
    /// Stops the camera and the link; a recording in progress is flushed and kept on disk.
    ~RigSession() override;

    // The camera.
    /// Opens the virtual car (for Source::Virtual) and starts the camera thread. False and
    /// *error when the virtual car cannot open; a device or file that cannot open is reported
    /// by cameraFailed().
    bool startCamera(const CameraRequest& request, QString* error);
    void stopCamera();
    bool cameraRunning() const { return camera_.isRunning(); }
    long long framesSeen() const { return camera_.framesDelivered(); }
    /// The newest tracked pose (empty: none in the last frame).
    std::optional<devices::PlanarPose> lastPose() const;
    /// The virtual car's port (empty until the virtual camera has started once).
    QString virtualPort() const;
    /// Link frames the virtual car has decoded so far (-1: no virtual car).
    long long virtualFramesDecoded() const;
    /// The action the virtual car's receiver holds now, from the newest link frame on its line
    /// (empty: no virtual car). Read after the link has stopped, it is what the car was left
    /// with: failsafe is neutral.
    std::optional<Eigen::VectorXd> virtualReceivedCommand() const;

    // The floor calibration the tracker uses.
    const devices::FloorCalibration& calibration() const { return calibration_; }
    void setCalibration(const devices::FloorCalibration& calibration);
    /// Reads a calibration file; a bad one changes nothing (false, *error names it and why).
    bool loadCalibration(const QString& path, QString* error);
    bool saveCalibration(const QString& path, QString* error) const;

    /// The fence every trial runs in (a breach ends it in failsafe, RigTrialResult::reason
    /// says why); takes effect at once. Empty by default.
    void setGeofence(const devices::Geofence& fence);
    devices::Geofence geofence() const;

    // The transmitter link.
    void connectLink(const devices::LinkSettings& settings);
    void disconnectLink();
    const devices::LinkStatus& linkStatus() const { return linkStatus_; }
    /// The channel mapping for commands; takes effect on the next trial.
    void setChannels(const devices::ChannelMap& channels);
    const devices::ChannelMap& channels() const { return channels_; }

    /// What is missing before a trial or a recording can start (the camera, the link); empty
    /// when ready.
    QString notReady() const;
    /// The pre-trial check for `request` now: the camera and the car in it, the calibration and
    /// the lens, the link, the latency, E-STOP, the task, and the demonstration's path and lot
    /// inside the fence and the camera's view. startTrial() refuses a trial it does not pass.
    PreTrialCheck preTrialCheck(const sim::Task& task, const sim::MethodSpec& method) const;
    /// The virtual car back at its start, at rest (after a trial that left it out of view);
    /// false and *error without a virtual car or during a trial.
    bool putVirtualCarBack(QString* error);

    // Trials.
    /// Starts a trial (the loop is kept for the same method: learners learn from trial to
    /// trial). False and *error if one already runs, the camera is off or the link is down.
    bool startTrial(const TrialRequest& request, QString* error);
    /// Ends the trial under way; trialFinished() follows.
    void stopTrial();
    bool trialRunning() const;
    /// Trials started since the loop was built (the one under way included).
    int trialNumber() const;

    // Recording by driving.
    /// Starts recording the tracked states with the commands given by setDriveCommand(),
    /// streamed to `path` as they come (the header at once). False and *error on failure.
    bool startRecording(const sim::PlantInfo& plant, const QString& path, QString* error);
    /// The operator's command in [-1, 1] per action: sent through the link and recorded.
    void setDriveCommand(const Eigen::VectorXd& action);
    /// Ends the recording; recordingFinished() follows once the take is resampled and written.
    void stopRecording();
    bool recording() const;
    /// How long the take being recorded is so far [s, the frames' clock, from its first frame
    /// with a pose]: the newest sample the writer has taken (on its way to disk within a
    /// quarter second); -1 before the first.
    double recordedSeconds() const;

    // The loop's latency.
    /// With the car at rest in view, steps the throttle (alternating forward and back) and
    /// times the response in the camera (devices::LatencyProbe); latencyMeasured() follows.
    /// False and *error if the camera is off, the link is down, or a trial or recording runs.
    bool measureLatency(const devices::LatencyProbeSettings& settings, QString* error);
    void cancelLatencyMeasurement();
    bool measuringLatency() const;
    /// The loop latency the controllers compensate on the next trials [s] (rounded to control
    /// periods); empty: the profile's assumption (the camera's latency in simulation). A
    /// finished measurement sets it by itself (LoopLatencySource::Measured); this is the operator's
    /// declared value (or empty, back to the assumption).
    void setLoopLatency(std::optional<double> seconds,
                        LoopLatencySource source = LoopLatencySource::Declared);
    std::optional<double> loopLatency() const;
    LoopLatencySource loopLatencySource() const;

    // Trial bundles.
    /// Every trial from now on is saved as a bundle (rig::TrialBundleWriter) in a new folder
    /// under `parent` (trial-<date>-<time>-<n>-<process id>), with the camera's frames at
    /// `videoFps` (0: no video); empty `parent`: no bundles. The folder of the newest is
    /// bundleSaved()'s.
    void setBundles(const QString& parent, double videoFps);
    QString bundleParent() const;

    /// E-STOP: failsafe on the link (latched until reset), the trial and recording end.
    void emergencyStop();
    void resetEmergencyStop();

  signals:
    /// A thinned copy of the camera's frames (about 30 per second) with the pose tracked in it.
    void frameReady(const prisca::devices::CameraFrame& frame,
                    const std::optional<prisca::devices::PlanarPose>& pose);
    void cameraFailed(const QString& message);
    /// The camera's source came to its end (a video file played through); no fault.
    void cameraEnded(const QString& message);
    /// The camera started or stopped (asked to, at the end of a file, or on a device error).
    void cameraRunningChanged(bool running);
    void linkStatusChanged(const prisca::devices::LinkStatus& status);
    void trialFinished(const prisca::rig::RigTrialResult& result);
    void latencyMeasured(const prisca::rig::LatencyMeasurement& result);
    /// A trial's bundle is complete on disk (or could not be written: `error`).
    void bundleSaved(const QString& folder, const QString& error);
    void recordingFinished(const prisca::rig::RigRecording& recording);

  private:
    struct Recorder;
    void onFrame(const devices::CameraFrame& frame);
    RigTrialResult finishTrialLocked(bool stopped, bool fault, const QString& reason = {});
    template <typename F>
    void onWorker(F&& f);

    devices::Camera camera_;
    devices::TransmitterLink link_;
    std::shared_ptr<rigsim::VirtualCar> car_;
    devices::FloorCalibration calibration_;  ///< the owner thread's copy
    devices::ChannelMap channels_ = devices::ChannelMap::car();
    devices::LinkStatus linkStatus_;
    QThread workerThread_;
    QObject* worker_;  ///< lives on workerThread_: the recorder's disk writes and the scoring
    std::unique_ptr<Recorder> recorder_;         ///< touched on the worker thread only
    std::unique_ptr<TrialBundleWriter> bundle_;  ///< the trial's bundle; worker thread only
    std::atomic<double> writtenSeconds_{-1.0};   ///< the recorder's newest sample [s]

    /// Shared by the camera thread and commands; held only for in-memory work, never disk I/O.
    mutable std::mutex mutex_;
    struct Loop;
    std::unique_ptr<Loop> loop_;
    mutable std::mutex poseMutex_;
    std::optional<devices::PlanarPose> pose_;
    std::atomic<int> frameWidth_{0}, frameHeight_{0};  ///< the newest frame's [px]
    CameraRequest::Source cameraSource_ = CameraRequest::Source::Virtual;
    double injectedCameraDelay_ = 0.0;  ///< the virtual camera's [s]
};

}  // namespace prisca::rig

Q_DECLARE_METATYPE(prisca::rig::RigTrialResult)
Q_DECLARE_METATYPE(prisca::rig::RigRecording)
Q_DECLARE_METATYPE(prisca::rig::LatencyMeasurement)
Q_DECLARE_METATYPE(std::optional<prisca::devices::PlanarPose>)
