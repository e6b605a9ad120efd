// ablation_table: PRISCA's changes one at a time against the product default, the paper's
// form, the best baseline and the oracle, on every slide-car demonstration style x the given
// seed sets (Table I's protocol: 16 training trials, then the evaluation trials). For README's
// ablation table; run it on seed sets that no decision was made on.
//
//     ablation_table [--seed S] [--sets N] [--trials T] [--oracle]
//
// Deterministic: the same build and arguments print the same table.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/Table1Protocol.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

using namespace prisca;

namespace {

struct Variant {
    const char* label;
    const char* method;
    std::function<void(sim::PlantProfile&, core::ActionMappingFitOptions&)> change;
};

}  // namespace

int main(int argc, char** argv) {
    std::uint64_t seed = 9101;
    int sets = 3, trials = 20;
    bool oracle = false;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seed") && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 10);
        } else if (!std::strcmp(argv[i], "--sets") && i + 1 < argc) {
            sets = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--trials") && i + 1 < argc) {
            trials = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--oracle")) {
            oracle = true;
        } else {
            std::fprintf(stderr, "usage: ablation_table [--seed S] [--sets N] [--trials T] [--oracle]\n");
            return 2;
        }
    }
    using Profile = sim::PlantProfile;
    using Fit = core::ActionMappingFitOptions;
    const Profile base = Profile::forPlant(sim::PlantCatalog::describe("slidecar"));
    const int defaultN = base.prisca.effectHorizon;
    std::vector<Variant> variants = {
        {"PRISCA (product default)", "prisca", [](Profile&, Fit&) {}},
        {defaultN > 1 ? "- eq. 5 truncated to one step (N = 1)" : "- eq. 5 over N = 7 steps",
         "prisca",
         [defaultN](Profile& p, Fit&) { p.prisca.effectHorizon = defaultN > 1 ? 1 : 7; }},
        {"- latency compensated (reference and u* for the observation age)", "prisca",
         [](Profile& p, Fit&) { p.compensateLatency = true; }},
        {"- closed-loop gradient (eq. 4 over the window)", "prisca",
         [](Profile& p, Fit&) { p.prisca.gradient = core::PriscaParameters::Gradient::ClosedLoop; }},
        {"- signs B~ only, no fit", "prisca",
         [](Profile& p, Fit&) { p.priscaModel = Profile::PriscaModel::Signs; }},
        {"- eq. 5 fitted in full (drift A)", "prisca",
         [](Profile& p, Fit& f) {
             p.priscaModel = Profile::PriscaModel::FittedWithDrift;
             f.drift = true;
         }},
        {"- no bound on theta", "prisca", [](Profile& p, Fit&) { p.prisca.thetaBound = 0.0; }},
        {"- no baseline (b = 0)", "prisca", [](Profile& p, Fit&) { p.prisca.useBaseline = false; }},
        {"- no inverse depreciation (D = 1)", "prisca",
         [](Profile& p, Fit&) { p.prisca.useInverseDepreciation = false; }},
        {"- no lost-track failsafe", "prisca", [](Profile& p, Fit&) { p.lostTrackDistance = 0.0; }},
        {"PRISCA (paper): Algorithm 1 as printed", "prisca-paper", [](Profile&, Fit&) {}},
        {"PD+H+LSD (best baseline)", "pd-h-lsd", [](Profile&, Fit&) {}},
        {"PD+H+LSD, latency compensated", "pd-h-lsd",
         [](Profile& p, Fit&) { p.compensateLatency = true; }},
    };
    if (oracle) {
        variants.push_back({"LIMIT (oracle)", "oracle", [](Profile&, Fit&) {}});
    }
    std::printf("Slide-car, every style x seed sets %llu..%llu, %d evaluation trials per cell after "
                "16 training trials, perturbation 1, sensor 1; means and 95%% intervals over the "
                "cells\n\n",
                static_cast<unsigned long long>(seed),
                static_cast<unsigned long long>(seed + sets - 1), trials);
    std::printf("| variant | position MAE [cm] | orientation MAE [deg] | worst style [cm] |\n");
    std::printf("| --- | ---: | ---: | ---: |\n");
    for (const Variant& v : variants) {
        Profile profile = base;
        sim::Table1ProtocolSettings settings;
        v.change(profile, settings.fit);
        settings.table.methods = {QString::fromLatin1(v.method)};
        settings.table.trials = trials;
        settings.styles = sim::DemonstrationStyles::names("slidecar");
        settings.seedSets = sim::consecutiveSeedSets(seed, sets);
        const sim::Table1ProtocolResult r = sim::runTable1Protocol(settings, profile);
        const core::ProtocolRow& row = r.summary.rows[0];
        double worst = 0.0;
        for (const core::MeanInterval& s : row.stylePosition) {
            worst = std::max(worst, s.mean);
        }
        std::printf("| %s | %.2f [%.2f, %.2f] | %.2f [%.2f, %.2f] | %.2f |\n", v.label,
                    row.position.mean, row.position.lower, row.position.upper,
                    row.orientation.mean, row.orientation.lower, row.orientation.upper, worst);
        std::fflush(stdout);
    }
    return 0;
}
