// Core benchmarks (make bench): one PRISCA control step and the least-state-deviation match.
// Prints medians over batches; compare with the targets in docs/architecture.md "Performance
// targets".
#include "core/Controller.h"
#include "core/DemonstrationCsv.h"
#include "core/DeviationModel.h"
#include "core/FeatureMap.h"
#include "core/LeastStateDeviationMatcher.h"
#include "core/PriscaController.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

using namespace prisca::core;

namespace {

// A smooth planar path of T samples: x, y, psi, vx, vy, r and two actions.
std::shared_ptr<Demonstration> syntheticDemonstration(int T) {
    auto demo = std::make_shared<Demonstration>();
    demo->plant = QStringLiteral("benchmark");
    demo->dt = 0.025;
    demo->stateNames = {"x", "y", "psi", "vx", "vy", "r"};
    demo->stateUnits = {"m", "m", "rad", "m/s", "m/s", "rad/s"};
    demo->actionNames = {"throttle", "steering"};
    demo->actionUnits = {"1", "1"};
    demo->time.resize(T);
    demo->states.resize(T, 6);
    demo->actions.resize(T, 2);
    for (int k = 0; k < T; ++k) {
        const double t = k * demo->dt;
        demo->time[k] = t;
        demo->states.row(k) << std::cos(0.1 * t) * t, std::sin(0.1 * t) * t, 0.1 * t, 1.0, 0.1, 0.1;
        demo->actions.row(k) << 0.5 + 0.1 * std::sin(t), 0.3 * std::cos(0.5 * t);
    }
    return demo;
}

TrackingProblem problemFor(std::shared_ptr<Demonstration> demo, int window) {
    TrackingProblem problem;
    problem.demonstration = demo;
    problem.deviation = DeviationModel::planarVehicle(6);
    problem.matching.mode = MatchingParameters::Mode::LeastStateDeviation;
    problem.matching.window = window;
    problem.matching.angleIndices = {2};
    problem.limits = ActionLimits::symmetric(2, 1.0);
    return problem;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Median over batches of the mean time per call [us].
template <typename F>
double medianMicroseconds(int batches, int perBatch, F&& call) {
    std::vector<double> samples;
    samples.reserve(batches);
    for (int b = 0; b < batches; ++b) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < perBatch; ++i) {
            call();
        }
        const auto stop = std::chrono::steady_clock::now();
        samples.push_back(std::chrono::duration<double, std::micro>(stop - start).count() /
                          perBatch);
    }
    return median(samples);
}

}  // namespace

int main() {
    constexpr int kDemoLength = 10000;
    auto demo = syntheticDemonstration(kDemoLength);
    std::mt19937 rng(7);
    std::normal_distribution<double> noise(0.0, 0.01);

    // One PRISCA step: n = 6, m = 2, p = 4, H = 10.
    {
        FeatureMap features = FeatureMap::deviationFeatures(2, {0, 1, 2, 3});
        Eigen::MatrixXd B(2, 6);
        B << 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1;
        PriscaParameters parameters;
        parameters.horizon = 10;
        PriscaController controller(problemFor(demo, 40), features, B, parameters);
        Eigen::VectorXd s(6);
        int k = 0;
        double sink = 0.0;
        const double us = medianMicroseconds(200, 200, [&] {
            if (k >= kDemoLength) {
                controller.reset(ResetMode::WarmStart);
                k = 0;
            }
            s = demo->states.row(k).transpose();
            s[0] += noise(rng);
            s[1] += noise(rng);
            sink += controller.step(s).action[0];
            ++k;
        });
        std::printf(
            "prisca_step (n=6, m=2, p=4, H=10, LSD window 40): median %.3f us "
            "(target <= 5 us) [%g]\n",
            us, sink * 0.0);
    }

    // Least-state-deviation match on a 10,000-sample demonstration.
    for (int window : {40, 400, kDemoLength}) {
        MatchingParameters matching;
        matching.window = window;
        matching.angleIndices = {2};
        LeastStateDeviationMatcher matcher(demo->states, matching);
        Eigen::VectorXd s(6);
        int k = 0;
        long long sink = 0;
        const double us = medianMicroseconds(100, 100, [&] {
            if (k >= kDemoLength) {
                matcher.reset();
                k = 0;
            }
            s = demo->states.row(k).transpose();
            s[0] += noise(rng);
            sink += matcher.match(s);
            ++k;
        });
        std::printf(
            "lsd_match (T=10000, window %d samples): median %.3f us per step "
            "(target <= 10 us) [%lld]\n",
            window, us, sink * 0);
    }
    // Reading a 100,000-row demonstration (about 40 minutes at 40 Hz).
    {
        auto big = syntheticDemonstration(100000);
        const QByteArray text = formatDemonstrationCsv(*big);
        FileError error;
        bool ok = true;
        const double us = medianMicroseconds(7, 1, [&] {
            ok = ok && parseDemonstrationCsv(text, QStringLiteral("bench"), &error).has_value();
        });
        std::printf("csv_read (100000 rows, %.1f MB): median %.1f ms%s\n", text.size() / 1e6,
                    us / 1000.0, ok ? "" : " (PARSE FAILED)");
    }
    return 0;
}
