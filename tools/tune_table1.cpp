// tune_table1: the random search behind the slide-car profile's tuned values (README "Results").
// Each method gets the same budget of settings, scored on tuning seeds that the evaluation never
// uses (seed sets 100 and 101, 20 trials each), by position MAE + position std + 0.5 x
// orientation MAE [cm, deg], averaged over the two sets. The five best settings are then shown on evaluation seed sets 1, 2 and 3.
//
//     tune_table1 prisca|pd-h-lsd|pgsd [settings, default 400]
//
// Deterministic: the same build prints the same list.
#include "core/ActionMapping.h"
#include "core/Statistics.h"
#include "sim/PlantCatalog.h"
#include "sim/Table1Experiment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

using namespace prisca;
using Source = core::FeatureTerm::Source;

namespace {

struct Setting {
    // PRISCA (and PGSD: stepScale is its fixed step, horizon its H)
    double stepScale = 3, beta = 3000, gamma = 0.9, bound = 1;
    int horizon = 15, trainingTrials = 16, responseSteps = 1;
    double lon = 1, vx = 0.3, throttleBias = 0, lat = 2, psi = 0.3, steeringBias = 0.1;
    // shared
    double weightPsi = 0.3, weightVelocity = 0.3;
    int window = 40;
    // PD
    double kpThrottle = 1, kpSteering = 2, kdThrottle = 0.05, kdSteering = 0.3;
    double comboVx = 0.3, comboPsi = 0, comboR = 0;
    int pdHorizon = 5;
};

struct Score {
    double value, position, positionStd, orientation;
};

Score evaluate(const Setting& s, const char* method, std::uint64_t seedSet) {
    auto demo = std::make_shared<core::Demonstration>(sim::PlantCatalog::demonstrate("slidecar", 1));
    sim::PlantProfile p = sim::PlantProfile::forPlant(sim::PlantCatalog::describe("slidecar"));
    core::ActionMappingFitOptions fitOptions;
    fitOptions.responseSteps = s.responseSteps;
    const Eigen::MatrixXd B = core::fitActionMapping(*demo, p.mapping, p.info.deviationModel(), fitOptions).b;
    p.features = core::FeatureMap({{{Source::Deviation, 0, s.lon}, {Source::Deviation, 3, s.vx}, {Source::Constant, 0, s.throttleBias}},
                                   {{Source::Deviation, 1, s.lat}, {Source::Deviation, 2, s.psi}, {Source::Constant, 0, s.steeringBias}}});
    p.costWeights << 1, 1, s.weightPsi, s.weightVelocity, s.weightVelocity, s.weightVelocity / 5;
    p.matchingWindow = s.window;
    p.prisca.stepSize.scale = s.stepScale;
    p.prisca.stepSize.beta = s.beta;
    p.prisca.horizon = s.horizon;
    p.prisca.gamma = s.gamma;
    p.prisca.thetaBound = s.bound;
    p.pgsd.stepSize = s.stepScale;
    p.pgsd.horizon = s.horizon;
    p.pgsd.thetaBound = s.bound;
    p.pd.kp << s.kpThrottle, s.kpSteering;
    p.pd.kd << s.kdThrottle, s.kdSteering;
    p.pd.errorCombination << 1, 0, 0, s.comboVx, 0, 0, 0, 1, s.comboPsi, 0, 0, s.comboR;
    p.pdHorizon = s.pdHorizon;
    sim::Table1Settings settings;
    settings.methods = {method};
    settings.seed = seedSet;
    settings.trainingTrials = s.trainingTrials;
    const sim::Table1Result r = sim::runTable1(settings, demo, p, B);
    std::vector<double> position, orientation;
    for (const sim::TrialSummary& t : r.methods[0].trials) {
        position.push_back(t.finalPositionError * 100.0);
        orientation.push_back(t.finalHeadingError * 180.0 / M_PI);
    }
    const core::ErrorSummary P = core::summarizeErrors(position), O = core::summarizeErrors(orientation);
    double value = P.meanAbsoluteError + P.standardDeviation + 0.5 * O.meanAbsoluteError;
    return {std::isfinite(value) ? value : 1e9, P.meanAbsoluteError, P.standardDeviation, O.meanAbsoluteError};
}

template <class T>
T pick(std::mt19937& g, std::initializer_list<T> values) {
    return *(values.begin() + std::uniform_int_distribution<int>(0, static_cast<int>(values.size()) - 1)(g));
}

Setting draw(std::mt19937& g, const char* method) {
    Setting s;
    if (!std::strcmp(method, "prisca")) {
        s.stepScale = pick(g, {0.3, 1.0, 3.0});
        s.beta = pick(g, {300.0, 1000.0, 3000.0, 10000.0});
        s.horizon = pick(g, {5, 10, 15});
        s.gamma = pick(g, {0.9, 0.95, 0.99});
        s.lon = pick(g, {0.5, 1.0, 2.0, 4.0});
        s.vx = pick(g, {0.1, 0.3, 1.0});
        s.throttleBias = pick(g, {0.0, 0.1});
        s.lat = pick(g, {0.5, 1.0, 2.0, 4.0});
        s.psi = pick(g, {0.1, 0.3, 1.0});
        s.steeringBias = pick(g, {0.0, 0.1});
        s.weightPsi = pick(g, {0.1, 0.3, 1.0});
        s.weightVelocity = pick(g, {0.03, 0.1, 0.3});
        s.trainingTrials = pick(g, {8, 16});
        s.window = pick(g, {20, 40});
        s.responseSteps = pick(g, {1, 2});
        s.bound = pick(g, {0.5, 1.0, 2.0, 4.0});
    } else if (!std::strcmp(method, "pgsd")) {
        // PGSD shares PRISCA's features, weights and training trials; its own knobs only.
        s.stepScale = pick(g, {0.01, 0.03, 0.1, 0.3, 1.0, 3.0});
        s.horizon = pick(g, {5, 10, 15});
        s.bound = pick(g, {0.0, 0.5, 1.0, 2.0, 4.0});
    } else {
        s.pdHorizon = pick(g, {5, 10, 15});
        s.window = pick(g, {20, 40});
        s.kpThrottle = pick(g, {0.25, 0.5, 1.0, 2.0, 4.0});
        s.kpSteering = pick(g, {0.5, 1.0, 2.0, 4.0, 8.0});
        s.kdThrottle = pick(g, {0.0, 0.05, 0.2});
        s.kdSteering = pick(g, {0.0, 0.1, 0.3});
        s.comboVx = pick(g, {0.0, 0.3, 1.0});
        s.comboPsi = pick(g, {0.0, 0.25, 0.5, 1.0});
        s.comboR = pick(g, {0.0, 0.1, 0.3});
    }
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const char* method = argc > 1 ? argv[1] : "prisca";
    if (std::strcmp(method, "prisca") && std::strcmp(method, "pgsd") && std::strcmp(method, "pd-h-lsd")) {
        std::fprintf(stderr, "usage: tune_table1 prisca|pgsd|pd-h-lsd [settings]\n");
        return 2;
    }
    const int count = argc > 2 ? std::atoi(argv[2]) : 400;
    std::mt19937 g(12345);
    std::vector<std::pair<Score, Setting>> results;
    for (int i = 0; i < count; ++i) {
        const Setting s = i == 0 ? Setting{} : draw(g, method);
        Score a = evaluate(s, method, 100);
        const Score b = evaluate(s, method, 101);
        a.value = 0.5 * (a.value + b.value);
        results.emplace_back(a, s);
        if ((i + 1) % 50 == 0) std::fprintf(stderr, "tune_table1: %d/%d settings\n", i + 1, count);
    }
    std::sort(results.begin(), results.end(), [](const auto& a, const auto& b) { return a.first.value < b.first.value; });
    for (int i = 0; i < std::min(5, count); ++i) {
        const Setting& s = results[i].second;
        std::printf("%d. tuning score %.1f | alpha0/step %g beta %g H %d gamma %g bound %g features (%g %g %g | %g %g %g) "
                    "W (psi %g, v %g) training %d window %d R %d | PD kp (%g %g) kd (%g %g) combo (vx %g psi %g r %g) H %d\n",
                    i + 1, results[i].first.value, s.stepScale, s.beta, s.horizon, s.gamma, s.bound, s.lon, s.vx,
                    s.throttleBias, s.lat, s.psi, s.steeringBias, s.weightPsi, s.weightVelocity, s.trainingTrials,
                    s.window, s.responseSteps, s.kpThrottle, s.kpSteering, s.kdThrottle, s.kdSteering, s.comboVx,
                    s.comboPsi, s.comboR, s.pdHorizon);
        for (std::uint64_t set : {1, 2, 3}) {
            const Score e = evaluate(s, method, set);
            std::printf("     evaluation seed set %llu: position %.1f ± %.1f cm, orientation %.1f deg\n",
                        static_cast<unsigned long long>(set), e.position, e.positionStd, e.orientation);
        }
    }
    return 0;
}
