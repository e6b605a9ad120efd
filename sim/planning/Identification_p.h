#pragma once

// Identification's search, shared by its sources (Identification.cpp: the data checks, the
// passes, the result; IdentificationSearch.cpp: the multiple-shooting cost, the local searches,
// the dead times' profiles, one fit). Internal to sim/planning.

#include "core/Demonstration.h"
#include "sim/planning/Identification.h"
#include "sim/plants/PlantParameters.h"

#include <nlopt.h>
#include <Eigen/Dense>

#include <QStringList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <vector>

namespace prisca::sim::identification {

// What identification fits per plant, and the dead times it searches on the physics grid.
struct Plan {
    QStringList continuous;  // fitted as log-factors of the prior
    QStringList delays;      // searched on the grid of physics steps [s]
    // Continuous keys that show in the data only at discrete events (the instant an axle's
    // tyres break away), so that the cost is piecewise constant in them and one may make up
    // for another far away: the profile check scans each one's partners over their range.
    std::vector<QStringList> traded;
};

Plan planFor(const QString& plant);

inline double wrapAngle(double a) {
    return std::remainder(a, 2.0 * M_PI);
}

int indexOfKey(const std::vector<PlantParameterSpec>& specs, const QString& key);

// One multiple-shooting segment: restart at step `begin` of run `run`, replay `length` steps.
struct Segment {
    int run = 0;
    int begin = 0;
    int length = 0;
};

// The commands in flight before a segment: this many control steps of history (covers any dead
// time and the servo's travel).
inline constexpr int kHistorySteps = 12;

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
        partners_.resize(fitted_.size());
        for (const QStringList& group : plan.traded) {
            for (int i = 0; i < plan.continuous.size(); ++i) {
                for (int k = 0; k < plan.continuous.size(); ++k) {
                    if (i != k && group.contains(plan.continuous[i]) &&
                        group.contains(plan.continuous[k])) {
                        partners_[static_cast<size_t>(i)].push_back(k);
                    }
                }
            }
        }
        for (int r = 0; r < static_cast<int>(runs_.size()); ++r) {
            const core::Demonstration& run = runs_[static_cast<size_t>(r)];
            const int length =
                std::max(2, static_cast<int>(std::lround(settings_.segmentSeconds / run.dt)));
            // Overlapping by half: an event (the snap into the slide) near one segment's end
            // is in the middle of the next.
            const int stride = strideOf(length);
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
    // The fitted coordinates that trade with fitted coordinate i (Plan::traded).
    const std::vector<int>& partners(int i) const { return partners_[static_cast<size_t>(i)]; }
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
        const std::vector<Eigen::MatrixXd> predictions = predict(parameters);
        for (size_t i = 0; i < segments_.size(); ++i) {
            const Segment& s = segments_[i];
            const core::Demonstration& run = runs_[static_cast<size_t>(s.run)];
            const Eigen::MatrixXd& predicted = predictions[i];
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

    // Each segment's prediction by this model: length x n states after each step. Each segment
    // restarts at the recorded state with the hidden state (Plant::hiddenState: whether the
    // tyres slide) of this model's run through the segment before it, which it overlaps by
    // half; the recorded poses do not show it, and a restart that guessed it wrong (gripping
    // wheels where they spin at the launch) kept even the true car from fitting its data.
    std::vector<Eigen::MatrixXd> predict(const PlantParameters& parameters) const {
        std::vector<Eigen::MatrixXd> out;
        out.reserve(segments_.size());
        Carried carried;
        for (const Segment& s : segments_) {
            const core::Demonstration& run = runs_[static_cast<size_t>(s.run)];
            const bool follows = carried.run == s.run && carried.step == s.begin;
            Carried next{s.run, s.begin + strideOf(s.length), {}};
            out.push_back(simulate(run, parameters, s.begin, s.length, settings_.physicsSubsteps,
                                   follows ? &carried.hidden : nullptr, next.step, &next.hidden));
            carried = next;
        }
        return out;
    }

    double cost(const std::vector<double>& values) {
        const Eigen::VectorXd r = residuals(values);
        return r.size() == 0 ? std::numeric_limits<double>::max() / 4 : r.squaredNorm();
    }

    // The model restarted at step `begin` of the run with the commands before it in flight,
    // replaying `length` recorded commands: length x n predicted states (after each step).
    // With hiddenIn, the plant's hidden state at the restart; with hiddenOut, its hidden state
    // after the step that reaches recorded step `captureAt`.
    static Eigen::MatrixXd simulate(const core::Demonstration& run,
                                    const PlantParameters& parameters, int begin, int length,
                                    int substeps, const std::vector<double>* hiddenIn = nullptr,
                                    int captureAt = -1, std::vector<double>* hiddenOut = nullptr) {
        SimulationTiming timing;
        timing.controlPeriod = run.dt;
        timing.physicsSubsteps = substeps;
        std::unique_ptr<Plant> plant = makePlant(parameters, timing);
        plant->resetTo(run.states.row(begin).transpose());
        std::vector<Eigen::VectorXd> history;
        for (int k = begin - kHistorySteps; k < begin; ++k) {
            history.push_back(k < 0 ? Eigen::VectorXd::Zero(run.actionDimension())
                                    : Eigen::VectorXd(run.actions.row(k).transpose()));
        }
        plant->primeActuators(history);
        if (hiddenIn != nullptr) {
            plant->setHiddenState(*hiddenIn);
        }
        Eigen::MatrixXd out(length, run.stateDimension());
        for (int k = 0; k < length; ++k) {
            out.row(k) = plant->step(run.actions.row(begin + k).transpose()).transpose();
            if (hiddenOut != nullptr && begin + k + 1 == captureAt) {
                *hiddenOut = plant->hiddenState();
            }
        }
        return out;
    }

  private:
    // Segments overlap by half: the next one starts this many steps after one of this length.
    static int strideOf(int length) { return std::max(1, length / 2); }
    struct Carried {
        int run = -1;
        int step = -1;
        std::vector<double> hidden;
    };
    const std::vector<core::Demonstration>& runs_;
    PlantParameters prior_;
    IdentificationSettings settings_;
    const std::vector<PlantParameterSpec>& specs_;
    std::vector<int> fitted_;
    std::vector<int> delays_;
    std::vector<std::vector<int>> partners_;
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

double objective(unsigned n, const double* x, double* gradient, void* data);

// A local search from u (in place) over the fitted log-factors; returns the cost reached.
// Coordinate `held` stays where it is, or with heldFrom < heldTo within [heldFrom, heldTo].
double localSearch(SearchContext& context, std::vector<double>& u, int evaluations,
                   double initialStep, nlopt_algorithm algorithm = NLOPT_LN_SBPLX, int held = -1,
                   double heldFrom = 0.0, double heldTo = 0.0);

// Each dead time's profile: on the physics grid around its current value, the continuous
// parameters searched again (briefly) for each candidate; the best candidate is kept, the window
// following it if it lies at an edge (whether the data determined it is fitOnce's verdict,
// after a thorough re-search of both neighbours).
void profileDelays(Problem& problem, SearchContext& context, std::vector<double>& u,
                   double physicsStep, int evaluations);

// One fit of the plan's parameters from `start` (log-factors relative to it): the dead times,
// local searches and restarts; then each fitted parameter's relative standard deviation from
// the residuals' Jacobian. Returns false when cancelled.
struct FitOutcome {
    std::vector<double> values;
    std::vector<double> relativeStd;    // per continuous key of the plan
    std::vector<bool> delayDetermined;  // per dead time of the plan
    double variance = 0.0;
    double cost = 0.0;  // the cost at `values`
};

bool fitOnce(Problem& problem, SearchContext& context, const IdentificationSettings& settings,
             double physicsStep, int evaluations, FitOutcome* outcome);

}  // namespace prisca::sim::identification
