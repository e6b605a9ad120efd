// Identification's search: the multiple-shooting cost, NLopt's local searches, the dead times'
// profiles and one fit with its uncertainties.
#include "sim/planning/Identification.h"
#include "sim/planning/Identification_p.h"

#include "sim/plants/PlantParameters.h"

#include <nlopt.h>
#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <QMap>
#include <random>
#include <stdexcept>

namespace prisca::sim::identification {

Plan planFor(const QString& plant) {
    if (plant == QLatin1String("slidecar")) {
        // The mass only scales the forces with it (every force here is a friction or a motor
        // force per mass), the geometry is measured with a ruler: held at the prior.
        return {{"maxDriveForce", "topSpeed", "staticFriction", "kineticFriction", "rearStaticGrip",
                 "rearKineticGrip", "yawInertia", "maxSteeringAngle", "servoRate", "drivelineDrag",
                 "rollingResistance"},
                {"servoDelay", "throttleDelay"},
                // A static grip shows only when its axle breaks away: one grip lower and the
                // other higher can let go at the same physics steps (research-log.md, issue
                // 33's ninth step).
                {{"staticFriction", "rearStaticGrip"}}};
    }
    return {};
}

int indexOfKey(const std::vector<PlantParameterSpec>& specs, const QString& key) {
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].key == key) {
            return static_cast<int>(i);
        }
    }
    throw std::logic_error("identification: undeclared key");
}

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
                   double initialStep, nlopt_algorithm algorithm, int held, double heldFrom,
                   double heldTo) {
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
    if (held >= 0 && heldFrom < heldTo) {
        const size_t k = static_cast<size_t>(held);
        lower[k] = std::max(lower[k], heldFrom);
        upper[k] = std::min(upper[k], heldTo);
        u[k] = std::clamp(u[k], lower[k], upper[k]);
    } else if (held >= 0) {
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
    // The cost is in squared centimetres (and degrees) summed over every recorded step: a gain
    // below 0.001 moves the fit's RMS by far less than the camera's noise, and on noise-free
    // data, whose floor is 0, the relative tolerance alone kept the searches going to their
    // budget.
    nlopt_set_ftol_abs(opt, 1e-3);
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
// following it if it lies at an edge.
void profileDelays(Problem& problem, SearchContext& context, std::vector<double>& u,
                   double physicsStep, int evaluations) {
    const int last = static_cast<int>(std::floor(0.1 / physicsStep + 1e-9));
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
    }
}

// The cost over a grid spanning the whole range of fitted coordinates i and k (localSearch's
// bounds), the rest as in u: where a traded pair's other fits lie, past steps in the cost that a
// local search does not cross.
struct GridPoint {
    double ui = 0.0;
    double uk = 0.0;
    double cost = 0.0;
};

static std::vector<GridPoint> pairGrid(Problem& problem, const std::vector<double>& u, int i,
                                       int k) {
    constexpr int kPoints = 25;
    const double range = std::log(3.0);
    std::vector<GridPoint> grid;
    std::vector<double> at = u;
    for (int a = 0; a < kPoints; ++a) {
        for (int b = 0; b < kPoints; ++b) {
            at[static_cast<size_t>(i)] = -range + 2.0 * range * a / (kPoints - 1);
            at[static_cast<size_t>(k)] = -range + 2.0 * range * b / (kPoints - 1);
            grid.push_back({at[static_cast<size_t>(i)], at[static_cast<size_t>(k)],
                            problem.cost(problem.valuesAt(at))});
        }
    }
    return grid;
}

// Each dead time's verdict, after a thorough re-fit on either side: its neighbours on the physics
// grid with the continuous parameters searched again on `evaluations` each (the profile's brief
// re-searches stop on a step of the cost, and a neighbour that the rest can make up for looks
// worse than it is). A neighbour that fits better is moved to (three times at most). gaps[d]: how
// much more the better neighbour costs than the value kept (negative: a neighbour of the last
// move fitted better still).
static void checkDelays(Problem& problem, SearchContext& context, std::vector<double>& u,
                        double physicsStep, int evaluations, std::vector<double>* gaps) {
    const int last = static_cast<int>(std::floor(0.1 / physicsStep + 1e-9));
    gaps->clear();
    for (const int jIndex : problem.delays()) {
        const size_t j = static_cast<size_t>(jIndex);
        double gap = std::numeric_limits<double>::infinity();
        for (int round = 0; round < 3 && !context.cancelled; ++round) {
            const int at = static_cast<int>(std::lround(problem.current()[j] / physicsStep));
            const double here = problem.cost(problem.valuesAt(u));
            double neighbourCost = std::numeric_limits<double>::infinity();
            int neighbour = at;
            std::vector<double> neighbourU;
            for (const int step : {at - 1, at + 1}) {
                if (step < 0 || step > last) {
                    continue;
                }
                problem.current()[j] = step * physicsStep;
                std::vector<double> from = u;
                const double reached = u.empty() ? problem.cost(problem.current())
                                                 : localSearch(context, from, evaluations, 0.03);
                if (reached < neighbourCost) {
                    neighbourCost = reached;
                    neighbour = step;
                    neighbourU = from;
                }
            }
            gap = neighbourCost - here;
            if (gap >= 0.0) {
                problem.current()[j] = at * physicsStep;
                break;
            }
            problem.current()[j] = neighbour * physicsStep;
            u = neighbourU;
        }
        gaps->push_back(gap);
    }
    problem.current() = problem.valuesAt(u);
}

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
        if (settings.global && !context.cancelled) {
            // The prior itself as a start too: the box search may settle in a valley where
            // parameters trade (a slow servo for a small lock) far from a prior that was close.
            std::vector<double> fromPrior(static_cast<size_t>(n), 0.0);
            const double reached = localSearch(context, fromPrior, evaluations, 0.1);
            if (reached < best) {
                best = reached;
                u = fromPrior;
            }
        }
    }
    if (context.cancelled) {
        return false;
    }
    problem.current() = problem.valuesAt(u);
    profileDelays(problem, context, u, physicsStep, evaluations / 8);
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
        profileDelays(problem, context, u, physicsStep, evaluations / 8);
        localSearch(context, u, evaluations, 0.02);
        problem.current() = problem.valuesAt(u);
    }
    checkDelays(problem, context, u, physicsStep, evaluations / 2, &gaps);
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
    // A pass with every parameter held (each undetermined in the last) has nothing to invert.
    const Eigen::MatrixXd covariance =
        n > 0 ? Eigen::MatrixXd(outcome->variance *
                                information.completeOrthogonalDecomposition().pseudoInverse())
              : Eigen::MatrixXd(0, 0);
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
    std::map<std::pair<int, int>, std::vector<GridPoint>> grids;
    for (int i = 0; i < n && !context.cancelled; ++i) {
        if (!(outcome->relativeStd[static_cast<size_t>(i)] < settings.identifiedBelow)) {
            continue;
        }
        for (const double side : {-shift, shift}) {
            std::vector<double> from = uBest;
            from[static_cast<size_t>(i)] += side;
            double reached = localSearch(context, from, evaluations / 2, 0.03, NLOPT_LN_SBPLX, i);
            for (const int k : problem.partners(i)) {
                // A traded pair's other fits may lie anywhere on this side, not only 10 % away:
                // the grid's best point at least that far is searched from as well.
                const std::pair<int, int> pair = std::minmax(i, k);
                if (grids.count(pair) == 0) {
                    grids[pair] = pairGrid(problem, uBest, pair.first, pair.second);
                }
                const GridPoint* start = nullptr;
                for (const GridPoint& point : grids[pair]) {
                    const double ui = i == pair.first ? point.ui : point.uk;
                    if ((ui - uBest[static_cast<size_t>(i)]) * side >= side * side * (1 - 1e-9) &&
                        (start == nullptr || point.cost < start->cost)) {
                        start = &point;
                    }
                }
                if (start == nullptr || context.cancelled) {
                    continue;
                }
                std::vector<double> scanned = uBest;
                scanned[static_cast<size_t>(pair.first)] = start->ui;
                scanned[static_cast<size_t>(pair.second)] = start->uk;
                // The grid's value is one of many this side: free on it, 10 % away at least.
                const double edge = uBest[static_cast<size_t>(i)] + side;
                const double alternative =
                    localSearch(context, scanned, evaluations / 2, 0.03, NLOPT_LN_SBPLX, i,
                                side < 0.0 ? -std::numeric_limits<double>::infinity() : edge,
                                side < 0.0 ? edge : std::numeric_limits<double>::infinity());
                if (alternative < reached) {
                    reached = alternative;
                    from = scanned;
                }
            }
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
    outcome->cost = bestCost;
    if (!better.empty()) {
        outcome->values = problem.valuesAt(better);
        outcome->cost = lowest;
    }

    // The dead times: determined when the profile's better neighbour costs at least four
    // times the residual's variance more (two standard deviations in chi-square).
    outcome->delayDetermined.clear();
    for (const double gap : gaps) {
        outcome->delayDetermined.push_back(gap > 4.0 * outcome->variance);
    }
    return true;
}

}  // namespace prisca::sim::identification
