#include "MethodCatalog.h"

#include "Identification.h"
#include "MpcController.h"

#include "OracleController.h"
#include "core/ActionPlayback.h"
#include "core/IlcController.h"
#include "core/LqrController.h"
#include "core/PdController.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"

#include <QCoreApplication>

#include <algorithm>
#include <limits>
#include <optional>
#include <stdexcept>

namespace prisca::sim {

namespace {

using Mode = core::MatchingParameters::Mode;
using Made = std::unique_ptr<core::Controller>;

// Per demonstration sample: 1 where the robust fit explains it, else 0 (the feedback gate of
// MethodTuning::feedbackWhereExplained).
std::vector<double> explainedGate(const MethodTuning& profile,
                                  const core::Demonstration& demonstration) {
    const std::vector<bool> explained =
        core::fitActionMapping(demonstration, profile.mapping, profile.info.deviationModel())
            .explained;
    return std::vector<double>(explained.begin(), explained.end());
}

// Per demonstration sample, -1 on a car-like vehicle's heading and yaw-rate errors where the
// demonstration drives backwards, else 1 (n x T); empty for other plants (a differential drive
// turns on its own command, in either direction) or when switched off.
// The heading error turns into lateral error at the signed speed, and the steering turns the
// heading at the signed speed: in reverse both change sign, so a law derived for forward travel
// keeps its lateral term and must turn its heading terms round (docs/research-log.md).
Eigen::MatrixXd reverseSchedule(const MethodTuning& profile,
                                const core::Demonstration& demonstration) {
    const auto& pose = profile.info.pose;
    const auto& body = profile.info.bodyVelocity;
    if (!profile.feedbackReverseAware || !pose || !body || !profile.info.steersThroughTravel) {
        return {};
    }
    Eigen::MatrixXd schedule =
        Eigen::MatrixXd::Ones(demonstration.stateDimension(), demonstration.length());
    for (int j = 0; j < demonstration.length(); ++j) {
        if (demonstration.states(j, body->forward) < 0.0) {
            schedule(pose->heading, j) = -1.0;
            schedule(body->yawRate, j) = -1.0;
        }
    }
    return schedule;
}

Made makePrisca(const MethodSpec& spec, const MethodInput& in) {
    const QString& method = spec.id;
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    const Eigen::MatrixXd& fittedB = in.fittedB;
    core::PriscaParameters parameters = profile.prisca;
    const bool demoStart = profile.start == MethodTuning::Start::Demonstration;
    if (profile.priscaFromPd) {
        const int horizon =
            profile.priscaPriorHorizon >= 0 ? profile.priscaPriorHorizon : profile.pdHorizon;
        // The law derived from the demonstration is a state feedback with no derivative to
        // smooth: unsmoothed (a smoothing would only add its lag to the loop's delay).
        parameters.prior = profile.startLaw(*demonstration, fittedB, demoStart ? 0 : horizon);
    }
    // A start no one tuned takes the automatic step and scales too.
    const bool automatic = profile.priscaAutomatic || demoStart;
    Eigen::MatrixXd model = fittedB;
    std::optional<Eigen::MatrixXd> drift;
    if (profile.priscaModel == MethodTuning::PriscaModel::Signs) {
        model = profile.mapping.asDouble();
    } else if (profile.priscaModel == MethodTuning::PriscaModel::FittedWithDrift) {
        // eq. 5 in full, fitted here on the demonstration: PRISCA's own model.
        core::ActionMappingFitOptions options;
        options.drift = true;
        const core::ActionMappingFit fit = core::fitActionMapping(
            *demonstration, profile.mapping, profile.info.deviationModel(), options);
        model = fit.b;
        drift = fit.a;
    }
    if (automatic) {
        parameters.stepSize.normalised = true;
        parameters.stepSize.scale = profile.priscaAutomaticStep;
    }
    core::TrackingProblem problem = profile.priscaProblem(demonstration);
    if (automatic) {
        problem.matching.window = MethodTuning::automaticWindow(*demonstration);
    }
    core::FeatureMap features = automatic ? profile.automaticFeatures(method, *demonstration)
                                          : profile.featuresOf(method);
    if (profile.priscaPhaseSeconds > 0.0) {
        features = features.withPhases(
            demonstration->length(),
            std::max(1, static_cast<int>(std::lround(profile.priscaPhaseSeconds /
                                                      demonstration->dt))));
    }
    auto prisca = std::make_unique<core::PriscaController>(std::move(problem), std::move(features),
                                                           model, parameters);
    if (drift) {
        prisca->setDrift(*drift);
    }
    if (profile.feedbackWhereExplained() && profile.priscaFromPd) {
        prisca->setPriorGate(explainedGate(profile, *demonstration));
    }
    if (profile.priscaFromPd) {
        prisca->setPriorErrorSchedule(reverseSchedule(profile, *demonstration));
    }
    if (profile.priscaLearnWhereExplained) {
        prisca->setModelValidity(
            core::fitActionMapping(*demonstration, profile.mapping, profile.info.deviationModel())
                .explained);
    }
    return prisca;
}

Made makePriscaPaper(const MethodSpec& spec, const MethodInput& in) {
    const QString& method = spec.id;
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    // Algorithm 1 exactly as printed: eq. 8 literally (the state change against the action
    // change, no sign constraint, no robust weights), eq. 15 as printed, alpha_0 = 1 and no
    // bound on theta; the one-step gradient of eq. 14 from theta = 0. The profile gives what
    // the paper leaves open (features, H, gamma, beta, the cost weights, the reference).
    core::ActionMappingFitOptions literal;
    literal.target = core::ActionMappingFitOptions::Target::StateChange;
    literal.nonNegative = false;
    literal.robust = false;
    const core::ActionMappingFit fit = core::fitActionMapping(
        *demonstration, profile.mapping, profile.info.deviationModel(), literal);
    core::PriscaParameters paper = profile.prisca;
    paper.baselineMode = core::LocalOptimalBaseline::Mode::PaperEq15;
    paper.useBaseline = true;
    paper.useInverseDepreciation = true;
    paper.stepSize.scale = 1.0;
    paper.thetaBound = 0.0;
    paper.gradient = core::PriscaParameters::Gradient::OneStep;
    paper.effortWeights.resize(0);
    paper.compensateLatency = false;
    paper.effectHorizon = 1;
    paper.prior = {};
    return std::make_unique<core::PriscaController>(profile.priscaProblem(demonstration),
                                                    profile.featuresOf(method), fit.b, paper,
                                                    QStringLiteral("prisca-paper"));
}

Made makePgsd(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::PgsdController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features, profile.mapping,
        profile.pgsd);
}

Made makePegasus(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    const Eigen::MatrixXd* theta = in.theta;
    // PEGASUS learns offline, episode by episode; online it is the same linear policy
    // around the demonstration, with theta frozen.
    core::PriscaParameters frozen = profile.prisca;
    frozen.learning = false;
    auto policy = std::make_unique<core::PriscaController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features,
        profile.mapping.asDouble(), frozen, QStringLiteral("pegasus"));
    if (theta) {
        policy->setInitialTheta(*theta);
    }
    return policy;
}

