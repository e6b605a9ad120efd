#pragma once

#include "core/Demonstration.h"
#include "sim/plants/Acrobot.h"
#include "sim/plants/Plant.h"

#include <cstdint>

namespace prisca::sim {

/// A scripted person swinging the simulated acrobot (docs/architecture.md "scripted demonstrator").
/// They have a smooth swing in mind: the shoulder swings with an amplitude that grows from 0 to
/// about 50 degrees over the first 5.5 s and is then held, the elbow counter-swings a little behind
/// it (aimed at 35 degrees, about 25 reached), near the arm's slow natural period. They push each
/// joint towards that swing with a soft PD-like torque (they know nothing of the dynamics), and
/// their hand adds a small, slowly wandering torque jitter that differs with every seed. The
/// torques stay within the plant's limits (the recorded action is the torque commanded, already
/// clamped).
class AcrobotDemonstrator {
  public:
    /// Tuning of the scripted swing. Plain data.
    struct Script {
        double duration = 8.0;            ///< length of the recording [s]
        double shoulderAmplitude = 0.9;   ///< final shoulder swing amplitude [rad]
        double elbowAmplitude = 0.6;      ///< final elbow counter-swing amplitude [rad]
        double elbowLag = 0.4;            ///< phase by which the elbow trails the shoulder [rad]
        double period = 3.0;              ///< swing period [s] (the slow mode's is 3.3 s)
        double growTime = 5.5;            ///< time for the swing to grow to full amplitude [s]
        double shoulderStiffness = 25.0;  ///< Kp at the shoulder [N m/rad]
        double shoulderDamping = 6.0;     ///< Kd at the shoulder [N m s/rad]
        double elbowStiffness = 12.0;     ///< Kp at the elbow [N m/rad]
        double elbowDamping = 3.0;        ///< Kd at the elbow [N m s/rad]
        double jitter = 0.2;              ///< std of the hand's torque jitter [N m] (0: exact)
        double jitterCorrelation = 0.15;  ///< correlation time of the jitter [s]
    };

    /// Records one demonstration on a nominal acrobot (Perturbation::none(), both joints driven)
    /// with this seed's hand jitter.
    static core::Demonstration record(std::uint64_t seed, const SimulationTiming& timing = {});
    /// The same with a given script and arm.
    static core::Demonstration record(std::uint64_t seed, const Script& script,
                                      const SimulationTiming& timing = {},
                                      const AcrobotParameters& arm = {},
                                      const Perturbation& conditions = Perturbation::none());
};

}  // namespace prisca::sim
