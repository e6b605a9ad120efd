#include "rigsim/VirtualRig.h"

#include "devices/RigLoop.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace prisca::rigsim {

VirtualRig::VirtualRig(VirtualRigSettings settings, std::unique_ptr<core::Controller> controller)
    : settings_(std::move(settings)),
      car_(std::make_unique<VirtualCar>(settings_.protocol, settings_.channels, 1,
                                        settings_.perturbation)),
      calibration_(devices::syntheticCeilingCamera()),
      link_(std::make_unique<devices::TransmitterLink>()) {
    loop_ = std::make_unique<devices::RigLoop>(calibration_, settings_.tracker,
                                               std::move(controller), settings_.channels, *link_);
    loop_->setLostTrackDistance(settings_.lostTrackDistance);
    loop_->setGeofence(settings_.fence);
}

VirtualRig::~VirtualRig() {
    // The loop uses the link; the link sends its last (failsafe) frame and closes before the
    // car's pseudo-terminal goes.
    loop_.reset();
    link_.reset();
    car_.reset();
}

bool VirtualRig::open(QString* error) {
    if (!car_->open(error)) {
        return false;
    }
    devices::LinkSettings link;
    link.port = car_->portPath();
    link.protocol = settings_.protocol;
    link.rateHz = settings_.linkRateHz;
    link.staleAfter = 3.0 / settings_.cameraFps;  // three missed frames
    link.failsafe = settings_.channels.failsafe();
    link.sendOnCommand = true;
    link_->start(link);
    return true;
}

VirtualRig::Trial VirtualRig::runTrial(double seconds, core::ResetMode mode, std::uint64_t seed,
                                       const std::function<bool()>& cancelled) {
    using Clock = std::chrono::steady_clock;
    Trial trial;
    car_->reset(seed);
    loop_->startTrial(mode);
    const long long decodedBefore = car_->framesDecoded();
    const double dt = 1.0 / settings_.cameraFps;
    const int frames = static_cast<int>(std::lround(seconds * settings_.cameraFps));
    const Clock::time_point start = Clock::now();
    devices::PlanarPose truth{};
    for (int k = 0; k < frames; ++k) {
        if (cancelled && cancelled()) {
            break;
        }
        std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(k * dt)));
        // The car moves with what its receiver last decoded; the camera sees it.
        truth = car_->poseAt(k * dt);
        trial.path.push_back(truth);
        devices::CameraFrame frame;
        frame.image = devices::renderLeds(truth, calibration_, settings_.camera,
                                          settings_.tracker.geometry, seed * 100003ULL + k);
        frame.steadyNs = devices::steadyNowNs();
        frame.index = k;
        const devices::RigStep step = loop_->onFrame(frame);
        ++trial.frames;
        if (step.fault && trial.stopFrame < 0) {
            trial.stopFrame = k;
            trial.stopReason = step.stopReason;
            // The link's next frame after the fault is failsafe: wait for two (the first may
            // have been on its way), at most half a second (a loaded machine, a sanitizer).
            const long long sent = link_->framesSent();
            const auto deadline = Clock::now() + std::chrono::milliseconds(500);
            while (link_->framesSent() <= sent + 1 && Clock::now() < deadline) {
                std::this_thread::sleep_for(std::chrono::microseconds(50));
            }
            if (link_->framesSent() > sent + 1) {
                trial.receivedAtStop = car_->receivedCommand();
            }
        }
        if (step.pose && !step.fault) {
            ++trial.framesWithPose;
            // Wait (briefly) for the link to write this frame's command, and time it.
            const auto deadline = Clock::now() + std::chrono::milliseconds(15);
            while (link_->lastCommandNs() < step.frameNs && Clock::now() < deadline) {
                std::this_thread::sleep_for(std::chrono::microseconds(50));
            }
            if (link_->lastCommandNs() >= step.frameNs) {
                trial.loopLatencyMs.push_back((link_->lastWriteNs() - step.frameNs) * 1e-6);
            }
        }
    }
    trial.finalPose = truth;
    trial.linkFramesDecoded = car_->framesDecoded() - decodedBefore;
    return trial;
}

}  // namespace prisca::rigsim
