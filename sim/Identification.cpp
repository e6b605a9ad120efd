#include "Identification.h"

#include "PlantCatalog.h"

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

namespace {

// What identification fits per plant, and the dead times it searches on the physics grid.
struct Plan {
    QStringList continuous;  // fitted as log-factors of the prior
    QStringList delays;      // searched on the grid of physics steps [s]
};

Plan planFor(const QString& plant) {
    if (plant == QLatin1String("slidecar")) {
        // The mass only scales the forces with it (every force here is a friction or a motor
        // force per mass), the geometry is measured with a ruler: held at the prior.
        return {{"maxDriveForce", "topSpeed", "staticFriction", "kineticFriction", "rearStaticGrip",
                 "rearKineticGrip", "yawInertia", "maxSteeringAngle", "servoRate", "drivelineDrag",
                 "rollingResistance"},
                {"servoDelay", "throttleDelay"}};
    }
    return {};
}

double wrapAngle(double a) {
    return std::remainder(a, 2.0 * M_PI);
}

int indexOfKey(const std::vector<PlantParameterSpec>& specs, const QString& key) {
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].key == key) {
            return static_cast<int>(i);
        }
    }
    throw std::logic_error("identification: undeclared key");
}

// One multiple-shooting segment: restart at step `begin` of run `run`, replay `length` steps.
struct Segment {
    int run = 0;
    int begin = 0;
    int length = 0;
};

// The commands in flight before a segment: this many control steps of history (covers any dead
// time and the servo's travel).
constexpr int kHistorySteps = 12;

class Problem {
  public:
    Problem(const std::vector<core::Demonstration>& runs, const PlantParameters& prior,
            const IdentificationSettings& settings, const Plan& plan)
        : runs_(runs),
          prior_(prior),
          settings_(settings),
          specs_(plantParameterSpecs(prior.plant)) {
        for (const QString& key : plan.continuous) {
            fitted_.push_back(indexOfKey(specs_, key));
        }
        for (const QString& key : plan.delays) {
            delays_.push_back(indexOfKey(specs_, key));
        }
        for (int r = 0; r < static_cast<int>(runs_.size()); ++r) {
            const core::Demonstration& run = runs_[static_cast<size_t>(r)];
            const int length =
                std::max(2, static_cast<int>(std::lround(settings_.segmentSeconds / run.dt)));
            // Overlapping by half: an event (the snap into the slide) near one segment's end
            // is in the middle of the next.
            const int stride = std::max(1, length / 2);
            for (int begin = 0; begin + length < run.length(); begin += stride) {
                // Segments with motion only: a car at rest says nothing of its parameters.
                double speed = 0.0;
                for (int k = begin; k <= begin + length; ++k) {
                    speed = std::max(speed, std::hypot(run.states(k, 3), run.states(k, 4)));
                }
                if (speed > 0.05) {
                    segments_.push_back({r, begin, length});
                }
            }
        }
        current_ = prior_.values;
    }

    const std::vector<Segment>& segments() const { return segments_; }
    const std::vector<int>& fitted() const { return fitted_; }
    const std::vector<int>& delays() const { return delays_; }
    const std::vector<PlantParameterSpec>& specs() const { return specs_; }
    std::vector<double>& current() { return current_; }
    double priorValue(int index) const { return prior_.values[static_cast<size_t>(index)]; }
    long long evaluations() const { return evaluations_; }

    // The values with these log-factors on the fitted parameters (the rest as current_).
    std::vector<double> valuesAt(const std::vector<double>& u) const {
        std::vector<double> v = current_;
        for (size_t i = 0; i < fitted_.size(); ++i) {
            const size_t j = static_cast<size_t>(fitted_[i]);
            v[j] = std::clamp(prior_.values[j] * std::exp(u[i]), specs_[j].lower, specs_[j].upper);
        }
        return v;
    }