Made makeIlc(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::IlcController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.ilcParameters());
}

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
    const OracleParameters planner = plannerFor(profile, *demonstration);
    // The fallback: the PD with the least-state-deviation reference, the profile's law.
    std::unique_ptr<core::Controller> fallback =
        MethodCatalog::create(QStringLiteral("pd-lsd"), profile, demonstration, in.fittedB);
    std::vector<core::Demonstration> data{*demonstration};
    const IdentificationSettings settings = mpcIdentificationSettings(profile.mpc, false);
    PlantParameters model;
    double fit = -1.0;
    if (profile.mpcModel) {
        model = *profile.mpcModel;
        fit = modelPositionRms(data, model, settings);
    } else {
        const PlantParameters prior =
            profile.mpcPrior ? *profile.mpcPrior : defaultPlantParameters(profile.info.name);
        const IdentificationResult identified = identifyPlant(data, prior, settings);
        if (identified.ok()) {
            model = identified.parameters;
            fit = identified.positionRms;
        } else {
            // Nothing to plan through: the fallback flies every trial, and says why.
            model = identified.parameters;
            fit = std::numeric_limits<double>::quiet_NaN();
        }
    }
    return std::make_unique<MpcController>(profile.trackingProblem(demonstration, Mode::TimeDriven),
                                           profile.mpc, planner, std::move(fallback),
                                           std::move(model), fit, std::move(data));
}

Made makePlayback(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::ActionPlayback>(
        profile.trackingProblem(demonstration, Mode::TimeDriven));
}

// The PD family: a plain PD, with the H-step smoothing, with the least-state-deviation
// reference, or both; PD (selected) is the PD with gains its training chose.
Made makePdFamily(const MethodSpec& spec, const MethodInput& in) {
    const bool smoothed = spec.id == QLatin1String("pd-h") || spec.id == QLatin1String("pd-h-lsd");
    const bool lsd = spec.id == QLatin1String("pd-lsd") || spec.id == QLatin1String("pd-h-lsd");
    const bool demoStart = in.profile.start == MethodTuning::Start::Demonstration;
    // The law derived from the demonstration smooths over PRISCA's horizon H (no tuned pd.H),
    // its lag counted in the loop's delay.
    const int horizon = !smoothed ? 0 : demoStart ? in.profile.prisca.horizon : in.profile.pdHorizon;
    core::PdParameters gains = in.profile.startLaw(*in.demonstration, in.fittedB, horizon);
    auto pd = std::make_unique<core::PdController>(
        in.profile.trackingProblem(in.demonstration,
                                   lsd ? Mode::LeastStateDeviation : Mode::TimeDriven),
        gains, spec.id);
    if (in.profile.feedbackWhereExplained()) {
        pd->setFeedbackGate(explainedGate(in.profile, *in.demonstration));
    }
    pd->setErrorSchedule(reverseSchedule(in.profile, *in.demonstration));
    return pd;
}


