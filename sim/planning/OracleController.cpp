#include "sim/planning/OracleController.h"

#include "core/DeviationModel.h"
#include "sim/episodes/TrialMetrics.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace prisca::sim {

OracleController::OracleController(core::TrackingProblem problem, OracleParameters parameters)
    : problem_(core::TrackingProblem::validated(std::move(problem))), parameters_(parameters) {
    if (parameters_.replanEvery < 1 || parameters_.samples < 1 || parameters_.knotSpacing < 1 ||
        parameters_.maxKnots < 2 || parameters_.horizon < 1) {
        throw std::invalid_argument(
            "OracleController: replanEvery, samples, knotSpacing, horizon >= 1 and maxKnots >= 2 "
            "needed");
    }
    if (parameters_.objective == OracleParameters::Objective::FinalPose &&
        (parameters_.trialSteps < 1 || !problem_.deviation.pose)) {
        throw std::invalid_argument(
            "OracleController: the final-pose objective needs a planar vehicle and the trial's "
            "length");
    }
    const int m = problem_.demonstration->actionDimension();
    const int n = problem_.demonstration->stateDimension();
    if (parameters_.feedback.size() > 0 &&
        (parameters_.feedback.rows() != m || parameters_.feedback.cols() != n)) {
        throw std::invalid_argument("OracleController: the feedback gain must be m x n");
    }
    deviation_.setZero(n);
    halfRange_ = 0.5 * (problem_.limits.upper - problem_.limits.lower);
    record_.action.setZero(m);
    record_.referenceAction.setZero(m);
    record_.deviation.setZero(n);
    reset();
}

std::unique_ptr<core::Controller> OracleController::clone() const {
    return std::make_unique<OracleController>(*this);
}

void OracleController::reset(core::ResetMode) {
    // Nothing is learned across trials: every trial plans afresh with the same sampling.
    random_.seed(parameters_.seed);
    planKnots_.resize(0, 0);
    planTimes_.clear();
    spread_ = parameters_.spread * halfRange_;
    step_ = 0;
    simulatedSteps_ = 0;
}

Eigen::VectorXd OracleController::correctionAt(int t) const {
    const int m = static_cast<int>(halfRange_.size());
    if (planTimes_.empty() || t < planTimes_.front()) {
        return Eigen::VectorXd::Zero(m);
    }
    if (t >= planTimes_.back()) {
        return planKnots_.col(planKnots_.cols() - 1);
    }
    const auto upper = std::upper_bound(planTimes_.begin(), planTimes_.end(), t);
    const int j = static_cast<int>(upper - planTimes_.begin());
    const double w =
        static_cast<double>(t - planTimes_[j - 1]) / (planTimes_[j] - planTimes_[j - 1]);
    return (1.0 - w) * planKnots_.col(j - 1) + w * planKnots_.col(j);
}

Eigen::VectorXd OracleController::actionAt(int t, const Eigen::VectorXd& correction,
                                           const Eigen::VectorXd& state) {
    const core::Demonstration& demo = *problem_.demonstration;
    const int j = std::min(t, demo.length() - 1);
    Eigen::VectorXd u = demo.actions.row(j).transpose() + correction;
    if (j < parameters_.calmUntil) {
        for (Eigen::Index l = 0; l < u.size(); ++l) {
            const double most = parameters_.calmCorrection * halfRange_[l];
            u[l] = std::clamp(u[l], demo.actions(j, l) - most, demo.actions(j, l) + most);
        }
    }
    if (parameters_.feedback.size() > 0) {
        problem_.deviation.deviation(state, demo.states.row(j).transpose(), deviation_);
        u.noalias() += parameters_.feedback * deviation_;
    }
    problem_.limits.saturate(u);
    return u;
}

Eigen::MatrixXd OracleController::clampedToLimits(Eigen::MatrixXd knots,
                                                  const std::vector<int>& times) const {
    // Corrections that would push the action past its limits change nothing but the search.
    const core::Demonstration& demo = *problem_.demonstration;
    for (int j = 0; j < knots.cols(); ++j) {
        const int t = std::min(times[j], demo.length() - 1);
        for (int l = 0; l < knots.rows(); ++l) {
            const double u0 = demo.actions(t, l);
            const double most = parameters_.maxCorrection * halfRange_[l];
            knots(l, j) = std::clamp(knots(l, j), std::max(problem_.limits.lower[l] - u0, -most),
                                     std::min(problem_.limits.upper[l] - u0, most));
        }
    }
    return knots;
}

namespace {

// The correction at step t of knots at `times`: linear between knots, the last one after.
Eigen::VectorXd interpolated(const Eigen::MatrixXd& knots, const std::vector<int>& times, int t) {
    const int J = static_cast<int>(times.size());
    if (t >= times.back()) {
        return knots.col(J - 1);
    }
    const auto upper = std::upper_bound(times.begin(), times.end(), t);
    const int j = std::max(1, static_cast<int>(upper - times.begin()));
    const double w = static_cast<double>(t - times[j - 1]) / (times[j] - times[j - 1]);
    return (1.0 - w) * knots.col(j - 1) + w * knots.col(j);
}

}  // namespace

