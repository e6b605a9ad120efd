#include "rigsim/VirtualCar.h"

#include "sim/PlantCatalog.h"

#include <fcntl.h>
#include <pty.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <stdexcept>

namespace prisca::rigsim {

VirtualCar::VirtualCar(devices::RcProtocol protocol, devices::ChannelMap channels,
                       std::uint64_t seed, double perturbation)
    : protocol_(protocol),
      channels_(std::move(channels)),
      perturbation_(perturbation),
      car_(sim::PlantCatalog::create(QStringLiteral("slidecar"))),
      decoder_(protocol) {
    resetLocked(seed);
}

VirtualCar::~VirtualCar() {
    if (master_ >= 0)
        ::close(master_);
    if (slave_ >= 0)
        ::close(slave_);
}

bool VirtualCar::open(QString* error) {
    char name[256] = {};
    termios raw{};
    cfmakeraw(&raw);
    if (openpty(&master_, &slave_, name, &raw, nullptr) != 0) {
        *error = QStringLiteral("no pseudo-terminal for the virtual car");
        return false;
    }
    fcntl(master_, F_SETFL, fcntl(master_, F_GETFL) | O_NONBLOCK);
    path_ = QString::fromLocal8Bit(name);
    return true;
}

void VirtualCar::usePlant(std::shared_ptr<const sim::PlantParameters> parameters) {
    if (parameters && parameters->plant != QLatin1String("slidecar")) {
        throw std::invalid_argument("the virtual rig drives a slide-car");
    }
    auto car = parameters ? sim::PlantCatalog::create(*parameters)
                          : sim::PlantCatalog::create(QStringLiteral("slidecar"));
    std::lock_guard<std::mutex> lock(mutex_);
    car_ = std::move(car);
    parameters_ = std::move(parameters);
    resetLocked(1);
}

std::shared_ptr<const sim::PlantParameters> VirtualCar::plant() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return parameters_;
}

void VirtualCar::reset(std::uint64_t seed) {
    std::lock_guard<std::mutex> lock(mutex_);
    resetLocked(seed);
}

void VirtualCar::resetLocked(std::uint64_t seed) {
    state_ = car_->reset(seed, sim::Perturbation{perturbation_, perturbation_, perturbation_});
    action_ = Eigen::VectorXd::Zero(car_->info().actionDimension());
    time_ = 0.0;
    history_.clear();
    history_.push_back({time_, {state_[0], state_[1], state_[2]}});
}

void VirtualCar::setCameraDelay(double seconds) {
    if (!(seconds >= 0.0 && seconds <= 2.0)) {
        throw std::invalid_argument("the virtual camera's delay must be from 0 to 2 s");
    }
    std::lock_guard<std::mutex> lock(mutex_);
    cameraDelay_ = seconds;
}

void VirtualCar::readCommands() {
    if (master_ < 0) {
        return;
    }
    char buffer[4096];
    for (ssize_t n; (n = ::read(master_, buffer, sizeof buffer)) > 0;) {
        for (const devices::ChannelValues& values :
             decoder_.push(QByteArray(buffer, static_cast<int>(n)))) {
            ++decoded_;
            for (Eigen::Index l = 0;
                 l < action_.size() && l < static_cast<Eigen::Index>(channels_.controls.size());
                 ++l) {
                const devices::ChannelSetting& c = channels_.controls[l];
                const double pulse = devices::valueToPulse(protocol_, values[c.channel]);
                const double u = (pulse - 1500.0 - c.trim) / 512.0;
                action_[l] = std::clamp(c.reversed ? -u : u, -1.0, 1.0);
            }
        }
    }
}

Eigen::VectorXd VirtualCar::receivedCommand() {
    std::lock_guard<std::mutex> lock(mutex_);
    readCommands();
    return action_;
}

devices::PlanarPose VirtualCar::poseAt(double t) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (resetRequested_.exchange(false)) {
        resetLocked(resetSeed_.load());
        time_ = t;  // the new trial starts now
    }
    readCommands();
    const double dt = car_->timing().controlPeriod;
    while (time_ + dt <= t + 1e-9) {
        state_ = car_->step(action_);
        time_ += dt;
        history_.push_back({time_, {state_[0], state_[1], state_[2]}});
    }
    // What the camera shows: the car as it was cameraDelay_ ago (linear between the physics
    // steps; the heading along the shorter way round).
    const double seen = t - cameraDelay_;
    while (history_.size() > 2 && history_[1].first <= seen) {
        history_.pop_front();
    }
    const auto& [t0, p0] = history_.front();
    if (history_.size() < 2 || seen <= t0) {
        return p0;
    }
    const auto& [t1, p1] = history_[1];
    const double w = std::clamp((seen - t0) / (t1 - t0), 0.0, 1.0);
    return {p0.x + w * (p1.x - p0.x), p0.y + w * (p1.y - p0.y),
            p0.heading + w * std::remainder(p1.heading - p0.heading, 2.0 * M_PI)};
}

}  // namespace prisca::rigsim
