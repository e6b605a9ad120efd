#include "sim/planning/MpcController.h"

#include "core/DeviationModel.h"
#include "sim/planning/Identification_p.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace prisca::sim {

namespace {

// How far a measured position is from the lot (the demonstration's last pose), as parkingError
// measures a trial.
double distanceFromLot(const core::TrackingProblem& problem, const Eigen::VectorXd& observation) {
    const core::Demonstration& demo = *problem.demonstration;
    const core::PlanarPoseIndices pose = *problem.deviation.pose;
    const int end = demo.length() - 1;
    return std::hypot(observation[pose.x] - demo.states(end, pose.x),
                      observation[pose.y] - demo.states(end, pose.y));
}

// Where the model's rolling resistance is among its parameters.
int rollingIndex(const PlantParameters& model) {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(model.plant);
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].key == QLatin1String("rollingResistance")) {
            return static_cast<int>(i);
        }
    }
    throw std::invalid_argument("mpc's model has no rolling resistance");
}

}  // namespace

double largestSidewaysSpeed(const core::Demonstration& demonstration,
                            const std::optional<core::BodyVelocityIndices>& velocity) {
    if (!velocity || demonstration.states.rows() == 0) {
        return std::numeric_limits<double>::infinity();
    }
    return demonstration.states.col(velocity->lateral).cwiseAbs().maxCoeff();
}

bool slideWorthPlanning(const core::Demonstration& demonstration,
                        const std::optional<core::BodyVelocityIndices>& velocity,
                        const MpcParameters& parameters) {
    return largestSidewaysSpeed(demonstration, velocity) >= parameters.planSlide;
}

IdentificationSettings mpcIdentificationSettings(const MpcParameters& parameters, bool refit) {
    IdentificationSettings settings;
    settings.physicsSubsteps = parameters.substeps;
    settings.segmentSeconds = parameters.modelSegment;
    if (refit) {
        settings.global = false;
        settings.restarts = 0;
        settings.passes = 1;
        settings.evaluationsPerStart = parameters.refitEvaluations;
    } else {
        settings.restarts = 1;
        settings.evaluationsPerStart = parameters.identifyEvaluations;
    }
    return settings;
}

IdentificationResult identifyForMpc(const std::vector<core::Demonstration>& data,
                                    const PlantParameters& prior, const MpcParameters& parameters,
                                    const std::function<bool()>& cancelled) {
    const IdentificationProgress goOn = [&cancelled](long long, long long) {
        return !(cancelled && cancelled());
    };
    IdentificationResult quick =
        identifyPlant(data, prior, mpcIdentificationSettings(parameters, false), goOn);
    if (!quick.ok() || quick.positionRms <= parameters.poorFit || parameters.retryEvaluations < 1) {
        return quick;
    }
    IdentificationSettings thorough = mpcIdentificationSettings(parameters, false);
    thorough.evaluationsPerStart = parameters.retryEvaluations;
    thorough.restarts = 2;
    IdentificationResult again = identifyPlant(data, prior, thorough, goOn);
    return again.ok() && again.positionRms < quick.positionRms ? again : quick;
}