    // Residuals of all segments (x, y / positionScale; heading / headingScale per step), or
    // empty when the values are not a valid plant.
    Eigen::VectorXd residuals(const std::vector<double>& values) {
        ++evaluations_;
        if (!plantParametersProblem(prior_.plant, values).isEmpty()) {
            return {};
        }
        PlantParameters parameters = prior_;
        parameters.values = values;
        int total = 0;
        for (const Segment& s : segments_) {
            total += 3 * s.length;
        }
        Eigen::VectorXd r(total);
        int at = 0;
        for (const Segment& s : segments_) {
            const core::Demonstration& run = runs_[static_cast<size_t>(s.run)];
            const Eigen::MatrixXd predicted =
                simulate(run, parameters, s.begin, s.length, settings_.physicsSubsteps);
            for (int k = 0; k < s.length; ++k) {
                const int recorded = s.begin + k + 1;
                r[at++] = (predicted(k, 0) - run.states(recorded, 0)) / settings_.positionScale;
                r[at++] = (predicted(k, 1) - run.states(recorded, 1)) / settings_.positionScale;
                r[at++] =
                    wrapAngle(predicted(k, 2) - run.states(recorded, 2)) / settings_.headingScale;
            }
        }
        return r;
    }

    double cost(const std::vector<double>& values) {
        const Eigen::VectorXd r = residuals(values);
        return r.size() == 0 ? std::numeric_limits<double>::max() / 4 : r.squaredNorm();
    }

    // The model restarted at step `begin` of the run with the commands before it in flight,
    // replaying `length` recorded commands: length x n predicted states (after each step).
    static Eigen::MatrixXd simulate(const core::Demonstration& run,
                                    const PlantParameters& parameters, int begin, int length,
                                    int substeps) {
        SimulationTiming timing;
        timing.controlPeriod = run.dt;
        timing.physicsSubsteps = substeps;
        std::unique_ptr<Plant> plant = PlantCatalog::create(parameters, timing);
        plant->resetTo(run.states.row(begin).transpose());
        std::vector<Eigen::VectorXd> history;
        for (int k = begin - kHistorySteps; k < begin; ++k) {
            history.push_back(k < 0 ? Eigen::VectorXd::Zero(run.actionDimension())
                                    : Eigen::VectorXd(run.actions.row(k).transpose()));
        }
        plant->primeActuators(history);
        Eigen::MatrixXd out(length, run.stateDimension());
        for (int k = 0; k < length; ++k) {
            out.row(k) = plant->step(run.actions.row(begin + k).transpose()).transpose();
        }
        return out;
    }

  private:
    const std::vector<core::Demonstration>& runs_;
    PlantParameters prior_;
    IdentificationSettings settings_;
    const std::vector<PlantParameterSpec>& specs_;
    std::vector<int> fitted_;
    std::vector<int> delays_;
    std::vector<Segment> segments_;
    std::vector<double> current_;
    long long evaluations_ = 0;
};

struct SearchContext {
    Problem* problem = nullptr;
    const IdentificationProgress* progress = nullptr;
    long long before = 0;  // model runs of the passes before this one (progress counts them all)
    long long budget = 0;
    bool cancelled = false;
    nlopt_opt search = nullptr;  // the search under way, stopped on a cancel
};

double objective(unsigned n, const double* x, double* gradient, void* data) {
    (void)gradient;  // derivative-free
    auto* context = static_cast<SearchContext*>(data);
    const std::vector<double> u(x, x + n);
    const double c = context->problem->cost(context->problem->valuesAt(u));
    if (!context->cancelled && context->progress && *context->progress &&
        context->problem->evaluations() % 20 == 0 &&
        !(*context->progress)(
            context->before + context->problem->evaluations(),
            std::max(context->budget, context->before + context->problem->evaluations()))) {
        context->cancelled = true;
    }
    if (context->cancelled && context->search) {
        nlopt_force_stop(context->search);
    }
    return c;
}

