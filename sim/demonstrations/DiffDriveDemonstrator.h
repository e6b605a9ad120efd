#pragma once

#include "core/Demonstration.h"
#include "sim/demonstrations/ScriptedStyles.h"
#include "sim/plants/DiffDrive.h"

#include <cstdint>

namespace prisca::sim {

/// A scripted operator who docks the differential-drive robot once with a two-axis stick (push:
/// forward speed; sideways: turn rate; the robot mixes them into its wheels): off the line along
/// +x, a turn until the robot faces the dock, a last straight into it and a stop. The dock is
/// the final pose. Inputs differ a little for every seed (reaction times, how far the stick is
/// pushed), as a person's would; the styles cover left or right, how far it turns, turning on
/// the spot, keys instead of a stick, an S-bend and a slow, careful approach.
class DiffDriveDemonstrator {
  public:
    /// Tuning of the scripted operator. Plain data.
    struct Script {
        double standstill = 0.0;      ///< time standing still before the start [s]
        double speed = 0.8;           ///< stick forward on the first straight [1]
        double straightTime = 2.0;    ///< first straight [s]
        double turnSpeed = 0.5;       ///< stick forward while turning (0: on the spot) [1]
        double turnRate = 0.4;        ///< stick sideways while turning [1]
        double direction = 1.0;       ///< +1 turns left, -1 right
        double turnHeading = 1.5708;  ///< heading turned at which the operator straightens [rad]
        /// An S-bend: after the first turn, the same turn the other way back to this heading.
        bool sBend = false;
        double finalSpeed = 0.6;  ///< stick forward on the last straight [1]
        double finalTime = 1.5;   ///< last straight [s]
        double ramp = 0.2;        ///< time for each stick move [s]
        /// Keys instead of a stick: each axis ramps towards full while its key is held and back
        /// to neutral when released, as the window's keyboard driving does.
        bool keyboard = false;
        double jitter = 1.0;        ///< scale of the seeded hand variation (0: exact script)
        double maxDuration = 14.0;  ///< recording stops by then in any case [s]
        double restTail = 0.5;      ///< kept recording at rest after the robot stops [s]
    };

    /// Records one demonstration on a nominal robot with this seed's hand variation.
    static core::Demonstration record(std::uint64_t seed, const Script& script,
                                      const SimulationTiming& timing = {},
                                      const DiffDriveParameters& robot = {},
                                      const Perturbation& conditions = Perturbation::none());
};

/// The differential-drive robot's demonstration styles (its PlantCatalog entry holds them).
StyleSet diffDriveStyles();

}  // namespace prisca::sim
