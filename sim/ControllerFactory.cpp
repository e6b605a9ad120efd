#include "ControllerFactory.h"

#include "OracleController.h"
#include "core/ActionPlayback.h"
#include "core/IlcController.h"
#include "core/PdController.h"
#include "core/PgsdController.h"
#include "core/PriscaController.h"

#include <stdexcept>

#include <optional>

namespace prisca::sim {

using Mode = core::MatchingParameters::Mode;

QStringList ControllerFactory::methods() {
    return {"prisca",   "prisca-paper", "pgsd",     "pegasus", "pd",    "pd-selected",
            "pd-h",     "pd-lsd",       "pd-h-lsd", "playback", "ilc",  "oracle"};
}

bool ControllerFactory::isMethod(const QString& method) {
    return methods().contains(method);
}

std::unique_ptr<core::Controller> ControllerFactory::create(
    const QString& method, const PlantProfile& profile,
    std::shared_ptr<const core::Demonstration> demonstration, const Eigen::MatrixXd& fittedB,
    const Eigen::MatrixXd* theta) {
    if (method == QLatin1String("prisca")) {
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
            prisca->setModelValidity(core::fitActionMapping(*demonstration, profile.mapping,
                                                            profile.info.deviationModel())
                                         .explained);
        }
        return prisca;
    }
    if (method == QLatin1String("prisca-paper")) {
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
        paper.compensateAge = false;
        paper.effectHorizon = 1;
        paper.prior = {};
        return std::make_unique<core::PriscaController>(profile.priscaProblem(demonstration),
                                                        profile.featuresOf(method), fit.b, paper,
                                                        QStringLiteral("prisca-paper"));
    }
    if (method == QLatin1String("pgsd")) {
        return std::make_unique<core::PgsdController>(
            profile.trackingProblem(demonstration, Mode::TimeDriven), profile.features,
            profile.mapping, profile.pgsd);
    }
    if (method == QLatin1String("pegasus")) {
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
    if (method == QLatin1String("ilc")) {
        return std::make_unique<core::IlcController>(
            profile.trackingProblem(demonstration, Mode::TimeDriven), profile.ilcParameters());
    }
    if (method == QLatin1String("oracle")) {
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
    if (method == QLatin1String("playback")) {
        return std::make_unique<core::ActionPlayback>(
            profile.trackingProblem(demonstration, Mode::TimeDriven));
    }
    const bool smoothed = method == QLatin1String("pd-h") || method == QLatin1String("pd-h-lsd");
    const bool lsd = method == QLatin1String("pd-lsd") || method == QLatin1String("pd-h-lsd");
    if (method == QLatin1String("pd") || method == QLatin1String("pd-selected") || smoothed ||
        lsd) {
        core::PdParameters gains = profile.pd;
        gains.horizon = smoothed ? profile.pdHorizon : 0;
        return std::make_unique<core::PdController>(
            profile.trackingProblem(demonstration,
                                    lsd ? Mode::LeastStateDeviation : Mode::TimeDriven),
            gains, method);
    }
    throw std::invalid_argument(QStringLiteral("unknown method '%1' (one of: %2)")
                                    .arg(method, methods().join(QLatin1Char(' ')))
                                    .toStdString());
}

}  // namespace prisca::sim
