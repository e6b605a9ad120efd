// Linear time in the demonstration's length (make bench): one PRISCA trial on the slide-car,
// set up, run, logged and scored as `prisca-cli run` does it (sim::makeTask, sim::RunSetup,
// runEpisode, the run log, summarizeTrial), over demonstrations of 1,000, 10,000 and 100,000
// samples; and over a take that drives for 5 s and then stands still (a camera take's long
// still tail) for 1,000, 10,000 and 40,000 samples. Fails if a sample of the longest costs more
// than 3x a sample of the shortest, in either.
#include "core/RunLogCsv.h"
#include "sim/PlantCatalog.h"
#include "sim/demonstrations/DemonstrationRecorder.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/run/RunLogBuilder.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"
#include "sim/tuning/MethodTuning.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace prisca;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kFlatnessLimit = 3.0;  // 100k per-sample time over 1k per-sample time

double seconds(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// A long drive of the slide-car at 40 Hz under smooth actions: gentle throttle, slow steering
// waves, so the path loops about a ten-metre area and passes the same places again and again
// (as a long demonstration in a lab arena does). `samples` rows, recorded from the simulator.
// With `stillAfter` >= 0 the actions are zero from that sample on: the car coasts to rest and
// stands there to the end.
core::Demonstration longDrive(int samples, int stillAfter = -1) {
    sim::SimulationTiming timing;
    timing.controlPeriod = 0.025;
    auto plant = sim::PlantCatalog::create("slidecar", timing);
    sim::DemonstrationRecorder recorder(plant->info(), timing.controlPeriod);
    Eigen::VectorXd state = plant->reset(0, sim::Perturbation::none());
    Eigen::VectorXd action = Eigen::VectorXd::Zero(plant->info().actionDimension());
    for (int k = 0; k + 1 < samples; ++k) {
        const double t = k * timing.controlPeriod;
        const double ramp = std::min(1.0, t / 2.0);
        action[0] = ramp * (0.25 + 0.05 * std::sin(2.0 * M_PI * t / 37.0));
        action[1] =
            ramp * (0.35 * std::sin(2.0 * M_PI * t / 23.0) + 0.1 * std::sin(2.0 * M_PI * t / 7.3));
        if (stillAfter >= 0 && k >= stillAfter) {
            action.setZero();
        }
        recorder.record(state, action);
        state = plant->step(action);
    }
    recorder.record(state, action);
    return recorder.demonstration();
}

struct Timing {
    double total = 0.0;    // [s] set-up, trial, run log and summary
    double scoring = 0.0;  // [s] summarizeTrial alone
};

// One trial as `prisca-cli run` takes it, from the demonstration in memory to its summary.
Timing runOnce(const std::shared_ptr<const core::Demonstration>& demonstration) {
    Timing timing;
    const auto start = Clock::now();
    const sim::MethodTuning profile =
        sim::PlantCatalog::tuning(sim::PlantCatalog::describe("slidecar"));
    const sim::RunSetup setup(sim::makeTask(profile, demonstration), "prisca");
    auto plant = setup.makePlant();
    auto controller = setup.makeController();
    core::RunLog log = setup.startRunLog(*controller, 1, QStringLiteral("in memory"));
    const sim::EpisodeResult result = sim::runEpisode(*plant, *controller, setup.trial(0));
    sim::appendRunLogTrial(log, 0, result, demonstration->dt);
    const auto scoring = Clock::now();
    const sim::TrialSummary summary = sim::summarizeTrial(plant->info(), *demonstration, result);
    timing.scoring = seconds(scoring);
    timing.total = seconds(start);
    if (!std::isfinite(summary.pathRms)) {
        std::printf("the trial diverged (path RMS %g)\n", summary.pathRms);
        std::exit(1);
    }
    return timing;
}

// Per-sample time of the longest over the shortest, printed for each size.
double flatness(const char* what, const std::vector<std::pair<int, int>>& sizes, int stillAfter) {
    std::vector<double> perSample;
    for (const auto& [samples, repeats] : sizes) {
        const auto demonstration =
            std::make_shared<const core::Demonstration>(longDrive(samples, stillAfter));
        std::vector<double> totals, scorings;
        for (int repeat = 0; repeat < repeats; ++repeat) {
            const Timing t = runOnce(demonstration);
            totals.push_back(t.total);
            scorings.push_back(t.scoring);
        }
        const double total = median(totals), scoring = median(scorings);
        perSample.push_back(total / samples);
        std::printf(
            "one PRISCA trial on a %d-sample slide-car %s: median %.1f ms, %.2f us per "
            "sample (scoring %.2f us per sample), %d runs\n",
            samples, what, 1e3 * total, 1e6 * perSample.back(), 1e6 * scoring / samples, repeats);
    }
    const double ratio = perSample.back() / perSample.front();
    std::printf("per-sample time, %d over %d samples (%s): %.2fx (limit %.0fx)\n",
                sizes.back().first, sizes.front().first, what, ratio, kFlatnessLimit);
    return ratio;
}

}  // namespace

int main() {
    // Enough repeats for a second or more of trials at each size.
    const double moving = flatness("demonstration", {{1000, 31}, {10000, 5}, {100000, 3}}, -1);
    const double still =
        flatness("take with a still tail after 5 s", {{1000, 31}, {10000, 5}, {40000, 3}}, 200);
    if (!(moving <= kFlatnessLimit) || !(still <= kFlatnessLimit)) {
        std::printf("FAIL: the time per sample grows with the demonstration's length\n");
        return 1;
    }
    return 0;
}