// ---- The parameters methods are tuned by (MethodParameter): declared once, here. -------------

Eigen::VectorXd one(double v) {
    return Eigen::VectorXd::Constant(1, v);
}

using Kind = MethodParameter::Kind;

MethodParameter integer(const char* name, const char* label, const char* unit, double low,
                        double high, const char* help) {
    MethodParameter p;
    p.name = name;
    p.label = label;
    p.unit = unit;
    p.kind = Kind::Integer;
    p.minimum = low;
    p.maximum = high;
    p.decimals = 0;
    p.help = help;
    return p;
}

MethodParameter real(const char* name, const char* label, const char* unit, double low,
                     double high, int decimals, const char* help) {
    MethodParameter p = integer(name, label, unit, low, high, help);
    p.kind = Kind::Real;
    p.decimals = decimals;
    return p;
}

MethodParameter onOff(const char* name, const char* label, const char* help) {
    MethodParameter p = integer(name, label, "", 0, 1, help);
    p.kind = Kind::Switch;
    return p;
}

const MethodParameter& priscaHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "prisca.H", QT_TRANSLATE_NOOP("MethodParameter", "Horizon H"), "steps", 1, 1000,
            QT_TRANSLATE_NOOP("MethodParameter", "Smoothing horizon H of the nested expectation "
                                                 "over the last H steps (eq. 9, 13)."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.horizon); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.prisca.horizon = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaGamma() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.gamma", QT_TRANSLATE_NOOP("MethodParameter", "Depreciation γ"), "", 0, 1, 3,
            QT_TRANSLATE_NOOP("MethodParameter", "Rate of inverse depreciation D (eq. 10); Lemma "
                                                 "4.1 needs γ ≥ 0.93 at H = 10."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.gamma); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.prisca.gamma = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaBeta() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.beta", QT_TRANSLATE_NOOP("MethodParameter", "Step rate β"), "steps", 1, 1e7, 0,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Rate of the decaying step size α_k = α_0 β / (k + β) (eq. 3)."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.stepSize.beta); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.prisca.stepSize.beta = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaAutomatic() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.automatic", QT_TRANSLATE_NOOP("MethodParameter", "Automatic scales"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Feature scales, α_0 and matching window derived from the "
                              "demonstration and the fit when PRISCA starts; off: the step scale "
                              "and feature scales set here."));
        p.get = [](const MethodTuning& f) { return one(f.priscaAutomatic ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.priscaAutomatic = v[0] != 0.0; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaAutomaticStep() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.automatic-alpha0", QT_TRANSLATE_NOOP("MethodParameter", "Automatic α_0"), "",
            0, 1, 5,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "α_0 of the automatic scales: the fraction of a Newton step on the "
                              "cost's curvature taken per control step."));
        p.get = [](const MethodTuning& f) { return one(f.priscaAutomaticStep); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.priscaAutomaticStep = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaStepScale() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.alpha0", QT_TRANSLATE_NOOP("MethodParameter", "Step scale α_0"), "", 0, 1e4, 4,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "α_0 of eq. 3 (the paper uses 1; its right size depends on the "
                              "units of e, φ and B). Not used with automatic scales."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.stepSize.scale); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.prisca.stepSize.scale = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaThetaBound() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.theta-bound", QT_TRANSLATE_NOOP("MethodParameter", "θ bound"), "", 0, 1e4, 2,
            QT_TRANSLATE_NOOP("MethodParameter", "If above 0, θ is kept in |θ_i| ≤ bound after "
                                                 "each update (projected descent)."));
        p.zeroMeans = QT_TRANSLATE_NOOP("MethodParameter", "none");
        p.get = [](const MethodTuning& f) { return one(f.prisca.thetaBound); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.prisca.thetaBound = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaFromPd() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.from-pd", QT_TRANSLATE_NOOP("MethodParameter", "Start from the PD law"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The policy is u = u* + the PD law + θᵀφ, so θ = 0 already holds "
                              "the robot on the path; off: θ = 0 is no feedback (Algorithm 1)."));
        p.get = [](const MethodTuning& f) { return one(f.priscaFromPd ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.priscaFromPd = v[0] != 0.0; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaGradient() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.gradient", QT_TRANSLATE_NOOP("MethodParameter", "Gradient"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "one-step: eq. 14 as printed; closed-loop: eq. 4's chain rule "
                              "carried over the window through the fitted model and the "
                              "policy's own feedback."));
        p.kind = Kind::Choice;
        p.choices = {"one-step", "closed-loop"};
        p.get = [](const MethodTuning& f) {
            return one(f.prisca.gradient == core::PriscaParameters::Gradient::ClosedLoop ? 1 : 0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.prisca.gradient = v[0] != 0.0 ? core::PriscaParameters::Gradient::ClosedLoop
                                            : core::PriscaParameters::Gradient::OneStep;
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaEffort() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.effort", QT_TRANSLATE_NOOP("MethodParameter", "Effort weight R"), "", 0, 1e4, 3,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The cost also charges the correction's effort, R (θᵀφ)² per "
                              "control: what makes learning settle without a θ bound."));
        p.zeroMeans = QT_TRANSLATE_NOOP("MethodParameter", "none");
        p.get = [](const MethodTuning& f) {
            return one(f.prisca.effortWeights.size() ? f.prisca.effortWeights.maxCoeff() : 0.0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            if (v[0] > 0.0) {
                f.prisca.effortWeights = Eigen::VectorXd::Constant(f.info.actionDimension(), v[0]);
            } else {
                f.prisca.effortWeights.resize(0);
            }
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaBaseline() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.baseline", QT_TRANSLATE_NOOP("MethodParameter", "Local optimal baseline"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Subtract the local optimal baseline b (eq. 15) from the gradient; "
                              "off: b = 0."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.useBaseline ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.prisca.useBaseline = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaDepreciation() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.depreciation", QT_TRANSLATE_NOOP("MethodParameter", "Inverse depreciation"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Weigh the window's gradients by the inverse depreciation D "
                              "(eq. 10); off: D = 1."));
        p.get = [](const MethodTuning& f) {
            return one(f.prisca.useInverseDepreciation ? 1.0 : 0.0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.prisca.useInverseDepreciation = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaModel() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.model", QT_TRANSLATE_NOOP("MethodParameter", "Model"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "fitted: B = B_v (.) B~ from the fit (eq. 8); signs: B~ alone; "
                              "drift: eq. 5 in full, the state's own drift A fitted with B."));
        p.kind = Kind::Choice;
        p.choices = {"fitted", "signs", "drift"};
        p.get = [](const MethodTuning& f) { return one(static_cast<int>(f.priscaModel)); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.priscaModel = static_cast<MethodTuning::PriscaModel>(static_cast<int>(v[0]));
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaModelDelay() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "prisca.model-delay", QT_TRANSLATE_NOOP("MethodParameter", "Model delay d"), "steps",
            0, 50,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The measurement's age d in the closed-loop gradient's model."));
        p.get = [](const MethodTuning& f) { return one(f.prisca.modelDelay); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.prisca.modelDelay = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& priscaPhase() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "prisca.phase", QT_TRANSLATE_NOOP("MethodParameter", "Phase features"), "s", 0, 60, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Length of the stretches of the demonstration over which PRISCA "
                              "learns a correction of the demonstration's action (one feature "
                              "per stretch and control); 0: none."));
        p.get = [](const MethodTuning& f) { return one(f.priscaPhaseSeconds); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.priscaPhaseSeconds = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& priscaExplainedOnly() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "prisca.explained-only", QT_TRANSLATE_NOOP("MethodParameter", "Learn where explained"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The closed-loop gradient learns only on the samples a robust fit "
                              "explains."));
        p.get = [](const MethodTuning& f) {
            return one(f.priscaLearnWhereExplained ? 1.0 : 0.0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.priscaLearnWhereExplained = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

const MethodParameter& feedbackReverseAware() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "feedback.reverse", QT_TRANSLATE_NOOP("MethodParameter", "Heading feedback reversed"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "For a vehicle, the feedback law (the PD family's, PRISCA's prior) "
                              "turns the sign of its heading and yaw-rate terms where the "
                              "demonstration drives backwards, where steering turns the car the "
                              "other way; off: the same law in both directions."));
        p.get = [](const MethodTuning& f) { return one(f.feedbackReverseAware ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.feedbackReverseAware = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

const MethodParameter& feedbackExplainedOnly() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "feedback.explained-only", QT_TRANSLATE_NOOP("MethodParameter", "Feedback where explained"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The feedback law (the PD family's, PRISCA's prior) acts only while "
                              "the reference is a sample the robust fit explains: not in a slide, "
                              "where the linear model the gains stand on does not hold. auto: with "
                              "the demonstration start, not with the tuned one."));
        p.kind = Kind::Choice;
        p.choices = {"auto", "on", "off"};
        p.get = [](const MethodTuning& f) {
            return one(f.feedbackGate == MethodTuning::FeedbackGate::On    ? 1
                       : f.feedbackGate == MethodTuning::FeedbackGate::Off ? 2
                                                                           : 0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.feedbackGate = v[0] == 1.0   ? MethodTuning::FeedbackGate::On
                             : v[0] == 2.0 ? MethodTuning::FeedbackGate::Off
                                           : MethodTuning::FeedbackGate::Auto;
        };
        return p;
    }();
    return p;
}

const MethodParameter& start() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "start", QT_TRANSLATE_NOOP("MethodParameter", "Start"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The feedback law the PD family and PRISCA (its prior) start from. "
                              "tuned: the plant profile's PD gains; demo: derived from the "
                              "demonstration, the fit and the actuator limits alone (a "
                              "stationary LQR gain on the fitted model with weights from the "
                              "demonstration's own scales, no faster than the fitted dead time "
                              "allows, on the errors B~ names per control but those the action "
                              "sets); PRISCA then also takes its automatic step and scales."));
        p.kind = Kind::Choice;
        p.choices = {"tuned", "demo"};
        p.get = [](const MethodTuning& f) {
            return one(f.start == MethodTuning::Start::Demonstration ? 1 : 0);
        };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.start = v[0] != 0.0 ? MethodTuning::Start::Demonstration : MethodTuning::Start::Tuned;
        };
        return p;
    }();
    return p;
}