MpcController::MpcController(core::TrackingProblem problem, MpcParameters parameters,
                             OracleParameters planner, std::unique_ptr<core::Controller> fallback,
                             PlantParameters model, double modelFit,
                             std::vector<core::Demonstration> data,
                             std::unique_ptr<core::Controller> startLaw, QString noModel)
    : problem_(core::TrackingProblem::validated(std::move(problem))),
      parameters_(parameters),
      plannerParameters_(std::move(planner)),
      fallback_(std::move(fallback)),
      startLaw_(std::move(startLaw)),
      firstModel_(model),
      firstFit_(modelFit),
      model_(std::move(model)),
      modelFit_(modelFit),
      data_(data),
      firstData_(std::move(data)),
      noModel_(std::move(noModel)) {
    if (!fallback_ || !startLaw_) {
        throw std::invalid_argument("MpcController: a fallback law and a start law are needed");
    }
    if (!problem_.deviation.pose) {
        throw std::invalid_argument(
            "MpcController: model-predictive parking needs a planar vehicle");
    }
    if (parameters_.replanEvery < 1 || parameters_.rollouts < 2 || parameters_.maxKnots < 2 ||
        parameters_.substeps < 1 || !(parameters_.tubeSeconds > 0.0) ||
        parameters_.tubeStrikes < 1 || !(parameters_.tubePosition > 0.0) ||
        !(parameters_.tubeHeading > 0.0) || !(parameters_.straightCorrection >= 0.0) ||
        !(parameters_.turnShare > 0.0 && parameters_.turnShare <= 1.0)) {
        throw std::invalid_argument(
            "MpcController: replanning, rollouts >= 2, knots >= 2, substeps, the tube's steps and "
            "strikes >= 1, positive tube bounds, a correction before the turn >= 0 and a turn's "
            "share in (0, 1] needed");
    }
    if (model_.plant != problem_.demonstration->plant && !problem_.demonstration->plant.isEmpty()) {
        throw std::invalid_argument(
            QStringLiteral("MpcController: the model is a '%1', the demonstration a '%2'")
                .arg(model_.plant, problem_.demonstration->plant)
                .toStdString());
    }
    plannerParameters_.objective = OracleParameters::Objective::FinalPose;
    if (!parameters_.feedback) {
        plannerParameters_.feedback.resize(0, 0);
    }
    plannerParameters_.replanEvery = parameters_.replanEvery;
    plannerParameters_.samples = parameters_.rollouts;
    plannerParameters_.maxKnots = parameters_.maxKnots;
    plannerParameters_.correctionScale = parameters_.correctionScale;
    plannerParameters_.maxCorrection = parameters_.maxCorrection;
    plannerParameters_.trackingScale = parameters_.trackingScale;
    record_.action.setZero(problem_.demonstration->actionDimension());
    if (problem_.deviation.bodyVelocity) {
        // A spin begins on the way into the slide; past the demonstration's fastest turn the
        // car is parking, and a slide there (a counter-slide as it settles, a car that lags
        // its demonstration) is the plan's to finish.
        const int yawRate = problem_.deviation.bodyVelocity->yawRate;
        const Eigen::MatrixXd& states = problem_.demonstration->states;
        for (Eigen::Index j = 0; j < states.rows(); ++j) {
            if (std::abs(states(j, yawRate)) > std::abs(states(spinUntil_, yawRate))) {
                spinUntil_ = static_cast<int>(j);
            }
        }
        const double fastest = std::abs(states(spinUntil_, yawRate));
        turnStart_ = spinUntil_;
        while (turnStart_ > 0 &&
               std::abs(states(turnStart_ - 1, yawRate)) > parameters_.turnShare * fastest) {
            --turnStart_;
        }
        plannerParameters_.calmUntil = turnStart_;
        plannerParameters_.calmCorrection = parameters_.straightCorrection;
    }
    demonstrationSlide_ =
        largestSidewaysSpeed(*problem_.demonstration, problem_.deviation.bodyVelocity);
    // The approach to the lot (parkingApproach): the throttle's index, and the way the
    // demonstration last moved, forwards or backwards, into its last pose.
    const core::Demonstration& demo = *problem_.demonstration;
    const int throttle = static_cast<int>(demo.actionNames.indexOf(QStringLiteral("throttle")));
    if (problem_.deviation.bodyVelocity && throttle >= 0 && throttle < demo.actionDimension()) {
        const int forward = problem_.deviation.bodyVelocity->forward;
        for (Eigen::Index j = demo.length() - 1; j >= 0 && arrival_ == 0.0; --j) {
            if (std::abs(demo.states(j, forward)) > 0.05) {
                arrival_ = std::copysign(1.0, demo.states(j, forward));
            }
        }
        throttle_ = arrival_ != 0.0 ? throttle : -1;
        // The demonstration's own coast into the lot (the same car): its last stretch with
        // nothing sent and the car moving; the deceleration less the model's drag over it.
        const double dt = demo.dt;
        Eigen::Index last = demo.length() - 1;
        while (last > 0 && std::abs(demo.states(last, forward)) < 0.1) {
            --last;
        }
        Eigen::Index begin = last;
        while (begin > 0 && std::abs(demo.actions(begin - 1, throttle)) < 1e-3 &&
               std::abs(demo.states(begin - 1, forward)) > 0.1) {
            --begin;
        }
        // The commands take effect a dead time later: the first 0.2 s are left out.
        begin += static_cast<Eigen::Index>(0.2 / dt);
        if (last - begin >= static_cast<Eigen::Index>(0.4 / dt)) {
            const double from = std::abs(demo.states(begin, forward));
            const double to = std::abs(demo.states(last, forward));
            demonstrationCoast_ = (from - to) / ((last - begin) * dt);
            demonstrationCoastSpeed_ = 0.5 * (from + to);
        }
    }
    reset(core::ResetMode::Cold);
}

