// The methods that plan through a model: the oracle (through the simulated plant itself: the limit)
// and MPC (through the car identified from its demonstration).
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include <limits>
#include <stdexcept>
#include "core/IlcController.h"
#include "sim/planning/Identification.h"
#include "sim/planning/MpcController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

// The oracle's planner for this demonstration's trials (their length and rest), through the
// proportional part of the profile's PD (u = u* - Kp C e) where the profile says so.
OracleParameters plannerFor(const MethodTuning& profile, const core::Demonstration& demonstration) {
    OracleParameters parameters = profile.oracle;
    const EpisodeSettings trial = profile.episode(demonstration, 1.0, 1.0);
    const double dt = demonstration.dt;
    parameters.trialSteps = static_cast<int>(trial.duration / dt + 0.5);
    parameters.restAfterStep =
        trial.stopAtRestAfter >= 0.0 ? static_cast<int>(trial.stopAtRestAfter / dt + 0.5) : -1;
    if (profile.oracleFeedback) {
        parameters.feedback = -(profile.pd.kp.asDiagonal() * profile.pd.errorCombination);
    }
    return parameters;
}

namespace {

const MethodParameter& oracleSamples() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "oracle.samples", QT_TRANSLATE_NOOP("MethodParameter", "Oracle samples"), "", 1, 1000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Candidate plans the oracle simulates at each planning."));
        p.get = [](const MethodTuning& f) { return one(f.oracle.samples); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.oracle.samples = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& oracleReplan() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "oracle.replan-every", QT_TRANSLATE_NOOP("MethodParameter", "Oracle replanning"),
            "steps", 1, 1000,
            QT_TRANSLATE_NOOP("MethodParameter", "Control steps between two plans of the oracle."));
        p.get = [](const MethodTuning& f) { return one(f.oracle.replanEvery); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.oracle.replanEvery = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& mpcReplan() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "mpc.replan-every", QT_TRANSLATE_NOOP("MethodParameter", "Replanning"), "steps", 1, 100,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Control steps between two plans through the model (2 at 25 Hz: "
                              "every 0.08 s)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.replanEvery); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.mpc.replanEvery = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& mpcRollouts() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "mpc.rollouts", QT_TRANSLATE_NOOP("MethodParameter", "Model runs per plan"), "", 2,
            1000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The planning's budget: runs of the model to the trial's end per "
                              "plan."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.rollouts); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.mpc.rollouts = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& mpcTube() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "mpc.tube", QT_TRANSLATE_NOOP("MethodParameter", "Predicted tube"), "m", 0.01, 10.0, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "How far the measured position may stray from the model's "
                              "prediction before the fallback law finishes the trial."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.tubePosition); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.tubePosition = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcPlanFit() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.plan-fit", QT_TRANSLATE_NOOP("MethodParameter", "Model good enough to plan"),
                 "cm", 0.1, 100.0, 1,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "How closely the model must fit its data to be planned through; "
                                   "a model that fits worse leaves the whole trial to the feedback "
                                   "law."));
        p.get = [](const MethodTuning& f) { return one(100.0 * f.mpc.planFit); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.planFit = v[0] / 100.0; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcStraight() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "mpc.straight", QT_TRANSLATE_NOOP("MethodParameter", "Corrections before the turn"), "",
            0.0, 2.0, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The largest change the plan makes to the demonstration's "
                              "actions before its turn, as a share of each action's half "
                              "range (2: no bound)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.straightCorrection); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.straightCorrection = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcRollingBias() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.rolling-bias", QT_TRANSLATE_NOOP("MethodParameter", "Rolling correction"), "",
                 0.0, 1.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "While the car parks, how fast the model's rolling resistance "
                                   "follows the deceleration it failed to predict (0: never)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.rollingBiasGain); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.rollingBiasGain = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcSteeringBias() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.steer-bias", QT_TRANSLATE_NOOP("MethodParameter", "Steering correction"), "",
                 0.0, 1.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "On the way into the slide, how fast the model's steering "
                                   "offset follows the heading it failed to predict: a trim the "
                                   "car has and the model has not (0: never)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.steeringBiasGain); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.steeringBiasGain = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcSpinGuard() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.spin-slip", QT_TRANSLATE_NOOP("MethodParameter", "Spin guard"), "deg", 0.0,
                 90.0, 0,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "How far the side-slip angle may stray from the demonstration's "
                                   "on the way into the slide before the fallback law finishes the "
                                   "trial (0: no guard)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.spinSideSlip * 180.0 / M_PI); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.mpc.spinSideSlip = v[0] * M_PI / 180.0;
            // 0 switches the whole guard off, the yaw rate's bound too.
            f.mpc.spinYawRate = v[0] == 0.0 ? 0.0 : MpcParameters{}.spinYawRate;
        };
        return p;
    }();
    return p;
}