Eigen::Vector3d OracleController::finalPoseOf(Plant& copy, const Eigen::MatrixXd& knots,
                                              const std::vector<int>& times, int k,
                                              std::vector<double>* away) {
    const core::Demonstration& demo = *problem_.demonstration;
    const core::PlanarPoseIndices& at = *problem_.deviation.pose;
    int t = k;
    while (t < parameters_.trialSteps &&
           !(parameters_.restAfterStep >= 0 && t >= parameters_.restAfterStep && copy.atRest())) {
        const Eigen::VectorXd s =
            copy.step(actionAt(t, interpolated(knots, times, t), copy.state()));
        ++t;
        if (away) {
            const int j = std::min(t, demo.length() - 1);
            away->push_back(s[at.x] - demo.states(j, at.x));
            away->push_back(s[at.y] - demo.states(j, at.y));
        }
    }
    if (t >= parameters_.trialSteps && parameters_.runOutSteps > 0 && !copy.atRest()) {
        const Eigen::VectorXd neutral = Eigen::VectorXd::Zero(copy.info().actionDimension());
        for (int out = 0; out < parameters_.runOutSteps && !copy.atRest(); ++out) {
            copy.step(neutral);
            ++t;
        }
    }
    simulatedSteps_ += t - k;
    const Eigen::VectorXd s = copy.state();
    const Eigen::VectorXd lot = demo.states.row(demo.length() - 1).transpose();
    return Eigen::Vector3d(
        (s[at.x] - lot[at.x]) / parameters_.positionScale,
        (s[at.y] - lot[at.y]) / parameters_.positionScale,
        core::wrapAngle(s[at.heading] - lot[at.heading]) / parameters_.headingScale);
}

Eigen::VectorXd OracleController::rollout(const Eigen::MatrixXd& knots,
                                          const std::vector<int>& times, int k) {
    const core::Demonstration& demo = *problem_.demonstration;
    std::unique_ptr<Plant> copy = plant_->clone(false);
    const int J = static_cast<int>(times.size());
    auto correction = [&](int t) -> Eigen::VectorXd { return interpolated(knots, times, t); };
    const PlantInfo& info = copy->info();
    if (finalPoseNow_) {
        const bool tracked = parameters_.trackingScale > 0.0;
        const bool regularised = parameters_.correctionScale > 0.0;
        const int models = 1 + static_cast<int>(ensemble_.size());
        // A fixed length per planning (the steps to the trial's end at most), so that the
        // residuals of two candidates compare: steps not taken (the car rested) count as 0.
        const int trackedSteps = tracked ? 2 * std::max(1, parameters_.trialSteps - k) : 0;
        if (!regularised && !tracked && models == 1) {
            return finalPoseOf(*copy, knots, times, k, nullptr);
        }
        Eigen::VectorXd r =
            Eigen::VectorXd::Zero(models * (3 + trackedSteps) + (regularised ? knots.size() : 0));
        // Each model's share of the cost is its mean: the plan is good on all of them.
        const double share = 1.0 / std::sqrt(static_cast<double>(models));
        const double weight = tracked ? parameters_.positionScale / (parameters_.trackingScale *
                                                                     std::sqrt(0.5 * trackedSteps))
                                      : 0.0;
        int next = 0;
        std::vector<double> away;
        for (int i = 0; i < models; ++i) {
            if (i > 0) {
                copy = ensemble_[static_cast<size_t>(i - 1)]->clone(false);
            }
            away.clear();
            r.segment<3>(next) =
                share * finalPoseOf(*copy, knots, times, k, tracked ? &away : nullptr);
            next += 3;
            for (int j = 0; j < trackedSteps; ++j) {
                const double d =
                    j < static_cast<int>(away.size()) ? away[static_cast<size_t>(j)] : 0.0;
                r[next++] = share * weight * d / parameters_.positionScale;
            }
        }
        if (regularised) {
            for (int j = 0; j < J; ++j) {
                for (int l = 0; l < knots.rows(); ++l) {
                    r[next++] = knots(l, j) / (halfRange_[l] * parameters_.correctionScale);
                }
            }
        }
        return r;
    }
    // The metric the trial is scored by (time-aligned): position for vehicles, joint angles
    // otherwise, of the state after each step.
    const int perStep = info.pose ? 2 : static_cast<int>(info.angleIndices.size());
    Eigen::VectorXd residuals(perStep * parameters_.horizon);
    for (int i = 0; i < parameters_.horizon; ++i) {
        const int t = k + i;
        const Eigen::VectorXd s = copy->step(actionAt(t, correction(t), copy->state()));
        const Eigen::VectorXd reference =
            demo.states.row(std::min(t + 1, demo.length() - 1)).transpose();
        if (info.pose) {
            residuals[2 * i] = s[info.pose->x] - reference[info.pose->x];
            residuals[2 * i + 1] = s[info.pose->y] - reference[info.pose->y];
        } else {
            for (int c = 0; c < perStep; ++c) {
                const int a = info.angleIndices[c];
                residuals[perStep * i + c] = core::wrapAngle(s[a] - reference[a]);
            }
        }
    }
    simulatedSteps_ += parameters_.horizon;
    return residuals;
}