MpcController::MpcController(const MpcController& other)
    : problem_(other.problem_),
      parameters_(other.parameters_),
      plannerParameters_(other.plannerParameters_),
      fallback_(other.fallback_->clone()),
      startLaw_(other.startLaw_->clone()),
      firstModel_(other.firstModel_),
      firstFit_(other.firstFit_),
      model_(other.model_),
      modelFit_(other.modelFit_),
      data_(other.data_),
      firstData_(other.firstData_),
      noModel_(other.noModel_),
      latency_(other.latency_),
      pendingLatency_(other.pendingLatency_),
      observations_(other.observations_),
      actions_(other.actions_),
      mode_(other.mode_),
      fallbackReason_(other.fallbackReason_),
      fallbackStep_(other.fallbackStep_),
      strikes_(other.strikes_),
      spinStrikes_(other.spinStrikes_),
      steeringBias_(other.steeringBias_),
      spinUntil_(other.spinUntil_),
      turnStart_(other.turnStart_),
      demonstrationSlide_(other.demonstrationSlide_),
      refits_(other.refits_),
      step_(other.step_),
      rollingBias_(other.rollingBias_),
      throttle_(other.throttle_),
      arrival_(other.arrival_),
      approachIntegral_(other.approachIntegral_),
      approaching_(other.approaching_),
      approachStep_(other.approachStep_),
      demonstrationCoast_(other.demonstrationCoast_),
      demonstrationCoastSpeed_(other.demonstrationCoastSpeed_),
      day_(other.day_),
      fallbackLawDrives_(other.fallbackLawDrives_),
      record_(other.record_) {
    buildModel();
    if (other.appliedBias_ != 0.0) {
        applyRollingBias(other.appliedBias_);
    }
    if (other.planner_) {
        planner_ = std::make_unique<OracleController>(*other.planner_);
        attachModels();
    }
    if (other.modelPlant_) {
        modelPlant_->resetTo(other.modelPlant_->state());
    }
}

std::unique_ptr<core::Controller> MpcController::clone() const {
    return std::make_unique<MpcController>(*this);
}

QString MpcController::trialNote() const {
    if (mode_ != MpcMode::Fallback) {
        const QString planned = modelFit_ >= 0.0
                                    ? QStringLiteral("planned through the model (fit %1 cm)")
                                          .arg(100.0 * modelFit_, 0, 'f', 1)
                                    : QStringLiteral("planned through the model");
        if (mode_ == MpcMode::Planning) {
            return planned;
        }
        const double dt = problem_.demonstration->dt;
        const QString parked = QStringLiteral("%1; the feedback law parked it from %2 s")
                                   .arg(planned)
                                   .arg(fallbackStep_ * dt, 0, 'f', 2);
        return approachStep_ < 0 ? parked
                                 : QStringLiteral("%1, pushed on towards the lot from %2 s")
                                       .arg(parked)
                                       .arg(approachStep_ * dt, 0, 'f', 2);
    }
    return fallbackStep_ > 0 ? QStringLiteral("the feedback law drove from %1 s: %2")
                                   .arg(fallbackStep_ * problem_.demonstration->dt, 0, 'f', 2)
                                   .arg(fallbackReason_)
                             : QStringLiteral("the feedback law drove: %1").arg(fallbackReason_);
}

void MpcController::setLoopLatencySteps(int steps) {
    pendingLatency_ = std::max(0, steps);
    fallback_->setLoopLatencySteps(steps);
    startLaw_->setLoopLatencySteps(steps);
}

void MpcController::buildModel() {
    planner_ = std::make_unique<OracleController>(problem_, plannerParameters_);
    appliedBias_ = 0.0;
    // The model's steering geometry, read once per model (the steering correction's every step).
    wheelbase_ = model_.value(QStringLiteral("wheelbase"));
    steeringLock_ = model_.value(QStringLiteral("maxSteeringAngle"));
    makeModels(model_);
}

void MpcController::makeModels(const PlantParameters& parameters) {
    SimulationTiming timing;
    timing.controlPeriod = problem_.demonstration->dt;
    timing.physicsSubsteps = parameters_.substeps;
    modelPlant_ = makePlant(parameters, timing);
    scratch_ = makePlant(parameters, timing);
    ensemble_.clear();
    if (parameters_.gripSpread > 0.0) {
        // The same car on less grip: the side a plan spins out on.
        const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(parameters.plant);
        PlantParameters slippery = parameters;
        for (size_t i = 0; i < specs.size(); ++i) {
            const QString& key = specs[i].key;
            if (key == QLatin1String("staticFriction") || key == QLatin1String("kineticFriction")) {
                slippery.values[i] = std::clamp(slippery.values[i] * (1.0 - parameters_.gripSpread),
                                                specs[i].lower, specs[i].upper);
            }
        }
        ensemble_.push_back(makePlant(slippery, timing));
    }
    applySteeringBias();
    attachModels();
}