const MethodParameter& matchingWindow() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "matching.window", QT_TRANSLATE_NOOP("MethodParameter", "Matching window"), "samples",
            0, 1000000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "How far ahead the least-state-deviation reference may search "
                              "(eq. 12); 0 searches the whole demonstration."));
        p.get = [](const MethodTuning& f) { return one(f.matchingWindow); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.matchingWindow = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pdKp() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pd.kp", QT_TRANSLATE_NOOP("MethodParameter", "PD gain Kp"), "", 0, 1e4, 3,
            QT_TRANSLATE_NOOP("MethodParameter", "Proportional gain per control on its error "
                                                 "combination c_l · e (u = u* − Kp ε − Kd dε/dt)."));
        p.perChannel = true;
        p.get = [](const MethodTuning& f) -> Eigen::VectorXd { return f.pd.kp; };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pd.kp = v; };
        return p;
    }();
    return p;
}

const MethodParameter& pdKd() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pd.kd", QT_TRANSLATE_NOOP("MethodParameter", "PD gain Kd"), "s", 0, 1e4, 3,
            QT_TRANSLATE_NOOP("MethodParameter", "Derivative gain per control on the rate of "
                                                 "its error combination."));
        p.perChannel = true;
        p.get = [](const MethodTuning& f) -> Eigen::VectorXd { return f.pd.kd; };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pd.kd = v; };
        return p;
    }();
    return p;
}

