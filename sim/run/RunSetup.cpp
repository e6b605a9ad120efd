#include "sim/run/RunSetup.h"

#include "sim/planning/Identification.h"

#include "sim/PlantCatalog.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/RunLogBuilder.h"

#include <stdexcept>

namespace prisca::sim {

RecordingConditions demonstrationConditions(const RunSettings& settings,
                                            const MethodTuning& profile,
                                            const PlantParameters* parameters, std::uint64_t day) {
    RecordingConditions conditions;
    conditions.parameters = parameters;
    if (settings.perturbationModel == Perturbation::Model::Session) {
        conditions.perturbation =
            Perturbation::dayOf(day, settings.perturbation * profile.perturbationShares.parameters);
    }
    return conditions;
}

RunSetup::RunSetup(Task task, const QString& method, const RunSettings& settings)
    : task_(std::move(task)), method_(&MethodCatalog::get(method)), settings_(settings) {
    if (!task_.demonstration) {
        throw std::invalid_argument("a run needs a demonstration");
    }
    if (!method_->runsOn(task_.profile.info.name)) {
        throw std::invalid_argument(QStringLiteral("%1 runs on %2, not on '%3'")
                                        .arg(method_->id,
                                             method_->plants.join(QStringLiteral(", ")),
                                             task_.profile.info.name)
                                        .toStdString());
    }
    if (settings_.trainingTrials < 0 || settings_.threads < 1 || !(settings_.perturbation >= 0.0) ||
        !(settings_.sensor >= 0.0)) {
        throw std::invalid_argument(
            "run settings out of range: training trials >= 0, threads >= 1, levels >= 0");
    }
    // The plant steps at the demonstration's own period, whatever rate it was recorded at.
    task_.timing.controlPeriod = task_.demonstration->dt;
    // A model identified from the demonstration starts from what a lab measures of this car
    // (its mass and geometry), knowing nothing else of it.
    if (!task_.profile.mpcModel && !task_.profile.mpcPrior && task_.plantParameters &&
        identificationAvailable(task_.plantParameters->plant)) {
        task_.profile.mpcPrior =
            std::make_shared<const PlantParameters>(measuredPrior(*task_.plantParameters));
    }
    episode_ =
        task_.profile.episode(*task_.demonstration, settings_.perturbation, settings_.sensor);
    episode_.perturbation.model = settings_.perturbationModel;
    episode_.perturbation.day = settings_.seed;
    if (settings_.poseFilter) {
        const PlantInfo& info = task_.profile.info;
        if (!info.pose || !info.bodyVelocity) {
            throw std::invalid_argument(
                QStringLiteral("the pose filter needs a planar vehicle; '%1' is not one")
                    .arg(info.name)
                    .toStdString());
        }
        episode_.poseFilter = true;
        episode_.poseFilterPredicts = settings_.poseFilterPredicts;
        // The input term from the demonstration's own fit (B's velocity columns).
        if (task_.fit.b.rows() == info.actionDimension() &&
            task_.fit.b.cols() == info.stateDimension()) {
            episode_.poseFilterParameters.inputGain =
                core::inputGainFromFit(task_.fit.b, *info.bodyVelocity);
        }
    }
}

std::unique_ptr<Plant> RunSetup::makePlant() const {
    if (task_.plantParameters) {
        return PlantCatalog::create(*task_.plantParameters, task_.timing);
    }
    return PlantCatalog::create(task_.plant, task_.timing);
}

EpisodeSettings RunSetup::trial(int trial, int trialsBefore) const {
    EpisodeSettings episode = episode_;
    setTrial(episode, settings_.seed, trial);
    episode.perturbation.trialIndex = trialsBefore + trial;
    return episode;
}

EpisodeSettings RunSetup::trainingTrial(int trial) const {
    EpisodeSettings episode = episode_;
    const std::vector<std::uint64_t> seeds = trainingSeeds();
    episode.seed = seeds.at(static_cast<size_t>(trial));
    episode.resetMode = resetForTrial(trial);
    episode.perturbation.trialIndex = trial;
    return episode;
}

EpisodeSettings RunSetup::curveScenario(std::uint64_t runSeed, int scenario) const {
    EpisodeSettings episode = episode_;
    episode.seed = mixSeed(runSeed, 1000 + static_cast<std::uint64_t>(scenario));
    episode.perturbation.trialIndex = scenario;
    return episode;
}

EpisodeSettings RunSetup::curveEvaluation(std::uint64_t runSeed, int index) const {
    EpisodeSettings episode = episode_;
    episode.seed = mixSeed(runSeed, 5000 + static_cast<std::uint64_t>(index));
    episode.perturbation.trialIndex = index;
    return episode;
}

std::vector<std::uint64_t> RunSetup::trainingSeeds() const {
    return sim::trainingSeeds(settings_.seed, settings_.trainingTrials);
}

std::unique_ptr<core::Controller> RunSetup::makeController(
    const std::function<bool()>& cancelled,
    const std::function<void(const QString&)>& progress) const {
    MethodTuning profile = task_.profile;
    Eigen::MatrixXd pegasusTheta;
    const TrainingHooks hooks{cancelled, progress};
    switch (method_->training) {
        case MethodSpec::Training::Pegasus:
            pegasusTheta = trainPegasus(*this, profile.pegasusIterations, hooks).theta;
            break;
        case MethodSpec::Training::SelectPdGains:
            profile.pd = selectPdGains(*this, hooks);
            break;
        case MethodSpec::Training::None:
            break;
    }
    if (method_->trainsOffline() && cancelled && cancelled()) {
        return nullptr;
    }
    auto controller =
        MethodCatalog::create(method_->id, profile, task_.demonstration, task_.fit.b,
                              pegasusTheta.size() ? &pegasusTheta : nullptr, cancelled);
    if (cancelled && cancelled()) {
        return nullptr;  // stopped while it was made (an identification cut short)
    }
    return controller;
}

std::unique_ptr<core::Controller> RunSetup::makeUntrainedController() const {
    return MethodCatalog::create(method_->id, task_.profile, task_.demonstration, task_.fit.b);
}

core::RunLog RunSetup::startRunLog(const core::Controller& controller, int trials,
                                   const QString& demonstrationSource) const {
    core::RunLog log =
        sim::startRunLog(task_.profile.info, method_->id, task_.demonstration->dt, controller);
    log.metadata.insert(QStringLiteral("seed"), QString::number(settings_.seed));
    log.metadata.insert(QStringLiteral("trials"), QString::number(trials));
    log.metadata.insert(QStringLiteral("perturbation"), QString::number(settings_.perturbation));
    log.metadata.insert(QStringLiteral("sensor"), QString::number(settings_.sensor));
    log.metadata.insert(QStringLiteral("perturbation-model"),
                        perturbationModelName(settings_.perturbationModel));
    if (task_.plantParameters && !task_.plantParameters->source.isEmpty()) {
        log.metadata.insert(QStringLiteral("plant-parameters"), task_.plantParameters->source);
    }
    if (settings_.poseFilter) {
        log.metadata.insert(QStringLiteral("pose-filter"), settings_.poseFilterPredicts
                                                               ? QStringLiteral("on")
                                                               : QStringLiteral("lagged"));
    }
    log.metadata.insert(QStringLiteral("demonstration"), demonstrationSource);
    return log;
}

}  // namespace prisca::sim
