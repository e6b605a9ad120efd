#include "DemonstrationRecorder.h"

#include "core/DeviationModel.h"

#include <algorithm>
#include <cmath>
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

core::Demonstration DemonstrationRecorder::fromTimedSamples(
    const PlantInfo& info, const std::vector<double>& times,
    const std::vector<Eigen::VectorXd>& states, const std::vector<Eigen::VectorXd>& actions) {
    const size_t count = times.size();
    if (count < 2 || states.size() != count || actions.size() != count) {
        throw std::invalid_argument(
            "DemonstrationRecorder::fromTimedSamples: at least two samples, one time, state and "
            "action each");
    }
    std::vector<double> intervals;
    for (size_t i = 1; i < count; ++i) {
        const double interval = times[i] - times[i - 1];
        if (!(interval > 0.0) || !std::isfinite(interval)) {
            throw std::invalid_argument(
                "DemonstrationRecorder::fromTimedSamples: sample times must increase");
        }
        intervals.push_back(interval);
    }
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    const double dt = intervals[intervals.size() / 2];
    DemonstrationRecorder recorder(info, dt);
    const double span = times.back() - times.front();
    const int samples = static_cast<int>(std::floor(span / dt + 1e-9)) + 1;
    size_t i = 0;  // times[i] <= t < times[i + 1]
    for (int k = 0; k < samples; ++k) {
        const double t = times.front() + k * dt;
        while (i + 2 < count && times[i + 1] <= t) {
            ++i;
        }
        const double w = std::clamp((t - times[i]) / (times[i + 1] - times[i]), 0.0, 1.0);
        Eigen::VectorXd state = states[i] + w * (states[i + 1] - states[i]);
        for (int a : info.angleIndices) {
            state[a] = core::wrapAngle(states[i][a] +
                                       w * core::wrapAngle(states[i + 1][a] - states[i][a]));
        }
        recorder.record(state, w >= 1.0 ? actions[i + 1] : actions[i]);
    }
    return recorder.demonstration();
}

}  // namespace prisca::sim
