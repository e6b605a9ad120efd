#include "SlideCarDemonstrator.h"

#include "DemonstrationRecorder.h"
#include "ScriptedInput.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace prisca::sim {

core::Demonstration SlideCarDemonstrator::record(std::uint64_t seed, const Script& script,
                                                 const SimulationTiming& timing,
                                                 const SlideCarParameters& parameters) {
    std::mt19937_64 draw(mixSeed(seed, 100));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double j = script.jitter;
    const double turnTime = script.turnTime + 0.03 * j * normal(draw);
    const double releaseHeading = script.releaseHeading + 0.05 * j * normal(draw);
    const double throttleLevel =
        std::clamp(script.launchThrottle + 0.02 * j * normal(draw), 0.0, 1.0);
    // Hand tremor on the straight: a slow random wobble of the wheel.
    const double wobbleAmplitude = 0.015 * j;
    const double wobbleFrequency = 0.7 + 0.3 * std::abs(normal(draw));
    const double wobblePhase = 6.283 * std::abs(normal(draw));

    SlideCar car(parameters, timing);
    car.reset(seed, Perturbation::none());
    DemonstrationRecorder recorder(car.info(), timing.controlPeriod);

    double releaseStart = -1.0;
    double restSince = -1.0;
    Eigen::VectorXd state = car.state();
    Eigen::Vector2d action;
    for (int k = 0;; ++k) {
        const double t = k * timing.controlPeriod;
        if (t > script.maxDuration) {
            break;
        }
        if (releaseStart < 0.0 && t > turnTime && state[2] >= releaseHeading) {
            releaseStart = t;  // the operator sees the car has turned far enough
        }
        double throttle = 0.0;
        double steering = 0.0;
        if (t < turnTime) {
            throttle = throttleLevel * smoothStep(t, 0.0, script.launchRamp);
            steering = wobbleAmplitude * std::sin(6.283 * wobbleFrequency * t + wobblePhase);
        } else {
            throttle = throttleLevel * (1.0 - smoothStep(t, turnTime, 0.05));
            steering = smoothStep(t, turnTime, script.steerRamp);
            if (releaseStart >= 0.0) {
                // Full lock -> opposite lock -> centre, each move a smooth hand motion.
                const double toCounter = smoothStep(t, releaseStart, script.releaseRamp);
                const double toCentre =
                    smoothStep(t, releaseStart + script.releaseRamp + script.counterDuration,
                               script.releaseRamp);
                steering = (1.0 - toCounter) * steering -
                           script.counterSteer * toCounter * (1.0 - toCentre);
            }
        }
        action << throttle, steering;
        recorder.record(state, action);
        state = car.step(action);
        if (t > turnTime && car.atRest()) {
            if (restSince < 0.0) {
                restSince = t;
            } else if (t - restSince >= script.restTail) {
                break;
            }
        }
    }
    return recorder.demonstration();
}

}  // namespace prisca::sim
