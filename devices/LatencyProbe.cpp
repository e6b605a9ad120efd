#include "devices/LatencyProbe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace prisca::devices {

LatencyProbe::LatencyProbe(LatencyProbeSettings settings) : s_(settings) {}

Eigen::VectorXd LatencyProbe::onFrame(std::int64_t frameNs, const std::optional<PlanarPose>& pose) {
    const double t = static_cast<double>(frameNs) * 1e-9;
    if (finished()) {
        return neutral();
    }
    if (phaseStart_ < 0.0) {
        phaseStart_ = t;
    }
    if (phase_ == Phase::Settle) {
        if (t - phaseStart_ > s_.settleTimeout) {
            failure_ = pose ? "the car did not come to rest (is it rolling, or the track noisy?)"
                            : "no pose: the camera does not see the car";
            return neutral();
        }
        if (!pose) {
            recent_.clear();
            return neutral();
        }
        recent_.emplace_back(t, *pose);
        while (!recent_.empty() && recent_.front().first < t - s_.stillFor) {
            recent_.erase(recent_.begin());
        }
        bool still = recent_.size() >= 3 && t - recent_.front().first >= 0.8 * s_.stillFor;
        for (const auto& [time, p] : recent_) {
            still = still && std::hypot(p.x - pose->x, p.y - pose->y) <= s_.stillWithin;
        }
        if (!still) {
            return neutral();
        }
        // Step now: this frame's command is the step.
        phase_ = Phase::Step;
        stepAt_ = t;
        // Where it stands: the mean of the still frames (one frame's noise would offset every
        // displacement measured from it).
        from_ = *pose;
        from_.x = from_.y = 0.0;
        for (const auto& [time, p] : recent_) {
            from_.x += p.x / recent_.size();
            from_.y += p.y / recent_.size();
        }
        response_.clear();
        Eigen::VectorXd a = neutral();
        a[s_.throttleIndex] = sign_ * s_.throttle;
        return a;
    }
    // Phase::Step: hold the step until the response is fitted or time is up.
    if (pose) {
        const double along = (pose->x - from_.x) * std::cos(from_.heading) +
                             (pose->y - from_.y) * std::sin(from_.heading);
        response_.emplace_back(t, sign_ * along);
    }
    const bool farEnough = !response_.empty() && response_.back().second > s_.fitUpTo;
    if (!farEnough && t - stepAt_ < s_.giveUpAfter) {
        Eigen::VectorXd a = neutral();
        a[s_.throttleIndex] = sign_ * s_.throttle;
        return a;
    }
    // Fit d(t) = c + q max(0, t - t0)^2 to every frame up to fitUpTo, least squares in d (the
    // camera's noise is the same at every displacement): for each t0 on a 0.5 ms grid q is
    // linear, the best t0 leaves the least residual. A threshold that picks the first frames
    // to fit would pick those whose noise pushed them over it, and time the onset early.
    int used = 0, moved = 0;
    for (const auto& [time, d] : response_) {
        used += d <= s_.fitUpTo;
        moved += d >= s_.onsetFrom && d <= s_.fitUpTo;
    }
    if (moved < 2) {
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", s_.giveUpAfter);
        failure_ = std::string("the car did not answer a throttle step within ") + seconds +
                   " s (is the link connected, the car on?)";
        return neutral();
    }
    double bestT0 = 0.0, bestResidual = std::numeric_limits<double>::infinity();
    const double last = response_.back().first - stepAt_;
    for (double t0 = 0.0; t0 < last; t0 += 0.0005) {
        // d = c + q basis: the 2 x 2 normal equations (c absorbs what is left of the start
        // pose's noise).
        double n = 0.0, sb = 0.0, sbb = 0.0, sd = 0.0, sbd = 0.0, sdd = 0.0;
        for (const auto& [time, d] : response_) {
            if (d > s_.fitUpTo) {
                continue;
            }
            const double x = std::max(0.0, time - stepAt_ - t0), basis = x * x;
            n += 1.0;
            sb += basis;
            sbb += basis * basis;
            sd += d;
            sbd += basis * d;
            sdd += d * d;
        }
        const double det = n * sbb - sb * sb;
        if (!(det > 0.0)) {
            continue;
        }
        const double q = (n * sbd - sb * sd) / det;
        const double c = (sd - q * sb) / n;
        if (!(q > 0.0)) {
            continue;
        }
        const double residual =
            sdd - 2.0 * c * sd - 2.0 * q * sbd + n * c * c + 2.0 * c * q * sb + q * q * sbb;
        if (residual < bestResidual) {
            bestResidual = residual;
            bestT0 = t0;
        }
    }
    if (!std::isfinite(bestResidual)) {
        failure_ = "the car's response could not be timed (no displacement fits a start)";
        return neutral();
    }
    steps_.push_back({bestT0, used});
    sign_ = -sign_;
    if (static_cast<int>(steps_.size()) >= s_.steps) {
        phase_ = Phase::Done;
    } else {
        phase_ = Phase::Settle;
        phaseStart_ = t;
        recent_.clear();
    }
    return neutral();
}

namespace {
std::vector<double> sorted(const std::vector<LatencyStep>& steps) {
    std::vector<double> v;
    for (const LatencyStep& s : steps) {
        v.push_back(s.latency);
    }
    std::sort(v.begin(), v.end());
    return v;
}
}  // namespace

double LatencyProbe::medianSeconds() const {
    const std::vector<double> v = sorted(steps_);
    if (v.empty()) {
        return -1.0;
    }
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

double LatencyProbe::minSeconds() const {
    const std::vector<double> v = sorted(steps_);
    return v.empty() ? -1.0 : v.front();
}

double LatencyProbe::maxSeconds() const {
    const std::vector<double> v = sorted(steps_);
    return v.empty() ? -1.0 : v.back();
}

double LatencyProbe::spreadSeconds() const {
    if (steps_.size() < 2) {
        return 0.0;
    }
    double mean = 0.0;
    for (const LatencyStep& s : steps_) {
        mean += s.latency;
    }
    mean /= steps_.size();
    double sum = 0.0;
    for (const LatencyStep& s : steps_) {
        sum += (s.latency - mean) * (s.latency - mean);
    }
    return std::sqrt(sum / (steps_.size() - 1));
}

}  // namespace prisca::devices