const MethodParameter& pdHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pd.H", QT_TRANSLATE_NOOP("MethodParameter", "PD smoothing H"), "steps", 0, 1000,
            QT_TRANSLATE_NOOP("MethodParameter", "PD+H and PD+H+LSD smooth the error over this "
                                                 "many steps (the weights of eq. 9)."));
        p.get = [](const MethodTuning& f) { return one(f.pdHorizon); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pdHorizon = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pgsdHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pgsd.H", QT_TRANSLATE_NOOP("MethodParameter", "PGSD horizon H"), "steps", 1, 1000,
            QT_TRANSLATE_NOOP("MethodParameter", "PGSD's smoothing horizon H (eq. 9)."));
        p.get = [](const MethodTuning& f) { return one(f.pgsd.horizon); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pgsd.horizon = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pgsdStep() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pgsd.alpha", QT_TRANSLATE_NOOP("MethodParameter", "PGSD step α"), "", 0, 1e6, 5,
            QT_TRANSLATE_NOOP("MethodParameter", "The fixed step size of PGSD (no decay)."));
        p.get = [](const MethodTuning& f) { return one(f.pgsd.stepSize); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pgsd.stepSize = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& pgsdThetaBound() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pgsd.theta-bound", QT_TRANSLATE_NOOP("MethodParameter", "PGSD θ bound"), "", 0, 1e4,
            2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "If above 0, PGSD's θ is kept in |θ_i| ≤ bound after each update."));
        p.zeroMeans = QT_TRANSLATE_NOOP("MethodParameter", "none");
        p.get = [](const MethodTuning& f) { return one(f.pgsd.thetaBound); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pgsd.thetaBound = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusIterations() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pegasus.iterations", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS iterations"), "",
            0, 100000,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Gradient steps PEGASUS takes on its fixed scenarios before a run."));
        p.get = [](const MethodTuning& f) { return one(f.pegasusIterations); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pegasusIterations = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusScenarios() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "pegasus.scenarios", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS scenarios"), "", 1,
            1000,
            QT_TRANSLATE_NOOP("MethodParameter", "Fixed scenarios (start, perturbation, noise) "
                                                 "each evaluation averages."));
        p.get = [](const MethodTuning& f) { return one(f.pegasus.scenarios); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.pegasus.scenarios = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& pegasusStep() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "pegasus.alpha", QT_TRANSLATE_NOOP("MethodParameter", "PEGASUS step α"), "", 0, 1e9, 4,
            QT_TRANSLATE_NOOP("MethodParameter", "Gradient-descent step on the mean episode cost."));
        p.get = [](const MethodTuning& f) { return one(f.pegasus.stepSize); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.pegasus.stepSize = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcLearning() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "ilc.learning", QT_TRANSLATE_NOOP("MethodParameter", "ILC learning Γ/Kp"), "", 0, 100,
            3,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "ILC's learning gain per control, as a share of the PD's Kp: how "
                              "much of a trial's error goes into the next trial's feedforward."));
        p.get = [](const MethodTuning& f) { return one(f.ilcLearningScale); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcLearningScale = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcLead() {
    static const MethodParameter p = [] {
        MethodParameter p = integer(
            "ilc.lead", QT_TRANSLATE_NOOP("MethodParameter", "ILC lead"), "steps", 0, 200,
            QT_TRANSLATE_NOOP("MethodParameter", "The error this many steps later corrects the "
                                                 "action now (covers the plant's delay)."));
        p.get = [](const MethodTuning& f) { return one(f.ilcLead); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.ilcLead = static_cast<int>(v[0]);
        };
        return p;
    }();
    return p;
}

const MethodParameter& ilcCutoff() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "ilc.cutoff", QT_TRANSLATE_NOOP("MethodParameter", "ILC Q cutoff"), "Hz", 0, 20, 2,
            QT_TRANSLATE_NOOP("MethodParameter", "Zero-phase low-pass on the learned feedforward "
                                                 "after each trial; 0 leaves it unfiltered."));
        p.get = [](const MethodTuning& f) { return one(f.ilcCutoff); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcCutoff = v[0]; };
        return p;
    }();
    return p;
}

