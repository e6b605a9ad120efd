// ablation_table: PRISCA's changes one at a time against the product default, the paper's
// form, the best baseline and the oracle, on every slide-car demonstration style x the given
// seed sets (Table I's protocol: 16 training trials, then the evaluation trials). For
// docs/results.md's ablation table; run it on seed sets that no decision was made on.
//
//     ablation_table [--seed S] [--sets N] [--trials T] [--oracle]
//
// Deterministic: the same build and arguments print the same table.
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"
#include "sim/experiments/Table1Protocol.h"

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
    std::function<void(sim::MethodTuning&, core::ActionMappingFitOptions&)> change;
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
            std::fprintf(stderr,
                         "usage: ablation_table [--seed S] [--sets N] [--trials T] [--oracle]\n");
            return 2;
        }
    }
    using Profile = sim::MethodTuning;
    using Fit = core::ActionMappingFitOptions;
    const Profile base = sim::PlantCatalog::tuning(sim::PlantCatalog::describe("slidecar"));
    using Gradient = core::PriscaParameters::Gradient;
    std::vector<Variant> variants = {
        {"PRISCA (product default)", "prisca", [](Profile&, Fit&) {}},
        {"- preset feature scales, alpha_0 and window (not automatic)", "prisca",
         [](Profile& p, Fit&) { p.priscaAutomatic = false; }},
        {"- learning off (its PD+H+LSD start alone)", "prisca",
         [](Profile& p, Fit&) { p.prisca.learning = false; }},
        {"- one-step gradient (eq. 14) instead of the closed loop", "prisca",
         [](Profile& p, Fit&) {
             p.prisca.gradient = Gradient::OneStep;
             p.prisca.effortWeights.resize(0);
         }},
        {"- no effort cost (R = 0)", "prisca",
         [](Profile& p, Fit&) { p.prisca.effortWeights.resize(0); }},
        {"- from theta = 0 (no PD+H+LSD start)", "prisca",
         [](Profile& p, Fit&) { p.priscaFromPd = false; }},
        {"- no latency compensation (every method)", "prisca",
         [](Profile& p, Fit&) { p.compensateLoopLatency = false; }},
        {"- signs B~ only, no fit", "prisca",
         [](Profile& p, Fit&) { p.priscaModel = Profile::PriscaModel::Signs; }},
        {"- eq. 5 fitted in full (drift A)", "prisca",
         [](Profile& p, Fit& f) {
             p.priscaModel = Profile::PriscaModel::FittedWithDrift;
             f.drift = true;
         }},
        {"- no lost-track failsafe (every method)", "prisca",
         [](Profile& p, Fit&) { p.lostTrackDistance = 0.0; }},
        {"PRISCA of issue 10 (one-step, theta box 0.5, from 0)", "prisca",
         [](Profile& p, Fit&) {
             using Source = core::FeatureTerm::Source;
             p.priscaFromPd = false;
             p.priscaAutomatic = false;
             p.priscaFeatures.reset();  // the shared features (2, 1, 0 | 2, 1, 0.1)
             p.prisca.gradient = Gradient::OneStep;
             p.prisca.effortWeights.resize(0);
             p.prisca.stepSize.scale = 1.0;
             p.prisca.thetaBound = 0.5;
             p.features = core::FeatureMap({{{Source::Deviation, 0, 2.0},
                                             {Source::Deviation, 3, 1.0},
                                             {Source::Constant, 0, 0.0}},
                                            {{Source::Deviation, 1, 2.0},
                                             {Source::Deviation, 2, 1.0},
                                             {Source::Constant, 0, 0.1}}});
         }},
        {"PRISCA (paper): Algorithm 1 as printed", "prisca-paper", [](Profile&, Fit&) {}},
        {"PD+H+LSD (best baseline)", "pd-h-lsd", [](Profile&, Fit&) {}},
        {"PD+H+LSD, no latency compensation", "pd-h-lsd",
         [](Profile& p, Fit&) { p.compensateLoopLatency = false; }},
        {"PD+LSD", "pd-lsd", [](Profile&, Fit&) {}},
    };
    if (oracle) {
        variants.push_back({"LIMIT (oracle)", "oracle", [](Profile&, Fit&) {}});
    }
    std::printf(
        "Slide-car, every style x seed sets %llu..%llu, %d evaluation trials per cell after "
        "16 training trials, perturbation 1, sensor 1; means and 95%% intervals over the "
        "cells\n\n",
        static_cast<unsigned long long>(seed), static_cast<unsigned long long>(seed + sets - 1),
        trials);
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
                    row.position.mean, row.position.lower, row.position.upper, row.orientation.mean,
                    row.orientation.lower, row.orientation.upper, worst);
        std::fflush(stdout);
    }
    return 0;
}
