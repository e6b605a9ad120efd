#include "sim/episodes/TrialMetrics.h"

#include "core/DeviationModel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

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

double distanceToPath(const PlantInfo& info, const core::Demonstration& demonstration, double x,
                      double y) {
    if (std::isnan(x) || std::isnan(y)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const auto& p = *info.pose;
    const int T = demonstration.length();
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < T; ++j) {
        const int next = std::min(j + 1, T - 1);  // the last term is the last sample alone
        best = std::min(
            best, distanceToSegment(demonstration.states(j, p.x), demonstration.states(j, p.y),
                                    demonstration.states(next, p.x),
                                    demonstration.states(next, p.y), x, y));
    }
    return best;
}

ParkingError parkingError(const PlantInfo& info, const core::Demonstration& demonstration, double x,
                          double y, double heading) {
    if (!info.pose || demonstration.length() == 0) {
        throw std::invalid_argument("parkingError: a planar vehicle and a demonstration needed");
    }
    const auto& p = *info.pose;
    const int end = demonstration.length() - 1;
    return {std::hypot(x - demonstration.states(end, p.x), y - demonstration.states(end, p.y)),
            std::abs(core::wrapAngle(heading - demonstration.states(end, p.heading)))};
}

TrialSummary summarizeTrial(const PlantInfo& info, const core::Demonstration& demonstration,
                            const EpisodeResult& result) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    TrialSummary summary;
    summary.meanCost = result.meanCost;
    summary.duration = result.duration;
    summary.runOutSeconds = result.runOutSeconds;
    summary.controllerNote = result.controllerNote;
    summary.controllerMicrosecondsPerStep =
        result.stepCount > 0 ? 1e6 * result.controllerSeconds / result.stepCount : 0.0;
    const Eigen::VectorXd lot = demonstration.states.row(demonstration.length() - 1).transpose();
    if (info.pose) {
        const auto& p = *info.pose;
        const ParkingError parked =
            parkingError(info, demonstration, result.finalState[p.x], result.finalState[p.y],
                         result.finalState[p.heading]);
        summary.finalPositionError = parked.position;
        summary.finalHeadingError = parked.heading;
    } else {
        summary.finalPositionError = nan;
        summary.finalHeadingError = nan;
    }
    if (result.steps.empty()) {
        summary.trackingRms = nan;
        summary.pathRms = nan;
    } else {
        double sum = 0.0, pathSum = 0.0;
        // Indexed once: the brute force per step made scoring quadratic in the demonstration.
        std::optional<PathDistance> path;
        if (info.pose) {
            path.emplace(info, demonstration);
        }
        for (size_t k = 0; k < result.steps.size(); ++k) {
            const Eigen::VectorXd& state = result.steps[k].state;
            const double e = trackedError(info, demonstration, state, static_cast<int>(k));
            sum += e * e;
            if (info.pose) {
                const double d = path->distance(state[info.pose->x], state[info.pose->y]);
                pathSum += d * d;
            }
        }
        const double count = static_cast<double>(result.steps.size());
        summary.trackingRms = std::sqrt(sum / count);
        summary.pathRms = info.pose ? std::sqrt(pathSum / count) : nan;
    }
    return summary;
}

double tuningScore(const PlantInfo& info, const TrialSummary& summary) {
    return info.pose ? summary.finalPositionError : summary.trackingRms;
}

}  // namespace prisca::sim