const MethodParameter& ilcFeedback() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "ilc.feedback", QT_TRANSLATE_NOOP("MethodParameter", "ILC feedback scale"), "", 0, 100,
            3,
            QT_TRANSLATE_NOOP("MethodParameter", "The PD gains in ILC's loop, scaled by this."));
        p.get = [](const MethodTuning& f) { return one(f.ilcFeedbackScale); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) { f.ilcFeedbackScale = v[0]; };
        return p;
    }();
    return p;
}

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
            "mpc.replan-every", QT_TRANSLATE_NOOP("MethodParameter", "Replanning"), "steps", 1,
            100,
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

const MethodParameter& mpcSpinGuard() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "mpc.spin-slip", QT_TRANSLATE_NOOP("MethodParameter", "Spin guard"), "deg", 0.0, 90.0,
            0,
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

// ---- lqr: a time-varying LQR on the model fitted from the demonstration ----------------------

// Its per-plant defaults, from grids on each plant's tuning cells only (docs/results.md, "LQR").
struct LqrDefaults {
    const char* plant;
    double throttleEffort, otherEffort;  // R of the first control, and of the others
    double terminal;
    bool drift;
};
constexpr LqrDefaults kLqrDefaults[] = {
    {"slidecar", 30.0, 100.0, 100.0, false},
    {"acrobot", 1e-6, 1e-6, 100.0, true},
    {"aircraft", 3.0, 3.0, 100.0, false},
    {"diffdrive", 1e-3, 1e-3, 100.0, false},
};
// Null for a plant with no entry: its parameters then have no value, which the catalog's tests
// catch for every catalog plant.
const LqrDefaults* lqrDefaults(const MethodTuning& f) {
    for (const LqrDefaults& d : kLqrDefaults) {
        if (f.info.name == QLatin1String(d.plant)) {
            return &d;
        }
    }
    return nullptr;
}

const MethodParameter& lqrEffort() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "lqr.effort", QT_TRANSLATE_NOOP("MethodParameter", "LQR effort weight R"),
            "1/action²", 1e-6, 1e6, 6,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "R per control in the LQR's cost e^T W e + (u − u*)^T R (u − u*): "
                              "larger is gentler."));
        p.perChannel = true;
        p.defaultFor = [](const MethodTuning& f) -> Eigen::VectorXd {
            const LqrDefaults* d = lqrDefaults(f);
            if (!d) {
                return Eigen::VectorXd();
            }
            Eigen::VectorXd r = Eigen::VectorXd::Constant(f.info.actionDimension(), d->otherEffort);
            r[0] = d->throttleEffort;
            return r;
        };
        return p;
    }();
    return p;
}

const MethodParameter& lqrTerminal() {
    static const MethodParameter p = [] {
        MethodParameter p = real(
            "lqr.terminal", QT_TRANSLATE_NOOP("MethodParameter", "LQR terminal weight"), "", 0.01,
            1e6, 2,
            QT_TRANSLATE_NOOP("MethodParameter",
                              "The deviation at the demonstration's end costs this many times a "
                              "step's (where a parking manoeuvre is judged)."));
        p.defaultFor = [](const MethodTuning& f) {
            const LqrDefaults* d = lqrDefaults(f);
            return d ? one(d->terminal) : Eigen::VectorXd();
        };
        return p;
    }();
    return p;
}

const MethodParameter& lqrDrift() {
    static const MethodParameter p = [] {
        MethodParameter p = onOff(
            "lqr.drift", QT_TRANSLATE_NOOP("MethodParameter", "LQR models the drift"),
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Fit eq. 5 in full (the state's own drift A with B); off: B alone, "
                              "each state driven only by the controls."));
        p.defaultFor = [](const MethodTuning& f) {
            const LqrDefaults* d = lqrDefaults(f);
            return d ? one(d->drift ? 1 : 0) : Eigen::VectorXd();
        };
        return p;
    }();
    return p;
}

