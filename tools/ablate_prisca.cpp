// ablate_prisca: PRISCA's variants on DEVELOPMENT cells only (the six tuning styles x seed sets
// 200 and 201, 10 trials each after the training trials), for the decisions behind the profile;
// no evaluation set is looked at here.
//
//     ablate_prisca METHOD [key value ...]    keys: grad delay scale beta bound H baseline D drift
//                                             signs wv wpsi R explained age lost prior pdH N
//     TRACE=STYLE [TRIALS=N] ablate_prisca ... theta and the final error trial by trial
//     DUMP=STYLE:SET [EVERY=K] ...            the worst trial of a cell, every K-th step
//     CELLS=1, FEATURES=..., PV=a,b,c, NOISE= LAT= DROP=, PERT= SENSOR=: see below

#include <QStringList>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include "core/ActionMapping.h"
#include "core/PriscaController.h"
#include "core/Statistics.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/experiments/Table1Experiment.h"
#include "sim/run/MethodTraining.h"
#include "sim/run/RunSetup.h"
using namespace prisca;
int main(int argc, char** argv) {
    const char* method = argv[1];
    sim::MethodTuning p = sim::PlantCatalog::tuning(sim::PlantCatalog::describe("slidecar"));
    bool drift = false;
    for (int i = 2; i + 1 < argc; i += 2) {
        std::string k = argv[i];
        double v = atof(argv[i + 1]);
        if (k == "grad")
            p.prisca.gradient = v ? core::PriscaParameters::Gradient::ClosedLoop
                                  : core::PriscaParameters::Gradient::OneStep;
        else if (k == "pdH")
            p.pdHorizon = (int)v;
        else if (k == "prior")
            p.priscaFromPd = v != 0.0;
        else if (k == "N")
            p.prisca.effectHorizon = (int)v;
        else if (k == "delay")
            p.prisca.modelDelay = (int)v;
        else if (k == "scale")
            p.prisca.stepSize.scale = v;
        else if (k == "beta")
            p.prisca.stepSize.beta = v;
        else if (k == "bound")
            p.prisca.thetaBound = v;
        else if (k == "H")
            p.prisca.horizon = (int)v;
        else if (k == "baseline")
            p.prisca.useBaseline = v;
        else if (k == "D")
            p.prisca.useInverseDepreciation = v;
        else if (k == "drift") {
            drift = v;
            if (v)
                p.priscaModel = sim::MethodTuning::PriscaModel::FittedWithDrift;
        } else if (k == "signs") {
            if (v)
                p.priscaModel = sim::MethodTuning::PriscaModel::Signs;
        } else if (k == "wv") {
            p.costWeights[3] = v;
            p.costWeights[4] = v;
            p.costWeights[5] = v / 5;
        } else if (k == "wpsi")
            p.costWeights[2] = v;
        else if (k == "R")
            p.prisca.effortWeights = Eigen::Vector2d(v, v);
        else if (k == "explained")
            p.priscaLearnWhereExplained = v != 0.0;
        else if (k == "lost")
            p.lostTrackDistance = v;
        else if (k == "age")
            p.compensateLoopLatency = v != 0.0;
    }
    // NOISE / LAT / DROP: the sensor's parts on their own (noise scale, latency, drop chance).
    if (getenv("NOISE"))
        p.measurement.noise *= atof(getenv("NOISE"));
    if (getenv("LAT"))
        p.measurement.loopLatencySteps = atoi(getenv("LAT"));
    if (getenv("DROP"))
        p.measurement.dropProbability = atof(getenv("DROP"));
    if (getenv("PV")) {  // PV=initial,parameters,actuator: the perturbation's parts' shares
        const QStringList v = QString::fromLatin1(getenv("PV")).split(',');
        p.perturbationShares = {v[0].toDouble(), v[1].toDouble(), v[2].toDouble()};
    }
    if (getenv("FEATURES")) {
        // FEATURES="0:2,3:1,c:0.1|1:4,2:1,c:0": per channel, deviation index:scale or c:scale.
        std::vector<std::vector<core::FeatureTerm>> channels;
        for (const QString& channel : QString::fromLatin1(getenv("FEATURES")).split('|')) {
            std::vector<core::FeatureTerm> terms;
            for (const QString& term : channel.split(',')) {
                const QStringList parts = term.split(':');
                core::FeatureTerm t;
                t.source = parts[0] == QLatin1String("c") ? core::FeatureTerm::Source::Constant
                                                          : core::FeatureTerm::Source::Deviation;
                t.index = parts[0] == QLatin1String("c") ? 0 : parts[0].toInt();
                t.scale = parts[1].toDouble();
                terms.push_back(t);
            }
            channels.push_back(terms);
        }
        p.features = core::FeatureMap(channels);
        p.priscaFeatures = p.features;
    }
    if (getenv("TRACE")) {
        auto demo = std::make_shared<core::Demonstration>(
            sim::DemonstrationStyles::record("slidecar", getenv("TRACE"), 200));
        core::ActionMappingFitOptions fo;
        fo.drift = drift;
        auto fit = core::fitActionMapping(*demo, p.mapping, p.info.deviationModel(), fo);
        std::printf("B:\n");
        for (int l = 0; l < 2; ++l) {
            for (int c = 0; c < 6; ++c)
                std::printf(" %8.3f", fit.b(l, c));
            std::printf("\n");
        }
        if (drift) {
            std::printf("A:\n");
            for (int r = 0; r < 6; ++r) {
                for (int c = 0; c < 6; ++c)
                    std::printf(" %8.3f", fit.a(r, c));
                std::printf("\n");
            }
        }
        sim::RunSettings traceSettings;
        traceSettings.seed = 999;
        const sim::RunSetup setup(sim::makeTask(p, demo, fo), method, traceSettings);
        auto ctrl = setup.makeController();
        auto plant = setup.makePlant();
        const int traceTrials = getenv("TRIALS") ? atoi(getenv("TRIALS")) : 30;
        for (int t = 0; t < traceTrials; ++t) {
            auto r = sim::runEpisode(*plant, *ctrl, setup.trial(t));
            auto sum = sim::summarizeTrial(plant->info(), *demo, r);
            std::printf("trial %2d: %.1f cm theta", t, 100 * sum.finalPositionError);
            const Eigen::MatrixXd& th = *ctrl->learnedParameters();
            for (int l = 0; l < th.cols(); ++l)
                for (int i = 0; i < th.rows(); ++i)
                    std::printf(" %7.3f", th(i, l));
            std::printf("\n");
        }
        return 0;
    }
    if (getenv("DUMP")) {
        // DUMP=style:set: the worst of the cell's evaluation trials, every 10th step.
        const QStringList where = QString::fromLatin1(getenv("DUMP")).split(':');
        auto demo = std::make_shared<core::Demonstration>(
            sim::DemonstrationStyles::record("slidecar", where[0], where[1].toULongLong()));
        sim::RunSettings dumpSettings;
        dumpSettings.seed = where[1].toULongLong();
        const sim::RunSetup setup(sim::makeTask(p, demo), method, dumpSettings);
        auto plant = setup.makePlant();
        double worst = -1.0;
        sim::EpisodeResult worstRun;
        for (int i = 0; i < 10; ++i) {
            auto controller = setup.makeController();
            sim::EpisodeSettings e = setup.trial(i);
            e.resetMode = core::ResetMode::Cold;
            auto r = sim::runEpisode(*plant, *controller, e);
            const double error = sim::summarizeTrial(plant->info(), *demo, r).finalPositionError;
            if (error > worst) {
                worst = error;
                worstRun = r;
            }
        }
        std::printf("worst %.1f cm, demo %d samples\n", 100 * worst, demo->length());
        const size_t every = getenv("EVERY") ? atoi(getenv("EVERY")) : 10;
        for (size_t k = 0; k < worstRun.steps.size(); k += every) {
            const sim::StepRecord& r = worstRun.steps[k];
            std::printf(
                "k %3zu x %6.2f y %6.2f psi %6.2f vx %5.2f | j %3d u %5.2f %5.2f u* %5.2f "
                "%5.2f | e %6.2f %6.2f %6.2f\n",
                k, r.state[0], r.state[1], r.state[2], r.state[3], r.referenceIndex, r.action[0],
                r.action[1], r.referenceAction[0], r.referenceAction[1], r.deviation[0],
                r.deviation[1], r.deviation[2]);
        }
        return 0;
    }
    const char* styles[] = {"stick-180-left", "keyboard-180-right", "stick-90-left",
                            "fast-180-right", "blip-180-left",      "coast-90-right"};
    std::vector<double> cellPos, cellOri;
    double worst = 0;
    for (const char* style : styles)
        for (std::uint64_t set : {200, 201}) {
            auto demo = std::make_shared<core::Demonstration>(
                sim::DemonstrationStyles::record("slidecar", style, set));
            core::ActionMappingFitOptions fo;
            fo.drift = drift;
            sim::Table1Settings s;
            s.methods = {method};
            s.run.seed = set;
            s.trials = 10;
            if (getenv("PERT"))
                s.run.perturbation = atof(getenv("PERT"));
            if (getenv("SENSOR"))
                s.run.sensor = atof(getenv("SENSOR"));
            auto r = sim::runTable1(s, sim::makeTask(p, demo, fo));
            auto rows = sim::table1Rows(r);
            cellPos.push_back(rows[0].position.meanAbsoluteError);
            cellOri.push_back(rows[0].orientation.meanAbsoluteError);
            worst = std::max(worst, rows[0].position.maximum);
            if (getenv("CELLS")) {
                std::printf("  %-20s set %llu: %.2f cm (worst %.1f)\n", style,
                            static_cast<unsigned long long>(set),
                            rows[0].position.meanAbsoluteError, rows[0].position.maximum);
            }
        }
    printf("%-10s pos %.2f ori %.2f worst %.1f\n", method, core::mean(cellPos), core::mean(cellOri),
           worst);
}
