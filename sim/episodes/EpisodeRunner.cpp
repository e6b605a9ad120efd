#include "sim/episodes/EpisodeRunner.h"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <stdexcept>

namespace prisca::sim {

namespace {

// The calling thread's CPU time [s]: what a controller costs, whatever else the machine does.
double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

EpisodeSettings withLoopLatency(EpisodeSettings settings, std::optional<double> seconds,
                                double controlPeriod, int maxSteps) {
    if (seconds && std::isfinite(*seconds) && controlPeriod > 0.0) {
        // Clamped before rounding: a huge value must not wrap.
        const double steps =
            std::clamp(*seconds / controlPeriod, 0.0, static_cast<double>(maxSteps));
        settings.measurement.loopLatencySteps = static_cast<int>(std::lround(steps));
    }
    return settings;
}

core::PoseFilterParameters poseFilterFor(const PlantInfo& info,
                                         const MeasurementParameters& measurement,
                                         double controlPeriod) {
    if (!info.pose || !info.bodyVelocity) {
        throw std::invalid_argument(
            QStringLiteral("the pose filter needs a planar vehicle (pose and body velocities); "
                           "'%1' has none")
                .arg(info.name)
                .toStdString());
    }
    core::PoseFilterParameters parameters;
    parameters.stateDimension = info.stateDimension();
    parameters.pose = *info.pose;
    parameters.velocity = *info.bodyVelocity;
    parameters.measureFullState();
    parameters.measurementStd = Eigen::VectorXd::Constant(parameters.stateDimension, 1e-6);
    if (measurement.noise.size() == parameters.stateDimension) {
        parameters.measurementStd = measurement.noise.cwiseMax(1e-6);
    }
    parameters.loopLatencySteps = measurement.loopLatencySteps;
    parameters.controlPeriod = controlPeriod;
    return parameters;
}

EpisodeStepper::EpisodeStepper(Plant& plant, core::Controller& controller,
                               const EpisodeSettings& settings)
    : plant_(plant),
      controller_(controller),
      settings_(settings),
      // The sensor's noise stream is its own, so changing the plant's draws never shifts it.
      guard_(settings.lostTrackDistance, plant.info().pose),
      sensor_(settings.measurement, mixSeed(settings.seed, 7)) {
    if (settings_.poseFilter) {
        // The plant and the sensor say where the pose is, how often and how late it comes.
        core::PoseFilterParameters parameters = settings_.poseFilterParameters;
        const core::PoseFilterParameters own =
            poseFilterFor(plant_.info(), settings_.measurement, plant_.timing().controlPeriod);
        parameters.stateDimension = own.stateDimension;
        parameters.pose = own.pose;
        parameters.velocity = own.velocity;
        parameters.controlPeriod = own.controlPeriod;
        parameters.loopLatencySteps = own.loopLatencySteps;
        if (parameters.measurementStd.size() != own.stateDimension) {
            parameters.measurementStd = own.measurementStd;
        }
        filter_.emplace(parameters, plant_.info().actionDimension());
    }
    state_ = plant_.reset(settings_.seed, settings_.perturbation);
    sensor_.reset(state_);
    if (auto* aware = dynamic_cast<PlantAware*>(&controller_)) {
        aware->attachPlant(&plant_);  // the oracle plans on copies of this very plant
    }
    // The sensor's latency is known to the loop; the rig sets the same from its RunSetup.
    controller_.setLoopLatencySteps(settings_.compensatedLoopLatencySteps());
    controller_.reset(settings_.resetMode);
    maxSteps_ = static_cast<int>(settings_.duration / plant_.timing().controlPeriod + 0.5);
    runOutSteps_ = static_cast<int>(
        std::max(0.0, settings_.runOutLimit) / plant_.timing().controlPeriod + 0.5);
}

bool EpisodeStepper::finished() const {
    if (k_ >= maxSteps_) {
        return k_ >= maxSteps_ + runOutSteps_ || plant_.atRest();
    }
    const double t = k_ * plant_.timing().controlPeriod;
    return settings_.stopAtRestAfter >= 0.0 && t >= settings_.stopAtRestAfter && plant_.atRest();
}

const StepRecord& EpisodeStepper::step() {
    const double t = k_ * plant_.timing().controlPeriod;
    last_.time = t;
    last_.state = state_;
    last_.observation = sensor_.observe(state_);
    if (filter_) {
        last_.observation = filter_->step(last_.observation, sensor_.lastDropped());
        if (!settings_.poseFilterPredicts) {
            // The estimate of the measurement's own time; the controller compensates the latency.
            last_.observation = filter_->predictTo(
                static_cast<double>(k_ - settings_.measurement.loopLatencySteps) *
                plant_.timing().controlPeriod);
        }
    }
    if (!guard_.tripped() && !runningOut()) {
        const double before = threadCpuSeconds();
        const core::ControlStep& control = controller_.step(last_.observation);
        controllerSeconds_ += threadCpuSeconds() - before;
        last_.referenceIndex = control.referenceIndex;
        last_.deviation = control.deviation;
        last_.action = control.action;
        last_.referenceAction = control.referenceAction;
        last_.cost = control.cost;
        guard_.check(control.deviation);
    }
    if (guard_.tripped() || runningOut()) {
        // Failsafe from the step that saw it on, and after the duration: the controller rests.
        last_.action = Eigen::VectorXd::Zero(plant_.info().actionDimension());
    }
    if (filter_) {
        filter_->commanded(last_.action);  // the action the plant is given from now on
    }
    costSum_ += last_.cost;
    if (const Eigen::MatrixXd* theta = controller_.learnedParameters()) {
        last_.parameters = theta->reshaped();
    }
    if (settings_.recordSteps) {
        steps_.push_back(last_);
    }
    state_ = plant_.step(last_.action);
    ++k_;
    return last_;
}

EpisodeResult EpisodeStepper::result() const {
    EpisodeResult result;
    result.finalState = state_;
    result.stepCount = k_;
    result.duration = k_ * plant_.timing().controlPeriod;
    result.runOutSeconds = std::max(0, k_ - maxSteps_) * plant_.timing().controlPeriod;
    result.meanCost = k_ > 0 ? costSum_ / k_ : 0.0;
    result.controllerSeconds = controllerSeconds_;
    result.lostTrack = guard_.tripped();
    result.controllerNote = controller_.trialNote();
    result.steps = steps_;
    return result;
}

EpisodeResult EpisodeStepper::takeResult() {
    std::vector<StepRecord> steps = std::move(steps_);
    steps_.clear();
    EpisodeResult result = this->result();  // the summary, with no steps left to copy
    result.steps = std::move(steps);
    return result;
}

EpisodeResult runEpisode(Plant& plant, core::Controller& controller,
                         const EpisodeSettings& settings, const std::function<bool()>& cancelled) {
    EpisodeStepper stepper(plant, controller, settings);
    bool wasCancelled = false;
    while (!stepper.finished()) {
        if (cancelled && cancelled()) {
            wasCancelled = true;
            break;
        }
        stepper.step();
    }
    EpisodeResult result = stepper.takeResult();
    result.cancelled = wasCancelled;
    return result;
}

}  // namespace prisca::sim