Made makeLqr(const MethodSpec&, const MethodInput& in) {
    const MethodTuning& profile = in.profile;
    // eq. 5 (A with B, or B alone) fitted on the demonstration: the model a control engineer
    // would identify from the one recording there is.
    const core::Demonstration& demonstration = *in.demonstration;
    const int n = demonstration.stateDimension();
    core::LqrParameters parameters;
    if (profile.parameter(QStringLiteral("lqr.drift"))[0] != 0.0) {
        core::ActionMappingFitOptions options;
        options.drift = true;
        const core::ActionMappingFit fit = core::fitActionMapping(
            demonstration, profile.mapping, profile.info.deviationModel(), options);
        parameters.a = fit.a;
        parameters.b = fit.b;
    } else {
        parameters.a = Eigen::MatrixXd::Zero(n, n);
        parameters.b = in.fittedB;  // the task's own fit, as the Mapping panel shows it
    }
    parameters.effort = profile.parameter(QStringLiteral("lqr.effort"));
    parameters.terminalWeight = profile.parameter(QStringLiteral("lqr.terminal"))[0];
    // The trial goes on for the settle time past the demonstration: plan over it too.
    parameters.holdSteps = static_cast<int>(std::lround(profile.settleTime / demonstration.dt));
    return std::make_unique<core::LqrController>(
        profile.trackingProblem(in.demonstration, Mode::TimeDriven), parameters);
}

MethodSpec entry(const char* id, const char* label, MethodSpec::Create create) {
    MethodSpec s;
    s.id = QString::fromLatin1(id);
    s.label = QString::fromUtf8(label);
    s.create = create;
    return s;
}

std::vector<MethodSpec> makeCatalog() {
    std::vector<MethodSpec> all;
    // The order is Table I's and every list's.
    MethodSpec s = entry("prisca", "OURS (PRISCA)", &makePrisca);
    s.learnsOnline = true;
    s.ownFeatures = true;
    s.usesFeatures = true;
    s.summary = "the product's PRISCA: from the PD law, closed-loop gradient, automatic scales";
    s.parameters = {priscaHorizon(), priscaGamma(),   priscaBeta(),     priscaAutomatic(),
                    priscaAutomaticStep(), priscaStepScale(), priscaThetaBound(), priscaFromPd(), priscaGradient(),
                    priscaEffort(),  priscaBaseline(), priscaDepreciation(), priscaModel(),
                    priscaModelDelay(), priscaExplainedOnly(), priscaPhase(), matchingWindow(), start(), feedbackExplainedOnly(), feedbackReverseAware(),
                    pdKp(),          pdKd(),          pdHorizon()};
    all.push_back(s);
    s = entry("prisca-paper", "PRISCA (paper)", &makePriscaPaper);
    s.learnsOnline = true;
    s.ownFeatures = true;
    s.usesFeatures = true;
    s.summary = "Algorithm 1 exactly as printed";
    s.parameters = {priscaHorizon(), priscaGamma(), priscaBeta(), matchingWindow()};
    all.push_back(s);
    s = entry("pd", "PD", &makePdFamily);
    s.summary = "proportional-derivative feedback around the demonstration, time-driven";
    s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd()};
    all.push_back(s);
    s = entry("pd-selected", "PD (SELECTED)", &makePdFamily);
    s.training = MethodSpec::Training::SelectPdGains;
    s.inCurves = false;  // selects its gains offline, before any curve starts
    s.summary = "PD with gains grid-searched on the training trials";
    s.parameters = {pdKp(), pdKd()};
    all.push_back(s);
    s = entry("pd-h", "PD+H", &makePdFamily);
    s.summary = "PD on the error smoothed over H steps";
    s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd(), pdHorizon()};
    all.push_back(s);
    s = entry("pd-lsd", "PD+LSD", &makePdFamily);
    s.summary = "PD with the least-state-deviation reference";
    s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd(), matchingWindow()};
    all.push_back(s);
    s = entry("pd-h-lsd", "PD+H+LSD", &makePdFamily);
    s.summary = "PD with both";
    s.parameters = {start(), feedbackExplainedOnly(), feedbackReverseAware(), pdKp(), pdKd(), pdHorizon(), matchingWindow()};
    all.push_back(s);
    s = entry("lqr", "LQR", &makeLqr);
    s.summary = "time-varying LQR on the model fitted from the demonstration (eq. 5)";
    s.parameters = {lqrEffort(), lqrTerminal(), lqrDrift()};
    all.push_back(s);
    s = entry("playback", "ACTION PLAYBACK", &makePlayback);
    s.summary = "the demonstration's actions, open loop";
    s.parameters = {};
    all.push_back(s);
    s = entry("pgsd", "PGSD", &makePgsd);
    s.learnsOnline = true;
    s.usesFeatures = true;
    s.summary = "policy search by the signed derivative";
    s.parameters = {pgsdHorizon(), pgsdStep(), pgsdThetaBound()};
    all.push_back(s);
    s = entry("pegasus", "PEGASUS", &makePegasus);
    s.training = MethodSpec::Training::Pegasus;
    s.inTable1 = false;  // its offline search is the learning curves' subject
    s.usesFeatures = true;
    s.summary = "offline policy search on fixed scenarios";
    s.parameters = {pegasusIterations(), pegasusScenarios(), pegasusStep()};
    all.push_back(s);
    s = entry("ilc", "ILC", &makeIlc);
    s.learnsOnline = true;
    s.summary = "iterative learning control around the PD";
    s.parameters = {ilcLearning(), ilcLead(), ilcCutoff(), ilcFeedback(), pdKp(), pdKd()};
    all.push_back(s);
    s = entry("mpc", "MPC", &makeMpc);
    s.learnsOnline = true;  // the model is refit on each trial
    s.inDefaultTable1 = false;
    s.plansThroughModel = true;
    s.plants = QStringList{QStringLiteral("slidecar")};  // what identification knows
    s.summary = "model-predictive parking through the car identified from its demonstration";
    s.parameters = {mpcReplan(), mpcRollouts(), mpcTube(), mpcSpinGuard(), mpcRefit()};
    all.push_back(s);
    s = entry("oracle", "LIMIT (oracle)", &makeOracle);
    s.limit = true;
    s.simulationOnly = true;
    s.summary = "plans on copies of the simulated plant itself: the limit, simulation only";
    s.parameters = {oracleSamples(), oracleReplan()};
    all.push_back(s);
    return all;
}

}  // namespace