void MpcController::correctRolling(const Eigen::VectorXd& predicted,
                                   const Eigen::VectorXd& observation) {
    if (!(parameters_.rollingBiasGain > 0.0) || !problem_.deviation.bodyVelocity ||
        step_ - latency_ <= spinUntil_) {
        return;
    }
    const core::BodyVelocityIndices v = *problem_.deviation.bodyVelocity;
    const double forward = observation[v.forward];
    // Rolling straight: no side slip or turn for the rolling resistance to hide behind.
    if (std::abs(forward) < 0.05 || std::abs(observation[v.lateral]) > 0.1 ||
        std::abs(observation[v.yawRate]) > 0.3) {
        return;
    }
    const double window = tubeSteps() * problem_.demonstration->dt;
    // The deceleration the model missed (positive: the car slows more than the model says).
    const double missed = -std::copysign(1.0, forward) * (forward - predicted[v.forward]) / window;
    const int i = rollingIndex(model_);
    const PlantParameterSpec& spec = plantParameterSpecs(model_.plant)[static_cast<size_t>(i)];
    const double base = model_.values[static_cast<size_t>(i)];
    rollingBias_ = std::clamp(rollingBias_ + parameters_.rollingBiasGain * missed / 9.81,
                              spec.lower - base, spec.upper - base);
}

void MpcController::correctSteering(const Eigen::VectorXd& predicted,
                                    const Eigen::VectorXd& observation) {
    if (!(parameters_.steeringBiasGain > 0.0) || !problem_.deviation.bodyVelocity ||
        step_ - latency_ >= turnStart_) {
        return;
    }
    const core::BodyVelocityIndices v = *problem_.deviation.bodyVelocity;
    const double forward = observation[v.forward];
    if (!(forward > 1.0)) {
        return;
    }
    const core::PlanarPoseIndices pose = *problem_.deviation.pose;
    const double window = tubeSteps() * problem_.demonstration->dt;
    // The yaw rate the model missed, and the wheel angle that turns the car so at this speed.
    const double missed =
        core::wrapAngle(observation[pose.heading] - predicted[pose.heading]) / window;
    if (!(wheelbase_ > 0.0 && steeringLock_ > 0.0)) {
        return;
    }
    const double offset = std::atan(missed * wheelbase_ / forward) / steeringLock_;
    steeringBias_ = std::clamp(steeringBias_ + parameters_.steeringBiasGain * offset, -0.15, 0.15);
    applySteeringBias();
}

void MpcController::applySteeringBias() {
    modelPlant_->setSteeringOffset(steeringBias_);
    scratch_->setSteeringOffset(steeringBias_);
    for (const auto& plant : ensemble_) {
        plant->setSteeringOffset(steeringBias_);
    }
}

void MpcController::applyRollingBias(double bias) {
    PlantParameters biased = model_;
    biased.values[static_cast<size_t>(rollingIndex(model_))] += bias;
    makeModels(biased);
    appliedBias_ = bias;
}

void MpcController::attachModels() {
    planner_->attachPlant(modelPlant_.get());
    std::vector<const Plant*> others;
    for (const auto& plant : ensemble_) {
        others.push_back(plant.get());
    }
    planner_->attachEnsemble(std::move(others));
}

void MpcController::reset(core::ResetMode mode) {
    if (mode == core::ResetMode::Cold) {
        model_ = firstModel_;
        modelFit_ = firstFit_;
        data_ = firstData_;
        refits_ = 0;
        day_ = {};
    } else if (step_ > 0) {
        recordLastTrial();
        refitOnLastTrial();
    }
    latency_ = pendingLatency_;
    steeringBias_ = 0.0;  // makeModels gives the new models this
    buildModel();
    fallback_->reset(mode);
    startLaw_->reset(mode);
    observations_.clear();
    actions_.clear();
    step_ = 0;
    strikes_ = 0;
    spinStrikes_ = 0;
    rollingBias_ = 0.0;
    approachIntegral_ = 0.0;
    approaching_ = false;
    approachStep_ = -1;
    mode_ = MpcMode::Planning;
    fallbackReason_.clear();
    fallbackStep_ = -1;
    fallbackLawDrives_ = false;
    if (demonstrationSlide_ < parameters_.planSlide) {
        fallBack(QStringLiteral("the demonstration slides at most %1 m/s sideways, and a plan is "
                                "for slides of %2 m/s or more")
                     .arg(demonstrationSlide_, 0, 'f', 2)
                     .arg(parameters_.planSlide, 0, 'f', 2));
    } else if (!(modelFit_ <= parameters_.planFit) && modelFit_ >= 0.0) {
        fallBack(QStringLiteral("the model fits its data to %1 cm, more than the %2 cm it may")
                     .arg(100.0 * modelFit_, 0, 'f', 1)
                     .arg(100.0 * parameters_.planFit, 0, 'f', 1));
    } else if (!std::isfinite(modelFit_)) {
        fallBack(noModel_.isEmpty()
                     ? QStringLiteral("the model's fit is unknown")
                     : QStringLiteral("no model to plan through (%1)").arg(noModel_));
    } else if (const QString why = dayPrefersStartLaw(); !why.isEmpty()) {
        fallBack(why);
    }
    if (mode_ == MpcMode::Fallback) {
        if (const QString why = dayPrefersFallbackLaw(); !why.isEmpty()) {
            fallbackLawDrives_ = true;
            fallbackReason_ = QStringLiteral("%1; %2").arg(fallbackReason_, why);
        }
    }
}