void OracleController::plan(int k) {
    const int m = static_cast<int>(halfRange_.size());
    finalPoseNow_ = parameters_.objective == OracleParameters::Objective::FinalPose &&
                    parameters_.trialSteps - k <= parameters_.finalPoseWindow;
    const int end =
        finalPoseNow_ ? std::max(parameters_.trialSteps, k + 1) : k + parameters_.horizon;
    const int remaining = end - k;
    const int spacing = std::max(parameters_.knotSpacing, (remaining + parameters_.maxKnots - 2) /
                                                              (parameters_.maxKnots - 1));
    std::vector<int> times;
    for (int t = k; t < end + spacing && static_cast<int>(times.size()) < parameters_.maxKnots;
         t += spacing) {
        times.push_back(t);
    }
    if (times.size() < 2) {
        times.push_back(k + spacing);
    }
    const int J = static_cast<int>(times.size());
    // Warm start: the current plan at the new knots.
    Eigen::MatrixXd mean(m, J);
    for (int j = 0; j < J; ++j) {
        mean.col(j) = correctionAt(times[j]);
    }
    Eigen::MatrixXd best = mean;
    Eigen::VectorXd bestResiduals = rollout(mean, times, k);
    double bestCost = bestResiduals.squaredNorm();
    bool improved = false;
    auto consider = [&](const Eigen::MatrixXd& candidate, bool sampled) {
        Eigen::VectorXd r = rollout(candidate, times, k);
        const double cost = r.squaredNorm();
        if (cost < bestCost) {
            bestCost = cost;
            best = candidate;
            bestResiduals = std::move(r);
            improved = improved || sampled;
        }
    };
    // The uncorrected plan is always a candidate, so a plan gone astray can be dropped.
    if (!mean.isZero()) {
        consider(Eigen::MatrixXd::Zero(m, J), false);
    }
    int budget = parameters_.samples - 1;
    if (parameters_.gaussNewton && budget > m * J) {
        // Jacobian of the residuals by forward differences, then Levenberg-Marquardt steps of
        // three dampings from the best plan so far.
        const Eigen::MatrixXd base = best;
        const Eigen::VectorXd r0 = bestResiduals;
        Eigen::MatrixXd jacobian(r0.size(), m * J);
        for (int j = 0; j < J; ++j) {
            for (int l = 0; l < m; ++l) {
                const double h = 0.01 * halfRange_[l];
                Eigen::MatrixXd probe = base;
                probe(l, j) += h;
                jacobian.col(j * m + l) = (rollout(probe, times, k) - r0) / h;
            }
        }
        budget -= m * J;
        const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
        const Eigen::VectorXd gradient = jacobian.transpose() * r0;
        const double scale = std::max(normal.diagonal().maxCoeff(), 1e-12);
        for (double damping : {1e-4, 1e-2, 1.0}) {
            if (budget <= 0) {
                break;
            }
            Eigen::MatrixXd system = normal;
            system.diagonal().array() += damping * scale;
            const Eigen::VectorXd delta = system.ldlt().solve(-gradient);
            if (delta.allFinite()) {
                consider(clampedToLimits(base + delta.reshaped(m, J), times), false);
            }
            --budget;
        }
    }
    std::normal_distribution<double> normal(0.0, 1.0);
    Eigen::MatrixXd candidate(m, J);
    for (int c = 0; c < budget; ++c) {
        const Eigen::MatrixXd centre = best;
        for (int j = 0; j < J; ++j) {
            for (int l = 0; l < m; ++l) {
                candidate(l, j) = centre(l, j) + spread_[l] * normal(random_);
            }
        }
        consider(clampedToLimits(candidate, times), true);
    }
    // Widen while samples find better plans, narrow when none does (a (1+lambda) search).
    const Eigen::VectorXd floor = parameters_.minimumSpread * halfRange_;
    const Eigen::VectorXd ceiling = parameters_.spread * halfRange_;
    spread_ = (improved ? 1.2 * spread_ : 0.7 * spread_).cwiseMax(floor).cwiseMin(ceiling);
    planKnots_ = best;
    planTimes_ = times;
}

const core::ControlStep& OracleController::step(const Eigen::Ref<const Eigen::VectorXd>&) {
    if (!plant_) {
        throw std::logic_error(
            "OracleController: no plant attached (the oracle runs only in "
            "simulation, through EpisodeStepper)");
    }
    const int k = step_;
    const core::Demonstration& demo = *problem_.demonstration;
    // The true state, not the sensor's: the oracle knows the plant.
    const Eigen::VectorXd state = plant_->state();
    if (k % parameters_.replanEvery == 0) {
        plan(k);
    }
    const int j = std::min(k, demo.length() - 1);
    problem_.deviation.deviation(state, demo.states.row(j).transpose(), record_.deviation);
    record_.cost = problem_.cost(record_.deviation);
    record_.referenceIndex = j;
    record_.referenceAction = demo.actions.row(j).transpose();
    record_.action = actionAt(k, correctionAt(k), state);
    record_.step = k;
    ++step_;
    return record_;
}

}  // namespace prisca::sim
