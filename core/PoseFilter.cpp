#include "PoseFilter.h"
#include "PoseFilter_p.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace prisca::core {

using namespace posefilter;

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
    const double takenAt = static_cast<double>(stepIndex_ - parameters_.loopLatencySteps) * dt;
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
