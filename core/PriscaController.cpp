#include "PriscaController.h"

#include "NestedExpectation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::core {

PriscaController::PriscaController(TrackingProblem problem, FeatureMap features,
                                   Eigen::MatrixXd actionMapping, PriscaParameters parameters,
                                   QString name)
    : problem_(TrackingProblem::validated(std::move(problem))),
      featureMap_(std::move(features)),
      parameters_(parameters),
      name_(std::move(name)),
      matcher_(problem_.demonstration->states, problem_.matching),
      baseline_(std::max(featureMap_.featureCount(), 1), std::max(featureMap_.channelCount(), 1),
                parameters.baselineWindow > 0 ? parameters.baselineWindow
                                              : 2 * std::max(parameters.horizon, 1),
                parameters.baselineMode),
      depreciation_(std::max(parameters.horizon, 1), parameters.gamma,
                    parameters.depreciationMode) {
    const Demonstration& demo = *problem_.demonstration;
    const int n = demo.stateDimension();
    const int m = demo.actionDimension();
    const int p = featureMap_.featureCount();
    const int H = parameters_.horizon;
    if (featureMap_.channelCount() != m) {
        throw std::invalid_argument(
            "PriscaController: the feature map must have one entry per control");
    }
    const QString featureProblem = featureMap_.validate(n);
    if (!featureProblem.isEmpty()) {
        throw std::invalid_argument(featureProblem.toStdString());
    }
    if (actionMapping.rows() != m || actionMapping.cols() != n) {
        throw std::invalid_argument("PriscaController: the action mapping B must be m x n");
    }
    if (H < 1) {
        throw std::invalid_argument("PriscaController: the horizon H must be >= 1");
    }
    if (parameters_.effectHorizon < 1) {
        throw std::invalid_argument("PriscaController: the effect horizon N must be >= 1");
    }
    if (parameters_.modelDelay < 0) {
        throw std::invalid_argument("PriscaController: the model delay must be >= 0");
    }
    referenceStates_ = demo.states.transpose();
    referenceActions_ = demo.actions.transpose();
    stateEffect_ = demo.dt * actionMapping;
    transition_ = Eigen::MatrixXd::Identity(n, n);
    const int ring = H + 1 + parameters_.modelDelay;
    errorHistory_.setZero(n, ring);
    referenceHistory_.assign(ring, 0);
    stepTransition_.setZero(n, n);
    if (parameters_.prior.kp.size() != 0) {
        prior_ = PdFeedback(parameters_.prior, n, m, demo.dt);
    }
    effectTerm_.setZero(n, m);
    effectSum_.setZero(n, m);
    effectNext_.setZero(n, m);
    featureHistory_.setZero(p * m, ring);
    sensitivity_.assign(H + 1, Eigen::MatrixXd::Zero(n, p * m));
    feedbackGain_.setZero(m, n);
    drive_.setZero(n, p * m);
    sample_.setZero(p * m);
    actionSensitivity_.setZero(m, p * m);
    effort_.setZero(m);
    if (parameters_.effortWeights.size() != 0 &&
        (parameters_.effortWeights.size() != m ||
         (parameters_.effortWeights.array() < 0.0).any())) {
        throw std::invalid_argument("PriscaController: effort weights must be m values >= 0");
    }
    for (int c = 1; c <= H + 1; ++c) {
        windowWeights_.push_back(nestedExpectationWeights(c));
    }
    theta_.setZero(p, m);
    feedbackMask_.setZero(p, m);
    for (int l = 0; l < m; ++l) {
        for (int i = 0; i < p; ++i) {
            const bool phase = featureMap_.terms()[l][i].source == FeatureTerm::Source::Phase;
            feedbackMask_(i, l) = phase ? 0.0 : 1.0;
            hasPhases_ = hasPhases_ || phase;
        }
    }
    moved_.setZero(1, p * m);
    previousTheta_.setZero(p, m);
    initialTheta_.setZero(p, m);
    phi_.setZero(p, m);
    gradient_.setZero(p, m);
    smoothedA_.setZero(p, m);
    smoothedG_.setZero(p, m);
    historyA_.setZero(p * m, H + 1);
    weightedError_.setZero(n);
    projected_.setZero(m);
    depreciationOfWindow_.resize(H + 1);
    record_.action.setZero(m);
    record_.referenceAction.setZero(m);
    record_.deviation.setZero(n);
}

