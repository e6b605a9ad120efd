#include "sim/demonstrations/DemonstrationRecorder.h"

#include <stdexcept>

namespace prisca::sim {

DemonstrationRecorder::DemonstrationRecorder(const PlantInfo& info, double dt)
    : info_(info), dt_(dt) {}

void DemonstrationRecorder::record(const Eigen::VectorXd& state, const Eigen::VectorXd& action) {
    if (state.size() != info_.stateDimension() || action.size() != info_.actionDimension()) {
        throw std::invalid_argument("DemonstrationRecorder: state or action of the wrong size");
    }
    states_.push_back(state);
    actions_.push_back(action);
}

core::Demonstration DemonstrationRecorder::demonstration() const {
    core::Demonstration d;
    d.plant = info_.name;
    d.dt = dt_;
    d.stateNames = info_.stateNames;
    d.stateUnits = info_.stateUnits;
    d.actionNames = info_.actionNames;
    d.actionUnits = info_.actionUnits;
    const int T = size();
    d.time.resize(T);
    d.states.resize(T, info_.stateDimension());
    d.actions.resize(T, info_.actionDimension());
    for (int k = 0; k < T; ++k) {
        d.time[k] = k * dt_;
        d.states.row(k) = states_[k].transpose();
        d.actions.row(k) = actions_[k].transpose();
    }
    return d;
}

}  // namespace prisca::sim
