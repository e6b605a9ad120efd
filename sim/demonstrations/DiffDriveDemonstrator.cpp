#include "sim/demonstrations/DiffDriveDemonstrator.h"

#include "sim/demonstrations/DemonstrationRecorder.h"
#include "sim/demonstrations/ScriptedInput.h"
#include "sim/plants/PlantParameters.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

namespace prisca::sim {

namespace {

struct DriveStyle {
    const char* name;
    const char* description;
    std::function<void(DiffDriveDemonstrator::Script&)> adjust;
};

const std::vector<DriveStyle>& styles() {
    using Script = DiffDriveDemonstrator::Script;
    static const std::vector<DriveStyle> all = {
        {"dock-90-left", "a straight, a 90 deg turn to the left and into the dock (the classic)",
         [](Script&) {}},
        {"dock-90-right", "the same to the right", [](Script& s) { s.direction = -1.0; }},
        {"u-turn-left", "a 180 deg turn to the left and back into a dock beside the start",
         [](Script& s) {
             s.turnHeading = 3.1416;
             s.straightTime = 1.5;
         }},
        {"spin-90-right", "stop, turn 90 deg to the right on the spot, drive into the dock",
         [](Script& s) {
             s.direction = -1.0;
             s.turnSpeed = 0.0;
             s.turnRate = 0.5;
         }},
        {"keyboard-90-left", "keys with the window's ramp, 90 deg to the left",
         [](Script& s) { s.keyboard = true; }},
        {"s-bend-left", "an S-bend: 45 deg to the left and back to the starting heading",
         [](Script& s) {
             s.turnHeading = 0.7854;
             s.sBend = true;
             s.straightTime = 1.5;
         }},
        {"slow-90-right", "a slow, careful approach, 90 deg to the right",
         [](Script& s) {
             s.direction = -1.0;
             s.speed = 0.4;
             s.turnSpeed = 0.3;
             s.turnRate = 0.25;
             s.finalSpeed = 0.3;
             s.straightTime = 3.0;
             s.finalTime = 2.5;
         }},
    };
    return all;
}

}  // namespace

core::Demonstration DiffDriveDemonstrator::record(std::uint64_t seed, const Script& script,
                                                  const SimulationTiming& timing,
                                                  const DiffDriveParameters& parameters,
                                                  const Perturbation& conditions) {
    std::mt19937_64 draw(mixSeed(seed, 100));
    std::normal_distribution<double> normal(0.0, 1.0);
    const double j = script.jitter;
    const double dt = timing.controlPeriod;
    const double start = script.standstill;
    const double straightEnd = start + script.straightTime * (1.0 + 0.05 * j * normal(draw));
    const double turnHeading = script.turnHeading + 0.03 * j * normal(draw);
    const double speed = std::clamp(script.speed + 0.03 * j * normal(draw), 0.0, 1.0);
    const double turnRate = std::clamp(script.turnRate + 0.03 * j * normal(draw), 0.05, 1.0);
    const double finalTime = script.finalTime * (1.0 + 0.05 * j * normal(draw));
    const double side = script.direction >= 0.0 ? 1.0 : -1.0;
    // The operator lets go of the turn a little early: the robot turns on while the stick comes
    // back and the wheels catch up.
    const double anticipation = 0.8 * turnRate * (script.turnSpeed > 0.0 ? 1.0 : 0.6);

    DiffDrive robot(parameters, timing);
    robot.reset(seed, conditions);
    DemonstrationRecorder recorder(robot.info(), dt);

    // Phases: 0 straight, 1 turn, 2 turn back (S-bend), 3 last straight, 4 stop.
    int phase = 0;
    double phaseStart = start;
    double restSince = -1.0;
    double keyForward = 0.0, keyTurn = 0.0;
    Eigen::VectorXd state = robot.state();
    Eigen::Vector2d action;
    for (int k = 0;; ++k) {
        const double t = k * dt;
        if (t > script.maxDuration) {
            break;
        }
        const double heading = side * state[2];
        if (phase == 0 && t >= straightEnd) {
            phase = 1;
            phaseStart = t;
        } else if (phase == 1 && heading >= turnHeading - anticipation) {
            phase = script.sBend ? 2 : 3;
            phaseStart = t;
        } else if (phase == 2 && heading <= anticipation) {
            phase = 3;
            phaseStart = t;
        } else if (phase == 3 && t >= phaseStart + finalTime) {
            phase = 4;
            phaseStart = t;
        }
        double forward = 0.0, turn = 0.0;
        const double in = smoothStep(t, phaseStart, script.ramp);
        switch (phase) {
            case 0:
                forward = t < start ? 0.0 : speed * smoothStep(t, start, script.ramp);
                break;
            case 1:
                forward = speed + (script.turnSpeed - speed) * in;
                turn = side * turnRate * in;
                break;
            case 2:
                forward = script.turnSpeed;
                turn = -side * turnRate * in;
                break;
            case 3:
                forward = script.turnSpeed + (script.finalSpeed - script.turnSpeed) * in;
                turn = (script.sBend ? -side : side) * turnRate * (1.0 - in);
                break;
            default:
                forward = script.finalSpeed * (1.0 - in);
                break;
        }
        if (script.keyboard) {
            keyForward = keyRamp(keyForward, keyFor(forward, keyForward), dt);
            keyTurn = keyRamp(keyTurn, keyFor(turn, keyTurn), dt);
            forward = keyForward;
            turn = keyTurn;
        }
        // The robot mixes the stick into its wheels.
        action << std::clamp(forward - turn, -1.0, 1.0), std::clamp(forward + turn, -1.0, 1.0);
        recorder.record(state, action);
        state = robot.step(action);
        if (phase == 4 && robot.atRest()) {
            if (restSince < 0.0) {
                restSince = t;
            } else if (t - restSince >= script.restTail) {
                break;
            }
        }
    }
    return recorder.demonstration();
}

StyleSet diffDriveStyles() {
    return {
        [] {
            std::vector<DemonstrationStyle> out;
            for (const DriveStyle& s : styles()) {
                out.push_back({QString::fromLatin1(s.name), QString::fromLatin1(s.description)});
            }
            return out;
        },
        [](const QString& style, std::uint64_t seed, const SimulationTiming& timing,
           const RecordingConditions& conditions) {
            for (const DriveStyle& s : styles()) {
                if (style == QLatin1String(s.name)) {
                    DiffDriveDemonstrator::Script script;
                    s.adjust(script);
                    return DiffDriveDemonstrator::record(
                        seed, script, timing,
                        conditions.parameters ? diffDriveParameters(*conditions.parameters)
                                              : DiffDriveParameters{},
                        conditions.perturbation);
                }
            }
            QStringList known;
            for (const DriveStyle& s : styles()) {
                known << QString::fromLatin1(s.name);
            }
            throw std::invalid_argument(QStringLiteral("unknown diffdrive style '%1' (one of: %2)")
                                            .arg(style, known.join(QLatin1Char(' ')))
                                            .toStdString());
        }};
}

}  // namespace prisca::sim