std::unique_ptr<Controller> PriscaController::clone() const {
    return std::make_unique<PriscaController>(*this);
}

void PriscaController::setTheta(const Eigen::MatrixXd& theta) {
    if (theta.rows() != theta_.rows() || theta.cols() != theta_.cols()) {
        throw std::invalid_argument("PriscaController::setTheta: theta must be p x m");
    }
    theta_ = theta;
}

void PriscaController::setModelValidity(std::vector<bool> valid) {
    if (!valid.empty() && static_cast<int>(valid.size()) != problem_.demonstration->length()) {
        throw std::invalid_argument(
            "PriscaController::setModelValidity: one flag per demonstration sample");
    }
    modelValid_ = std::move(valid);
}

void PriscaController::setLoopLatencySteps(int steps) {
    loopLatencySteps_ = parameters_.honourLoopLatency ? std::max(0, steps) : 0;
    matcher_.setLoopLatencySteps(loopLatencySteps_);
}

void PriscaController::setDrift(const Eigen::MatrixXd& a) {
    const Eigen::Index n = transition_.rows();
    if (a.rows() != n || a.cols() != n || !a.allFinite()) {
        throw std::invalid_argument("PriscaController::setDrift: A must be a finite n x n matrix");
    }
    transition_ = Eigen::MatrixXd::Identity(n, n) + problem_.demonstration->dt * a;
}

void PriscaController::transitionAt(int j) {
    problem_.deviation.kinematics(referenceStates_.col(j), stepTransition_);
    stepTransition_ *= problem_.demonstration->dt;
    stepTransition_ += transition_;
}

void PriscaController::closedLoopTerms(int k, int count) {
    // K = d(theta^T phi)/de: every deviation (or state) feature term adds theta * scale.
    const int m = static_cast<int>(theta_.cols());
    const int p = static_cast<int>(theta_.rows());
    const int ring = static_cast<int>(errorHistory_.cols());
    const int d = parameters_.modelDelay;
    feedbackGain_.setZero();
    for (int l = 0; l < m; ++l) {
        const auto& terms = featureMap_.terms()[l];
        for (int i = 0; i < p; ++i) {
            if (terms[i].isFeedback()) {
                feedbackGain_(l, terms[i].index) += theta_(i, l) * terms[i].scale;
            }
        }
    }
    if (parameters_.prior.kp.size() != 0) {
        // The prior's proportional part closes the loop too (its smoothing and rate left out).
        feedbackGain_.noalias() -=
            parameters_.prior.kp.asDiagonal() * parameters_.prior.errorCombination;
    }
    // S over the window, from 0 at its first sample: what theta changed in the errors since.
    const int first = k - count + 1;
    sensitivity_[0].setZero();
    for (int t = first; t < k; ++t) {
        const int age = t - d;  // the sample the action at t was computed from
        drive_.setZero();
        if (age >= 0 && age > k - ring) {
            const int slot = age % ring;
            for (int l = 0; l < m; ++l) {
                drive_.middleCols(l * p, p).noalias() =
                    stateEffect_.row(l).transpose() *
                    featureHistory_.col(slot).segment(l * p, p).transpose();
            }
        }
        if (age >= first) {
            drive_.noalias() +=
                stateEffect_.transpose() * (feedbackGain_ * sensitivity_[age - first]);
        }
        transitionAt(referenceHistory_[t % ring]);
        sensitivity_[t + 1 - first].noalias() = stepTransition_ * sensitivity_[t - first];
        sensitivity_[t + 1 - first] += drive_;
        if (!modelValid_.empty() && !modelValid_[referenceHistory_[(t + 1) % ring]]) {
            sensitivity_[t + 1 - first].setZero();  // the model does not hold there: start afresh
        }
    }
    // a_t = 2 S_t^T W e_t (+ the effort's 2 (du_t/dtheta)^T R (u_t - u*_t)), stored where the
    // one-step form keeps its a_t.
    const bool effort = parameters_.effortWeights.size() != 0;
    for (int t = first; t <= k; ++t) {
        const int slot = t % ring;
        weightedError_ = problem_.costWeights.cwiseProduct(errorHistory_.col(slot));
        if (!modelValid_.empty() && !modelValid_[referenceHistory_[slot]]) {
            weightedError_.setZero();  // no lesson from where the model does not hold
        }
        sample_.noalias() = 2.0 * sensitivity_[t - first].transpose() * weightedError_;
        if (effort) {
            // u_l - u*_l = theta_l^T phi_l(e_t): its change with theta is phi_l in block l,
            // plus K S_t through the errors theta moved.
            actionSensitivity_.noalias() = feedbackGain_ * sensitivity_[t - first];
            // The effort charged is the feedback's: a phase feature's correction of u* is the
            // demonstration's action made right for this car, not effort.
            for (int l = 0; l < m; ++l) {
                const auto phi = featureHistory_.col(slot).segment(l * p, p);
                const auto mask = feedbackMask_.col(l);
                actionSensitivity_.row(l).segment(l * p, p) += phi.cwiseProduct(mask).transpose();
                effort_[l] =
                    parameters_.effortWeights[l] * theta_.col(l).cwiseProduct(mask).dot(phi);
            }
            sample_.noalias() += 2.0 * actionSensitivity_.transpose() * effort_;
        }
        historyA_.col(t % (parameters_.horizon + 1)) = sample_;
    }
    if (parameters_.stepSize.normalised) {
        // tr(S_k^T W S_k) (+ tr(J_k^T R J_k)): the cost's curvature in theta at this step.
        const Eigen::MatrixXd& S = sensitivity_[k - first];
        double curvature = (S.array().square().colwise() * problem_.costWeights.array()).sum();
        if (effort) {
            // actionSensitivity_ still holds du_k/dtheta from the loop's last sample (t = k).
            curvature +=
                (actionSensitivity_.array().square().colwise() * parameters_.effortWeights.array())
                    .sum();
        }
        double parameters = static_cast<double>(theta_.size());
        if (hasPhases_) {
            // Averaged over the parameters this step moves: the phase features idle here do
            // not dilute the curvature of the ones at work (which would inflate their step).
            moved_ = S.array().square().colwise().sum();
            if (effort) {
                moved_ += actionSensitivity_.array().square().colwise().sum();
            }
            const Eigen::Index active = (moved_ > 0.0).count();
            parameters = active > 0 ? static_cast<double>(active) : parameters;
        }
        addCurvature(curvature, parameters);
    }
}

