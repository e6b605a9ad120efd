#pragma once

#include "Plant.h"
#include "SlideCar.h"
#include "core/Demonstration.h"

#include <cstdint>

namespace prisca::sim {

/// A scripted operator who slide-parks the simulated car once (DESIGN.md "scripted
/// demonstrator"): launch along +x, throttle off and full left lock at speed; the rear lets go
/// and the car yaws and slides sideways; the operator centres the wheel (optionally with a
/// counter-steer) once it has turned about 65 degrees, and the car spins on into a 180-degree
/// slide-park and comes to rest. The parking lot is the final pose. Inputs are smooth and differ
/// a little for every seed (hand tremor, reaction times), as a person's would.
class SlideCarDemonstrator {
  public:
    /// Tuning of the scripted operator. Plain data.
    struct Script {
        double launchThrottle = 0.9;  ///< throttle held on the straight
        double launchRamp = 0.25;     ///< time to open the throttle [s]
        double turnTime = 1.4;        ///< when the operator steers in [s]
        double steerRamp = 0.08;      ///< time to reach full lock [s]
        double releaseHeading =
            1.13;                   ///< heading at which the wheel is centred again (65 deg) [rad]
        double releaseRamp = 0.15;  ///< time to centre the wheel [s]
        double counterSteer = 0.0;  ///< opposite lock applied to catch the spin (0: none)
        double counterDuration = 0.3;  ///< how long the counter-steer is held [s]
        double jitter = 1.0;           ///< scale of the seeded hand variation (0: exact script)
        double maxDuration = 8.0;      ///< recording stops by then in any case [s]
        double restTail = 0.5;         ///< kept recording at rest after the car stops [s]
    };

    /// Records one demonstration on a nominal slide-car (no perturbation) with this seed's hand
    /// variation.
    static core::Demonstration record(std::uint64_t seed, const Script& script,
                                      const SimulationTiming& timing = {},
                                      const SlideCarParameters& car = {});
    static core::Demonstration record(std::uint64_t seed, const SimulationTiming& timing = {}) {
        return record(seed, Script{}, timing);
    }
};

}  // namespace prisca::sim
