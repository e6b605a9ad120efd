#pragma once

#include "devices/RcProtocols.h"

#include <Eigen/Core>
#include <QString>

#include <vector>

namespace prisca::devices {

/// How one control reaches the transmitter: which channel, its trim, its travel limits and its
/// direction. Pulses in microseconds.
struct ChannelSetting {
    int channel = 0;          ///< 0..15 (CH1 is 0)
    double trim = 0.0;        ///< added to the centre (1500 us) [us]
    double minimum = 988.0;   ///< lowest pulse sent [us]
    double maximum = 2012.0;  ///< highest pulse sent [us]
    bool reversed = false;    ///< +1 on the control gives the low end
};

/// Maps a control vector (each control in [-1, 1]: throttle, steering, ...) onto 16 channel
/// pulses. A control of 0 gives the centre plus trim, +-1 gives centre +- 512 us, clamped to the
/// channel's limits. Unmapped channels sit at 1500 us. Failsafe is every mapped channel at its
/// centre plus trim: throttle neutral and steering centred.
struct ChannelMap {
    std::vector<ChannelSetting> controls;  ///< one per control, in the plant's action order

    /// The usual car: throttle on CH3 (index 2), steering on CH1 (index 0), as most RC car
    /// transmitters wire them.
    static ChannelMap car();

    /// Empty when usable, else what is wrong (channel out of range or used twice, limits
    /// inverted or outside 800..2200 us, trim outside the limits).
    QString validate() const;
    ChannelPulses command(const Eigen::VectorXd& controlsIn) const;
    ChannelPulses failsafe() const;
};

}  // namespace prisca::devices
