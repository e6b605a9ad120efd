#pragma once

#include "core/Controller.h"
#include "core/LostTrackGuard.h"
#include "core/PoseFilter.h"
#include "sim/plants/MeasurementModel.h"
#include "sim/plants/Plant.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <vector>

namespace prisca::sim {

/// How one closed-loop trial is run.
struct EpisodeSettings {
    std::uint64_t seed = 1;             ///< draws the plant perturbation and the sensor noise
    Perturbation perturbation;          ///< plant perturbation
    MeasurementParameters measurement;  ///< the sensor between plant and controller
    double duration = 10.0;             ///< longest trial [s]
    /// End early once the plant is at rest and at least this much time has passed [s]
    /// (negative: never end early).
    double stopAtRestAfter = -1.0;
    /// A trial whose duration ends with the plant still moving runs out in failsafe: the zero
    /// action (throttle neutral, steering centred: what the rig sends when a trial ends), the
    /// controller no longer stepped, until the plant rests or this much longer [s]. A car that
    /// passes through the lot at the last step is scored where it comes to rest, not there.
    /// 0: the trial ends at its duration, moving or not.
    double runOutLimit = 0.0;
    core::ResetMode resetMode = core::ResetMode::Cold;  ///< how the controller starts the trial
    /// Latency compensation: tell the controller how old its observations are (the sensor's
    /// latency), so that trackers compensate it (Controller::setLoopLatencySteps). Off: they
    /// are told 0.
    bool compensateLoopLatency = false;
    /// Pose filter (core::PoseFilter, planar vehicles only): the sensor's observation passes
    /// through an extended Kalman filter before the controller sees it, and what the controller
    /// sees is the estimate predicted across the sensor's latency to now (dropped samples
    /// bridged by prediction, outliers gated). The controller is then told latency 0
    /// (compensatedLoopLatencySteps()). Off by default.
    bool poseFilter = false;
    /// With the pose filter: hand the controller the estimate predicted to now and tell it
    /// latency 0 (true, the default), or the estimate at the measurement's own time and let the
    /// controller compensate the latency as without the filter (false: the filter only filters,
    /// bridges and gates).
    bool poseFilterPredicts = true;
    /// The filter's parameters (MethodTuning::episode fills them from the sensor and the
    /// demonstration). The stepper sets the state dimension, the pose and velocity indices, the
    /// control period and the latency from the plant and the sensor itself.
    core::PoseFilterParameters poseFilterParameters;
    /// Position deviation [m] past which the robot has left the demonstration and the trial
    /// ends in failsafe: zero action (throttle neutral, steering centred) for the rest of it,
    /// the controller no longer stepped (core::LostTrackGuard). 0: never.
    double lostTrackDistance = 0.0;
    bool recordSteps = true;  ///< keep a StepRecord per control step

    /// The latency the controller compensates [control steps]: the sensor's, if compensated
    /// and no pose filter has already predicted the observation to now.
    int compensatedLoopLatencySteps() const {
        return compensateLoopLatency && !(poseFilter && poseFilterPredicts)
                   ? measurement.loopLatencySteps
                   : 0;
    }
};

/// The settings with the sensor's latency replaced by a measured one (a rig's loop latency
/// from its probe): `seconds` rounded to control steps of `controlPeriod`, at most `maxSteps`;
/// no measurement (nullopt) leaves them as they are. Everything that follows from the latency,
/// the controller's compensation (compensatedLoopLatencySteps(): the tuning's switch, none while
/// the pose filter predicts) and the pose filter's prediction, then follows the one rule.
EpisodeSettings withLoopLatency(EpisodeSettings settings, std::optional<double> seconds,
                                double controlPeriod, int maxSteps = 40);

/// The pose filter's parameters for a plant behind a sensor: full-state measurement with the
/// sensor's noise (each std at least 1e-6 of its unit, so a perfect sensor is simply believed),
/// its latency, the control period, and the plant's pose and velocity indices; the other fields
/// keep core::PoseFilterParameters' defaults. Throws std::invalid_argument for a plant without a
/// planar pose and body velocities.
core::PoseFilterParameters poseFilterFor(const PlantInfo& info,
                                         const MeasurementParameters& measurement,
                                         double controlPeriod);

/// One control step of a trial.
struct StepRecord {
    double time = 0.0;                ///< t_k [s]
    Eigen::VectorXd state;            ///< true state s_k
    Eigen::VectorXd observation;      ///< what the controller saw
    int referenceIndex = 0;           ///< matched demonstration sample j_k
    Eigen::VectorXd deviation;        ///< e_k as the controller formed it
    Eigen::VectorXd action;           ///< u_k applied over [t_k, t_k + dt)
    Eigen::VectorXd referenceAction;  ///< u*_{j_k}
    double cost = 0.0;                ///< C_k
    Eigen::VectorXd parameters;       ///< theta flattened column by column (empty if none)
};

/// What a trial produced.
struct EpisodeResult {
    std::vector<StepRecord> steps;  ///< per step, if recorded
    Eigen::VectorXd finalState;     ///< true state at the end
    double duration = 0.0;          ///< simulated time [s]
    int stepCount = 0;              ///< control steps taken
    double meanCost = 0.0;          ///< mean of C_k over the steps
    /// CPU time the controller took over the trial [s] (its thread's clock, for reports only:
    /// nothing in the trial depends on it).
    double controllerSeconds = 0.0;
    bool cancelled = false;  ///< stopped by the cancel predicate
    bool lostTrack = false;  ///< ended in failsafe: the robot left the demonstration
    /// Time the plant ran out in failsafe after the duration, still moving (runOutLimit) [s].
    double runOutSeconds = 0.0;
    QString controllerNote;  ///< the controller's word on the trial (Controller::trialNote)
};

/// One trial taken a control step at a time, for callers that pace it themselves (the
/// application's live run: real time, 10x, or as fast as possible, pausing and stopping between
/// steps). runEpisode() is this stepper run to its end, so both give the same trial bit for bit.
/// The plant and controller must outlive the stepper; it is single-threaded like them.
class EpisodeStepper {
  public:
    /// Resets the plant (seed, perturbation), the sensor and the controller (settings.resetMode).
    EpisodeStepper(Plant& plant, core::Controller& controller, const EpisodeSettings& settings);

