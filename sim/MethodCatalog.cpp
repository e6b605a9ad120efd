#include "MethodCatalog.h"

#include "OracleController.h"
#include "core/ActionPlayback.h"
#include "core/IlcController.h"
#include "core/PdController.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"

#include <optional>
#include <stdexcept>

namespace prisca::sim {

namespace {

using Mode = core::MatchingParameters::Mode;
using Made = std::unique_ptr<core::Controller>;

Made makePrisca(const MethodSpec& spec, const MethodInput& in) {
    const QString& method = spec.id;
    const PlantProfile& profile = in.profile;
    const auto& demonstration = in.demonstration;
    const Eigen::MatrixXd& fittedB = in.fittedB;
    core::PriscaParameters parameters = profile.prisca;
    if (profile.priscaFromPd) {
        parameters.prior = profile.pd;
        parameters.prior.horizon =
            profile.priscaPriorHorizon >= 0 ? profile.priscaPriorHorizon : profile.pdHorizon;
    }
    Eigen::MatrixXd model = fittedB;
    std::optional<Eigen::MatrixXd> drift;
    if (profile.priscaModel == PlantProfile::PriscaModel::Signs) {
        model = profile.mapping.asDouble();
    } else if (profile.priscaModel == PlantProfile::PriscaModel::FittedWithDrift) {
        // eq. 5 in full, fitted here on the demonstration: PRISCA's own model.
        core::ActionMappingFitOptions options;
        options.drift = true;
        const core::ActionMappingFit fit = core::fitActionMapping(
            *demonstration, profile.mapping, profile.info.deviationModel(), options);
        model = fit.b;
        drift = fit.a;
    }
    if (profile.priscaAutomatic) {
        parameters.stepSize.normalised = true;
        parameters.stepSize.scale = PlantProfile::automaticStep;
    }
    core::TrackingProblem problem = profile.priscaProblem(demonstration);
    if (profile.priscaAutomatic) {
        problem.matching.window = PlantProfile::automaticWindow(*demonstration);
    }
    auto prisca = std::make_unique<core::PriscaController>(
        std::move(problem),
        profile.priscaAutomatic ? profile.automaticFeatures(method, *demonstration)
                                : profile.featuresOf(method),
        model, parameters);
    if (drift) {
        prisca->setDrift(*drift);
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
    const PlantProfile& profile = in.profile;
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
    const PlantProfile& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::PgsdController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features, profile.mapping,
        profile.pgsd);
}

Made makePegasus(const MethodSpec&, const MethodInput& in) {
    const PlantProfile& profile = in.profile;
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
    const PlantProfile& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::IlcController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), profile.ilcParameters());
}

Made makeOracle(const MethodSpec&, const MethodInput& in) {
    const PlantProfile& profile = in.profile;
    const auto& demonstration = in.demonstration;
    OracleParameters parameters = profile.oracle;
    const EpisodeSettings trial = profile.episode(*demonstration, 1.0, 1.0);
    const double dt = demonstration->dt;
    parameters.trialSteps = static_cast<int>(trial.duration / dt + 0.5);
    parameters.restAfterStep =
        trial.stopAtRestAfter >= 0.0 ? static_cast<int>(trial.stopAtRestAfter / dt + 0.5) : -1;
    if (profile.oracleFeedback) {
        // The proportional part of the profile's PD (u = u* - Kp C e), planned through.
        parameters.feedback = -(profile.pd.kp.asDiagonal() * profile.pd.errorCombination);
    }
    return std::make_unique<OracleController>(
        profile.trackingProblem(demonstration, Mode::TimeDriven), parameters);
}

Made makePlayback(const MethodSpec&, const MethodInput& in) {
    const PlantProfile& profile = in.profile;
    const auto& demonstration = in.demonstration;
    return std::make_unique<core::ActionPlayback>(
        profile.trackingProblem(demonstration, Mode::TimeDriven));
}

// The PD family: a plain PD, with the H-step smoothing, with the least-state-deviation
// reference, or both; PD (selected) is the PD with gains its training chose.
Made makePdFamily(const MethodSpec& spec, const MethodInput& in) {
    const bool smoothed = spec.id == QLatin1String("pd-h") || spec.id == QLatin1String("pd-h-lsd");
    const bool lsd = spec.id == QLatin1String("pd-lsd") || spec.id == QLatin1String("pd-h-lsd");
    core::PdParameters gains = in.profile.pd;
    gains.horizon = smoothed ? in.profile.pdHorizon : 0;
    return std::make_unique<core::PdController>(
        in.profile.trackingProblem(in.demonstration,
                                   lsd ? Mode::LeastStateDeviation : Mode::TimeDriven),
        gains, spec.id);
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
    s.summary = "the product's PRISCA: from the PD law, closed-loop gradient, automatic scales";
    all.push_back(s);
    s = entry("prisca-paper", "PRISCA (paper)", &makePriscaPaper);
    s.learnsOnline = true;
    s.ownFeatures = true;
    s.summary = "Algorithm 1 exactly as printed";
    all.push_back(s);
    s = entry("pd", "PD", &makePdFamily);
    s.summary = "proportional-derivative feedback around the demonstration, time-driven";
    all.push_back(s);
    s = entry("pd-selected", "PD (SELECTED)", &makePdFamily);
    s.training = MethodSpec::Training::SelectPdGains;
    s.inCurves = false;  // selects its gains offline, before any curve starts
    s.summary = "PD with gains grid-searched on the training trials";
    all.push_back(s);
    s = entry("pd-h", "PD+H", &makePdFamily);
    s.summary = "PD on the error smoothed over H steps";
    all.push_back(s);
    s = entry("pd-lsd", "PD+LSD", &makePdFamily);
    s.summary = "PD with the least-state-deviation reference";
    all.push_back(s);
    s = entry("pd-h-lsd", "PD+H+LSD", &makePdFamily);
    s.summary = "PD with both";
    all.push_back(s);
    s = entry("playback", "ACTION PLAYBACK", &makePlayback);
    s.summary = "the demonstration's actions, open loop";
    all.push_back(s);
    s = entry("pgsd", "PGSD", &makePgsd);
    s.learnsOnline = true;
    s.summary = "policy search by the signed derivative";
    all.push_back(s);
    s = entry("pegasus", "PEGASUS", &makePegasus);
    s.training = MethodSpec::Training::Pegasus;
    s.inTable1 = false;  // its offline search is the learning curves' subject
    s.summary = "offline policy search on fixed scenarios";
    all.push_back(s);
    s = entry("ilc", "ILC", &makeIlc);
    s.learnsOnline = true;
    s.summary = "iterative learning control around the PD";
    all.push_back(s);
    s = entry("oracle", "LIMIT (oracle)", &makeOracle);
    s.limit = true;
    s.simulationOnly = true;
    s.summary = "plans on copies of the simulated plant itself: the limit, simulation only";
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
    const QString& method, const PlantProfile& profile,
    std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
    const Eigen::MatrixXd* theta) {
    const MethodSpec& s = get(method);
    return s.create(s, MethodInput{profile, std::move(demonstration), fittedB, theta});
}

}  // namespace prisca::sim
