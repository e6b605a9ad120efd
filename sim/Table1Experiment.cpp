#include "Table1Experiment.h"

#include <cmath>

#include "MethodCatalog.h"
#include "MethodTraining.h"
#include "ParallelTrials.h"
#include "PlantCatalog.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace prisca::sim {


Table1Result runTable1(const Table1Settings& settings,
                       std::shared_ptr<const core::Demonstration> demonstration,
                       const PlantProfile& profile, const Eigen::MatrixXd& fittedB) {
    if (!profile.info.pose) {
        throw std::invalid_argument("Table I needs a planar vehicle (final position and heading)");
    }
    for (const QString& method : settings.methods) {
        const MethodSpec* spec = MethodCatalog::find(method);
        if (!spec || !spec->inTable1) {
            throw std::invalid_argument(
                QStringLiteral("Table I has no row for method '%1'").arg(method).toStdString());
        }
    }
    const auto say = [&](const QString& text) {
        if (settings.progress) {
            settings.progress(text);
        }
    };
    const EpisodeSettings base =
        profile.episode(*demonstration, settings.perturbation, settings.sensor);
    const std::vector<std::uint64_t> trainingSeeds =
        sim::trainingSeeds(settings.seed, settings.trainingTrials);

    Table1Result result;
    const int T = demonstration->length();
    result.lot = demonstration->states.row(T - 1).head<3>().transpose();

    // Training: the grid search of PD (selected), and the learners' warm-up runs (each learner
    // a sequential chain of trials, the chains side by side on the pool).
    std::map<QString, std::shared_ptr<const core::Controller>> trained;
    PlantProfile selectedProfile = profile;
    const bool selects = std::any_of(settings.methods.begin(), settings.methods.end(),
                                     [](const QString& method) {
                                         return MethodCatalog::get(method).training ==
                                                MethodSpec::Training::SelectPdGains;
                                     });
    if (selects && !trainingSeeds.empty()) {
        TrainingSetup training;
        training.plant = settings.plant;
        training.profile = profile;
        training.demonstration = demonstration;
        training.fittedB = fittedB;
        training.episode = base;
        training.episode.recordSteps = false;
        training.seeds = trainingSeeds;
        training.threads = settings.threads;
        training.cancelled = settings.cancelled;
        training.progress = settings.progress;
        selectedProfile.pd = selectPdGains(training);
    }
    QStringList learners;
    for (const QString& method : settings.methods) {
        if (MethodCatalog::get(method).learnsOnline) {
            learners << method;
        }
    }
    const std::function<std::shared_ptr<const core::Controller>(int)> warmUp = [&](int i) {
        auto plant = PlantCatalog::create(settings.plant);
        std::shared_ptr<core::Controller> controller =
            MethodCatalog::create(learners[i], profile, demonstration, fittedB);
        for (size_t t = 0; t < trainingSeeds.size(); ++t) {
            EpisodeSettings episode = base;
            episode.seed = trainingSeeds[t];
            episode.recordSteps = false;
            episode.resetMode = resetForTrial(static_cast<int>(t));
            runEpisode(*plant, *controller, episode, settings.cancelled);
        }
        say(QStringLiteral("table1: %1 learned on %2 training trials")
                .arg(learners[i])
                .arg(trainingSeeds.size()));
        return std::shared_ptr<const core::Controller>(controller);
    };
    const auto warmed = runParallel<std::shared_ptr<const core::Controller>>(
        static_cast<int>(learners.size()), settings.threads, warmUp, settings.cancelled);
    for (int i = 0; i < learners.size(); ++i) {
        trained[learners[i]] = warmed[i];
    }

    // Evaluation: every (method, trial) pair is an independent job.
    const int methods = static_cast<int>(settings.methods.size());
    const int trials = settings.trials;
    struct Outcome {
        TrialSummary summary;
        std::vector<Eigen::Vector3d> path;
        bool finished = false;  // false if cancellation cut the trial short
    };
    const std::function<Outcome(int)> evaluate = [&](int job) {
        const QString& method = settings.methods[job / trials];
        const int trial = job % trials;
        auto plant = PlantCatalog::create(settings.plant);
        std::unique_ptr<core::Controller> controller;
        EpisodeSettings episode = base;
        episode.seed = mixSeed(settings.seed, trial);
        episode.recordSteps = settings.keepPaths;
        const auto learned = trained.find(method);
        if (learned != trained.end() && learned->second) {
            controller = learned->second->clone();
            episode.resetMode = core::ResetMode::WarmStart;
        } else {
            controller = MethodCatalog::create(
                method,
                MethodCatalog::get(method).training == MethodSpec::Training::SelectPdGains
                    ? selectedProfile
                    : profile,
                demonstration, fittedB);
        }
        // Summaries need only the final state; the path is kept for Fig. 7 when asked.
        const EpisodeResult run = runEpisode(*plant, *controller, episode, settings.cancelled);
        Outcome outcome;
        outcome.summary = summarizeTrial(plant->info(), *demonstration, run);
        for (const StepRecord& step : run.steps) {
            outcome.path.emplace_back(step.state[0], step.state[1], step.state[2]);
        }
        if (settings.keepPaths) {
            outcome.path.emplace_back(run.finalState[0], run.finalState[1], run.finalState[2]);
        }
        outcome.finished = !run.cancelled;
        return outcome;
    };
    std::vector<bool> completed;
    const std::vector<Outcome> outcomes = runParallel<Outcome>(
        methods * trials, settings.threads, evaluate, settings.cancelled,
        [&](int done, int total) {
            if (done == total || done * 20 / total != (done - 1) * 20 / total) {
                say(QStringLiteral("table1: %1/%2 trials").arg(done).arg(total));
            }
        },
        &completed);
    result.cancelled = settings.cancelled && settings.cancelled();
    for (int m = 0; m < methods; ++m) {
        MethodTrials rows;
        rows.method = settings.methods[m];
        for (int t = 0; t < trials; ++t) {
            const int job = m * trials + t;
            // Kept only if it ran to its end: a cancelled trial's pose means nothing.
            const bool done = completed[job] && outcomes[job].finished;
            rows.completed.push_back(done);
            rows.trials.push_back(done ? outcomes[job].summary : TrialSummary{});
            if (settings.keepPaths) {
                rows.paths.push_back(done ? outcomes[job].path : std::vector<Eigen::Vector3d>{});
            }
        }
        result.methods.push_back(std::move(rows));
    }
    return result;
}

std::vector<core::Table1Row> table1Rows(const Table1Result& result, int* finished) {
    std::vector<core::Table1Row> rows;
    int count = 0;
    for (const MethodTrials& method : result.methods) {
        std::vector<double> position, orientation, cpu;
        for (size_t t = 0; t < method.trials.size(); ++t) {
            if (method.completed[t]) {
                position.push_back(method.trials[t].finalPositionError * 100.0);
                orientation.push_back(method.trials[t].finalHeadingError * 180.0 / M_PI);
                cpu.push_back(method.trials[t].controllerMicrosecondsPerStep);
                ++count;
            }
        }
        const MethodSpec& spec = MethodCatalog::get(method.method);
        rows.push_back({method.method, core::summarizeErrors(position),
                        core::summarizeErrors(orientation), core::mean(cpu), spec.label,
                        spec.limit});
    }
    if (finished) {
        *finished = count;
    }
    return rows;
}

}  // namespace prisca::sim
