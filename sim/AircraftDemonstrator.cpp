#include "AircraftDemonstrator.h"

#include "DemonstrationRecorder.h"
#include "ScriptedInput.h"

#include <algorithm>
#include <cmath>
#include <random>

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

enum class Phase { FirstStraight, LeftTurn, MiddleStraight, RightTurn, FinalStraight };

}  // namespace

core::Demonstration AircraftDemonstrator::record(std::uint64_t seed, const Script& script,
                                                 const SimulationTiming& timing,
                                                 const PlanarAircraftParameters& parameters) {
    std::mt19937_64 draw(mixSeed(seed, 100));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double j = script.jitter;
    const double dt = timing.controlPeriod;
    // Per-flight variation: when the pilot starts each move and how hard they push.
    const double firstStraight = std::max(0.5, script.firstStraight + 0.3 * j * normal(draw));
    const double middleStraight = std::max(0.5, script.middleStraight + 0.3 * j * normal(draw));
    const double finalStraight = std::max(0.5, script.finalStraight + 0.3 * j * normal(draw));
    const double leftRudder = std::clamp(script.turnRudder + 0.04 * j * normal(draw), 0.05, 1.0);
    const double rightRudder = std::clamp(script.turnRudder + 0.04 * j * normal(draw), 0.05, 1.0);
    const double rollOutLead = std::max(0.0, script.rollOutLead + 0.04 * j * normal(draw));
    HandTremor rudderTremor(0.02 * j, 0.5, dt, mixSeed(seed, 101));
    HandTremor throttleTremor(0.015 * j, 1.0, dt, mixSeed(seed, 102));

    PlanarAircraft aircraft(parameters, timing);
    Eigen::VectorXd state = aircraft.reset(seed, Perturbation::none());
    DemonstrationRecorder recorder(aircraft.info(), dt);

    const double trim = PlanarAircraft::trimThrottle(parameters, script.cruiseSpeed);
    const double startHeading = state[2];
    const double hand = 1.0 - std::exp(-dt / script.handLag);
    Phase phase = Phase::FirstStraight;
    double phaseStart = 0.0;
    double targetHeading = startHeading;
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
            case Phase::FirstStraight:
                if (t - phaseStart >= firstStraight) {
                    phase = Phase::LeftTurn;
                    phaseStart = t;
                    targetHeading = startHeading + script.turnAngle;
                }
                break;
            case Phase::LeftTurn:
                if (targetHeading - psi <= rollOutLead) {
                    phase = Phase::MiddleStraight;
                    phaseStart = t;
                }
                break;
            case Phase::MiddleStraight:
                if (t - phaseStart >= middleStraight) {
                    phase = Phase::RightTurn;
                    phaseStart = t;
                    targetHeading = startHeading;
                }
                break;
            case Phase::RightTurn:
                if (psi - targetHeading <= rollOutLead) {
                    phase = Phase::FinalStraight;
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
        if (phase == Phase::LeftTurn) {
            wantedRudder = leftRudder * smoothStep(t, phaseStart, script.rudderRamp);
        } else if (phase == Phase::RightTurn) {
            wantedRudder = -rightRudder * smoothStep(t, phaseStart, script.rudderRamp);
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
