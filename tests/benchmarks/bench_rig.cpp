// Virtual-rig benchmark (make bench): camera frame -> serial bytes written, through tracker,
// state estimator, PRISCA, channel map and the link on a pseudo-terminal; one slide-park in
// real time.
#include "rigsim/VirtualRig.h"
#include "core/ActionMapping.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace prisca;

int main(int argc, char** argv) {
    QCoreApplication application(argc, argv);
    auto demo = std::make_shared<core::Demonstration>(
        sim::PlantCatalog::demonstrate(QStringLiteral("slidecar"), 1));
    const sim::PlantProfile profile =
        sim::PlantProfile::forPlant(sim::PlantCatalog::describe(QStringLiteral("slidecar")));
    const Eigen::MatrixXd b =
        core::fitActionMapping(*demo, profile.mapping, profile.info.deviationModel()).b;
    rigsim::VirtualRig rig({}, sim::MethodCatalog::create("prisca", profile, demo, b));
    QString error;
    if (!rig.open(&error)) {
        std::printf("bench_rig: %s\n", qPrintable(error));
        return 1;
    }
    std::vector<double> latency;
    for (int trial = 0; trial < 3; ++trial) {
        const auto t = rig.runTrial(demo->length() * demo->dt + 1.5,
                                    trial == 0 ? core::ResetMode::Cold : core::ResetMode::WarmStart,
                                    trial + 1);
        latency.insert(latency.end(), t.latencyMs.begin(), t.latencyMs.end());
    }
    std::sort(latency.begin(), latency.end());
    std::printf(
        "virtual rig, camera frame -> serial bytes written (%zu frames): median %.2f ms, "
        "95th percentile %.2f ms, worst %.2f ms\n",
        latency.size(), latency[latency.size() / 2], latency[latency.size() * 95 / 100],
        latency.back());
    return 0;
}
