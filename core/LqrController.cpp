#include "LqrController.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

namespace {

TrackingProblem timeDriven(TrackingProblem problem) {
    problem.matching.mode = MatchingParameters::Mode::TimeDriven;
    return TrackingProblem::validated(std::move(problem));
}

}  // namespace

LqrController::LqrController(TrackingProblem problem, LqrParameters parameters)
    : problem_(timeDriven(std::move(problem))),
      parameters_(std::move(parameters)),
      matcher_(problem_.demonstration->states, problem_.matching) {
    const Demonstration& demo = *problem_.demonstration;
    const Eigen::Index n = demo.stateDimension();
    const Eigen::Index m = demo.actionDimension();
    const LqrParameters& p = parameters_;
    if (p.a.rows() != n || p.a.cols() != n || p.b.rows() != m || p.b.cols() != n ||
        p.effort.size() != m) {
        throw std::invalid_argument(
            QStringLiteral("LQR: the model must be A %1 x %1, B %2 x %1 and R %2 values")
                .arg(n)
                .arg(m)
                .toStdString());
    }
    if ((p.effort.array() <= 0.0).any() || !p.effort.allFinite() || !(p.terminalWeight > 0.0) ||
        p.holdSteps < 0) {
        throw std::invalid_argument(
            "LQR: effort weights and the terminal weight must be > 0, the hold steps >= 0");
    }
    const double dt = demo.dt;
    const Eigen::MatrixXd bd = dt * p.b.transpose();  // n x m
    const Eigen::MatrixXd q = problem_.costWeights.asDiagonal();
    const Eigen::MatrixXd r = p.effort.asDiagonal();
    // Backwards from the end: P_N = terminal Q; K_k from P_{k+1}; P_k = Q + Ad^T P (Ad - Bd K).
    const int T = demo.length();
    const int N = T + p.holdSteps;
    gains_.assign(static_cast<size_t>(N), Eigen::MatrixXd::Zero(m, n));
    Eigen::MatrixXd cost = p.terminalWeight * q;
    Eigen::MatrixXd kinematics(n, n);
    for (int k = N - 1; k >= 0; --k) {
        const int j = std::min(k, T - 1);  // held at the last sample past the end
        problem_.deviation.kinematics(demo.states.row(j).transpose(), kinematics);
        const Eigen::MatrixXd ad = Eigen::MatrixXd::Identity(n, n) + dt * (p.a + kinematics);
        const Eigen::MatrixXd s = r + bd.transpose() * cost * bd;
        Eigen::MatrixXd gain = s.ldlt().solve(bd.transpose() * cost * ad);
        const Eigen::MatrixXd closed = ad - bd * gain;
        cost = q + ad.transpose() * cost * closed;
        cost = 0.5 * (cost + cost.transpose()).eval();  // keep it symmetric against round-off
        if (!gain.allFinite() || !cost.allFinite()) {
            throw std::invalid_argument(
                "LQR: the Riccati recursion left the numbers on the fitted model");
        }
        gains_[static_cast<size_t>(k)] = std::move(gain);
    }
    record_.action.resize(m);
}

void LqrController::reset(ResetMode) {
    matcher_.reset();
    step_ = 0;
}

void LqrController::setLoopLatencySteps(int steps) {
    loopLatencySteps_ = std::max(0, steps);
    matcher_.setLoopLatencySteps(loopLatencySteps_);
}

std::unique_ptr<Controller> LqrController::clone() const {
    return std::make_unique<LqrController>(*this);
}

const Eigen::MatrixXd& LqrController::gain(int k) const {
    return gains_[static_cast<size_t>(std::clamp(k, 0, gainCount() - 1))];
}

const ControlStep& LqrController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    // The observation's own time (latency compensated); the action of now.
    const int j = matcher_.match(observation);
    record_.deviation = problem_.deviation.deviation(observation, demo.states.row(j).transpose());
    const int now = std::min(j + std::min(loopLatencySteps_, step_), demo.length() - 1);
    record_.step = step_;
    record_.referenceIndex = j;
    record_.referenceAction = demo.actions.row(now).transpose();
    record_.action.noalias() = record_.referenceAction - gain(step_) * record_.deviation;
    problem_.limits.saturate(record_.action);
    record_.cost = problem_.cost(record_.deviation);
    ++step_;
    return record_;
}

}  // namespace prisca::core