void MpcController::recordLastTrial() {
    if (observations_.empty() || !problem_.deviation.pose) {
        return;
    }
    // The distance from the lot as the last measurement has it (the car is at rest by the
    // trial's end, or what is left of its motion counts against whoever drove it).
    const double miss = distanceFromLot(problem_, observations_.back());
    const bool fromStart = mode_ == MpcMode::Fallback && fallbackStep_ == 0;
    if (!fromStart) {
        day_.planned.push_back(miss);
    } else {
        (fallbackLawDrives_ ? day_.fallbackLaw : day_.startLaw).push_back(miss);
    }
}

namespace {

double meanOf(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// "trial 5.0 cm from the lot" or "3 trials 5.0 cm from the lot on average"
QString trialsText(const std::vector<double>& v) {
    return v.size() == 1
               ? QStringLiteral("trial %1 cm from the lot").arg(100.0 * v.front(), 0, 'f', 1)
               : QStringLiteral("%1 trials %2 cm from the lot on average")
                     .arg(v.size())
                     .arg(100.0 * meanOf(v), 0, 'f', 1);
}

}  // namespace

QString MpcController::dayPrefersFallbackLaw() const {
    if (!parameters_.lawChoice || !(parameters_.planTrust > 0.0) || day_.startLaw.empty()) {
        return {};
    }
    if (day_.fallbackLaw.empty()) {
        if (!(meanOf(day_.startLaw) > parameters_.planTrust)) {
            return {};
        }
        return QStringLiteral(
                   "the fallback law drives it from its start, as the start law "
                   "parked this day's %1, more than the %2 cm it may")
            .arg(trialsText(day_.startLaw))
            .arg(100.0 * parameters_.planTrust, 0, 'f', 1);
    }
    if (!(meanOf(day_.fallbackLaw) < meanOf(day_.startLaw))) {
        return {};
    }
    return QStringLiteral(
               "the fallback law drives it from its start: it parked this day's %1, "
               "the start law its %2")
        .arg(trialsText(day_.fallbackLaw))
        .arg(trialsText(day_.startLaw));
}

QString MpcController::dayPrefersStartLaw() const {
    if (!(parameters_.planTrust > 0.0) || day_.planned.empty()) {
        return {};
    }
    const double planned = meanOf(day_.planned);
    if (day_.startLaw.empty()) {
        if (planned <= parameters_.planTrust) {
            return {};
        }
        return QStringLiteral("the plan parked this day's %1, more than the %2 cm it may")
            .arg(trialsText(day_.planned))
            .arg(100.0 * parameters_.planTrust, 0, 'f', 1);
    }
    // The plan against the better of the laws that drove trials from their start.
    const bool fallbackBetter =
        !day_.fallbackLaw.empty() && meanOf(day_.fallbackLaw) < meanOf(day_.startLaw);
    const std::vector<double>& law = fallbackBetter ? day_.fallbackLaw : day_.startLaw;
    if (planned <= meanOf(law)) {
        return {};
    }
    return QStringLiteral("the %1 law parked this day's %2, the plan its %3")
        .arg(fallbackBetter ? QStringLiteral("fallback") : QStringLiteral("start"))
        .arg(trialsText(law))
        .arg(trialsText(day_.planned));
}

double MpcController::approachThrottle(double law) {
    const double nothing = std::numeric_limits<double>::quiet_NaN();
    if (!(parameters_.parkingApproach > 0.0)) {
        return nothing;
    }
    const core::Demonstration& demo = *problem_.demonstration;
    const core::PlanarPoseIndices pose = *problem_.deviation.pose;
    const core::BodyVelocityIndices v = *problem_.deviation.bodyVelocity;
    const Eigen::VectorXd& now = observations_.back();
    const double dt = demo.dt;
    const double mass = model_.value(QStringLiteral("mass"));
    const double drag = model_.value(QStringLiteral("drivelineDrag")) / mass;  // [1/s]
    const double rolling =
        9.81 * (model_.value(QStringLiteral("rollingResistance")) + rollingBias_);        // [m/s^2]
    const double pushPerThrottle = model_.value(QStringLiteral("maxDriveForce")) / mass;  // [m/s^2]
    // The speed towards the lot (over the last three measurements: one is noisy), and the
    // distance to go along the lot's heading, both of the time of now (the measurement is the
    // latency old).
    const size_t seen = observations_.size();
    const size_t from = seen - std::min<size_t>(seen, 3);
    double speed = 0.0;
    for (size_t i = from; i < seen; ++i) {
        speed += arrival_ * observations_[i][v.forward] / static_cast<double>(seen - from);
    }
    const int end = demo.length() - 1;
    const double heading = demo.states(end, pose.heading);
    const double toGo = arrival_ * (std::cos(heading) * (demo.states(end, pose.x) - now[pose.x]) +
                                    std::sin(heading) * (demo.states(end, pose.y) - now[pose.y])) -
                        std::max(0.0, speed) * latency_ * dt;
    // The car coasts at a0 + drag * speed: the model's drag, and the rest of the deceleration
    // the demonstration's own coast into the lot had (the same car); the model's rolling
    // resistance for a demonstration that did not coast in.
    const double a0 = demonstrationCoast_ > 0.0
                          ? std::max(0.05, demonstrationCoast_ - drag * demonstrationCoastSpeed_)
                          : std::max(0.05, rolling);
    // How far the car coasts from a speed: the integral of u du / (a0 + drag u).
    auto coast = [&](double u) {
        return drag > 1e-9 ? u / drag - a0 / (drag * drag) * std::log1p(drag * u / a0)
                           : u * u / (2.0 * a0);
    };
    // Pushed once its coast would end more than parkingApproach short, until it ends
    // kApproachAim short: a car that coasts in about right is the law's alone.
    constexpr double kApproachAim = 0.02;  // [m]
    const double coasted = coast(std::max(0.0, speed));
    if (!approaching_ && toGo - coasted > parameters_.parkingApproach) {
        approaching_ = true;
        approachIntegral_ = 0.0;
        if (approachStep_ < 0) {
            approachStep_ = step_;
        }
    }
    const double room = toGo - kApproachAim;
    if (approaching_ && !(room > 0.0 && coasted < room)) {
        approaching_ = false;
    }
    if (!approaching_) {
        return nothing;
    }
    double low = std::max(0.0, speed), high = low + 1.0;
    while (coast(high) < room) {
        high *= 2.0;
    }
    for (int i = 0; i < 30; ++i) {
        const double middle = 0.5 * (low + high);
        (coast(middle) < room ? low : high) = middle;
    }
    const double wanted = low;
    // A PI law on the speed, with the force that holds the speed against the coast's
    // deceleration fed forward; the integral finds what the model lacks (the ESC's neutral
    // band, a slower motor). The law's own throttle stands where it pushes harder.
    const double error = wanted - speed;
    const double gain = 1.0 / (0.5 * pushPerThrottle);  // the speed within about 0.5 s
    approachIntegral_ += gain * error * dt;
    const double hold = (a0 + drag * std::max(0.0, speed)) / pushPerThrottle;
    const double push = std::clamp(hold + gain * error + approachIntegral_, 0.0, 0.3);
    return arrival_ * std::max(push, arrival_ * law);
}

int MpcController::tubeSteps() const {
    return std::max(
        1, static_cast<int>(std::lround(parameters_.tubeSeconds / problem_.demonstration->dt)));
}

QString MpcController::spinOf(const Eigen::VectorXd& observation) const {
    if (!problem_.deviation.bodyVelocity) {
        return {};
    }
    const core::BodyVelocityIndices v = *problem_.deviation.bodyVelocity;
    const double forward = observation[v.forward];
    const double lateral = observation[v.lateral];
    if (!(std::hypot(forward, lateral) > parameters_.spinSpeed)) {
        return {};
    }
    const double yawRate = observation[v.yawRate];
    const double slip = std::atan2(lateral, std::abs(forward));
    // The demonstration near this time (its own pace may differ by the window).
    const core::Demonstration& demo = *problem_.demonstration;
    const int k = step_ - latency_;
    if (k > spinUntil_) {
        return {};  // past the demonstration's fastest turn: the car is parking
    }
    const int w = std::max(0, static_cast<int>(std::lround(parameters_.spinWindow / demo.dt)));
    double nearestRate = std::numeric_limits<double>::infinity();
    double nearestSlip = std::numeric_limits<double>::infinity();
    double demoRate = 0.0;
    double demoSlip = 0.0;
    for (int j = std::max(0, k - w); j <= std::min(demo.length() - 1, k + w); ++j) {
        const double r = demo.states(j, v.yawRate);
        const double speed = std::hypot(demo.states(j, v.forward), demo.states(j, v.lateral));
        const double b = speed > 0.05 ? std::atan2(demo.states(j, v.lateral),
                                                   std::abs(demo.states(j, v.forward)))
                                      : 0.0;
        if (std::abs(yawRate - r) < nearestRate) {
            nearestRate = std::abs(yawRate - r);
            demoRate = r;
        }
        if (std::abs(slip - b) < nearestSlip) {
            nearestSlip = std::abs(slip - b);
            demoSlip = b;
        }
    }
    if (!std::isfinite(nearestRate)) {
        return {};  // past the demonstration's end
    }
    if (parameters_.spinYawRate > 0.0 && nearestRate > parameters_.spinYawRate) {
        return QStringLiteral("a yaw rate of %1 deg/s where the demonstration had %2 (bound %3)")
            .arg(yawRate * 180.0 / M_PI, 0, 'f', 0)
            .arg(demoRate * 180.0 / M_PI, 0, 'f', 0)
            .arg(parameters_.spinYawRate * 180.0 / M_PI, 0, 'f', 0);
    }
    if (parameters_.spinSideSlip > 0.0 && nearestSlip > parameters_.spinSideSlip) {
        return QStringLiteral(
                   "a side-slip angle of %1 deg where the demonstration had %2 "
                   "(bound %3)")
            .arg(slip * 180.0 / M_PI, 0, 'f', 0)
            .arg(demoSlip * 180.0 / M_PI, 0, 'f', 0)
            .arg(parameters_.spinSideSlip * 180.0 / M_PI, 0, 'f', 0);
    }
    return {};
}

void MpcController::fallBack(const QString& reason) {
    mode_ = MpcMode::Fallback;
    fallbackReason_ = reason;
    fallbackStep_ = step_;
}

void MpcController::predictInto(Plant& model, int from, int count) const {
    model.resetTo(observations_[static_cast<size_t>(from)]);
    const int m = problem_.demonstration->actionDimension();
    auto sent = [&](int k) -> Eigen::VectorXd {
        return k < 0 ? Eigen::VectorXd::Zero(m) : actions_[static_cast<size_t>(k)];
    };
    const int start = from - latency_;  // the observation's own time
    std::vector<Eigen::VectorXd> history;
    history.reserve(identification::kHistorySteps);
    for (int k = start - identification::kHistorySteps; k < start; ++k) {
        history.push_back(sent(k));
    }
    model.primeActuators(history);
    for (int i = 0; i < count; ++i) {
        model.step(sent(start + i));
    }
}

const core::ControlStep& MpcController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const int k = step_;
    observations_.emplace_back(observation);
    // The fallback follows every step, so that its reference is current when it takes over;
    // a trial not planned through at all (handed over at reset, step 0) is the start law's,
    // or the fallback law's where the day's trials chose it (lawChoice).
    const bool fromStart = mode_ == MpcMode::Fallback && fallbackStep_ == 0;
    const core::ControlStep& law = fromStart && !fallbackLawDrives_ ? startLaw_->step(observation)
                                                                    : fallback_->step(observation);
    const core::PlanarPoseIndices pose = *problem_.deviation.pose;
    const int lag = tubeSteps();
    if (mode_ == MpcMode::Planning && k >= lag) {
        // Where the model said the car would be, given the commands sent since then.
        predictInto(*scratch_, k - lag, lag);
        const Eigen::VectorXd predicted = scratch_->state();
        const double position = std::hypot(predicted[pose.x] - observation[pose.x],
                                           predicted[pose.y] - observation[pose.y]);
        const double heading =
            std::abs(core::wrapAngle(predicted[pose.heading] - observation[pose.heading]));
        correctRolling(predicted, observation);
        correctSteering(predicted, observation);
        if (position > parameters_.tubePosition || heading > parameters_.tubeHeading) {
            ++strikes_;
        } else {
            strikes_ = 0;
        }
        if (strikes_ >= parameters_.tubeStrikes) {
            fallBack(QStringLiteral("the measured pose left the model's predicted tube at %1 s: "
                                    "%2 cm and %3 deg from the prediction (bounds %4 cm, %5 deg)")
                         .arg(k * problem_.demonstration->dt, 0, 'f', 2)
                         .arg(100.0 * position, 0, 'f', 1)
                         .arg(heading * 180.0 / M_PI, 0, 'f', 1)
                         .arg(100.0 * parameters_.tubePosition, 0, 'f', 1)
                         .arg(parameters_.tubeHeading * 180.0 / M_PI, 0, 'f', 1));
        }
    }
    if (mode_ == MpcMode::Planning) {
        const QString spin = spinOf(observations_.back());
        spinStrikes_ = spin.isEmpty() ? 0 : spinStrikes_ + 1;
        if (spinStrikes_ >= parameters_.tubeStrikes) {
            fallBack(QStringLiteral("a spin the plan did not intend at %1 s: %2")
                         .arg(k * problem_.demonstration->dt, 0, 'f', 2)
                         .arg(spin));
        }
    }
    if (mode_ == MpcMode::Planning && parameters_.parkingSpeed > 0.0 && k - latency_ > spinUntil_ &&
        problem_.deviation.bodyVelocity) {
        const core::BodyVelocityIndices v = *problem_.deviation.bodyVelocity;
        const double speed = std::hypot(observation[v.forward], observation[v.lateral]);
        // mpc.park-near: the lot is the demonstration's last pose (as parkingError measures).
        if (speed < parameters_.parkingSpeed &&
            (parameters_.parkingDistance <= 0.0 ||
             distanceFromLot(problem_, observation) < parameters_.parkingDistance)) {
            mode_ = MpcMode::Parking;
            fallbackStep_ = k;
        }
    }
    if (mode_ != MpcMode::Planning) {
        record_ = law;
        if (mode_ == MpcMode::Parking && throttle_ >= 0) {
            const double approach = approachThrottle(record_.action[throttle_]);
            if (std::isfinite(approach)) {
                record_.action[throttle_] = approach;
                problem_.limits.saturate(record_.action);
            }
        }
    } else {
        if (k % parameters_.replanEvery == 0 && std::abs(rollingBias_ - appliedBias_) > 1e-3) {
            applyRollingBias(rollingBias_);
        }
        // The model at the state of now: the measurement predicted through the latency.
        predictInto(*modelPlant_, k, latency_);
        // The other grips are planned from, not stepped: they need the state of now only on
        // the steps the planner plans.
        if (k % parameters_.replanEvery == 0) {
            for (const auto& other : ensemble_) {
                predictInto(*other, k, latency_);
            }
        }
        record_ = planner_->step(modelPlant_->state());
    }
    record_.step = k;
    actions_.push_back(record_.action);
    ++step_;
    return record_;
}