// A local search from u (in place) over the fitted log-factors; returns the cost reached.
double localSearch(SearchContext& context, std::vector<double>& u, int evaluations,
                   double initialStep, nlopt_algorithm algorithm = NLOPT_LN_SBPLX, int held = -1) {
    const unsigned n = static_cast<unsigned>(u.size());
    nlopt_opt opt = nlopt_create(algorithm, n);
    nlopt_srand(7);
    // At most a factor 3 from the prior, and never outside the declared range; a held
    // coordinate stays where it is (equal bounds).
    std::vector<double> lower(n, -std::log(3.0)), upper(n, std::log(3.0));
    std::vector<double> step(n, initialStep);
    for (unsigned i = 0; i < n; ++i) {
        u[i] = std::clamp(u[i], lower[i], upper[i]);
    }
    if (held >= 0) {
        lower[static_cast<size_t>(held)] = upper[static_cast<size_t>(held)] =
            u[static_cast<size_t>(held)];
        step[static_cast<size_t>(held)] = 0.0;
    }
    nlopt_set_lower_bounds(opt, lower.data());
    nlopt_set_upper_bounds(opt, upper.data());
    nlopt_set_min_objective(opt, objective, &context);
    nlopt_set_maxeval(opt, evaluations);
    nlopt_set_xtol_rel(opt, 1e-4);
    if (held < 0) {
        nlopt_set_ftol_rel(opt, 1e-7);
    }
    nlopt_set_initial_step(opt, step.data());
    double best = std::numeric_limits<double>::max();
    if (context.cancelled) {
        nlopt_destroy(opt);
        return best;
    }
    context.search = opt;
    nlopt_optimize(opt, u.data(), &best);  // a stop by evaluations or tolerance alike
    context.search = nullptr;
    nlopt_destroy(opt);
    return best;
}

