#include "sim/plants/AcrobotEquations.h"

#include "core/DeviationModel.h"

#include <cmath>
#include <stdexcept>

namespace prisca::sim {

namespace {

using core::kPi;

// A point at distance r along a link whose absolute angle from the downward vertical is a.
Eigen::Vector2d along(double r, double a) {
    return {r * std::sin(a), -r * std::cos(a)};
}

}  // namespace

Eigen::Matrix2d AcrobotEquations::massMatrix(double theta2) const {
    const AcrobotConstants& c = constants;
    const double cos2 = std::cos(theta2);
    const double d1 = c.m1 * c.lc1 * c.lc1 +
                      c.m2 * (c.l1 * c.l1 + c.lc2 * c.lc2 + 2.0 * c.l1 * c.lc2 * cos2) + c.I1 +
                      c.I2;
    const double d2 = c.m2 * (c.lc2 * c.lc2 + c.l1 * c.lc2 * cos2) + c.I2;
    const double d3 = c.m2 * c.lc2 * c.lc2 + c.I2;
    Eigen::Matrix2d m;
    m << d1, d2, d2, d3;
    return m;
}

Eigen::Vector4d AcrobotEquations::derivative(const Eigen::Vector4d& s,
                                             const Eigen::Vector2d& tau) const {
    const AcrobotConstants& c = constants;
    const double th1 = s[0];
    const double th2 = s[1];
    const double dth1 = s[2];
    const double dth2 = s[3];
    const Eigen::Matrix2d m = massMatrix(th2);
    const double sin2 = std::sin(th2);
    // The book's phi terms, written exactly as the book dynamics write them, so the reduction test
    // compares like with like.
    const double phi2 = c.m2 * c.lc2 * c.g * std::cos(th1 + th2 - kPi / 2.0);
    const double phi1 = -c.m2 * c.l1 * c.lc2 * dth2 * dth2 * sin2 -
                        2.0 * c.m2 * c.l1 * c.lc2 * dth2 * dth1 * sin2 +
                        (c.m1 * c.lc1 + c.m2 * c.l1) * c.g * std::cos(th1 - kPi / 2.0) + phi2;
    const Eigen::Vector2d rhs(tau[0] - phi1,
                              tau[1] - c.m2 * c.l1 * c.lc2 * dth1 * dth1 * sin2 - phi2);
    // Explicit 2 x 2 inverse: the mass matrix is symmetric positive definite (det > 0).
    const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    const double ddth1 = (m(1, 1) * rhs[0] - m(0, 1) * rhs[1]) / det;
    const double ddth2 = (m(0, 0) * rhs[1] - m(1, 0) * rhs[0]) / det;
    return {dth1, dth2, ddth1, ddth2};
}

Eigen::Vector4d AcrobotEquations::rk4Step(const Eigen::Vector4d& s, const Eigen::Vector2d& tau,
                                          double h) const {
    const Eigen::Vector4d k1 = derivative(s, tau);
    const Eigen::Vector4d k2 = derivative(s + 0.5 * h * k1, tau);
    const Eigen::Vector4d k3 = derivative(s + 0.5 * h * k2, tau);
    const Eigen::Vector4d k4 = derivative(s + h * k3, tau);
    return s + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

Eigen::Vector4d AcrobotEquations::integrate(const Eigen::Vector4d& s, const Eigen::Vector2d& tau,
                                            double duration, double maxStep) const {
    if (!(maxStep > 0.0) || !(duration >= 0.0)) {
        throw std::invalid_argument("AcrobotEquations::integrate: needs duration >= 0, step > 0");
    }
    // Equal steps that land exactly on the end, so control periods line up with the plant's.
    const int n = static_cast<int>(std::ceil(duration / maxStep - 1e-9));
    Eigen::Vector4d x = s;
    for (int i = 0; i < n; ++i) {
        x = rk4Step(x, tau, duration / n);
    }
    return x;
}

double AcrobotEquations::kineticEnergy(const Eigen::Vector4d& s) const {
    const Eigen::Vector2d rates = s.tail<2>();
    return 0.5 * rates.dot(massMatrix(s[1]) * rates);
}

double AcrobotEquations::potentialEnergy(const Eigen::Vector4d& s) const {
    const AcrobotConstants& c = constants;
    return -(c.m1 * c.lc1 + c.m2 * c.l1) * c.g * std::cos(s[0]) -
           c.m2 * c.lc2 * c.g * std::cos(s[0] + s[1]);
}

double AcrobotEquations::energy(const Eigen::Vector4d& s) const {
    return kineticEnergy(s) + potentialEnergy(s);
}

AcrobotPoints AcrobotEquations::points(const Eigen::Vector4d& s) const {
    const AcrobotConstants& c = constants;
    const double a1 = s[0];
    const double a2 = s[0] + s[1];
    AcrobotPoints p;
    p.elbow = along(c.l1, a1);
    p.tip = p.elbow + along(c.l2, a2);
    p.centre1 = along(c.lc1, a1);
    p.centre2 = p.elbow + along(c.lc2, a2);
    return p;
}

}  // namespace prisca::sim
