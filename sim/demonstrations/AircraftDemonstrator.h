#pragma once

#include "core/Demonstration.h"
#include "sim/plants/PlanarAircraft.h"
#include "sim/plants/Plant.h"

#include <cstdint>
#include <vector>

namespace prisca::sim {

/// A scripted pilot who flies the planar aircraft through an S-turn once (docs/architecture.md
/// "scripted demonstrator"; the paper's desired UAV trajectory, Fig. 4): a straight along +x, a
/// left turn of about 180 deg, a straight back along -x, a right turn of about 180 deg, and a final
/// straight along +x again; about 26 s at the control rate in still air (Perturbation::none()).
/// The rudder is moved in and out with smooth hand motions and held through each turn; the pilot
/// eases it out a little before the new heading and then holds that heading with small
/// corrections. The throttle is worked to hold the cruise speed (more power in the turns). Inputs
/// carry seeded hand jitter and timing variation, as a person's would.
class AircraftDemonstrator {
  public:
    /// Tuning of the scripted pilot. Plain data.
    struct Script {
        double cruiseSpeed = 17.0;    ///< speed the pilot holds [m/s]
        double firstStraight = 3.0;   ///< straight before the first turn [s]
        double middleStraight = 3.0;  ///< straight between two turns, from the roll-out [s]
        double finalStraight = 3.0;   ///< straight after the last turn, from the roll-out [s]
        /// The turns flown in order: heading change of each, positive to the left [rad]. The
        /// S-turn is a left and a right half circle; a circle is one full left turn; a figure
        /// eight a full left and a full right turn.
        std::vector<double> turns = {3.14159265358979323846, -3.14159265358979323846};
        double turnRudder = 0.7;          ///< rudder held through the turns, in (0, 1] [1]
        double rudderRamp = 0.6;          ///< time to move the rudder into the turn [s]
        double rollOutLead = 0.35;        ///< heading still to go when easing out of a turn [rad]
        double headingGain = 2.5;         ///< heading hold: rudder per heading error [1/rad]
        double yawRateGain = 0.3;         ///< heading hold: rudder per yaw rate [s/rad]
        double handLag = 0.2;             ///< time constant of the pilot's hand on both sticks [s]
        double speedGain = 0.15;          ///< throttle per speed error [s/m]
        double speedIntegralGain = 0.08;  ///< throttle per integrated speed error [1/m]
        double jitter = 1.0;              ///< scale of the seeded hand variation (0: exact script)
        double maxDuration = 30.0;        ///< recording stops by then in any case [s]
    };

    /// Records one demonstration on a nominal aircraft in still air with this seed's hand
    /// variation. The nominal start: origin, heading 0, 17 m/s.
    static core::Demonstration record(std::uint64_t seed, const Script& script,
                                      const SimulationTiming& timing = {},
                                      const PlanarAircraftParameters& aircraft = {},
                                      const Perturbation& conditions = Perturbation::none());
    static core::Demonstration record(std::uint64_t seed, const SimulationTiming& timing = {}) {
        return record(seed, Script{}, timing);
    }
};

}  // namespace prisca::sim
