#include "app/VirtualRig.h"

#include "devices/RigLoop.h"
#include "sim/PlantCatalog.h"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <thread>

namespace prisca::app {

VirtualRig::VirtualRig(VirtualRigSettings settings, std::unique_ptr<core::Controller> controller)
    : settings_(std::move(settings)),
      car_(sim::PlantCatalog::create(QStringLiteral("slidecar"))),
      calibration_(devices::syntheticCeilingCamera()),
      link_(std::make_unique<devices::TransmitterLink>()) {
    loop_ = std::make_unique<devices::RigLoop>(calibration_, settings_.tracker,
                                               std::move(controller), settings_.channels, *link_);
}

VirtualRig::~VirtualRig() {
    // The loop uses the link; the link sends its last (failsafe) frame and closes before the
    // pseudo-terminal goes.
    loop_.reset();
    link_.reset();
    if (master_ >= 0)
        ::close(master_);
    if (slave_ >= 0)
        ::close(slave_);
}

bool VirtualRig::open(QString* error) {
    char name[256] = {};
    termios raw{};
    cfmakeraw(&raw);
    if (openpty(&master_, &slave_, name, &raw, nullptr) != 0) {
        *error = QStringLiteral("no pseudo-terminal for the virtual rig");
        return false;
    }
    fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
    devices::LinkSettings link;
    link.port = QString::fromLocal8Bit(name);
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
    Eigen::VectorXd state = car_->reset(
        seed,
        sim::Perturbation{settings_.perturbation, settings_.perturbation, settings_.perturbation});
    loop_->startTrial(mode);
    devices::RcFrameDecoder decoder(settings_.protocol);
    const int m = car_->info().actionDimension();
    Eigen::VectorXd action = Eigen::VectorXd::Zero(m);
    const double dt = 1.0 / settings_.cameraFps;
    const int frames = static_cast<int>(std::lround(seconds * settings_.cameraFps));
    const Clock::time_point start = Clock::now();
    char buffer[4096];
    for (int k = 0; k < frames; ++k) {
        if (cancelled && cancelled()) {
            break;
        }
        std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                  std::chrono::duration<double>(k * dt)));
        // The far end: decode what the link wrote and apply the newest command to the car, as
        // the car's receiver would.
        for (ssize_t n; (n = ::read(master_, buffer, sizeof buffer)) > 0;) {
            for (const devices::ChannelValues& values :
                 decoder.push(QByteArray(buffer, static_cast<int>(n)))) {
                ++trial.linkFramesDecoded;
                for (int l = 0; l < m && l < static_cast<int>(settings_.channels.controls.size());
                     ++l) {
                    const devices::ChannelSetting& c = settings_.channels.controls[l];
                    const double pulse =
                        devices::valueToPulse(settings_.protocol, values[c.channel]);
                    const double u = (pulse - 1500.0 - c.trim) / 512.0;
                    action[l] = std::clamp(c.reversed ? -u : u, -1.0, 1.0);
                }
            }
        }
        if (k > 0) {
            state = car_->step(action);
        }
        const devices::PlanarPose truth{state[0], state[1], state[2]};
        trial.path.push_back(truth);
        // The camera sees the car; the rig loop does the rest.
        devices::CameraFrame frame;
        frame.image = devices::renderLeds(truth, calibration_, settings_.camera,
                                          settings_.tracker.geometry, seed * 100003ULL + k);
        frame.steadyNs = devices::steadyNowNs();
        frame.index = k;
        const devices::RigStep step = loop_->onFrame(frame);
        ++trial.frames;
        if (step.pose) {
            ++trial.framesWithPose;
            // Wait (briefly) for the link to write this frame's command, and time it.
            const auto deadline = Clock::now() + std::chrono::milliseconds(15);
            while (link_->lastCommandNs() < step.frameNs && Clock::now() < deadline) {
                std::this_thread::sleep_for(std::chrono::microseconds(50));
            }
            if (link_->lastCommandNs() >= step.frameNs) {
                trial.latencyMs.push_back((link_->lastWriteNs() - step.frameNs) * 1e-6);
            }
        }
    }
    trial.finalPose = {state[0], state[1], state[2]};
    return trial;
}

}  // namespace prisca::app
