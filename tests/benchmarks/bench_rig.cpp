// Virtual-rig benchmark (make bench): camera frame -> serial bytes written, through tracker,
// state estimator, PRISCA, channel map and the link on a pseudo-terminal; one slide-park in
// real time.
#include "rigsim/VirtualRig.h"

#include "core/ActionMapping.h"
#include "devices/ThreadPriority.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <QCoreApplication>

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>
#include <vector>

using namespace prisca;

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    auto demo = std::make_shared<core::Demonstration>(
        sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1));
    const sim::MethodTuning profile =
        sim::PlantCatalog::tuning(sim::PlantCatalog::describe(QStringLiteral("slidecar")));
    const Eigen::MatrixXd b =
        core::fitActionMapping(*demo, profile.mapping, profile.info.deviationModel()).b;
    rigsim::VirtualRig rig({}, sim::MethodCatalog::create("prisca", profile, demo, b));
    QString error;
    if (!rig.open(&error)) {
        std::printf("bench_rig: %s\n", qPrintable(error));
        return 1;
    }
    // The loop runs on this thread in the harness (the camera's thread in the application).
    const bool raised = devices::raiseCurrentThreadPriority();
    const auto measure = [&](const char* condition) {
        std::vector<double> latency;
        for (int trial = 0; trial < 3; ++trial) {
            const auto t = rig.runTrial(
                demo->length() * demo->dt + 1.5,
                trial == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart, trial + 1);
            latency.insert(latency.end(), t.loopLatencyMs.begin(), t.loopLatencyMs.end());
        }
        std::sort(latency.begin(), latency.end());
        std::printf(
            "virtual rig, camera frame -> serial bytes written, %s (%zu frames): median %.2f ms, "
            "95th percentile %.2f ms, 99th percentile %.2f ms, worst %.2f ms\n",
            condition, latency.size(), latency[latency.size() / 2],
            latency[latency.size() * 95 / 100], latency[latency.size() * 99 / 100], latency.back());
        std::fflush(stdout);
    };
    std::printf("loop and link threads at raised priority: %s\n",
                raised ? "yes" : "no (needs CAP_SYS_NICE)");
    measure("idle machine");
    // Every core kept busy by other work at normal priority, as a lab PC running a build.
    std::atomic<bool> stop{false};
    std::vector<std::thread> busy;
    for (unsigned i = 0; i < std::max(1u, std::thread::hardware_concurrency()); ++i) {
        busy.emplace_back([&stop] {
            // Ordinary work: not the real-time policy this thread would inherit from ours.
            sched_param normal{};
            pthread_setschedparam(pthread_self(), SCHED_OTHER, &normal);
            volatile unsigned long spin = 0;
            while (!stop.load(std::memory_order_relaxed)) {
                spin = spin + 1;
            }
        });
    }
    measure("every core busy");
    stop.store(true);
    for (std::thread& t : busy) {
        t.join();
    }
    return 0;
}
