#pragma once

#include "core/Controller.h"
#include "core/Demonstration.h"
#include "devices/ChannelMap.h"
#include "devices/Geofence.h"
#include "devices/LedTracker.h"
#include "devices/RcProtocols.h"
#include "devices/SyntheticCamera.h"
#include "devices/TransmitterLink.h"
#include "rigsim/VirtualCar.h"
#include "sim/plants/Plant.h"

#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace prisca::devices {
class RigLoop;
}

namespace prisca::rigsim {

/// The virtual rig's settings.
struct VirtualRigSettings {
    devices::RcProtocol protocol = devices::RcProtocol::Crsf;
    double linkRateHz = 100.0;  ///< the link's slowest pace; it also sends on every command
    double cameraFps = 40.0;    ///< = the control rate
    devices::SyntheticCameraSettings camera;
    devices::ChannelMap channels = devices::ChannelMap::car();
    devices::TrackerSettings tracker;
    double perturbation = 1.0;  ///< of the simulated car (start offsets, friction, gains, trim)
    double lostTrackDistance = 0.0;  ///< [m], the loop's lost-track failsafe (0: none)
    devices::Geofence fence;         ///< the loop's fence (off by default)
};

/// The whole real-rig loop with no hardware: a simulated slide-car is driven by the bytes the
/// transmitter link writes to a pseudo-terminal (decoded at the far end, as a transmitter
/// would); the synthetic camera renders the car's LEDs; the tracker, the state estimator and
/// the controller close the loop through the link. Every stage is the real-rig code; only the
/// car and the camera are simulated. Runs in real time in the calling thread (the link has
/// its own).
class VirtualRig {
  public:
    VirtualRig(VirtualRigSettings settings, std::unique_ptr<core::Controller> controller);
    ~VirtualRig();

    /// Opens the pseudo-terminal and starts the link. False with *error on failure.
    bool open(QString* error);

    struct Trial {
        devices::PlanarPose finalPose;          ///< the simulated car's true final pose
        std::vector<devices::PlanarPose> path;  ///< true pose per frame
        int frames = 0;
        int framesWithPose = 0;             ///< frames the tracker found the car in
        std::vector<double> loopLatencyMs;  ///< camera frame -> its command's bytes written
        long long linkFramesDecoded = 0;    ///< frames the far end decoded
        /// The frame in which the loop ended the trial in failsafe (the fence, the lost-track
        /// guard, a controller fault), and why; -1 and empty if it ran its length. The car is
        /// simulated on to the trial's length (it coasts, in failsafe), so `path` shows where
        /// it came to rest.
        int stopFrame = -1;
        QString stopReason;
        /// What the car's receiver held once the link had written two frames after the stop
        /// (the first may have been on its way; waited for at most 0.5 s); empty if they did
        /// not come by then.
        std::optional<Eigen::VectorXd> receivedAtStop;
    };
    /// One trial: the car starts from its (perturbed) start, the controller resets with
    /// `mode`, and the loop runs for `seconds` of real time (or until `cancelled`).
    Trial runTrial(double seconds, core::ResetMode mode, std::uint64_t seed,
                   const std::function<bool()>& cancelled = {});

    devices::TransmitterLink& link() { return *link_; }

  private:
    VirtualRigSettings settings_;
    std::unique_ptr<VirtualCar> car_;
    devices::FloorCalibration calibration_;
    std::unique_ptr<devices::TransmitterLink> link_;
    std::unique_ptr<devices::RigLoop> loop_;
};

}  // namespace prisca::rigsim
