#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Plant.h"
#include "sim/plants/SlideCar.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace prisca::sim {

/// A scripted operator who slide-parks the simulated car once (docs/architecture.md "scripted
/// demonstrator"): launch along +x, throttle off and full lock at speed; the rear lets go and the
/// car yaws and slides sideways; the operator centres the wheel (optionally with a counter-steer)
/// once it has turned far enough, and the car spins on into the lot and comes to rest. The
/// parking lot is the final pose. Inputs differ a little for every seed (hand tremor, reaction
/// times), as a person's would, and the script covers the ways operators differ: analogue stick
/// or keyboard keys, a wait at standstill, left or right, how far it rotates, how fast it comes
/// in, a throttle blip in the slide, a shaky hand, coasting before the turn.
class SlideCarDemonstrator {
  public:
    /// Tuning of the scripted operator. Plain data.
    struct Script {
        double standstill = 0.0;      ///< time standing still before the launch [s]
        double launchThrottle = 0.9;  ///< throttle held on the straight [1]
        double launchRamp = 0.25;     ///< time to open the throttle [s]
        double turnTime = 1.4;        ///< when the operator steers in, from the launch [s]
        /// Throttle released this long before steering in, so the car coasts into the turn [s].
        double coastTime = 0.0;
        double direction = 1.0;   ///< +1 slides to the left (counter-clockwise), -1 to the right
        double steerRamp = 0.08;  ///< time to reach full lock [s]
        /// Heading turned (magnitude) at which the wheel is centred again; the car spins on after
        /// that: 1.13 rad (65 deg) gives about 180 deg in all [rad].
        double releaseHeading = 1.13;
        double releaseRamp = 0.15;     ///< time to centre the wheel [s]
        double counterSteer = 0.0;     ///< opposite lock applied to catch the spin (0: none) [1]
        double counterDuration = 0.3;  ///< how long the counter-steer is held [s]
        double blipThrottle = 0.0;     ///< a throttle blip in the slide (0: none) [1]
        double blipDelay = 0.25;       ///< the blip starts this long after steering in [s]
        double blipDuration = 0.15;    ///< and lasts this long [s]
        /// Keys instead of an analogue stick: each control is pushed towards full (2 per second)
        /// while its key is held and returns to neutral (3 per second) when released, as the
        /// window's keyboard driving does; the operator holds a key while the stick would be past
        /// half way.
        bool keyboard = false;
        double stickJitter = 0.0;  ///< rms of a shaking hand on both sticks (about 8 Hz) [1]
        double jitter = 1.0;       ///< scale of the seeded hand variation (0: exact script)
        double maxDuration = 8.0;  ///< recording stops by then in any case [s]
        double restTail = 0.5;     ///< kept recording at rest after the car stops [s]
    };

    /// Records one demonstration on a nominal slide-car (no perturbation) with this seed's hand
    /// variation.
    static core::Demonstration record(std::uint64_t seed, const Script& script,
                                      const SimulationTiming& timing = {},
                                      const SlideCarParameters& car = {},
                                      const Perturbation& conditions = Perturbation::none());
    static core::Demonstration record(std::uint64_t seed, const SimulationTiming& timing = {}) {
        return record(seed, Script{}, timing);
    }
};

}  // namespace prisca::sim