const std::vector<MethodSpec>& MethodCatalog::all() {
    static const std::vector<MethodSpec> catalog = makeCatalog();
    return catalog;
}

QStringList MethodCatalog::ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        ids << s.id;
    }
    return ids;
}

QStringList MethodCatalog::table1Ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inTable1) {
            ids << s.id;
        }
    }
    return ids;
}

QStringList MethodCatalog::defaultTable1Ids() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inTable1 && s.inDefaultTable1) {
            ids << s.id;
        }
    }
    return ids;
}

QStringList MethodCatalog::curveIds() {
    QStringList ids;
    for (const MethodSpec& s : all()) {
        if (s.inCurves) {
            ids << s.id;
        }
    }
    return ids;
}

const MethodSpec* MethodCatalog::find(const QString& id) {
    for (const MethodSpec& s : all()) {
        if (s.id == id) {
            return &s;
        }
    }
    return nullptr;
}

const MethodSpec& MethodCatalog::get(const QString& id) {
    if (const MethodSpec* s = find(id)) {
        return *s;
    }
    throw std::invalid_argument(QStringLiteral("unknown method '%1' (one of: %2)")
                                    .arg(id, ids().join(QLatin1Char(' ')))
                                    .toStdString());
}

std::unique_ptr<core::Controller> MethodCatalog::create(
    const QString& method, const MethodTuning& profile,
    std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
    const Eigen::MatrixXd* theta) {
    const MethodSpec& s = get(method);
    return s.create(s, MethodInput{profile, std::move(demonstration), fittedB, theta});
}

std::vector<const MethodParameter*> MethodCatalog::parameters() {
    std::vector<const MethodParameter*> found;
    for (const MethodSpec& spec : all()) {
        for (const MethodParameter& p : spec.parameters) {
            const bool known = std::any_of(found.begin(), found.end(), [&](const MethodParameter* q) {
                return QLatin1String(q->name) == QLatin1String(p.name);
            });
            if (!known) {
                found.push_back(&p);
            }
        }
    }
    return found;
}

const MethodParameter* MethodCatalog::parameter(const QString& name) {
    for (const MethodParameter* p : parameters()) {
        if (name == QLatin1String(p->name)) {
            return p;
        }
    }
    return nullptr;
}

void MethodCatalog::setParameter(MethodTuning& profile, const QString& assignment) {
    const int equals = assignment.indexOf(QLatin1Char('='));
    if (equals <= 0) {
        throw std::invalid_argument(
            QStringLiteral("'%1' is not NAME=VALUE").arg(assignment).toStdString());
    }
    const QString name = assignment.left(equals).trimmed();
    const MethodParameter* declared = parameter(name);
    if (!declared) {
        QStringList names;
        for (const MethodParameter* p : parameters()) {
            names << QString::fromLatin1(p->name);
        }
        throw std::invalid_argument(QStringLiteral("no method has a parameter '%1' (one of: %2)")
                                        .arg(name, names.join(QLatin1Char(' ')))
                                        .toStdString());
    }
    QString error;
    const auto value =
        declared->parse(assignment.mid(equals + 1), profile.info.actionDimension(), &error);
    if (!value) {
        throw std::invalid_argument(error.toStdString());
    }
    declared->assign(profile, *value);
}

}  // namespace prisca::sim
