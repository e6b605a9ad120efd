#include "PdController.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

PdController::PdController(TrackingProblem problem, PdParameters parameters, QString name)
    : problem_(TrackingProblem::validated(std::move(problem))),
      name_(std::move(name)),
      matcher_(problem_.demonstration->states, problem_.matching),
      feedback_(std::move(parameters), problem_.demonstration->stateDimension(),
                problem_.demonstration->actionDimension(), problem_.demonstration->dt) {}

void PdController::reset(ResetMode) {
    // PD learns nothing, so a warm start is the same as a cold one.
    matcher_.reset();
    feedback_.reset();
    step_ = 0;
}

std::unique_ptr<Controller> PdController::clone() const {
    return std::make_unique<PdController>(*this);
}

const ControlStep& PdController::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    const int j = matcher_.match(observation);
    record_.deviation = problem_.deviation.deviation(observation, demo.states.row(j).transpose());
    feedback_.update(record_.deviation, j);

    record_.step = step_;
    record_.referenceIndex = j;
    record_.referenceAction =
        demo.actions.row(std::min(j + std::min(loopLatencySteps_, step_), demo.length() - 1))
            .transpose();
    record_.action = record_.referenceAction;
    feedback_.apply(record_.action, j);
    problem_.limits.saturate(record_.action);
    record_.cost = problem_.cost(record_.deviation);
    ++step_;
    return record_;
}

}  // namespace prisca::core
