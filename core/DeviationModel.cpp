#include "DeviationModel.h"

#include <cmath>

namespace prisca::core {

double wrapAngle(double angle) {
    constexpr double kTwoPi = 2.0 * kPi;
    // ceil keeps +pi and maps -pi to +pi, giving the half-open interval (-pi, pi].
    return angle - kTwoPi * std::ceil((angle - kPi) / kTwoPi);
}

void DeviationModel::deviation(const Eigen::Ref<const Eigen::VectorXd>& state,
                               const Eigen::Ref<const Eigen::VectorXd>& reference,
                               Eigen::Ref<Eigen::VectorXd> out) const {
    out = state - reference;
    for (int i : angleIndices) {
        out[i] = wrapAngle(out[i]);
    }
    if (pose) {
        const double dx = out[pose->x];
        const double dy = out[pose->y];
        const double c = std::cos(reference[pose->heading]);
        const double s = std::sin(reference[pose->heading]);
        out[pose->x] = c * dx + s * dy;   // longitudinal, along the desired heading
        out[pose->y] = -s * dx + c * dy;  // lateral, positive to the left
        out[pose->heading] = wrapAngle(state[pose->heading] - reference[pose->heading]);
    }
}

void DeviationModel::kinematics(const Eigen::Ref<const Eigen::VectorXd>& reference,
                                Eigen::Ref<Eigen::MatrixXd> out) const {
    out.setZero();
    if (!pose || !bodyVelocity) {
        return;
    }
    const PlanarPoseIndices& p = *pose;
    const BodyVelocityIndices& v = *bodyVelocity;
    const double forward = reference[v.forward];
    const double lateral = reference[v.lateral];
    const double yawRate = reference[v.yawRate];
    out(p.x, v.forward) = 1.0;
    out(p.x, p.heading) = -lateral;
    out(p.x, p.y) = yawRate;
    out(p.y, v.lateral) = 1.0;
    out(p.y, p.heading) = forward;
    out(p.y, p.x) = -yawRate;
    out(p.heading, v.yawRate) = 1.0;
}

Eigen::VectorXd DeviationModel::deviation(
    const Eigen::Ref<const Eigen::VectorXd>& state,
    const Eigen::Ref<const Eigen::VectorXd>& reference) const {
    Eigen::VectorXd out(state.size());
    deviation(state, reference, out);
    return out;
}

DeviationModel DeviationModel::euclidean(int dimension) {
    DeviationModel model;
    model.dimension = dimension;
    return model;
}

DeviationModel DeviationModel::planarVehicle(int dimension, PlanarPoseIndices pose) {
    DeviationModel model;
    model.dimension = dimension;
    model.pose = pose;
    return model;
}

QString DeviationModel::validate() const {
    if (dimension < 1) {
        return QStringLiteral("state dimension must be >= 1, got %1").arg(dimension);
    }
    auto bad = [this](int i) { return i < 0 || i >= dimension; };
    for (int i : angleIndices) {
        if (bad(i)) {
            return QStringLiteral("angle index %1 is outside 0..%2").arg(i).arg(dimension - 1);
        }
    }
    if (bodyVelocity && (!pose || bad(bodyVelocity->forward) || bad(bodyVelocity->lateral) ||
                         bad(bodyVelocity->yawRate))) {
        return QStringLiteral("body velocities need a pose and indices within 0..%1")
            .arg(dimension - 1);
    }
    if (pose && (bad(pose->x) || bad(pose->y) || bad(pose->heading) || pose->x == pose->y ||
                 pose->x == pose->heading || pose->y == pose->heading)) {
        return QStringLiteral("pose indices (%1, %2, %3) must be distinct and within 0..%4")
            .arg(pose->x)
            .arg(pose->y)
            .arg(pose->heading)
            .arg(dimension - 1);
    }
    return {};
}

}  // namespace prisca::core
