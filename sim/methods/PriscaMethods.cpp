// PRISCA as the product runs it and as the paper prints it: their parameters and how each is made.
#include "sim/methods/Declarations.h"

#include <QCoreApplication>
#include "core/PriscaController.h"
#include "sim/tuning/MethodTuning.h"

namespace prisca::sim::methods {

namespace {

const MethodParameter& priscaHorizon() {
    static const MethodParameter p = [] {
        MethodParameter p =
            integer("prisca.H", QT_TRANSLATE_NOOP("MethodParameter", "Horizon H"), "steps", 1, 1000,
                    QT_TRANSLATE_NOOP("MethodParameter",
                                      "Smoothing horizon H of the nested expectation "
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
            QT_TRANSLATE_NOOP("MethodParameter",
                              "Rate of inverse depreciation D (eq. 10); Lemma "
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
            "prisca.automatic-alpha0", QT_TRANSLATE_NOOP("MethodParameter", "Automatic α_0"), "", 0,
            1, 5,
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
        MethodParameter p = real("prisca.theta-bound",
                                 QT_TRANSLATE_NOOP("MethodParameter", "θ bound"), "", 0, 1e4, 2,
                                 QT_TRANSLATE_NOOP("MethodParameter",
                                                   "If above 0, θ is kept in |θ_i| ≤ bound after "
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
        MethodParameter p =
            onOff("prisca.gradient", QT_TRANSLATE_NOOP("MethodParameter", "Gradient"),
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
            "prisca.model-delay", QT_TRANSLATE_NOOP("MethodParameter", "Model delay d"), "steps", 0,
            50,
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
        p.get = [](const MethodTuning& f) { return one(f.priscaLearnWhereExplained ? 1.0 : 0.0); };
        p.set = [](MethodTuning& f, const Eigen::VectorXd& v) {
            f.priscaLearnWhereExplained = v[0] != 0.0;
        };
        return p;
    }();
    return p;
}

Made makePrisca(const MethodSpec& spec, const MethodInput& in) {
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
    core::FeatureMap features = automatic
                                    ? profile.automaticFeatures(spec.ownFeatures, *demonstration)
                                    : profile.featuresFor(spec.ownFeatures);
    if (profile.priscaPhaseSeconds > 0.0) {
        features = features.withPhases(
            demonstration->length(),
            std::max(
                1, static_cast<int>(std::lround(profile.priscaPhaseSeconds / demonstration->dt))));
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
    paper.honourLoopLatency = false;
    paper.effectHorizon = 1;
    paper.prior = {};
    return std::make_unique<core::PriscaController>(profile.priscaProblem(demonstration),
                                                    profile.featuresFor(spec.ownFeatures), fit.b,
                                                    paper, QStringLiteral("prisca-paper"));
}

}  // namespace

/// The product's PRISCA.
MethodSpec priscaMethod() {
    MethodSpec s = entry("prisca", "OURS (PRISCA)", &makePrisca);
    s.learnsOnline = true;
    s.ownFeatures = true;
    s.usesFeatures = true;
    s.summary = "the product's PRISCA: from the PD law, closed-loop gradient, automatic scales";
    s.parameters = {priscaHorizon(),
                    priscaGamma(),
                    priscaBeta(),
                    priscaAutomatic(),
                    priscaAutomaticStep(),
                    priscaStepScale(),
                    priscaThetaBound(),
                    priscaFromPd(),
                    priscaGradient(),
                    priscaEffort(),
                    priscaBaseline(),
                    priscaDepreciation(),
                    priscaModel(),
                    priscaModelDelay(),
                    priscaExplainedOnly(),
                    priscaPhase(),
                    matchingWindow(),
                    start(),
                    feedbackExplainedOnly(),
                    feedbackReverseAware(),
                    pdKp(),
                    pdKd(),
                    pdHorizon()};
    return s;
}

/// Algorithm 1 exactly as printed.
MethodSpec priscaPaperMethod() {
    MethodSpec s = entry("prisca-paper", "PRISCA (paper)", &makePriscaPaper);
    s.learnsOnline = true;
    s.ownFeatures = true;
    s.usesFeatures = true;
    s.summary = "Algorithm 1 exactly as printed";
    s.parameters = {priscaHorizon(), priscaGamma(), priscaBeta(), matchingWindow()};
    return s;
}

}  // namespace prisca::sim::methods