void MpcController::refitOnLastTrial() {
    const int L = latency_;
    const int steps = static_cast<int>(actions_.size());
    // Only a trial the plan drove is data for the model: one the fallback finished went where
    // the model did not hold (a spin the model's tyres cannot have), and would pull the whole
    // fit towards it.
    if (!parameters_.refit || data_.empty() || steps - L < 4 || mode_ == MpcMode::Fallback) {
        return;
    }
    // The trial as a run: the observation of step k + L is the state at step k.
    const core::Demonstration& demonstration = data_.front();
    core::Demonstration trial;
    trial.plant = demonstration.plant;
    trial.dt = demonstration.dt;
    trial.stateNames = demonstration.stateNames;
    trial.stateUnits = demonstration.stateUnits;
    trial.actionNames = demonstration.actionNames;
    trial.actionUnits = demonstration.actionUnits;
    const int T = steps - L;
    const int n = demonstration.stateDimension();
    const int m = demonstration.actionDimension();
    trial.time.resize(T);
    trial.states.resize(T, n);
    trial.actions.resize(T, m);
    for (int i = 0; i < T; ++i) {
        trial.time[i] = i * trial.dt;
        trial.states.row(i) = observations_[static_cast<size_t>(i + L)].transpose();
        trial.actions.row(i) = actions_[static_cast<size_t>(i)].transpose();
    }
    data_.push_back(std::move(trial));
    // The refit is fitted on the demonstration and the trials before this one (at most
    // refitTrials), and judged on this trial, data it was not fitted on: kept only when it
    // predicts it better than the model it would replace. (Judged on its own data, a search
    // that starts from the model nearly always "improves": the development day's trials 12-16
    // went from 18.3 cm to 8.0 with this judge, research-log.md, issue 33's eleventh step.)
    // This trial joins the fit from the next refit on.
    std::vector<core::Demonstration> runs{data_.front()};  // data_ grew: no older reference
    const int newest = static_cast<int>(data_.size()) - 1;
    for (int i = std::max(1, newest - parameters_.refitTrials); i < newest; ++i) {
        runs.push_back(data_[static_cast<size_t>(i)]);
    }
    const std::vector<core::Demonstration> judge{data_.back()};
    const IdentificationSettings settings = mpcIdentificationSettings(parameters_, true);
    const IdentificationResult fit = identifyPlant(runs, model_, settings);
    const double before = modelPositionRms(judge, model_, settings);
    const double after = fit.ok() ? modelPositionRms(judge, fit.parameters, settings) : -1.0;
    if (fit.ok() && std::isfinite(fit.positionRms) && after >= 0.0 &&
        (before < 0.0 || after < before)) {
        model_ = fit.parameters;
        modelFit_ = fit.positionRms;
        ++refits_;
    }
}

}  // namespace prisca::sim