// Each dead time's profile: on the physics grid around its current value, the continuous
// parameters searched again (briefly) for each candidate; the best candidate is kept, the window
// following it if it lies at an edge. gaps[d]: how much more the better neighbour of the chosen
// value costs (the profile's curvature there, for whether the data determined it).
void profileDelays(Problem& problem, SearchContext& context, std::vector<double>& u,
                   double physicsStep, int evaluations, std::vector<double>* gaps) {
    const int last = static_cast<int>(std::floor(0.1 / physicsStep + 1e-9));
    gaps->clear();
    for (const int jIndex : problem.delays()) {
        const size_t j = static_cast<size_t>(jIndex);
        std::map<int, std::pair<double, std::vector<double>>> profile;
        int centre = static_cast<int>(std::lround(problem.current()[j] / physicsStep));
        int best = centre;
        for (int round = 0; round < 6 && !context.cancelled; ++round) {
            for (int step = std::max(0, centre - 2); step <= std::min(last, centre + 2); ++step) {
                if (profile.count(step) != 0) {
                    continue;
                }
                problem.current()[j] = step * physicsStep;
                std::vector<double> from = u;
                const double reached = u.empty() ? problem.cost(problem.current())
                                                 : localSearch(context, from, evaluations, 0.03);
                profile[step] = {reached, from};
            }
            if (profile.empty() || context.cancelled) {
                return;
            }
            best = profile.begin()->first;
            for (const auto& [step, entry] : profile) {
                if (entry.first < profile[best].first) {
                    best = step;
                }
            }
            const bool atEdge =
                (best == centre - 2 && best > 0) || (best == centre + 2 && best < last);
            if (!atEdge) {
                break;
            }
            centre = best;
        }
        if (context.cancelled) {
            return;
        }
        problem.current()[j] = best * physicsStep;
        u = profile[best].second;
        double gap = std::numeric_limits<double>::infinity();
        for (const int neighbour : {best - 1, best + 1}) {
            if (profile.count(neighbour) != 0) {
                gap = std::min(gap, profile[neighbour].first - profile[best].first);
            }
        }
        gaps->push_back(gap);
    }
}

}  // namespace

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
        for (const QString& name : PlantCatalog::names()) {
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
    const std::unique_ptr<Plant> model = PlantCatalog::create(plant);
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

// One fit of the plan's parameters from `start` (log-factors relative to it): the dead times,
// local searches and restarts; then each fitted parameter's relative standard deviation from
// the residuals' Jacobian. Returns false when cancelled.
struct FitOutcome {
    std::vector<double> values;
    std::vector<double> relativeStd;    // per continuous key of the plan
    std::vector<bool> delayDetermined;  // per dead time of the plan
    double variance = 0.0;
};

bool fitOnce(Problem& problem, SearchContext& context, const IdentificationSettings& settings,
             double physicsStep, int evaluations, FitOutcome* outcome) {
    const int n = static_cast<int>(problem.fitted().size());
    std::vector<double> u(static_cast<size_t>(n), 0.0);
    double best = std::numeric_limits<double>::max();
    std::vector<double> gaps;
    if (n > 0) {
        // First over the whole box (a controlled random search: the cost is rugged where the
        // tyres snap), then locally.
        if (settings.global) {
            best = localSearch(context, u, 3 * evaluations, 0.2, NLOPT_GN_CRS2_LM);
        }
        best = localSearch(context, u, evaluations, settings.global ? 0.1 : 0.05);
    }
    if (context.cancelled) {
        return false;
    }
    problem.current() = problem.valuesAt(u);
    profileDelays(problem, context, u, physicsStep, evaluations / 8, &gaps);
    if (n > 0) {
        best = localSearch(context, u, evaluations, 0.05);
        std::mt19937_64 draw(settings.seed);
        std::normal_distribution<double> normal(0.0, 0.25);
        for (int restart = 0; restart < settings.restarts && !context.cancelled; ++restart) {
            std::vector<double> from = u;
            for (double& x : from) {
                x += normal(draw);
            }
            const double reached = localSearch(context, from, evaluations, 0.1);
            if (reached < best) {
                best = reached;
                u = from;
            }
        }
        problem.current() = problem.valuesAt(u);
        // The dead times once more on the model the restarts found, and a last polish.
        profileDelays(problem, context, u, physicsStep, evaluations / 8, &gaps);
        localSearch(context, u, evaluations, 0.02);
        problem.current() = problem.valuesAt(u);
    }
    if (context.cancelled) {
        return false;
    }
    const std::vector<double> values = problem.current();
    const Eigen::VectorXd r0 = problem.residuals(values);
    // A step of 5 %: stick-slip makes the residuals step-wise in the frictions at the physics
    // step's resolution, and a secant over a few steps sees their slope where a tangent is 0.
    const double h = 0.05;
    Eigen::MatrixXd jacobian(r0.size(), n);
    for (int i = 0; i < n; ++i) {
        const size_t j = static_cast<size_t>(problem.fitted()[static_cast<size_t>(i)]);
        std::vector<double> up = values;
        std::vector<double> down = values;
        up[j] = values[j] * std::exp(h);
        down[j] = values[j] * std::exp(-h);
        const Eigen::VectorXd rUp = problem.residuals(up);
        const Eigen::VectorXd rDown = problem.residuals(down);
        if (rUp.size() == r0.size() && rDown.size() == r0.size()) {
            jacobian.col(i) = (rUp - rDown) / (2.0 * h);
        } else {
            jacobian.col(i).setZero();  // at a relation's edge: no information claimed
        }
    }
    const double dof = std::max(1.0, static_cast<double>(r0.size() - n));
    const double noiseFloor = settings.poseNoise / settings.positionScale;
    outcome->variance = std::max(r0.squaredNorm() / dof, noiseFloor * noiseFloor);
    const Eigen::MatrixXd information = jacobian.transpose() * jacobian;
    const Eigen::MatrixXd covariance =
        outcome->variance * information.completeOrthogonalDecomposition().pseudoInverse();
    outcome->values = values;
    outcome->relativeStd.assign(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        outcome->relativeStd[static_cast<size_t>(i)] =
            information(i, i) > 0.0 ? std::sqrt(std::max(0.0, covariance(i, i)))
                                    : std::numeric_limits<double>::infinity();
    }
    // The Jacobian sees the cost's slope, not a wider valley where other parameters make up
    // for this one (the stick-slip tyres' frictions trade off with each other): each parameter
    // it calls determined is also moved by the threshold share either way, the others searched
    // again briefly; it stays determined only if both sides then cost at least four times the
    // variance more. A side that costs less is a better fit: it is taken, and the parameter
    // counts as undetermined in this pass.
    const double bestCost = r0.squaredNorm();
    const double shift = std::log(1.0 + settings.identifiedBelow);
    std::vector<double> uBest(static_cast<size_t>(n), 0.0);
    for (int i = 0; i < n; ++i) {
        uBest[static_cast<size_t>(i)] =
            std::log(values[static_cast<size_t>(problem.fitted()[static_cast<size_t>(i)])] /
                     problem.priorValue(problem.fitted()[static_cast<size_t>(i)]));
    }
    double lowest = bestCost;
    std::vector<double> better;
    for (int i = 0; i < n && !context.cancelled; ++i) {
        if (!(outcome->relativeStd[static_cast<size_t>(i)] < settings.identifiedBelow)) {
            continue;
        }
        for (const double side : {-shift, shift}) {
            std::vector<double> from = uBest;
            from[static_cast<size_t>(i)] += side;
            const double reached =
                localSearch(context, from, evaluations / 10, 0.03, NLOPT_LN_SBPLX, i);
            if (reached - bestCost <= 4.0 * outcome->variance) {
                outcome->relativeStd[static_cast<size_t>(i)] =
                    std::numeric_limits<double>::infinity();
            }
            if (reached < lowest) {
                lowest = reached;
                better = from;
            }
        }
    }
    if (context.cancelled) {
        return false;
    }
    if (!better.empty()) {
        outcome->values = problem.valuesAt(better);
    }

    // The dead times: determined when the profile's better neighbour costs at least four
    // times the residual's variance more (two standard deviations in chi-square).
    outcome->delayDetermined.clear();
    for (const double gap : gaps) {
        outcome->delayDetermined.push_back(gap > 4.0 * outcome->variance);
    }
    return true;
}

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
    // over the box, the local searches and restarts, each dead time's profile of about five
    // candidates twice), for the progress report.
    const auto fitRuns = [&](int evaluations, int delays) {
        return static_cast<long long>(evaluations) *
                   ((settings.global ? 3 : 0) + 3 + settings.restarts) +
               static_cast<long long>(delays) * 2 * 5 * (evaluations / 8);
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
    for (int pass = 0; pass < std::max(1, settings.passes); ++pass) {
        Problem problem(runs, start, settings, plan);
        context.problem = &problem;
        const int budget =
            pass == 0 ? settings.evaluationsPerStart : settings.evaluationsPerStart / 2;
        // This pass, and (while passes are left) one more on what it leaves undetermined.
        context.before = evaluations;
        context.budget =
            evaluations + fitRuns(budget, static_cast<int>(plan.delays.size())) +
            (pass + 1 < std::max(1, settings.passes)
                 ? fitRuns(settings.evaluationsPerStart / 2, static_cast<int>(plan.delays.size()))
                 : 0);
        FitOutcome outcome;
        const bool done = fitOnce(problem, context, settings, physicsStep, budget, &outcome);
        evaluations += problem.evaluations();
        if (!done) {
            result.cancelled = true;
            result.evaluations = evaluations;
            return result;
        }
        values = outcome.values;
        Plan kept;
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
    for (const Segment& s : first.segments()) {  // the same segments in every pass
        const core::Demonstration& run = runs[static_cast<size_t>(s.run)];
        const Eigen::MatrixXd predicted =
            Problem::simulate(run, result.parameters, s.begin, s.length, settings.physicsSubsteps);
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