    /// True once the duration is reached and the plant rests (or has run out for
    /// settings.runOutLimit), or once it rests past settings.stopAtRestAfter.
    bool finished() const;
    /// Takes one control step: observe, control, step the plant. Returns the step's record (the
    /// state and observation at its start, the action applied over it). Must not be called once
    /// finished(). The reference stays valid until the next call.
    const StepRecord& step();
    /// The true state now (after the last step).
    const Eigen::VectorXd& state() const { return state_; }
    /// Control steps taken so far.
    int stepCount() const { return k_; }
    /// Control steps of the trial's duration (over the control period); it may end sooner at
    /// rest, or run out in failsafe after them for at most runOutSteps() while still moving.
    int maxSteps() const { return maxSteps_; }
    int runOutSteps() const { return runOutSteps_; }
    /// True while the trial runs out in failsafe after its duration.
    bool runningOut() const { return k_ >= maxSteps_; }
    /// The trial so far (steps only if settings.recordSteps).
    EpisodeResult result() const;
    /// The same, moving the recorded steps out (the stepper keeps none afterwards).
    EpisodeResult takeResult();

  private:
    Plant& plant_;
    core::Controller& controller_;
    EpisodeSettings settings_;
    core::LostTrackGuard guard_;
    MeasurementModel sensor_;
    std::optional<core::PoseFilter> filter_;  ///< settings.poseFilter
    Eigen::VectorXd state_;
    StepRecord last_;
    std::vector<StepRecord> steps_;
    double costSum_ = 0.0;
    double controllerSeconds_ = 0.0;
    int k_ = 0;
    int maxSteps_ = 0;
    int runOutSteps_ = 0;
};

/// The reset of trial `trial` (0-based) in a row of trials: a cold start for the first (the
/// learner starts from its initial policy), warm starts after (learning carries on).
inline core::ResetMode resetForTrial(int trial) {
    return trial == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart;
}

/// Trial `trial` of a row of trials whose run is seeded `runSeed`: its seed is
/// mixSeed(runSeed, trial) and its reset resetForTrial(trial). Every front end and experiment
/// numbers its trials this way, so the same run seed gives the same trials everywhere.
inline void setTrial(EpisodeSettings& episode, std::uint64_t runSeed, int trial) {
    episode.seed = mixSeed(runSeed, static_cast<std::uint64_t>(trial));
    episode.resetMode = resetForTrial(trial);
}

/// Runs one trial: reset plant (seed, perturbation) and controller, then at every control step
/// measure -> control -> step the plant, until the duration (or rest) is reached. The result is a
/// pure function of the arguments: the same seed gives the same trial bit for bit.
/// `cancelled` is polled every step (any thread may flip what it reads).
EpisodeResult runEpisode(Plant& plant, core::Controller& controller,
                         const EpisodeSettings& settings,
                         const std::function<bool()>& cancelled = {});

}  // namespace prisca::sim
