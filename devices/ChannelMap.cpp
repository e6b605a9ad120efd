#include "devices/ChannelMap.h"

#include <algorithm>
#include <cmath>

namespace prisca::devices {

namespace {
constexpr double kCentre = 1500.0;
constexpr double kHalfTravel = 512.0;
}  // namespace

ChannelMap ChannelMap::car() {
    ChannelMap map;
    ChannelSetting throttle;
    throttle.channel = 2;
    ChannelSetting steering;
    steering.channel = 0;
    map.controls = {throttle, steering};
    return map;
}

QString ChannelMap::validate() const {
    std::vector<bool> used(16, false);
    for (size_t i = 0; i < controls.size(); ++i) {
        const ChannelSetting& c = controls[i];
        if (c.channel < 0 || c.channel > 15) {
            return QStringLiteral("control %1: channel %2 is not 1..16").arg(i).arg(c.channel + 1);
        }
        if (used[c.channel]) {
            return QStringLiteral("control %1: channel %2 is used twice").arg(i).arg(c.channel + 1);
        }
        used[c.channel] = true;
        if (!(c.minimum < c.maximum) || c.minimum < 800.0 || c.maximum > 2200.0) {
            return QStringLiteral(
                       "control %1: limits %2..%3 us must be increasing within 800..2200")
                .arg(i)
                .arg(c.minimum)
                .arg(c.maximum);
        }
        const double centre = kCentre + c.trim;
        if (!std::isfinite(c.trim) || centre < c.minimum || centre > c.maximum) {
            return QStringLiteral("control %1: trim %2 us puts the centre outside the limits")
                .arg(i)
                .arg(c.trim);
        }
    }
    return {};
}

ChannelPulses ChannelMap::command(const Eigen::VectorXd& in) const {
    ChannelPulses pulses = failsafe();
    for (size_t i = 0; i < controls.size() && static_cast<Eigen::Index>(i) < in.size(); ++i) {
        const ChannelSetting& c = controls[i];
        // A non-finite control is treated as neutral: nothing undefined ever leaves.
        const double u = std::isfinite(in[i]) ? std::clamp(in[i], -1.0, 1.0) : 0.0;
        const double pulse = kCentre + c.trim + (c.reversed ? -u : u) * kHalfTravel;
        pulses[c.channel] = std::clamp(pulse, c.minimum, c.maximum);
    }
    return pulses;
}

ChannelPulses ChannelMap::failsafe() const {
    ChannelPulses pulses;
    pulses.fill(kCentre);
    for (const ChannelSetting& c : controls) {
        if (c.channel >= 0 && c.channel < 16) {
            pulses[c.channel] = std::clamp(kCentre + c.trim, c.minimum, c.maximum);
        }
    }
    return pulses;
}

}  // namespace prisca::devices