const MethodParameter& mpcSegment() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.segment", QT_TRANSLATE_NOOP("MethodParameter", "Model fit's segments"), "s",
                 0.2, 3.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "How long a stretch of the data the model is fitted to predict "
                                   "from each recorded state (identification's segment)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.modelSegment); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.modelSegment = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcParking() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.park-speed", QT_TRANSLATE_NOOP("MethodParameter", "Parking hand-over"), "m/s",
                 0.0, 3.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "Past the demonstration's fastest turn, the feedback law parks "
                                   "the car once it is slower than this (0: the plan drives to "
                                   "the end)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.parkingSpeed); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.parkingSpeed = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcParkingDistance() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.park-near", QT_TRANSLATE_NOOP("MethodParameter", "Hand-over near the lot"),
                 "m", 0.0, 2.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "The parking hand-over waits until the car is this close to the "
                                   "lot; farther away the plan drives on (0: at any distance)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.parkingDistance); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.parkingDistance = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcParkingApproach() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "mpc.park-approach", QT_TRANSLATE_NOOP("MethodParameter", "Approach to the lot"), "m",
            0.0, 1.0, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Once the feedback law parks the car, a car that would coast to "
                              "rest more than this short of the lot is driven on towards it (0: "
                              "off, the law's throttle)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.parkingApproach); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.parkingApproach = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcPlanSlide() {
    static const MethodParameter p = [] {
        MethodParameter p =
            real("mpc.plan-slide", QT_TRANSLATE_NOOP("MethodParameter", "Slide worth planning"),
                 "m/s", 0.0, 5.0, 2,
                 QT_TRANSLATE_NOOP("MethodParameter",
                                   "A demonstration whose largest sideways speed is under this is "
                                   "driven by the feedback law, not planned through (0: every "
                                   "slide is planned)."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.planSlide); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.planSlide = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcRefit() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "mpc.refit", QT_TRANSLATE_NOOP("MethodParameter", "Refit after each trial"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Refit the model on the demonstration and the day's newest trials "
                              "after each trial."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.refit ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.refit = v[0] > 0.5; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcStartLearning() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "mpc.start-learning",
            QT_TRANSLATE_NOOP("MethodParameter", "Start law learns across trials"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The feedback law that drives a trial not planned through (ILC's "
                              "loop) learns from the day's trials it drove."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.startLearning ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.startLearning = v[0] > 0.5; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcLawChoice() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "mpc.law-choice", QT_TRANSLATE_NOOP("MethodParameter", "Day's trials choose the law"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Once the start law's trials park farther than the plan's bound "
                              "on average, the next trial not planned through is the fallback "
                              "law's (PD+LSD) from its start, and from then on the one of the "
                              "two that has parked the day's trials closer drives them."));
        p.get = [](const MethodTuning& f) { return one(f.mpc.lawChoice ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.lawChoice = v[0] > 0.5; };
        return p;
    }();
    return p;
}

const MethodParameter& mpcPlanTrust() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "mpc.plan-trust",
            QT_TRANSLATE_NOOP("MethodParameter", "Plan kept while it parks within"), "cm", 0.0,
            500.0, 1,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Once a planned trial parks farther than this from the lot, the "
                              "next trial is the feedback law's, and from then on each trial "
                              "goes to whichever has parked the day's trials closer (0: the plan "
                              "drives every trial it may)."));
        p.get = [](const MethodTuning& f) { return one(100.0 * f.mpc.planTrust); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.mpc.planTrust = v[0] / 100.0; };
        return p;
    }();
    return p;
}

Made makeOracle(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    const OracleParameters parameters = plannerFor(profile, *demonstration);
    return std::make_unique<OracleController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), parameters);
}