void PriscaController::heldEffect(int j, int steps) {
    // sum_{i<steps} (I + dt (A + kinematics at s*_j))^i dt B^T into effectSum_.
    transitionAt(j);
    effectTerm_ = stateEffect_.transpose();
    effectSum_ = effectTerm_;
    for (int i = 1; i < steps; ++i) {
        effectNext_.noalias() = stepTransition_ * effectTerm_;
        effectTerm_ = effectNext_;
        effectSum_ += effectTerm_;
    }
}

void PriscaController::addCurvature(double curvature, double parameters) {
    if (std::isfinite(curvature)) {
        curvatureSum_ += curvature / parameters;
        curvatureSteps_ += 1.0;
    }
}

void PriscaController::setInitialTheta(const Eigen::MatrixXd& theta) {
    setTheta(theta);
    initialTheta_ = theta;
}

void PriscaController::reset(ResetMode mode) {
    matcher_.reset();
    baseline_.reset();
    step_ = 0;
    gradient_.setZero();
    smoothedA_.setZero();
    smoothedG_.setZero();
    alpha_ = 0.0;
    prior_.reset();
    if (mode == ResetMode::Cold) {
        theta_ = initialTheta_;
        learningStep_ = 0;
        curvatureSum_ = 0.0;
        curvatureSteps_ = 0.0;
    }
}

