#include "TrialMetrics.h"

#include "core/DeviationModel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prisca::sim {

double trackedError(const PlantInfo& info, const core::Demonstration& demonstration,
                    const Eigen::VectorXd& state, int step) {
    const int j = std::clamp(step, 0, demonstration.length() - 1);
    const Eigen::VectorXd reference = demonstration.states.row(j).transpose();
    if (info.pose) {
        return std::hypot(state[info.pose->x] - reference[info.pose->x],
                          state[info.pose->y] - reference[info.pose->y]);
    }
    double sum = 0.0;
    for (int i : info.angleIndices) {
        const double d = core::wrapAngle(state[i] - reference[i]);
        sum += d * d;
    }
    return std::sqrt(sum);
}

TrialSummary summarizeTrial(const PlantInfo& info, const core::Demonstration& demonstration,
                            const EpisodeResult& result) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    TrialSummary summary;
    summary.meanCost = result.meanCost;
    summary.duration = result.duration;
    const Eigen::VectorXd lot = demonstration.states.row(demonstration.length() - 1).transpose();
    if (info.pose) {
        const auto& p = *info.pose;
        summary.finalPositionError =
            std::hypot(result.finalState[p.x] - lot[p.x], result.finalState[p.y] - lot[p.y]);
        summary.finalHeadingError =
            std::abs(core::wrapAngle(result.finalState[p.heading] - lot[p.heading]));
    } else {
        summary.finalPositionError = nan;
        summary.finalHeadingError = nan;
    }
    if (result.steps.empty()) {
        summary.trackingRms = nan;
    } else {
        double sum = 0.0;
        for (size_t k = 0; k < result.steps.size(); ++k) {
            const double e =
                trackedError(info, demonstration, result.steps[k].state, static_cast<int>(k));
            sum += e * e;
        }
        summary.trackingRms = std::sqrt(sum / result.steps.size());
    }
    return summary;
}

double tuningScore(const PlantInfo& info, const TrialSummary& summary) {
    return info.pose ? summary.finalPositionError : summary.trackingRms;
}

}  // namespace prisca::sim
