#pragma once

#include "devices/ChannelMap.h"
#include "devices/LedTracker.h"
#include "devices/RcProtocols.h"
#include "sim/plants/Plant.h"
#include "sim/plants/PlantParameters.h"

#include <QString>

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>

namespace prisca::rigsim {

/// The far end of a transmitter link with no hardware: a pseudo-terminal whose bytes are
/// decoded as a car's receiver would, driving a simulated slide-car. The synthetic camera asks
/// it where the car is (poseAt), which steps the car up to that time with the newest command.
/// Used by the virtual rig: the camera's thread steps it; receivedCommand() may be called from any
/// thread once the camera has stopped or while it runs.
class VirtualCar {
  public:
    VirtualCar(devices::RcProtocol protocol, devices::ChannelMap channels, std::uint64_t seed,
               double perturbation);
    ~VirtualCar();
    VirtualCar(const VirtualCar&) = delete;
    VirtualCar& operator=(const VirtualCar&) = delete;

    /// Drives a car of these physical parameters from the next reset on (null: the catalog's
    /// slide-car). std::invalid_argument for another plant's parameters. Any thread.
    void usePlant(std::shared_ptr<const sim::PlantParameters> parameters);
    /// The parameters of the car driven (null: the catalog's). Any thread.
    std::shared_ptr<const sim::PlantParameters> plant() const;

    /// Opens the pseudo-terminal; false with *error on failure.
    bool open(QString* error);
    /// The path a link should open to drive this car.
    const QString& portPath() const { return path_; }
    /// Steps the car to time t [s] (control periods of 25 ms) with the newest decoded command,
    /// and returns its true pose.
    devices::PlanarPose poseAt(double t);
    /// Frames decoded from the link so far. Any thread.
    long long framesDecoded() const { return decoded_.load(); }
    /// What the receiver holds now: reads the bytes waiting on the line (so a link that has
    /// just sent its last frame and closed is heard) and returns the action [-1, 1] decoded
    /// from the newest frame (zeros before any frame). Any thread.
    Eigen::VectorXd receivedCommand();
    /// The camera sees the car as it was `seconds` ago (a camera's exposure-to-arrival
    /// latency, injected to test what measures it). 0 by default. Any thread.
    void setCameraDelay(double seconds);
    /// Puts the car back at its start (a new trial), with a new seed.
    void reset(std::uint64_t seed);
    /// Any thread: the car goes back to its start at the next poseAt() (a new trial on the
    /// virtual rig while the camera runs).
    void requestReset(std::uint64_t seed) {
        resetSeed_.store(seed);
        resetRequested_.store(true);
    }

  private:
    void readCommands();  ///< under mutex_
    void resetLocked(std::uint64_t seed);

    mutable std::mutex mutex_;  ///< the line, the decoder, the car (camera thread vs readback)

    devices::RcProtocol protocol_;
    devices::ChannelMap channels_;
    double perturbation_;
    std::unique_ptr<sim::Plant> car_;
    std::shared_ptr<const sim::PlantParameters> parameters_;
    devices::RcFrameDecoder decoder_;
    Eigen::VectorXd state_;
    Eigen::VectorXd action_;
    double time_ = 0.0;
    double cameraDelay_ = 0.0;
    std::deque<std::pair<double, devices::PlanarPose>> history_;  ///< time, pose per step
    std::atomic<bool> resetRequested_{false};
    std::atomic<std::uint64_t> resetSeed_{1};
    std::atomic<long long> decoded_{0};
    int master_ = -1;
    int slave_ = -1;
    QString path_;
};

}  // namespace prisca::rigsim