const ControlStep& PriscaController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const int H = parameters_.horizon;
    const int m = static_cast<int>(theta_.cols());
    const int k = step_;

    // 1. Reference and tracking error.
    const int j = matcher_.match(observation);
    problem_.deviation.deviation(observation, referenceStates_.col(j), record_.deviation);
    const Eigen::VectorXd& e = record_.deviation;
    featureMap_.evaluate(e, observation, phi_, j);

    // 2. a_k: column l is phi_l scaled by how much control l moves the weighted error (the
    // paper's one step), or every a_t of the window through the closed loop.
    weightedError_ = problem_.costWeights.cwiseProduct(e);
    const int slot = k % (H + 1);
    record_.cost = e.dot(weightedError_);
    const int count = std::min(k, H) + 1;
    if (parameters_.gradient == PriscaParameters::Gradient::ClosedLoop) {
        const int ring = static_cast<int>(errorHistory_.cols());
        errorHistory_.col(k % ring) = e;
        referenceHistory_[k % ring] = j;
        featureHistory_.col(k % ring) = phi_.reshaped();
        closedLoopTerms(k, count);
    } else if (parameters_.effectHorizon > 1) {
        // What holding u_k for N steps does to the error (eq. 5 before its truncation).
        heldEffect(j, parameters_.effectHorizon);
        projected_.noalias() = effectSum_.transpose() * weightedError_;
    } else {
        projected_.noalias() = stateEffect_ * weightedError_;
    }
    if (parameters_.gradient != PriscaParameters::Gradient::ClosedLoop) {
        for (int l = 0; l < m; ++l) {
            historyA_.col(slot).segment(l * phi_.rows(), phi_.rows()) = phi_.col(l) * projected_[l];
        }
        if (parameters_.stepSize.normalised) {
            // sum_l |phi_l|^2 (E_l^T W E_l), E_l what holding control l for the window's H
            // steps does to the error, as the closed-loop form's S carries it: the one-step
            // effect dt B alone would scale the step to a dead-beat gain.
            heldEffect(j, std::max(H, 1));
            double curvature = 0.0;
            for (int l = 0; l < m; ++l) {
                curvature +=
                    phi_.col(l).squaredNorm() *
                    (effectSum_.col(l).array().square() * problem_.costWeights.array()).sum();
            }
            addCurvature(curvature, static_cast<double>(theta_.size()));
        }
    }

    // 3. Nested-expectation smoothing over the window, with the inverse depreciation.
    const Eigen::VectorXd& w = windowWeights_[count - 1];
    smoothedA_.setZero();
    smoothedG_.setZero();
    depreciationOfWindow_.resize(count);  // changes size only while the first window fills
    for (int t = 0; t < count; ++t) {
        const int sample = k - count + 1 + t;
        const int ring = sample % (H + 1);
        const double D = parameters_.useInverseDepreciation ? depreciation_.at(sample, k) : 1.0;
        depreciationOfWindow_[t] = D;
        const auto a = historyA_.col(ring).reshaped(phi_.rows(), m);
        smoothedA_ += w[t] * a;
        smoothedG_ += (w[t] * D) * a;
    }

    // 4. Gradient with the local optimal baseline.
    if (parameters_.useBaseline) {
        baseline_.push(smoothedA_, smoothedG_);
        baseline_.gradient(smoothedA_, smoothedG_, gradient_);
    } else {
        gradient_ = smoothedG_;
    }

    // 5. Parameter update.
    alpha_ = parameters_.stepSize.at(learningStep_);
    if (parameters_.stepSize.normalised) {
        alpha_ = curvatureSum_ > 0.0 ? alpha_ * curvatureSteps_ / curvatureSum_ : 0.0;
    }
    previousTheta_ = theta_;
    if (parameters_.learning && gradient_.allFinite()) {
        theta_ -= alpha_ * gradient_;
        if (parameters_.thetaBound > 0.0) {
            theta_ = theta_.cwiseMax(-parameters_.thetaBound).cwiseMin(parameters_.thetaBound);
        }
        if (!theta_.allFinite()) {
            theta_ = previousTheta_;  // an update that overflowed is no update
        }
    }

    // 6. Control input from the updated theta.
    record_.referenceIndex = j;
    // The demonstration's action of now: the observation's sample plus its age (less at the
    // start, before the observations had any age to show).
    record_.referenceAction = referenceActions_.col(std::min(
        j + std::min(loopLatencySteps_, k), static_cast<int>(referenceActions_.cols()) - 1));
    record_.action =
        (theta_.cwiseProduct(phi_)).colwise().sum().transpose() + record_.referenceAction;
    if (parameters_.prior.kp.size() != 0) {
        prior_.update(e, j);  // the PD law the policy starts from, as PdController forms it
        prior_.apply(record_.action, j);
    }
    problem_.limits.saturate(record_.action);
    record_.step = k;
    ++step_;
    ++learningStep_;
    return record_;
}

}  // namespace prisca::core
