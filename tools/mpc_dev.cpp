// Developer tool (not installed): model-predictive parking trial by trial on one cell of the
// new-car protocol (a variant, a style, a seed set), with a feedback law on the same trials (LAW=,
// PD+LSD by default), what mpc did each trial (planned or fell back, and why; its model's fit;
// refits; its rolling correction at the end). DEMO_CSV=PATH writes the cell's demonstration.
//   mpc_dev VARIANT.json STYLE SEED_SET TRIALS [NAME=VALUE ...]
#include "core/ActionMapping.h"
#include "core/DemonstrationCsv.h"
#include "sim/DemonstrationStyles.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"
#include "sim/episodes/EpisodeRunner.h"
#include "sim/episodes/TrialMetrics.h"
#include "sim/planning/MpcController.h"
#include "sim/run/RunSetup.h"
#include "sim/run/Task.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace prisca;
using namespace prisca::sim;

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc < 5) {
        std::fprintf(stderr,
                     "usage: mpc_dev VARIANT.json STYLE SEED_SET TRIALS [NAME=VALUE ...]\n");
        return 2;
    }
    QString error;
    const auto read = readPlantParameters(QString::fromLocal8Bit(argv[1]), "slidecar", &error);
    if (!read) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 2;
    }
    const auto variant = std::make_shared<const PlantParameters>(*read);
    const QString style = QString::fromLocal8Bit(argv[2]);
    const std::uint64_t set = std::stoull(argv[3]);
    const int trials = std::atoi(argv[4]);
    MethodTuning profile = PlantCatalog::tuning(PlantCatalog::describe("slidecar"));
    MethodCatalog::setParameter(profile, QStringLiteral("start=demo"));
    for (int i = 5; i < argc; ++i) {
        MethodCatalog::setParameter(profile, QString::fromLocal8Bit(argv[i]));
    }
    // Development overrides of fields no parameter declares.
    if (qEnvironmentVariableIsSet("MPC_CS"))
        profile.mpc.correctionScale = qEnvironmentVariable("MPC_CS").toDouble();
    if (qEnvironmentVariableIsSet("MPC_MC"))
        profile.mpc.maxCorrection = qEnvironmentVariable("MPC_MC").toDouble();
    if (qEnvironmentVariableIsSet("MPC_TH"))
        profile.mpc.tubeHeading = qEnvironmentVariable("MPC_TH").toDouble();
    if (qEnvironmentVariableIsSet("MPC_PF"))
        profile.mpc.poorFit = qEnvironmentVariable("MPC_PF").toDouble();
    if (qEnvironmentVariableIsSet("MPC_KN"))
        profile.mpc.maxKnots = qEnvironmentVariable("MPC_KN").toInt();
    if (qEnvironmentVariableIsSet("MPC_FB"))
        profile.mpc.feedback = qEnvironmentVariableIntValue("MPC_FB") != 0;
    if (qEnvironmentVariableIsSet("MPC_GS"))
        profile.mpc.gripSpread = qEnvironmentVariable("MPC_GS").toDouble();
    if (qEnvironmentVariableIsSet("MPC_RO"))
        profile.mpc.rollouts = qEnvironmentVariable("MPC_RO").toInt();
    if (qEnvironmentVariableIsSet("MPC_TS"))
        profile.mpc.trackingScale = qEnvironmentVariable("MPC_TS").toDouble();
    if (qEnvironmentVariableIsSet("MPC_IE"))
        profile.mpc.identifyEvaluations = qEnvironmentVariable("MPC_IE").toInt();
    if (qEnvironmentVariableIsSet("MPC_RB"))
        profile.mpc.rollingBiasGain = qEnvironmentVariable("MPC_RB").toDouble();
    RunSettings settings;
    settings.seed = set;
    const Task task = makeTask(profile,
                               std::make_shared<core::Demonstration>(DemonstrationStyles::record(
                                   "slidecar", style, set, {},
                                   demonstrationConditions(settings, profile, variant.get(), set))),
                               {}, variant);
    {
        // The demonstration's slide: the largest sideways speed, side-slip angle (moving faster
        // than 0.5 m/s) and yaw rate.
        const Eigen::MatrixXd& st = task.demonstration->states;
        double lateral = 0.0, slip = 0.0, yaw = 0.0, slid = 0.0, turned = 0.0, top = 0.0;
        for (Eigen::Index j = 0; j < st.rows(); ++j) {
            lateral = std::max(lateral, std::abs(st(j, 4)));
            slid += std::abs(st(j, 4)) * task.demonstration->dt;
            top = std::max(top, std::hypot(st(j, 3), st(j, 4)));
            turned += std::abs(st(j, 5)) * task.demonstration->dt;
            yaw = std::max(yaw, std::abs(st(j, 5)));
            if (std::hypot(st(j, 3), st(j, 4)) > 0.5)
                slip = std::max(slip, std::abs(std::atan2(st(j, 4), std::abs(st(j, 3)))));
        }
        std::printf(
            "demo: sideways %.2f m/s, side slip %.1f deg, yaw rate %.2f rad/s, slid %.2f m, "
            "turned %.2f rad, top speed %.2f m/s\n",
            lateral, slip * 180.0 / M_PI, yaw, slid, turned, top);
        if (qEnvironmentVariableIsSet("DEMO_CSV")) {
            core::FileError error;
            if (!core::writeDemonstrationCsv(*task.demonstration, qEnvironmentVariable("DEMO_CSV"),
                                             &error))
                std::fprintf(stderr, "DEMO_CSV: %s\n", qPrintable(error.toString()));
        }
        if (trials <= 0)
            return 0;
    }
    const RunSetup mpcRun(task,
                          qEnvironmentVariableIsSet("METHOD") ? qEnvironmentVariable("METHOD")
                                                              : QStringLiteral("mpc"),
                          settings);
    const RunSetup lawRun(
        task,
        qEnvironmentVariableIsSet("LAW") ? qEnvironmentVariable("LAW") : QStringLiteral("pd-lsd"),
        settings);
    auto mpc = mpcRun.makeController();
    auto law = lawRun.makeController();
    auto* planner = dynamic_cast<MpcController*>(mpc.get());
    if (planner)
        std::printf("model fit %.2f cm\n", 100.0 * planner->modelFit());
    if (planner && qEnvironmentVariableIsSet("MODEL")) {
        const auto& specs = plantParameterSpecs(planner->model().plant);
        for (size_t i = 0; i < specs.size(); ++i)
            std::printf("  %-18s %g (variant %g)\n", qPrintable(specs[i].key),
                        planner->model().values[i], variant->values[i]);
    }
    const core::Demonstration& demo = *task.demonstration;
    const PlantInfo& info = profile.info;
    double sumMpc = 0.0, sumLaw = 0.0;
    for (int t = 0; t < trials; ++t) {
        auto errorOf = [&](const RunSetup& run, core::Controller& c) {
            auto plant = run.makePlant();
            EpisodeSettings e = run.trial(t);
            const bool trace = qEnvironmentVariableIntValue("TRACE") == t + 1 && &c == mpc.get();
            e.recordSteps = trace;
            const EpisodeResult r = runEpisode(*plant, c, e);
            if (qEnvironmentVariableIsSet("SPLIT"))
                std::printf("    ran out %.2f s, trial %.2f s\n", r.runOutSeconds, r.duration);
            for (size_t k = 0; trace && k < r.steps.size(); k += 5) {
                const StepRecord& s = r.steps[k];
                const int j = std::min<int>(static_cast<int>(k), demo.length() - 1);
                std::printf(
                    "  t %5.2f  x %6.2f y %6.2f psi %6.2f v %5.2f,%5.2f | demo x %6.2f y %6.2f "
                    "psi %6.2f | u %5.2f %5.2f  u* %5.2f %5.2f\n",
                    s.time, s.state[0], s.state[1], s.state[2], s.state[3], s.state[4],
                    demo.states(j, 0), demo.states(j, 1), demo.states(j, 2), s.action[0],
                    s.action[1], demo.actions(j, 0), demo.actions(j, 1));
            }
            const core::PlanarPoseIndices p = *info.pose;
            if (qEnvironmentVariableIntValue("SPLIT") != 0) {
                // The miss in the lot's frame: along the parked heading (+ beyond), and across.
                const Eigen::VectorXd lot = demo.states.row(demo.length() - 1).transpose();
                const double dx = r.finalState[p.x] - lot[p.x], dy = r.finalState[p.y] - lot[p.y];
                const double ch = std::cos(lot[p.heading]), sh = std::sin(lot[p.heading]);
                std::printf("    %s along %+6.1f cm across %+6.1f cm  speed at end %.2f m/s\n",
                            &c == mpc.get() ? "mpc" : "law", 100.0 * (ch * dx + sh * dy),
                            100.0 * (-sh * dx + ch * dy),
                            std::hypot(r.finalState[3], r.finalState[4]));
            }
            return 100.0 * parkingError(info, demo, r.finalState[p.x], r.finalState[p.y],
                                        r.finalState[p.heading])
                               .position;
        };
        const double a = errorOf(mpcRun, *mpc);
        const double b = errorOf(lawRun, *law);
        sumMpc += a;
        sumLaw += b;
        std::printf(
            "trial %2d: mpc %6.1f cm  law %6.1f cm  fit %.2f cm refits %d rolling %+.3f steer "
            "%+.3f  %s\n",
            t + 1, a, b, planner ? 100.0 * planner->modelFit() : -1.0,
            planner ? planner->refits() : 0, planner ? planner->rollingCorrection() : 0.0,
            planner ? planner->steeringBias() : 0.0,
            planner ? qPrintable(planner->fallbackReason()) : "");
    }
    std::printf("mean: mpc %.1f cm, law %.1f cm\n", sumMpc / trials, sumLaw / trials);
    return 0;
}
