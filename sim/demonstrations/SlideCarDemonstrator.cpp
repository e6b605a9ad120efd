#include "sim/demonstrations/SlideCarDemonstrator.h"

#include "sim/demonstrations/DemonstrationRecorder.h"
#include "sim/demonstrations/ScriptedInput.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace prisca::sim {

core::Demonstration SlideCarDemonstrator::record(std::uint64_t seed, const Script& script,
                                                 const SimulationTiming& timing,
                                                 const SlideCarParameters& parameters,
                                                 const Perturbation& conditions) {
    std::mt19937_64 draw(mixSeed(seed, 100));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double j = script.jitter;
    const double dt = timing.controlPeriod;
    // The wait at the line varies too (its own stream, so a script without one keeps its draws).
    std::mt19937_64 waitDraw(mixSeed(seed, 102));
    const double launch =
        script.standstill > 0.0 ? script.standstill * (1.0 + 0.1 * j * normal(waitDraw)) : 0.0;
    const double turnTime = launch + script.turnTime + 0.03 * j * normal(draw);
    const double releaseHeading = script.releaseHeading + 0.05 * j * normal(draw);
    const double throttleLevel =
        std::clamp(script.launchThrottle + 0.02 * j * normal(draw), 0.0, 1.0);
    const double side = script.direction >= 0.0 ? 1.0 : -1.0;
    // Hand tremor on the straight: a slow random wobble of the wheel.
    const double wobbleAmplitude = 0.015 * j;
    const double wobbleFrequency = 0.7 + 0.3 * std::abs(normal(draw));
    const double wobblePhase = 6.283 * std::abs(normal(draw));
    // A shaking hand: a first-order filtered noise of about 8 Hz bandwidth on both sticks.
    const double shakeDecay = std::exp(-dt * 2.0 * 3.14159265358979 * 8.0);
    const double shakeKick = script.stickJitter * std::sqrt(1.0 - shakeDecay * shakeDecay);
    std::mt19937_64 shakeDraw(mixSeed(seed, 101));
    Eigen::Vector2d shake(script.stickJitter * normal(shakeDraw),
                          script.stickJitter * normal(shakeDraw));

    SlideCar car(parameters, timing);
    car.reset(seed, conditions);
    DemonstrationRecorder recorder(car.info(), dt);

    double releaseStart = -1.0;
    double restSince = -1.0;
    Eigen::VectorXd state = car.state();
    Eigen::Vector2d keys = Eigen::Vector2d::Zero();  // keyboard controls as ramped
    Eigen::Vector2d action;
    for (int k = 0;; ++k) {
        const double t = k * dt;
        if (t > script.maxDuration) {
            break;
        }
        if (releaseStart < 0.0 && t > turnTime && side * state[2] >= releaseHeading) {
            releaseStart = t;  // the operator sees the car has turned far enough
        }
        double throttle = 0.0;
        double steering = 0.0;
        const double throttleOff = turnTime - script.coastTime;
        if (t < launch) {
            // Waiting at the line.
        } else if (t < turnTime) {
            throttle = throttleLevel * smoothStep(t, launch, script.launchRamp) *
                       (1.0 - smoothStep(t, throttleOff, 0.05));
            steering = wobbleAmplitude * std::sin(6.283 * wobbleFrequency * t + wobblePhase);
        } else {
            throttle = script.coastTime > 0.0
                           ? 0.0
                           : throttleLevel * (1.0 - smoothStep(t, turnTime, 0.05));
            if (script.blipThrottle > 0.0) {
                const double blipStart = turnTime + script.blipDelay;
                throttle += script.blipThrottle * smoothStep(t, blipStart, 0.04) *
                            (1.0 - smoothStep(t, blipStart + script.blipDuration, 0.04));
            }
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
            steering *= side;
        }
        if (script.keyboard) {
            // Keys have no shades: the operator holds one while the control is short of what
            // they want and lets go once it is past, so a part throttle becomes a sawtooth.
            keys[0] = keyRamp(keys[0], keyFor(throttle, keys[0]), dt);
            keys[1] = keyRamp(keys[1], keyFor(steering, keys[1]), dt);
            throttle = keys[0];
            steering = keys[1];
        } else if (script.stickJitter > 0.0 && t >= launch) {
            throttle += shake[0];
            steering += shake[1];
        }
        shake[0] = shakeDecay * shake[0] + shakeKick * normal(shakeDraw);
        shake[1] = shakeDecay * shake[1] + shakeKick * normal(shakeDraw);
        if (restSince >= 0.0 && script.stickJitter > 0.0) {
            // Parked: the shaking hand lets go of the sticks.
            throttle = 0.0;
            steering = 0.0;
        }
        action << std::clamp(throttle, -1.0, 1.0), std::clamp(steering, -1.0, 1.0);
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
