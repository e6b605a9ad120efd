#include "PoseFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace prisca::core {

namespace {

// Two times closer than this [s] are the same instant (step() computes them as k * dt, so equal
// steps give equal times; the rig's come from a nanosecond clock).
constexpr double kTimeTolerance = 1e-9;

// The filter's component order: x, y, psi, vx, vy, r.
constexpr int kHeading = 2;

const char* const kComponentNames[6] = {
    "x", "y", "heading", "forward velocity", "lateral velocity", "yaw rate"};

[[noreturn]] void fail(const std::string& message) {
    throw std::invalid_argument("PoseFilter: " + message);
}

}  // namespace

double normalQuantile(double p) {
    if (!(p > 0.0 && p < 1.0)) {
        throw std::invalid_argument("normalQuantile: p = " + std::to_string(p) +
                                    " is outside (0, 1)");
    }
    // A rational approximation on three ranges (relative error about 1e-9) ...
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,
                               -2.759285104469687e+02, 1.383577518672690e+02,
                               -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02,
                               -1.556989798598866e+02, 6.680131188771972e+01,
                               -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01,
                               -2.400758277161838e+00, -2.549732539343734e+00,
                               4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};
    constexpr double low = 0.02425;
    double x = 0.0;
    if (p < low || p > 1.0 - low) {
        const double q = std::sqrt(-2.0 * std::log(p < low ? p : 1.0 - p));
        x = (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
            ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
        if (p > 1.0 - low) {
            x = -x;
        }
    } else {
        const double q = p - 0.5;
        const double r = q * q;
        x = (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
            (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    // ... refined by one step of Halley's iteration on the exact distribution function.
    const double e = 0.5 * std::erfc(-x / std::sqrt(2.0)) - p;
    const double u = e * std::sqrt(2.0 * kPi) * std::exp(0.5 * x * x);
    return x - u / (1.0 + 0.5 * x * u);
}

double chiSquareQuantile(double p, int dof) {
    if (dof < 1) {
        throw std::invalid_argument("chiSquareQuantile: degrees of freedom " + std::to_string(dof) +
                                    " < 1");
    }
    const double z = normalQuantile(p);
    const double k = dof;
    const double h = 2.0 / (9.0 * k);
    const double cube = 1.0 - h + z * std::sqrt(h);
    return cube > 0.0 ? k * cube * cube * cube : 0.0;
}

std::array<int, 6> PoseFilterParameters::componentIndices() const {
    return {pose.x, pose.y, pose.heading, velocity.forward, velocity.lateral, velocity.yawRate};
}

void PoseFilterParameters::validate() const {
    if (stateDimension < 6) {
        fail("state dimension " + std::to_string(stateDimension) + " < 6 (pose and velocities)");
    }
    const std::array<int, 6> indices = componentIndices();
    for (int i = 0; i < 6; ++i) {
        if (indices[i] < 0 || indices[i] >= stateDimension) {
            fail(std::string(kComponentNames[i]) + " index " + std::to_string(indices[i]) +
                 " is outside the state (n = " + std::to_string(stateDimension) + ")");
        }
        for (int j = 0; j < i; ++j) {
            if (indices[j] == indices[i]) {
                fail(std::string(kComponentNames[i]) + " and " + kComponentNames[j] +
                     " share index " + std::to_string(indices[i]));
            }
        }
    }
    if (measured.empty() || measured.size() > 6) {
        fail("the measured set has " + std::to_string(measured.size()) +
             " components (1 to 6 needed)");
    }
    for (std::size_t i = 0; i < measured.size(); ++i) {
        if (std::find(indices.begin(), indices.end(), measured[i]) == indices.end()) {
            fail("measured index " + std::to_string(measured[i]) +
                 " is none of the pose and velocity indices");
        }
        if (std::find(measured.begin(), measured.begin() + static_cast<long>(i), measured[i]) !=
            measured.begin() + static_cast<long>(i)) {
            fail("measured index " + std::to_string(measured[i]) + " is listed twice");
        }
    }
    if (measurementStd.size() != stateDimension) {
        fail("measurement std has " + std::to_string(measurementStd.size()) +
             " components, the state " + std::to_string(stateDimension));
    }
    for (int index : measured) {
        if (!(measurementStd[index] > 0.0) || !std::isfinite(measurementStd[index])) {
            fail("measurement std of component " + std::to_string(index) + " = " +
                 std::to_string(measurementStd[index]) + " (finite and > 0 needed)");
        }
    }
    for (int i = 0; i < 3; ++i) {
        if (!(accelerationDensity[i] >= 0.0) || !std::isfinite(accelerationDensity[i])) {
            fail("acceleration density of the " + std::string(kComponentNames[3 + i]) + " = " +
                 std::to_string(accelerationDensity[i]) + " (finite and >= 0 needed)");
        }
    }
    for (int i = 0; i < 3; ++i) {
        if (!(jerkDensity[i] >= 0.0) || !std::isfinite(jerkDensity[i])) {
            fail("jerk density of the " + std::string(kComponentNames[3 + i]) + " = " +
                 std::to_string(jerkDensity[i]) + " (finite and >= 0 needed)");
        }
    }
    if (!(initialAccelerationStd.array() > 0.0).all() || !initialAccelerationStd.allFinite()) {
        fail("initial acceleration std must be finite and > 0");
    }
    if (!(controlPeriod > 0.0) || !std::isfinite(controlPeriod)) {
        fail("control period " + std::to_string(controlPeriod) + " s (> 0 needed)");
    }
    if (latencySteps < 0) {
        fail("latency " + std::to_string(latencySteps) + " steps (>= 0 needed)");
    }
    if (inputGain.size() && (inputGain.rows() != 3 || !inputGain.allFinite())) {
        fail("input gain is " + std::to_string(inputGain.rows()) + " x " +
             std::to_string(inputGain.cols()) + " or not finite (3 x m, finite needed)");
    }
    if (!(gateProbability > 0.0)) {
        fail("gate probability " + std::to_string(gateProbability) + " (in (0, 1], 1 = no gate)");
    }
    if (reinitialiseAfter < 1) {
        fail("re-initialisation count " + std::to_string(reinitialiseAfter) + " (>= 1 needed)");
    }
    if (!(initialStd.array() > 0.0).all() || !initialStd.allFinite()) {
        fail("initial std must be finite and > 0 for all six components");
    }
    if (!(maxPredictionSpan > 0.0) || !std::isfinite(maxPredictionSpan)) {
        fail("largest prediction span " + std::to_string(maxPredictionSpan) + " s (> 0 needed)");
    }
}

Eigen::MatrixXd inputGainFromFit(const Eigen::MatrixXd& b, const BodyVelocityIndices& velocity) {
    const int columns[3] = {velocity.forward, velocity.lateral, velocity.yawRate};
    Eigen::MatrixXd g(3, b.rows());
    for (int i = 0; i < 3; ++i) {
        if (columns[i] < 0 || columns[i] >= b.cols()) {
            throw std::invalid_argument("inputGainFromFit: velocity index " +
                                        std::to_string(columns[i]) + " is outside B's " +
                                        std::to_string(b.cols()) + " columns");
        }
        g.row(i) = b.col(columns[i]).transpose();
    }
    return g;
}

namespace {

// The random-walk density of each body velocity's `order`-th difference per step (1: the
// velocity's change, an acceleration density; 2: the change of that change per step, a jerk
// density): the nearest-rank 99th percentile of the differences' size over the demonstration,
// squared, per dt, and at least `floor`. `name` names the caller in messages.
Eigen::Vector3d differenceDensity(const Eigen::MatrixXd& states,
                                  const BodyVelocityIndices& velocity, double dt, double floor,
                                  int order, const char* name) {
    if (states.rows() < order + 2) {
        throw std::invalid_argument(std::string(name) + ": " + std::to_string(states.rows()) +
                                    " samples (" + std::to_string(order + 2) + " or more needed)");
    }
    if (!(dt > 0.0)) {
        throw std::invalid_argument(std::string(name) + ": dt = " + std::to_string(dt) +
                                    " (> 0 needed)");
    }
    const int columns[3] = {velocity.forward, velocity.lateral, velocity.yawRate};
    Eigen::Vector3d density;
    std::vector<double> changes(static_cast<std::size_t>(states.rows() - order));
    for (int i = 0; i < 3; ++i) {
        if (columns[i] < 0 || columns[i] >= states.cols()) {
            throw std::invalid_argument(std::string(name) + ": velocity index " +
                                        std::to_string(columns[i]) + " is outside the state");
        }
        const int c = columns[i];
        for (Eigen::Index k = 0; k + order < states.rows(); ++k) {
            changes[static_cast<std::size_t>(k)] =
                order == 1
                    ? std::abs(states(k + 1, c) - states(k, c))
                    // the change of a per-step change, per step
                    : std::abs(states(k + 2, c) - 2.0 * states(k + 1, c) + states(k, c)) / dt;
        }
        // Nearest-rank 99th percentile.
        const std::size_t rank =
            static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(changes.size()))) - 1;
        std::nth_element(changes.begin(), changes.begin() + static_cast<long>(rank), changes.end());
        const double change = changes[rank];
        density[i] = std::max(change * change / dt, floor);
    }
    return density;
}

}  // namespace

Eigen::Vector3d accelerationDensityFromStates(const Eigen::MatrixXd& states,
                                              const BodyVelocityIndices& velocity, double dt,
                                              double floor) {
    return differenceDensity(states, velocity, dt, floor, 1, "accelerationDensityFromStates");
}

Eigen::Vector3d jerkDensityFromStates(const Eigen::MatrixXd& states,
                                      const BodyVelocityIndices& velocity, double dt,
                                      double floor) {
    return differenceDensity(states, velocity, dt, floor, 2, "jerkDensityFromStates");
}

PoseFilter::PoseFilter(PoseFilterParameters parameters, int actionDimension)
    : parameters_(std::move(parameters)) {
    parameters_.validate();
    actionDimension_ = parameters_.inputGain.size() ? static_cast<int>(parameters_.inputGain.cols())
                                                    : actionDimension;
    if (actionDimension_ < 1) {
        fail("action dimension " + std::to_string(actionDimension_) + " (>= 1 needed)");
    }
    index_ = parameters_.componentIndices();
    measuredCount_ = static_cast<int>(parameters_.measured.size());
    for (int i = 0; i < measuredCount_; ++i) {
        measuredComponent_[i] = static_cast<int>(
            std::find(index_.begin(), index_.end(), parameters_.measured[i]) - index_.begin());
    }
    headingMeasured_ =
        std::find(measuredComponent_.begin(), measuredComponent_.begin() + measuredCount_,
                  kHeading) != measuredComponent_.begin() + measuredCount_;
    gate_ = parameters_.gateProbability < 1.0
                ? chiSquareQuantile(parameters_.gateProbability, measuredCount_)
                : std::numeric_limits<double>::infinity();
    output_ = Eigen::VectorXd::Zero(parameters_.stateDimension);
    reference_ = Eigen::VectorXd::Zero(actionDimension_);
    scratch_ = Eigen::VectorXd::Zero(actionDimension_);
    actions_ = Eigen::MatrixXd::Zero(actionDimension_, kActionCapacity);
    actionTimes_.assign(kActionCapacity, 0.0);
    reset();
}

void PoseFilter::reset() {
    x_.setZero();
    p_.setIdentity();
    time_ = 0.0;
    xNow_.setZero();
    pNow_.setIdentity();
    refreshViews();
    now6_ = lagged6_;
    nowP6_ = laggedP6_;
    output_.setZero();
    headingBranch_ = 0.0;
    haveReference_ = false;
    actionHead_ = -1;
    actionCount_ = 0;
    status_ = PoseFilterStatus{};
    consecutiveGated_ = 0;
    gatedCount_ = 0;
    reinitialisations_ = 0;
    predictOnlyCount_ = 0;
    stepIndex_ = 0;
}

PoseFilter::Vector6 PoseFilter::propagate(const Vector6& x, double tau, Matrix6* f) {
    const double psi = x[2], vx = x[3], vy = x[4], r = x[5];
    const double th = r * tau;
    double s, c, ds, dc;  // S, C and their derivatives in r
    if (std::abs(th) < 1e-3) {
        const double th2 = th * th;
        s = tau * (1.0 - th2 / 6.0 + th2 * th2 / 120.0);
        c = tau * (0.5 * th - th * th2 / 24.0);
        ds = tau * tau * (-th / 3.0 + th * th2 / 30.0);
        dc = tau * tau * (0.5 - th2 / 8.0);
    } else {
        const double sn = std::sin(th), cs = std::cos(th);
        s = sn / r;
        c = (1.0 - cs) / r;
        ds = (tau * cs * r - sn) / (r * r);
        dc = (tau * sn * r - (1.0 - cs)) / (r * r);
    }
    const double bx = s * vx - c * vy;  // displacement in the body frame at the start
    const double by = c * vx + s * vy;
    const double sp = std::sin(psi), cp = std::cos(psi);
    Vector6 out = x;
    out[0] += cp * bx - sp * by;
    out[1] += sp * bx + cp * by;
    out[2] = wrapAngle(psi + th);
    if (f) {
        f->setIdentity();
        (*f)(0, 2) = -sp * bx - cp * by;
        (*f)(1, 2) = cp * bx - sp * by;
        (*f)(0, 3) = cp * s - sp * c;
        (*f)(1, 3) = sp * s + cp * c;
        (*f)(0, 4) = -cp * c - sp * s;
        (*f)(1, 4) = -sp * c + cp * s;
        const double dbx = ds * vx - dc * vy, dby = dc * vx + ds * vy;
        (*f)(0, 5) = cp * dbx - sp * dby;
        (*f)(1, 5) = sp * dbx + cp * dby;
        (*f)(2, 5) = tau;
    }
    return out;
}

PoseFilter::Matrix6 PoseFilter::processNoise(const Vector6& x, double tau,
                                             const Eigen::Vector3d& density) {
    // The exact discrete noise of a constant-velocity axis driven by white acceleration of
    // density q over tau: [tau^3/3, tau^2/2; tau^2/2, tau] q, per body axis, the position part
    // rotated into the world at the start heading.
    const double t1 = tau, t2 = 0.5 * tau * tau, t3 = tau * tau * tau / 3.0;
    Eigen::Matrix2d rot;
    const double sp = std::sin(x[2]), cp = std::cos(x[2]);
    rot << cp, -sp, sp, cp;
    const Eigen::Matrix2d q = density.head<2>().asDiagonal();
    Matrix6 out = Matrix6::Zero();
    out.block<2, 2>(0, 0) = t3 * rot * q * rot.transpose();
    out.block<2, 2>(0, 3) = t2 * rot * q;
    out.block<2, 2>(3, 0) = out.block<2, 2>(0, 3).transpose();
    out.block<2, 2>(3, 3) = t1 * q;
    out(2, 2) = t3 * density[2];
    out(2, 5) = out(5, 2) = t2 * density[2];
    out(5, 5) = t1 * density[2];
    return out;
}

PoseFilter::Vector9 PoseFilter::propagateFull(const Vector9& x, double tau, Matrix9* f) {
    // The pose along the arc at the span's mid velocities (exact for constant accelerations in
    // the heading, psi + r tau + ar tau^2 / 2), the velocities integrating the accelerations.
    Vector6 mid = x.head<6>();
    mid.tail<3>() += 0.5 * tau * x.tail<3>();
    Matrix6 f6;
    const Vector6 moved = propagate(mid, tau, f ? &f6 : nullptr);
    Vector9 out = x;
    out.head<3>() = moved.head<3>();
    out.segment<3>(3) = x.segment<3>(3) + tau * x.tail<3>();
    if (f) {
        f->setIdentity();
        f->topLeftCorner<6, 6>() = f6;
        f->block<3, 3>(0, 6) = 0.5 * tau * f6.block<3, 3>(0, 3);
        f->block<3, 3>(3, 6) = tau * Eigen::Matrix3d::Identity();
    }
    return out;
}

PoseFilter::Matrix9 PoseFilter::processNoiseFull(const Vector9& x, double tau,
                                                 const Eigen::Vector3d& density,
                                                 const Eigen::Vector3d& jerk) {
    // Per body axis (position or heading, rate, acceleration): white acceleration q on the rate
    // [tau^3/3, tau^2/2, 0; tau^2/2, tau, 0; 0 0 0] q plus white jerk j on the acceleration
    // [tau^5/20, tau^4/8, tau^3/6; tau^4/8, tau^3/3, tau^2/2; tau^3/6, tau^2/2, tau] j; the
    // position rows rotated into the world at the start heading.
    const double t1 = tau, t2 = tau * tau / 2.0, t3 = tau * tau * tau / 3.0;
    const double t4 = tau * tau * tau * tau / 8.0, t5 = tau * tau * tau * tau * tau / 20.0;
    const double t3j = tau * tau * tau / 6.0;
    Matrix9 body = Matrix9::Zero();
    for (int i = 0; i < 3; ++i) {
        const int p = i, v = 3 + i, a = 6 + i;
        const double q = density[i], j = jerk[i];
        body(p, p) = t3 * q + t5 * j;
        body(p, v) = body(v, p) = t2 * q + t4 * j;
        body(v, v) = t1 * q + t3 * j;
        body(p, a) = body(a, p) = t3j * j;
        body(v, a) = body(a, v) = t2 * j;
        body(a, a) = t1 * j;
    }
    Matrix9 rotate = Matrix9::Identity();
    const double sp = std::sin(x[2]), cp = std::cos(x[2]);
    rotate(0, 0) = cp;
    rotate(0, 1) = -sp;
    rotate(1, 0) = sp;
    rotate(1, 1) = cp;
    return rotate * body * rotate.transpose();
}

int PoseFilter::slot(int age) const {
    return (actionHead_ - age + kActionCapacity) % kActionCapacity;
}

int PoseFilter::actionInForce(double t) const {
    for (int age = 0; age < actionCount_; ++age) {
        if (actionTimes_[static_cast<std::size_t>(slot(age))] <= t + kTimeTolerance) {
            return age;
        }
    }
    return -1;
}

void PoseFilter::predictSpan(Vector9& x, Matrix9& p, double t0, double t1) const {
    const bool input = parameters_.inputGain.size() > 0 && haveReference_;
    Matrix9 f;
    // One stretch of tau under the action `age` places back (-1: none known).
    auto stretch = [&](double tau, int age) {
        if (tau <= kTimeTolerance) {
            return;
        }
        const Matrix9 q =
            processNoiseFull(x, tau, parameters_.accelerationDensity, parameters_.jerkDensity);
        x = propagateFull(x, tau, &f);
        p = f * p * f.transpose() + q;
        if (input && age >= 0) {
            scratch_ = actions_.col(slot(age)) - reference_;
            for (int i = 0; i < 3; ++i) {
                double dv = 0.0;
                for (int j = 0; j < actionDimension_; ++j) {
                    dv += parameters_.inputGain(i, j) * scratch_[j];
                }
                x[3 + i] += tau * dv;
            }
        }
    };
    double a = t0;
    int age = actionInForce(a);
    while (a < t1 - kTimeTolerance) {
        // The action that starts next (the oldest known if none is in force yet).
        const int nextAge = age < 0 ? actionCount_ - 1 : age - 1;
        double b = t1;
        if (nextAge >= 0) {
            const double start = actionTimes_[static_cast<std::size_t>(slot(nextAge))];
            if (start < t1) {
                b = std::max(a, start);
            }
        }
        stretch(b - a, age);
        if (b >= t1 - kTimeTolerance) {
            break;
        }
        a = b;
        age = nextAge;
    }
}

void PoseFilter::checkObservation(const Eigen::Ref<const Eigen::VectorXd>& observation) const {
    if (observation.size() != parameters_.stateDimension) {
        fail("observation has " + std::to_string(observation.size()) + " components, expected " +
             std::to_string(parameters_.stateDimension));
    }
    for (int i = 0; i < measuredCount_; ++i) {
        const int component = measuredComponent_[i];
        if (!std::isfinite(observation[index_[component]])) {
            fail(std::string("observation's ") + kComponentNames[component] + " (component " +
                 std::to_string(index_[component]) + ") is not finite");
        }
    }
}

void PoseFilter::initialise(const Eigen::Ref<const Eigen::VectorXd>& observation, double takenAt) {
    const bool first = !status_.initialised;
    p_.setZero();
    for (int i = 0; i < 9; ++i) {
        if (first) {
            x_[i] = 0.0;
        }
        if (i < 6) {
            p_(i, i) = parameters_.initialStd[i] * parameters_.initialStd[i];
        } else if (parameters_.jerkDensity[i - 6] > 0.0) {
            p_(i, i) = parameters_.initialAccelerationStd[i - 6] *
                       parameters_.initialAccelerationStd[i - 6];
        } else {
            x_[i] = 0.0;  // no acceleration state on this axis
        }
    }
    for (int i = 0; i < measuredCount_; ++i) {
        const int component = measuredComponent_[i];
        const int index = index_[component];
        x_[component] = observation[index];
        const double std = parameters_.measurementStd[index];
        p_(component, component) = std * std;
    }
    x_[kHeading] = wrapAngle(x_[kHeading]);
    time_ = takenAt;
    refreshViews();
    output_ = observation;
    if (headingMeasured_) {
        headingBranch_ = observation[index_[kHeading]];
    }
    status_.initialised = true;
    consecutiveGated_ = 0;
    const int age = actionInForce(takenAt - 2.0 * kTimeTolerance);
    haveReference_ = age >= 0;
    if (haveReference_) {
        reference_ = actions_.col(slot(age));
    }
}

void PoseFilter::measure(const Eigen::Ref<const Eigen::VectorXd>& observation) {
    MeasurementVector innovation(measuredCount_);
    MeasurementMatrix s(measuredCount_, measuredCount_);
    for (int i = 0; i < measuredCount_; ++i) {
        const int component = measuredComponent_[i];
        innovation[i] = observation[index_[component]] - x_[component];
        if (component == kHeading) {
            innovation[i] = wrapAngle(innovation[i]);
        }
        for (int j = 0; j < measuredCount_; ++j) {
            s(i, j) = p_(component, measuredComponent_[j]);
        }
        const double std = parameters_.measurementStd[index_[component]];
        s(i, i) += std * std;
    }
    const Eigen::LLT<MeasurementMatrix> llt(s);
    const MeasurementVector whitened = llt.matrixL().solve(innovation);
    status_.nis = whitened.squaredNorm();
    status_.innovationDimension = measuredCount_;
    output_ = observation;  // the pass-through components follow the newest measurement
    if (headingMeasured_) {
        headingBranch_ = observation[index_[kHeading]];
    }
    if (!(status_.nis <= gate_)) {
        status_.gated = true;
        ++gatedCount_;
        if (++consecutiveGated_ >= parameters_.reinitialiseAfter) {
            ++reinitialisations_;
            status_.reinitialised = true;
            initialise(observation, time_);
        }
        return;
    }
    consecutiveGated_ = 0;
    // K = P H^T S^-1 (6 x m), Joseph-form covariance update.
    GainMatrix pht(9, measuredCount_);
    for (int j = 0; j < measuredCount_; ++j) {
        pht.col(j) = p_.col(measuredComponent_[j]);
    }
    const GainMatrix gain = llt.solve(pht.transpose()).transpose();
    x_.noalias() += gain * innovation;
    x_[kHeading] = wrapAngle(x_[kHeading]);
    Matrix9 ikh = Matrix9::Identity();
    for (int j = 0; j < measuredCount_; ++j) {
        ikh.col(measuredComponent_[j]) -= gain.col(j);
    }
    Matrix9 kr = Matrix9::Zero();
    for (int j = 0; j < measuredCount_; ++j) {
        const double std = parameters_.measurementStd[index_[measuredComponent_[j]]];
        kr.noalias() += (std * std) * gain.col(j) * gain.col(j).transpose();
    }
    p_ = ikh * p_ * ikh.transpose() + kr;
    refreshViews();
}

void PoseFilter::update(const Eigen::Ref<const Eigen::VectorXd>& observation, double takenAt) {
    checkObservation(observation);
    if (!std::isfinite(takenAt)) {
        fail("measurement time is not finite");
    }
    if (status_.initialised && takenAt < time_ - kTimeTolerance) {
        fail("measurement taken at " + std::to_string(takenAt) + " s, before the previous one (" +
             std::to_string(time_) + " s)");
    }
    status_.predictedOnly = false;
    status_.gated = false;
    status_.reinitialised = false;
    status_.nis = 0.0;
    if (!status_.initialised || takenAt - time_ > parameters_.maxPredictionSpan) {
        initialise(observation, takenAt);
        return;
    }
    predictSpan(x_, p_, time_, takenAt);
    time_ = takenAt;
    refreshViews();
    const int age = actionInForce(takenAt - 2.0 * kTimeTolerance);
    haveReference_ = age >= 0;
    if (haveReference_) {
        reference_ = actions_.col(slot(age));
    }
    measure(observation);
}

void PoseFilter::commandedAt(const Eigen::Ref<const Eigen::VectorXd>& action, double from) {
    if (action.size() != actionDimension_) {
        fail("action has " + std::to_string(action.size()) + " components, expected " +
             std::to_string(actionDimension_));
    }
    if (!action.allFinite() || !std::isfinite(from)) {
        fail("action or its time is not finite");
    }
    if (actionCount_ > 0) {
        const double newest = actionTimes_[static_cast<std::size_t>(actionHead_)];
        if (from < newest - kTimeTolerance) {
            fail("action from " + std::to_string(from) + " s, before the previous one (" +
                 std::to_string(newest) + " s)");
        }
        if (from <= newest + kTimeTolerance) {  // the same instant: the newer command replaces it
            actions_.col(actionHead_) = action;
            return;
        }
    }
    actionHead_ = (actionHead_ + 1) % kActionCapacity;
    actions_.col(actionHead_) = action;
    actionTimes_[static_cast<std::size_t>(actionHead_)] = from;
    actionCount_ = std::min(actionCount_ + 1, kActionCapacity);
}

const Eigen::VectorXd& PoseFilter::predictTo(double now) {
    if (!status_.initialised) {
        throw std::logic_error("PoseFilter: predictTo() before any measurement");
    }
    if (!std::isfinite(now)) {
        fail("prediction time is not finite");
    }
    const double span = std::clamp(now - time_, 0.0, parameters_.maxPredictionSpan);
    xNow_ = x_;
    pNow_ = p_;
    predictSpan(xNow_, pNow_, time_, time_ + span);
    now6_ = xNow_.head<6>();
    nowP6_ = pNow_.topLeftCorner<6, 6>();
    writeOutput(xNow_);
    return output_;
}

const Eigen::VectorXd& PoseFilter::step(const Eigen::Ref<const Eigen::VectorXd>& observation,
                                        bool dropped) {
    checkObservation(observation);
    const double dt = parameters_.controlPeriod;
    const double now = static_cast<double>(stepIndex_) * dt;
    const double takenAt = static_cast<double>(stepIndex_ - parameters_.latencySteps) * dt;
    if (!status_.initialised || !dropped) {
        update(observation, takenAt);
    } else {
        status_.predictedOnly = true;
        status_.gated = false;
        status_.reinitialised = false;
        status_.nis = 0.0;
        ++predictOnlyCount_;
    }
    return predictTo(now);
}

void PoseFilter::commanded(const Eigen::Ref<const Eigen::VectorXd>& action) {
    commandedAt(action, static_cast<double>(stepIndex_) * parameters_.controlPeriod);
    ++stepIndex_;
}

void PoseFilter::refreshViews() {
    lagged6_ = x_.head<6>();
    laggedP6_ = p_.topLeftCorner<6, 6>();
}

void PoseFilter::writeOutput(const Vector9& x) {
    for (int i = 0; i < 6; ++i) {
        output_[index_[i]] = x[i];
    }
    // The heading continues the newest measurement's branch (a plant may count whole turns).
    output_[index_[kHeading]] = headingBranch_ + wrapAngle(x[kHeading] - headingBranch_);
}

}  // namespace prisca::core
