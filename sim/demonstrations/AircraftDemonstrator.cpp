#include "sim/demonstrations/AircraftDemonstrator.h"

#include "sim/demonstrations/DemonstrationRecorder.h"
#include "sim/demonstrations/ScriptedInput.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

namespace prisca::sim {

namespace {

// A slow random wander of a hand (first-order Gauss-Markov, exact step), rms sigma.
class HandTremor {
  public:
    HandTremor(double sigma, double timeConstant, double dt, std::uint64_t seed)
        : a_(std::exp(-dt / timeConstant)),
          drive_(sigma * std::sqrt(1.0 - a_ * a_)),
          random_(seed) {
        value_ = sigma * normal_(random_);
    }
    double next() {
        value_ = a_ * value_ + drive_ * normal_(random_);
        return value_;
    }

  private:
    double a_;
    double drive_;
    std::mt19937_64 random_;
    std::normal_distribution<double> normal_{0.0, 1.0};
    double value_ = 0.0;
};

enum class Phase { Straight, Turn, FinalStraight };

}  // namespace

core::Demonstration AircraftDemonstrator::record(std::uint64_t seed, const Script& script,
                                                 const SimulationTiming& timing,
                                                 const PlanarAircraftParameters& parameters,
                                                 const Perturbation& conditions) {
    std::mt19937_64 draw(mixSeed(seed, 100));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double j = script.jitter;
    const double dt = timing.controlPeriod;
    // Per-flight variation: when the pilot starts each move and how hard they push.
    // The draws keep the order of the original two-turn script (first, middle, final straight,
    // left and right rudder, roll-out lead), so an S-turn of a seed is the same flight as before.
    const int turns = static_cast<int>(script.turns.size());
    std::vector<double> straights(std::max(turns, 1));  // before each turn, then the final one
    std::vector<double> rudders(std::max(turns, 2));
    straights[0] = std::max(0.5, script.firstStraight + 0.3 * j * normal(draw));
    const double middle = std::max(0.5, script.middleStraight + 0.3 * j * normal(draw));
    const double finalStraight = std::max(0.5, script.finalStraight + 0.3 * j * normal(draw));
    rudders[0] = std::clamp(script.turnRudder + 0.04 * j * normal(draw), 0.05, 1.0);
    rudders[1] = std::clamp(script.turnRudder + 0.04 * j * normal(draw), 0.05, 1.0);
    const double rollOutLead = std::max(0.0, script.rollOutLead + 0.04 * j * normal(draw));
    for (int i = 1; i < turns; ++i) {
        straights[i] =
            i == 1 ? middle : std::max(0.5, script.middleStraight + 0.3 * j * normal(draw));
    }
    for (int i = 2; i < turns; ++i) {
        rudders[i] = std::clamp(script.turnRudder + 0.04 * j * normal(draw), 0.05, 1.0);
    }
    HandTremor rudderTremor(0.02 * j, 0.5, dt, mixSeed(seed, 101));
    HandTremor throttleTremor(0.015 * j, 1.0, dt, mixSeed(seed, 102));

    PlanarAircraft aircraft(parameters, timing);
    Eigen::VectorXd state = aircraft.reset(seed, conditions);
    DemonstrationRecorder recorder(aircraft.info(), dt);

    const double trim = PlanarAircraft::trimThrottle(parameters, script.cruiseSpeed);
    // A pilot flies only an aircraft that can hold the script's speed: say which part cannot.
    if (!(trim <= 1.0)) {
        char text[320];
        if (parameters.propellerPitchSpeed <= script.cruiseSpeed) {
            std::snprintf(text, sizeof text,
                          "this aircraft cannot fly the demonstration: its propeller gives no "
                          "thrust at %g m/s and above (propellerPitchSpeed), and the pilot "
                          "cruises at %g m/s",
                          parameters.propellerPitchSpeed, script.cruiseSpeed);
        } else {
            std::snprintf(text, sizeof text,
                          "this aircraft cannot fly the demonstration: full throttle does not "
                          "hold the pilot's cruise speed of %g m/s (it would take %.2g times "
                          "the thrust: staticThrust, propellerPitchSpeed, or the drag)",
                          script.cruiseSpeed, trim);
        }
        throw std::invalid_argument(text);
    }
    const double startHeading = state[2];
    const double hand = 1.0 - std::exp(-dt / script.handLag);
    Phase phase = turns > 0 ? Phase::Straight : Phase::FinalStraight;
    int turn = 0;  // the turn flown or next to fly
    double phaseStart = 0.0;
    double targetHeading = startHeading;
    double turnSign = 1.0;
    double rudder = 0.0;
    double throttle = trim;
    double speedIntegral = 0.0;
    Eigen::Vector2d action;
    for (int k = 0;; ++k) {
        const double t = k * dt;
        if (t > script.maxDuration) {
            break;
        }
        const double psi = state[2];
        const double r = state[5];
        const double speed = std::hypot(state[3], state[4]);

        // What the pilot looks at: time on the straights, heading still to go in the turns.
        switch (phase) {
            case Phase::Straight:
                if (t - phaseStart >= straights[turn]) {
                    phase = Phase::Turn;
                    phaseStart = t;
                    turnSign = script.turns[turn] >= 0.0 ? 1.0 : -1.0;
                    targetHeading += script.turns[turn];
                }
                break;
            case Phase::Turn:
                if (turnSign * (targetHeading - psi) <= rollOutLead) {
                    ++turn;
                    phase = turn < turns ? Phase::Straight : Phase::FinalStraight;
                    phaseStart = t;
                }
                break;
            case Phase::FinalStraight:
                break;
        }
        if (phase == Phase::FinalStraight && t - phaseStart >= finalStraight) {
            break;
        }

        double wantedRudder = 0.0;
        if (phase == Phase::Turn) {
            wantedRudder = turnSign * rudders[turn] * smoothStep(t, phaseStart, script.rudderRamp);
        } else {
            // Holding a heading: small, bounded corrections, as a pilot on a straight makes.
            wantedRudder = std::clamp(
                script.headingGain * (targetHeading - psi) - script.yawRateGain * r, -0.5, 0.5);
        }
        const double speedError = script.cruiseSpeed - speed;
        speedIntegral = std::clamp(speedIntegral + speedError * dt, -5.0, 5.0);
        const double wantedThrottle = std::clamp(
            trim + script.speedGain * speedError + script.speedIntegralGain * speedIntegral, 0.0,
            1.0);

        // The hand follows what the pilot wants with a lag, so every input is smooth.
        rudder += hand * (wantedRudder - rudder);
        throttle += hand * (wantedThrottle - throttle);
        action << std::clamp(throttle + throttleTremor.next(), 0.0, 1.0),
            std::clamp(rudder + rudderTremor.next(), -1.0, 1.0);
        recorder.record(state, action);
        state = aircraft.step(action);
    }
    return recorder.demonstration();
}

}  // namespace prisca::sim
