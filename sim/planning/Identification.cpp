#include "sim/planning/Identification.h"
#include "sim/planning/Identification_p.h"

#include "sim/plants/PlantParameters.h"

#include <nlopt.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <QMap>
#include <random>
#include <stdexcept>

namespace prisca::sim {

using namespace identification;

PlantParameters measuredPrior(const PlantParameters& car) {
    PlantParameters prior = defaultPlantParameters(car.plant);
    const Plan plan = planFor(car.plant);
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(car.plant);
    for (size_t j = 0; j < specs.size() && j < car.values.size(); ++j) {
        const bool fitted =
            plan.continuous.contains(specs[j].key) || plan.delays.contains(specs[j].key);
        if (!fitted && !specs[j].unmodelled) {
            prior.values[j] = car.values[j];
        }
    }
    if (!plantParametersProblem(prior.plant, prior.values).isEmpty()) {
        return defaultPlantParameters(car.plant);  // the measured keys alone break a relation
    }
    return prior;
}

bool identificationAvailable(const QString& plant) {
    return !planFor(plant).continuous.isEmpty();
}

QStringList identifiedKeys(const QString& plant) {
    const Plan plan = planFor(plant);
    return plan.continuous + plan.delays;
}

QString identificationDataProblem(const QString& plant,
                                  const std::vector<core::Demonstration>& runs,
                                  const IdentificationSettings& settings) {
    if (!identificationAvailable(plant)) {
        QStringList known;
        for (const QString& name : plantParameterPlants()) {
            if (identificationAvailable(name)) {
                known << name;
            }
        }
        return QStringLiteral("identification is not available for the %1 (only: %2)")
            .arg(plant, known.join(QStringLiteral(", ")));
    }
    if (runs.empty()) {
        return QStringLiteral("no recorded run to identify from");
    }
    const std::unique_ptr<Plant> model = makePlant(defaultPlantParameters(plant));
    const PlantInfo& info = model->info();
    double driving = 0.0;
    double sideways = 0.0;
    std::vector<double> lowest(static_cast<size_t>(info.actionDimension()),
                               std::numeric_limits<double>::max());
    std::vector<double> highest(static_cast<size_t>(info.actionDimension()),
                                std::numeric_limits<double>::lowest());
    for (size_t r = 0; r < runs.size(); ++r) {
        const core::Demonstration& run = runs[r];
        const QString name =
            run.metadata.value(QStringLiteral("source"), QStringLiteral("run %1").arg(r + 1));
        if (!run.plant.isEmpty() && run.plant != plant) {
            return QStringLiteral("%1 is a recording of the %2, not the %3")
                .arg(name, run.plant, plant);
        }
        if (run.stateDimension() != info.stateDimension() ||
            run.actionDimension() != info.actionDimension()) {
            return QStringLiteral("%1 has %2 state and %3 action columns; the %4 has %5 and %6")
                .arg(name)
                .arg(run.stateDimension())
                .arg(run.actionDimension())
                .arg(plant)
                .arg(info.stateDimension())
                .arg(info.actionDimension());
        }
        if (const QString problem = run.validate(); !problem.isEmpty()) {
            return QStringLiteral("%1: %2").arg(name, problem);
        }
        for (int k = 1; k < run.length(); ++k) {
            const double step = run.time[k] - run.time[k - 1];
            if (step > 1.5 * run.dt) {
                return QStringLiteral(
                           "%1 has a gap in the poses from t = %2 s to %3 s (%4 "
                           "samples missing): identification needs every step")
                    .arg(name)
                    .arg(run.time[k - 1], 0, 'f', 3)
                    .arg(run.time[k], 0, 'f', 3)
                    .arg(static_cast<int>(std::lround(step / run.dt)) - 1);
            }
        }
        for (int k = 0; k < run.length(); ++k) {
            const double speed = std::hypot(run.states(k, 3), run.states(k, 4));
            if (speed > 0.05 && k > 0) {
                driving += run.time[k] - run.time[k - 1];
            }
            sideways = std::max(sideways, std::abs(run.states(k, 4)));
            for (int c = 0; c < run.actionDimension(); ++c) {
                lowest[static_cast<size_t>(c)] =
                    std::min(lowest[static_cast<size_t>(c)], run.actions(k, c));
                highest[static_cast<size_t>(c)] =
                    std::max(highest[static_cast<size_t>(c)], run.actions(k, c));
            }
        }
    }
    const double needed = 2.0 * settings.segmentSeconds;
    if (driving < needed) {
        return QStringLiteral(
                   "too short: %1 s of driving, at least %2 s needed (two segments "
                   "of %3 s)")
            .arg(driving, 0, 'f', 2)
            .arg(needed, 0, 'f', 1)
            .arg(settings.segmentSeconds, 0, 'f', 1);
    }
    for (int c = 0; c < info.actionDimension(); ++c) {
        const double span = highest[static_cast<size_t>(c)] - lowest[static_cast<size_t>(c)];
        if (span < 0.05) {
            return QStringLiteral(
                       "constant %1: it stays within %2 to %3, and a command that "
                       "never changes cannot tell its effect from the rest")
                .arg(info.actionNames.value(c))
                .arg(lowest[static_cast<size_t>(c)], 0, 'g', 3)
                .arg(highest[static_cast<size_t>(c)], 0, 'g', 3);
        }
    }
    if (sideways < 0.3) {
        return QStringLiteral(
                   "no slide: the largest sideways speed is %1 m/s (at least 0.3 m/s "
                   "is needed to identify the grips)")
            .arg(sideways, 0, 'f', 2);
    }
    return {};
}

namespace {
IdentificationResult identifyModel(const std::vector<core::Demonstration>& runs,
                                   const PlantParameters& prior,
                                   const IdentificationSettings& settings,
                                   const IdentificationProgress& progress);
}  // namespace

IdentificationResult identifyPlant(const std::vector<core::Demonstration>& runs,
                                   const PlantParameters& prior,
                                   const IdentificationSettings& settings,
                                   const IdentificationProgress& progress) {
    IdentificationResult result;
    result.refusal = identificationDataProblem(prior.plant, runs, settings);
    // The model identified is the plant's model: the effects it leaves out are off in it,
    // whatever the prior file says of them.
    PlantParameters modelPrior = prior;
    const std::vector<PlantParameterSpec>& allSpecs = plantParameterSpecs(prior.plant);
    for (size_t j = 0; j < allSpecs.size() && j < modelPrior.values.size(); ++j) {
        if (allSpecs[j].unmodelled) {
            modelPrior.values[j] = allSpecs[j].value;
        }
    }
    result.parameters = modelPrior;
    if (!result.refusal.isEmpty()) {
        return result;
    }
    return identifyModel(runs, modelPrior, settings, progress);
}

namespace {

IdentificationResult identifyModel(const std::vector<core::Demonstration>& runs,
                                   const PlantParameters& prior,
                                   const IdentificationSettings& settings,
                                   const IdentificationProgress& progress) {
    IdentificationResult result;
    result.parameters = prior;
    const Plan fullPlan = planFor(prior.plant);
    Problem first(runs, prior, settings, fullPlan);
    if (first.segments().size() < 2) {
        result.refusal = QStringLiteral("too short: fewer than two segments of %1 s with motion")
                             .arg(settings.segmentSeconds, 0, 'f', 1);
        return result;
    }
    SearchContext context;
    context.progress = &progress;
    // About how many model runs a fit with this budget per search takes (fitOnce: the search
    // over the box and the one from the prior, the local searches and restarts, each dead
    // time's profile of about five candidates twice and its check on half the budget either
    // way, the profile check's half budget either way of each continuous parameter), for the
    // progress report.
    const auto fitRuns = [&](int evaluations, const Plan& fitted) {
        // The profile check's traded pairs: a 25 x 25 grid each, a re-search per side and key.
        long long pairs = 0;
        for (const QStringList& group : fitted.traded) {
            long long m = 0;
            for (const QString& key : group) {
                m += fitted.continuous.contains(key) ? 1 : 0;
            }
            pairs += m * (m - 1);
        }
        return static_cast<long long>(evaluations) *
                   ((settings.global ? 4 : 0) + 3 + settings.restarts +
                    static_cast<int>(fitted.continuous.size())) +
               static_cast<long long>(fitted.delays.size()) * 2 * 5 * (evaluations / 8) +
               static_cast<long long>(fitted.delays.size()) * evaluations + pairs * evaluations +
               pairs / 2 * 625;
    };
    const double physicsStep = runs.front().dt / settings.physicsSubsteps;
    {
        // The prior's own fit, to compare.
        const Eigen::VectorXd r = first.residuals(prior.values);
        double sum = 0.0;
        for (int i = 0; i + 2 < r.size(); i += 3) {
            sum += r[i] * r[i] + r[i + 1] * r[i + 1];
        }
        result.priorPositionRms =
            settings.positionScale * std::sqrt(sum / std::max<Eigen::Index>(1, r.size() / 3));
    }

    // Everything in the plan; then, while the data leave some undetermined, those back at their
    // prior and the rest fitted again (they may have been covering for each other). Each key's
    // last verdict: whether the data determined it, and its relative deviation.
    struct Verdict {
        bool identified = false;
        double relativeStd = std::numeric_limits<double>::infinity();
    };
    QMap<QString, Verdict> verdicts;
    Plan plan = fullPlan;
    PlantParameters start = prior;
    std::vector<double> values = prior.values;
    long long evaluations = 0;
    double previousCost = 0.0;
    int rejectedKeys = 0;
    std::vector<double> lastFitted = prior.values;
    for (int pass = 0; pass < std::max(1, settings.passes); ++pass) {
        Problem problem(runs, start, settings, plan);
        context.problem = &problem;
        const int budget =
            pass == 0 ? settings.evaluationsPerStart : settings.evaluationsPerStart / 2;
        // This pass, and (while passes are left) one more on what it leaves undetermined.
        context.before = evaluations;
        context.budget = evaluations + fitRuns(budget, plan) +
                         (pass + 1 < std::max(1, settings.passes)
                              ? fitRuns(settings.evaluationsPerStart / 2, plan)
                              : 0);
        FitOutcome outcome;
        const bool done = fitOnce(problem, context, settings, physicsStep, budget, &outcome);
        evaluations += problem.evaluations();
        if (!done) {
            result.cancelled = true;
            result.evaluations = evaluations;
            return result;
        }
        if (pass > 0 &&
            outcome.cost - previousCost > 4.0 * std::max(1, rejectedKeys) * outcome.variance) {
            // The data reject the prior of what the last pass left undetermined (it is determined
            // only together with others, as the two static grips): the last pass's values stay,
            // those parameters reported as not identified.
            values = lastFitted;
            break;
        }
        previousCost = outcome.cost;
        values = outcome.values;
        lastFitted = outcome.values;
        Plan kept;
        kept.traded = plan.traded;
        std::vector<double> next = outcome.values;
        for (int i = 0; i < plan.continuous.size(); ++i) {
            const QString& key = plan.continuous[i];
            const double relative = outcome.relativeStd[static_cast<size_t>(i)];
            verdicts[key] = {relative < settings.identifiedBelow, relative};
            if (verdicts[key].identified) {
                kept.continuous << key;
            } else {
                const size_t j = static_cast<size_t>(indexOfKey(problem.specs(), key));
                next[j] = prior.values[j];
            }
        }
        for (int i = 0; i < plan.delays.size(); ++i) {
            const QString& key = plan.delays[i];
            const bool determined = outcome.delayDetermined[static_cast<size_t>(i)];
            verdicts[key] = {determined,
                             determined ? 0.0 : std::numeric_limits<double>::infinity()};
            if (determined) {
                kept.delays << key;
            } else {
                const size_t j = static_cast<size_t>(indexOfKey(problem.specs(), key));
                next[j] = prior.values[j];
            }
        }
        if (kept.continuous.size() == plan.continuous.size() &&
            kept.delays.size() == plan.delays.size()) {
            break;
        }
        if (!plantParametersProblem(prior.plant, next).isEmpty()) {
            break;  // the prior's values do not fit with the rest: this pass's whole set stays
        }
        // The undetermined at their prior; out of passes, the rest as last fitted.
        rejectedKeys = static_cast<int>((plan.continuous.size() - kept.continuous.size()) +
                                        (plan.delays.size() - kept.delays.size()));
        values = next;
        plan = kept;
        start.values = next;
    }
    result.parameters.values = values;
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(prior.plant);
    for (size_t j = 0; j < specs.size(); ++j) {
        IdentifiedParameter p;
        p.key = specs[j].key;
        p.unit = specs[j].unit;
        p.prior = prior.values[j];
        p.value = values[j];
        p.fitted = fullPlan.continuous.contains(p.key) || fullPlan.delays.contains(p.key);
        if (p.fitted) {
            const Verdict verdict = verdicts.value(p.key);
            p.identified = verdict.identified;
            if (fullPlan.delays.contains(p.key)) {
                p.std = verdict.identified ? 0.5 * physicsStep
                                           : std::numeric_limits<double>::infinity();
            } else {
                p.std = verdict.relativeStd * p.value;
            }
        }
        result.table.push_back(p);
    }
    result.evaluations = evaluations;

    // The fit per segment, with the parameters as reported.
    double sumPosition = 0.0;
    double sumHeading = 0.0;
    int steps = 0;
    const std::vector<Eigen::MatrixXd> predictions = first.predict(result.parameters);
    for (size_t i = 0; i < first.segments().size(); ++i) {  // the same segments in every pass
        const Segment& s = first.segments()[i];
        const core::Demonstration& run = runs[static_cast<size_t>(s.run)];
        const Eigen::MatrixXd& predicted = predictions[i];
        double position = 0.0;
        double heading = 0.0;
        for (int k = 0; k < s.length; ++k) {
            const int recorded = s.begin + k + 1;
            position += std::pow(predicted(k, 0) - run.states(recorded, 0), 2) +
                        std::pow(predicted(k, 1) - run.states(recorded, 1), 2);
            heading += std::pow(wrapAngle(predicted(k, 2) - run.states(recorded, 2)), 2);
        }
        sumPosition += position;
        sumHeading += heading;
        steps += s.length;
        SegmentFit fit;
        fit.run = s.run;
        fit.start = run.time[s.begin] - run.time[0];
        fit.duration = s.length * run.dt;
        fit.positionRms = std::sqrt(position / s.length);
        fit.headingRms = std::sqrt(heading / s.length);
        result.segments.push_back(fit);
    }
    result.positionRms = std::sqrt(sumPosition / std::max(1, steps));
    result.headingRms = std::sqrt(sumHeading / std::max(1, steps));
    return result;
}

}  // namespace

double modelPositionRms(const std::vector<core::Demonstration>& runs,
                        const PlantParameters& parameters, const IdentificationSettings& settings) {
    Problem problem(runs, parameters, settings, Plan{});
    if (problem.segments().size() < 2) {
        return -1.0;
    }
    const Eigen::VectorXd r = problem.residuals(parameters.values);
    if (r.size() == 0) {
        return -1.0;
    }
    double sum = 0.0;
    for (int i = 0; i + 2 < r.size(); i += 3) {
        sum += r[i] * r[i] + r[i + 1] * r[i + 1];
    }
    return settings.positionScale * std::sqrt(sum / std::max<Eigen::Index>(1, r.size() / 3));
}

Eigen::MatrixXd replayRun(const core::Demonstration& run, const PlantParameters& parameters,
                          int physicsSubsteps) {
    Eigen::MatrixXd out(run.length(), run.stateDimension());
    if (run.length() == 0) {
        return out;
    }
    out.row(0) = run.states.row(0);
    if (run.length() > 1) {
        out.bottomRows(run.length() - 1) =
            Problem::simulate(run, parameters, 0, run.length() - 1, physicsSubsteps);
    }
    return out;
}

}  // namespace prisca::sim
