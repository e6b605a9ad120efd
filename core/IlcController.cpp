#include "IlcController.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::core {

IlcController::IlcController(TrackingProblem problem, IlcParameters parameters)
    : problem_(TrackingProblem::validated(std::move(problem))), parameters_(std::move(parameters)) {
    const int n = problem_.demonstration->stateDimension();
    const int m = problem_.demonstration->actionDimension();
    feedback_ = PdFeedback(parameters_.feedback, n, m, problem_.demonstration->dt);
    if (parameters_.learningGain.size() != m) {
        throw std::invalid_argument("IlcController: the learning gain must be of size m");
    }
    if (parameters_.lead < 0 || !(parameters_.cutoff >= 0.0) || !(parameters_.forgetting >= 0.0) ||
        parameters_.forgetting >= 1.0 || !parameters_.learningGain.allFinite() ||
        (parameters_.learningGain.array() < 0.0).any()) {
        throw std::invalid_argument(
            "IlcController: lead >= 0, cutoff >= 0, forgetting in [0, 1), learning gain >= 0");
    }
    feedforward_.setZero(m, problem_.demonstration->length());
    record_.action.setZero(m);
    record_.referenceAction.setZero(m);
    record_.deviation.setZero(n);
}

std::unique_ptr<Controller> IlcController::clone() const {
    return std::make_unique<IlcController>(*this);
}

void IlcController::reset(ResetMode mode) {
    if (mode == ResetMode::Cold) {
        feedforward_.setZero();
        iterations_ = 0;
    } else if (!signals_.empty()) {
        learn();
    }
    signals_.clear();
    feedback_.reset();
    step_ = 0;
}

void IlcController::learn() {
    const int K = static_cast<int>(signals_.size());
    const int m = static_cast<int>(feedforward_.rows());
    const int covered = static_cast<int>(feedforward_.cols());
    if (covered < K) {
        feedforward_.conservativeResize(Eigen::NoChange, K);
        feedforward_.rightCols(K - covered).setZero();
    }
    // The trial covers steps 0..K-1; the error of step k + lead corrects the action at k (the
    // last error stands in past the trial's end). Later steps keep what they had.
    const double keep = 1.0 - parameters_.forgetting;
    for (int k = 0; k < K; ++k) {
        const Eigen::VectorXd& eps = signals_[std::min(k + parameters_.lead, K - 1)];
        feedforward_.col(k) =
            keep * feedforward_.col(k) - parameters_.learningGain.cwiseProduct(eps);
    }
    if (parameters_.cutoff > 0.0) {
        // Zero-phase first-order low-pass over the whole feedforward: forward, then backward.
        const double a = std::exp(-2.0 * M_PI * parameters_.cutoff * problem_.demonstration->dt);
        const int T = static_cast<int>(feedforward_.cols());
        for (int l = 0; l < m; ++l) {
            Eigen::RowVectorXd f = feedforward_.row(l);
            for (int k = 1; k < T; ++k) {
                f[k] = a * f[k - 1] + (1.0 - a) * f[k];
            }
            for (int k = T - 2; k >= 0; --k) {
                f[k] = a * f[k + 1] + (1.0 - a) * f[k];
            }
            feedforward_.row(l) = f;
        }
    }
    ++iterations_;
}

const ControlStep& IlcController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    const int k = step_;
    const int j = std::min(k, demo.length() - 1);
    // The observation is loopLatencySteps_ steps old: its error against the reference of that time.
    const int seen = std::clamp(k - loopLatencySteps_, 0, demo.length() - 1);
    problem_.deviation.deviation(observation, demo.states.row(seen).transpose(), record_.deviation);
    feedback_.update(record_.deviation, seen);
    signals_.push_back(feedback_.signal());

    record_.step = k;
    record_.referenceIndex = j;
    record_.referenceAction = demo.actions.row(j).transpose();
    record_.action = record_.referenceAction;
    feedback_.apply(record_.action);
    if (k < feedforward_.cols()) {
        record_.action += feedforward_.col(k);
    }
    problem_.limits.saturate(record_.action);
    record_.cost = problem_.cost(record_.deviation);
    ++step_;
    return record_;
}

}  // namespace prisca::core
