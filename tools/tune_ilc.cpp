// tune_ilc: the random search behind ILC's values on the trajectory plants (acrobot, aircraft),
// where the learners are compared by tracking error over consecutive trials. Each setting is
// scored on tuning cells only (two of the plant's demonstration styles x tuning seed sets 100 and
// 101): 4 runs of 5 trials in a row (ILC learns between trials), score = mean time-aligned
// tracking RMS of trials 2-5. The best settings are printed with their tuning scores only.
//
//     tune_ilc acrobot|aircraft [settings, default 120]
//
// Deterministic: the same build prints the same list.
#include "core/ActionMapping.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/ParallelTrials.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/run/RunSetup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

using namespace prisca;

namespace {

constexpr int kRuns = 4;
constexpr int kTrials = 5;

struct Setting {
    double scale = 0.3, cutoff = 2.0, feedback = 1.0;
    int lead = 2;
};

template <class T>
T pick(std::mt19937& g, std::initializer_list<T> values) {
    return *(values.begin() +
             std::uniform_int_distribution<int>(0, static_cast<int>(values.size()) - 1)(g));
}

double score(const QString& plant, const QStringList& styles, const Setting& s) {
    sim::MethodTuning p = sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant));
    p.ilcLearningScale = s.scale;
    p.ilcLead = s.lead;
    p.ilcCutoff = s.cutoff;
    p.ilcFeedbackScale = s.feedback;
    double total = 0.0;
    int cells = 0;
    for (const QString& style : styles) {
        for (std::uint64_t set : {100, 101}) {
            auto demo = std::make_shared<core::Demonstration>(
                sim::DemonstrationStyles::record(plant, style, set));
            const sim::Task task = sim::makeTask(p, demo);
            const auto runs = sim::runParallel<double>(kRuns, 2, [&](int run) {
                sim::RunSettings settings;
                settings.seed = sim::mixSeed(set, run);
                const sim::RunSetup setup(task, "ilc", settings);
                auto plantObject = setup.makePlant();
                auto controller = setup.makeController();
                double rms = 0.0;
                for (int trial = 0; trial < kTrials; ++trial) {
                    const sim::EpisodeResult r =
                        sim::runEpisode(*plantObject, *controller, setup.trial(trial));
                    if (trial > 0) {
                        rms += sim::summarizeTrial(plantObject->info(), *demo, r).trackingRms /
                               (kTrials - 1);
                    }
                }
                return rms;
            });
            for (double rms : runs) {
                total += std::isfinite(rms) ? rms / kRuns : 1e6;
            }
            ++cells;
        }
    }
    return total / cells;
}

}  // namespace

int main(int argc, char** argv) {
    const QString plant = QString::fromLatin1(argc > 1 ? argv[1] : "acrobot");
    if (plant != QLatin1String("acrobot") && plant != QLatin1String("aircraft")) {
        std::fprintf(stderr, "usage: tune_ilc acrobot|aircraft [settings]\n");
        return 2;
    }
    const int count = argc > 2 ? std::atoi(argv[2]) : 120;
    // Tuning styles; the plant's other styles are kept out of tuning.
    const QStringList styles = plant == QLatin1String("acrobot")
                                   ? QStringList{"swing-medium", "swing-large"}
                                   : QStringList{"s-turn", "circle"};
    std::mt19937 g(12345);
    std::vector<std::pair<double, Setting>> results;
    const sim::MethodTuning profile = sim::PlantCatalog::tuning(sim::PlantCatalog::describe(plant));
    for (int i = 0; i < count; ++i) {
        Setting s;
        if (i == 0) {
            s = {profile.ilcLearningScale, profile.ilcCutoff, profile.ilcFeedbackScale,
                 profile.ilcLead};
        } else {
            s.scale = pick(g, {0.0, 0.03, 0.1, 0.2, 0.4, 0.8});
            s.lead = pick(g, {0, 1, 2, 4, 6, 10});
            s.cutoff = pick(g, {0.0, 0.5, 1.0, 2.0, 4.0});
            s.feedback = pick(g, {0.25, 0.5, 1.0, 2.0});
        }
        results.emplace_back(score(plant, styles, s), s);
        if ((i + 1) % 10 == 0) {
            std::fprintf(stderr, "tune_ilc %s: %d/%d settings\n", qPrintable(plant), i + 1, count);
        }
    }
    std::printf("profile's current setting: tuning RMS %.4f\n", results[0].first);
    std::sort(results.begin(), results.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (int i = 0; i < std::min(5, count); ++i) {
        const Setting& s = results[i].second;
        std::printf("%d. tuning RMS %.4f | ILC scale %g lead %d cutoff %g feedback %g\n", i + 1,
                    results[i].first, s.scale, s.lead, s.cutoff, s.feedback);
    }
    return 0;
}
