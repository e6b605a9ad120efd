// Simulation benchmarks (make bench): slide-car speed against real time, and a 20-trial batch
// of closed-loop PRISCA trials on 1 and 2 threads.
#include "core/ActionMapping.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/tuning/MethodTuning.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace prisca;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main() {
    // Plant speed: 60 simulated seconds of driving around, 10 physics substeps per 25 ms step.
    for (const QString& name : sim::PlantCatalog::names()) {
        std::vector<double> factors;
        for (int repeat = 0; repeat < 5; ++repeat) {
            auto plant = sim::PlantCatalog::create(name);
            plant->reset(1, sim::Perturbation::realistic());
            const int m = plant->info().actionDimension();
            const int steps = 2400;
            const auto start = Clock::now();
            for (int k = 0; k < steps; ++k) {
                Eigen::VectorXd u = plant->info().actionLower +
                                    (plant->info().actionUpper - plant->info().actionLower) *
                                        (0.5 + 0.4 * std::sin(0.01 * k));
                if (m != u.size())
                    return 1;
                plant->step(u);
            }
            factors.push_back(steps * plant->timing().controlPeriod / seconds(start));
        }
        std::printf("%s simulation: median %.0fx real time on one core (400 Hz physics)%s\n",
                    qPrintable(name), median(factors),
                    name == QLatin1String("slidecar") ? " (target >= 200x)" : "");
    }

    // A 20-trial batch of PRISCA on the slide-car with realistic perturbation and sensor.
    auto demo =
        std::make_shared<core::Demonstration>(sim::PlantCatalog::demonstrate("slidecar", 1));
    const sim::MethodTuning profile =
        sim::PlantCatalog::tuning(sim::PlantCatalog::describe("slidecar"));
    const Eigen::MatrixXd B =
        core::fitActionMapping(*demo, profile.mapping, profile.info.deviationModel()).b;
    const std::function<double(int)> trial = [&](int i) {
        auto plant = sim::PlantCatalog::create("slidecar");
        auto controller = sim::MethodCatalog::create("prisca", profile, demo, B);
        sim::EpisodeSettings s;
        s.seed = sim::mixSeed(7, i);
        s.perturbation = sim::Perturbation::realistic();
        s.measurement = profile.measurement;
        s.duration = demo->length() * demo->dt + profile.settleTime;
        s.stopAtRestAfter = demo->length() * demo->dt;
        s.recordSteps = false;
        return sim::runEpisode(*plant, *controller, s).finalState[0];
    };
    double oneThread = 0.0;
    for (int threads : {1, 2}) {
        std::vector<double> times;
        for (int repeat = 0; repeat < 5; ++repeat) {
            const auto start = Clock::now();
            sim::runParallel<double>(20, threads, trial);
            times.push_back(seconds(start));
        }
        const double t = median(times);
        if (threads == 1)
            oneThread = t;
        std::printf(
            "20-trial slide-car batch (PRISCA) on %d thread%s: median %.1f ms%s\n", threads,
            threads == 1 ? "" : "s", t * 1000.0,
            threads == 1
                ? ""
                : qPrintable(QStringLiteral(" (speed-up %1x)").arg(oneThread / t, 0, 'f', 2)));
    }
    const sim::Task task = sim::makeTask(profile, demo);
    // Table I: 8 methods x 20 trials (plus the training phases), as `prisca-cli table1 --jobs N`.
    for (int threads : {1, 2}) {
        std::vector<double> times;
        for (int repeat = 0; repeat < 3; ++repeat) {
            sim::Table1Settings settings;
            settings.methods = {"prisca", "pd",       "pd-selected", "pd-h",
                                "pd-lsd", "pd-h-lsd", "playback",    "pgsd"};
            settings.run.threads = threads;
            const auto start = Clock::now();
            sim::runTable1(settings, task);
            times.push_back(seconds(start));
        }
        std::printf(
            "table1 (8 methods x 20 trials, 16 training trials) on %d thread%s: median %.2f s%s\n",
            threads, threads == 1 ? "" : "s", median(times),
            threads == 2 ? " (target <= 10 s on 2 cores)" : "");
    }
    // The oracle (the limit): its planning time is reported, not bounded.
    {
        sim::Table1Settings settings;
        settings.methods = {"oracle"};
        settings.run.threads = 2;
        const auto start = Clock::now();
        const sim::Table1Result result = sim::runTable1(settings, task);
        const auto rows = sim::table1Rows(result);
        std::printf(
            "table1, the oracle alone (20 trials) on 2 threads: %.2f s, %.0f us of CPU per "
            "control step\n",
            seconds(start), rows.front().cpuMicrosecondsPerStep);
    }
    return 0;
}
