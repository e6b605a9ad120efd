#include "ActionPlayback.h"

#include <algorithm>
#include <stdexcept>

namespace prisca::core {

ActionPlayback::ActionPlayback(TrackingProblem problem)
    : problem_(TrackingProblem::validated(std::move(problem))) {}

void ActionPlayback::reset(ResetMode) {
    step_ = 0;
}

std::unique_ptr<Controller> ActionPlayback::clone() const {
    return std::make_unique<ActionPlayback>(*this);
}

const ControlStep& ActionPlayback::step(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    const Demonstration& demo = *problem_.demonstration;
    const int j = std::min(step_, demo.length() - 1);
    record_.step = step_;
    record_.referenceIndex = j;
    record_.referenceAction = demo.actions.row(j).transpose();
    record_.action = record_.referenceAction;
    problem_.limits.saturate(record_.action);
    record_.deviation = problem_.deviation.deviation(observation, demo.states.row(j).transpose());
    record_.cost = problem_.cost(record_.deviation);
    ++step_;
    return record_;
}

}  // namespace prisca::core
