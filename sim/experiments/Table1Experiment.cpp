#include "sim/experiments/Table1Experiment.h"

#include <cmath>

#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/run/MethodTraining.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace prisca::sim {

Table1Result runTable1(const Table1Settings& settings, const Task& task) {
    const MethodTuning& profile = task.profile;
    if (!profile.info.pose) {
        throw std::invalid_argument("Table I needs a planar vehicle (final position and heading)");
    }
    // One set-up per method: the plant at the task's period, the trials, the training.
    std::vector<RunSetup> setups;
    for (const QString& method : settings.methods) {
        const MethodSpec* spec = MethodCatalog::find(method);
        if (!spec || !spec->inTable1) {
            throw std::invalid_argument(
                QStringLiteral("Table I has no row for method '%1'").arg(method).toStdString());
        }
        setups.emplace_back(task, method, settings.run);
    }
    const auto say = [&](const QString& text) {
        if (settings.progress) {
            settings.progress(text);
        }
    };
    const std::shared_ptr<const core::Demonstration>& demonstration = task.demonstration;

    Table1Result result;
    const int T = demonstration->length();
    result.lot = demonstration->states.row(T - 1).head<3>().transpose();

    // Training: the offline methods train (PD (selected) selects its gains), and the online
    // learners warm up on the training trials in a row (each learner a sequential chain of
    // trials, the chains side by side on the pool).
    std::vector<std::shared_ptr<const core::Controller>> trained(setups.size());
    std::vector<int> learners;
    for (size_t m = 0; m < setups.size(); ++m) {
        if (setups[m].method().trainsOffline()) {
            trained[m] = setups[m].makeController(settings.cancelled, settings.progress);
        } else if (setups[m].method().learnsOnline) {
            learners.push_back(static_cast<int>(m));
        }
    }
    struct WarmUp {
        std::shared_ptr<const core::Controller> controller;
        std::vector<TrialSummary> trials;  // each training trial, in order
    };
    const std::function<WarmUp(int)> warmUp = [&](int i) {
        const RunSetup& setup = setups[learners[i]];
        auto plant = setup.makePlant();
        std::shared_ptr<core::Controller> controller = setup.makeController();
        const std::vector<std::uint64_t> seeds = setup.trainingSeeds();
        WarmUp out;
        for (size_t t = 0; t < seeds.size(); ++t) {
            EpisodeSettings episode = setup.trainingTrial(static_cast<int>(t));
            episode.recordSteps = false;
            const EpisodeResult run = runEpisode(*plant, *controller, episode, settings.cancelled);
            if (run.cancelled) {
                break;
            }
            out.trials.push_back(summarizeTrial(plant->info(), *demonstration, run));
        }
        say(QStringLiteral("table1: %1 learned on %2 training trials")
                .arg(setup.method().id)
                .arg(seeds.size()));
        out.controller = controller;
        return out;
    };
    const auto warmed = runParallel<WarmUp>(static_cast<int>(learners.size()), settings.run.threads,
                                            warmUp, settings.cancelled);
    std::vector<std::vector<TrialSummary>> trainingTrials(setups.size());
    for (size_t i = 0; i < learners.size(); ++i) {
        trained[learners[i]] = warmed[i].controller;
        trainingTrials[learners[i]] = warmed[i].trials;
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
        const RunSetup& setup = setups[job / trials];
        const int trial = job % trials;
        auto plant = setup.makePlant();
        std::unique_ptr<core::Controller> controller;
        // The day's trials: the training trials first, then these.
        EpisodeSettings episode = setup.trial(trial, setup.settings().trainingTrials);
        episode.recordSteps = settings.keepPaths;
        if (const auto& learned = trained[job / trials]) {
            controller = learned->clone();
            // Learners go on from what they learned; the others learn nothing to keep.
            episode.resetMode = core::ResetMode::WarmStart;
        } else {
            controller = setup.makeController();
            episode.resetMode = core::ResetMode::Cold;
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
        methods * trials, settings.run.threads, evaluate, settings.cancelled,
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
        rows.training = trainingTrials[m];
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
                        core::summarizeErrors(orientation), core::mean(cpu), spec.label, spec.limit,
                        static_cast<int>(method.trials.size()), spec.plansThroughModel});
    }
    if (finished) {
        *finished = count;
    }
    return rows;
}

}  // namespace prisca::sim
