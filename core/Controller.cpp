#include "Controller.h"

namespace prisca::core {

ActionLimits ActionLimits::symmetric(int channels, double bound) {
    return {Eigen::VectorXd::Constant(channels, -bound),
            Eigen::VectorXd::Constant(channels, bound)};
}

void ActionLimits::saturate(Eigen::Ref<Eigen::VectorXd> u) const {
    u = u.cwiseMax(lower).cwiseMin(upper);
}

QString TrackingProblem::validate() const {
    if (!demonstration) {
        return QStringLiteral("no demonstration");
    }
    const QString demoProblem = demonstration->validate();
    if (!demoProblem.isEmpty()) {
        return demoProblem;
    }
    const int n = demonstration->stateDimension();
    const int m = demonstration->actionDimension();
    if (deviation.dimension != n) {
        return QStringLiteral("the deviation model has dimension %1, the states %2")
            .arg(deviation.dimension)
            .arg(n);
    }
    const QString deviationProblem = deviation.validate();
    if (!deviationProblem.isEmpty()) {
        return deviationProblem;
    }
    if (costWeights.size() != 0 && costWeights.size() != n) {
        return QStringLiteral("%1 cost weights for %2 states").arg(costWeights.size()).arg(n);
    }
    if (limits.lower.size() != m || limits.upper.size() != m) {
        return QStringLiteral("action limits must have %1 entries").arg(m);
    }
    if ((limits.lower.array() > limits.upper.array()).any()) {
        return QStringLiteral("an action lower limit exceeds its upper limit");
    }
    if (matching.weights.size() != 0 && matching.weights.size() != n) {
        return QStringLiteral("%1 matching weights for %2 states")
            .arg(matching.weights.size())
            .arg(n);
    }
    if (matching.window < 0) {
        return QStringLiteral("the matching window must be >= 0");
    }
    return {};
}

TrackingProblem TrackingProblem::validated(TrackingProblem problem) {
    const QString text = problem.validate();
    if (!text.isEmpty()) {
        throw std::invalid_argument(text.toStdString());
    }
    if (problem.costWeights.size() == 0) {
        problem.costWeights = Eigen::VectorXd::Ones(problem.demonstration->stateDimension());
    }
    return problem;
}

}  // namespace prisca::core