Made makeMpc(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    if (!identificationAvailable(profile.info.name)) {
        throw std::invalid_argument(
            QStringLiteral("mpc plans through an identified model; identification knows %1, not "
                           "'%2'")
                .arg(QStringLiteral("slidecar"), profile.info.name)
                .toStdString());
    }
    OracleParameters planner = plannerFor(profile, *demonstration);
    // A plan is scored where the car comes to rest after its trial, as the trial is.
    planner.runOutSteps = static_cast<int>(
        profile.episode(*demonstration, 1.0, 1.0).runOutLimit / demonstration->dt + 0.5);
    // The fallback: the PD with the least-state-deviation reference, the profile's law.
    std::unique_ptr<core::Controller> fallback =
        makePdLsd(MethodInput{profile, demonstration, in.fittedB, nullptr});
    // A trial not planned through at all is driven from its start by ILC's loop: the PD on the
    // time-aligned error at the profile's ILC gains (half the PD's on the slide-car). On the
    // development cars with the reality gap it parked at 17.9 cm where PD+LSD parked at 34.3
    // (docs/research-log.md, issue 33's twelfth step); from the middle of a trial the
    // least-state-deviation reference did better. It learns from the trials it drove as ILC
    // does (mpc.start-learning); the controller steps it on those trials only.
    core::IlcParameters startLawParameters = profile.ilcParameters();
    if (!profile.mpc.startLearning) {
        startLawParameters.learningGain.setZero();
    }
    auto startLaw = std::make_unique<core::IlcController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), startLawParameters);
    std::vector<core::Demonstration> data{*demonstration};
    const IdentificationSettings settings = mpcIdentificationSettings(profile.mpc, false);
    PlantParameters model;
    double fit = -1.0;
    QString noModel;
    if (profile.mpcModel) {
        model = *profile.mpcModel;
        fit = modelPositionRms(data, model, settings);
    } else if (!slideWorthPlanning(*demonstration, profile.info.bodyVelocity, profile.mpc)) {
        // A demonstration with too little slide to plan through (the controller says so and
        // the start law drives): no identification is run for it.
        model = profile.mpcPrior ? *profile.mpcPrior : defaultPlantParameters(profile.info.name);
        fit = std::numeric_limits<double>::quiet_NaN();
    } else {
        const PlantParameters prior =
            profile.mpcPrior ? *profile.mpcPrior : defaultPlantParameters(profile.info.name);
        const IdentificationResult identified =
            identifyForMpc(data, prior, profile.mpc, in.cancelled);
        if (identified.ok()) {
            model = identified.parameters;
            fit = identified.positionRms;
        } else {
            // Nothing to plan through: the start law drives every trial, and the note says why.
            // (PD+LSD as this law, for demonstrations without a slide, parked the refused
            // development cells at 1.0-1.4 cm where ILC's loop parked 5.3-13.2, and held out
            // two refused cells of three at 66 and 27 cm where ILC's loop parked 14 and 12:
            // not adopted; docs/research-log.md, issue 33's fourteenth step.)
            model = identified.parameters;
            fit = std::numeric_limits<double>::quiet_NaN();
            noModel = identified.cancelled ? QStringLiteral("identification was cancelled")
                                           : identified.refusal;
        }
    }
    return std::make_unique<MpcController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.mpc, planner,
        std::move(fallback), std::move(model), fit, std::move(data), std::move(startLaw), noModel);
}

}  // namespace

/// MPC, with the PD+LSD law as its fallback.
MethodSpec mpcMethod() {
    MethodSpec s = entry("mpc", "MPC", &makeMpc);
    s.learnsOnline = true;  // the start law learns (mpc.start-learning); the model may be refit
    s.inDefaultTable1 = false;
    s.plansThroughModel = true;
    s.plants = QStringList{QStringLiteral("slidecar")};  // what identification knows
    s.summary = "model-predictive parking through the car identified from its demonstration";
    s.parameters = {mpcReplan(),          mpcRollouts(),  mpcTube(),
                    mpcPlanFit(),         mpcPlanSlide(), mpcStraight(),
                    mpcSteeringBias(),    mpcSpinGuard(), mpcSegment(),
                    mpcRollingBias(),     mpcParking(),   mpcParkingDistance(),
                    mpcParkingApproach(), mpcPlanTrust(), mpcStartLearning(),
                    mpcLawChoice(),       mpcRefit()};
    return s;
}

/// The oracle.
MethodSpec oracleMethod() {
    MethodSpec s = entry("oracle", "LIMIT (oracle)", &makeOracle);
    s.limit = true;
    s.simulationOnly = true;
    s.summary = "plans on copies of the simulated plant itself: the limit, simulation only";
    s.parameters = {oracleSamples(), oracleReplan()};
    return s;
}

}  // namespace prisca::sim::methods
