#pragma once

// RigSession's private parts, shared by its two sources (RigSession.cpp: the devices, the
// calibration, the latency, the recording; RigSessionTrials.cpp: the pre-trial check, the
// trials and the camera's frames). Nothing outside rig/ includes it.

#include "core/DemonstrationStream.h"
#include "devices/LedTracker.h"
#include "devices/RigLoop.h"
#include "devices/ThreadHandOff.h"
#include "rig/RigSession.h"

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace prisca::rig {

/// How long the session waits for its threads when it goes [ms].
constexpr int kShutdownWaitMs = 3000;

/// A car rests when its tracked pose moved less than kRestDistance [m] and turned less than
/// kRestTurn [rad] over the last kRestWindowSeconds: the simulator's rest (0.02 m/s, 0.05 rad/s)
/// measured over frames, as one frame's finite difference is swamped by the camera's few mm of
/// noise.
constexpr double kRestWindowSeconds = 0.5;
constexpr double kRestDistance = 0.01;
constexpr double kRestTurn = 0.03;

/// What the camera thread and the commands share (under mutex_).
struct RigSession::Loop {
    devices::FloorCalibration calibration;       ///< the tracker's, outside trials
    devices::Geofence fence;                     ///< every trial's (RigLoop::setGeofence)
    std::optional<devices::LatencyProbe> probe;  ///< a latency measurement under way
    std::optional<double> loopLatency;           ///< measured [s], for the compensation
    LoopLatencySource loopLatencySource = LoopLatencySource::Assumed;
    QString bundleParent;            ///< where trial bundles go (empty: none)
    double bundleFps = 10.0;         ///< their video's frame rate
    double lastBundleFrameT = -1.0;  ///< the trial's newest frame stored [s]
    devices::LedTracker tracker;
    // The closed loop, kept from trial to trial for one method.
    std::unique_ptr<devices::RigLoop> loop;
    QString method;
    bool poseFilter = false;  ///< the loop estimates with the pose filter
    bool stale = false;  ///< the calibration or channels changed: rebuild before the next trial
    int trials = 0;
    // The trial under way.
    bool running = false;
    double trialSeconds = 0.0;
    std::int64_t trialStartNs = -1;  ///< its first frame; -1 before it
    /// When the trial was started: a frame taken before it (the virtual car not yet back at its
    /// start, or a real car's stale pose still in the pipeline) does not drive the loop.
    std::int64_t startedNs = 0;
    std::int64_t lastFrameNs = -1;
    long long frames = 0;
    long long framesWithPose = 0;
    std::vector<double> loopLatencyMs;
    std::optional<devices::PlanarPose> lastTrackedPose;
    /// The tracked poses of the last kRestWindowSeconds (with their frames' times): whether
    /// the car rests.
    std::deque<std::pair<std::int64_t, devices::PlanarPose>> recentPoses;
    /// A car still moving when the trial's time is up runs out in neutral for at most this
    /// long [s] and is scored where it rests (sim::MethodTuning::runOutLimit); 0: never.
    double runOutLimit = 0.0;
    std::int64_t runOutStartNs = -1;  ///< when the run-out began; -1: none
    sim::PlantInfo plant;
    std::shared_ptr<const core::Demonstration> demonstration;
    // Recording by driving.
    bool recording = false;
    Eigen::VectorXd driveAction;
    devices::PoseStateEstimator estimator;
    std::int64_t firstFrameNs = -1;  ///< the recording's first frame with a pose
    double lastTime = -1.0;          ///< its newest sample's time [s]
};

/// The take being recorded, on the worker thread only: the one streaming recorder (the
/// window's too), fed with the frames' own times.
struct RigSession::Recorder {
    core::DemonstrationStream stream;
};

template <typename F>
void RigSession::onWorker(F&& f) {
    devices::postTo(worker_, std::forward<F>(f));
}

}  // namespace prisca::rig
