// The scripted operators of the slide-car, the acrobot and the aircraft: each style a change of
// its plant's default script (the catalog lists them; DemonstrationStyles looks them up by name).
#include "sim/demonstrations/ScriptedStyles.h"

#include "core/DeviationModel.h"
#include "sim/demonstrations/AcrobotDemonstrator.h"
#include "sim/demonstrations/AircraftDemonstrator.h"
#include "sim/demonstrations/SlideCarDemonstrator.h"

#include <QStringList>

#include <functional>
#include <stdexcept>

namespace prisca::sim {

namespace {

using core::kPi;

using CarScript = SlideCarDemonstrator::Script;
using ArmScript = AcrobotDemonstrator::Script;
using PilotScript = AircraftDemonstrator::Script;

// A named way of demonstrating: how it changes the plant's default script.
template <class Script>
struct Style {
    const char* name;
    const char* description;
    std::function<void(Script&)> adjust;
};
using CarStyle = Style<CarScript>;
using ArmStyle = Style<ArmScript>;
using PilotStyle = Style<PilotScript>;

// Slide-car operators. Rotation is set by when the wheel is centred (and a counter-steer to
// catch a 90-degree slide); the approach by throttle and how long the straight is.
const std::vector<CarStyle>& carStyles() {
    static const std::vector<CarStyle> styles = {
        {"stick-180-left", "analogue stick, 180 deg slide to the left (the classic)",
         [](CarScript&) {}},
        {"keyboard-180-right", "keyboard keys with the window's ramp, 180 deg slide to the right",
         [](CarScript& s) {
             s.keyboard = true;
             s.direction = -1.0;
             s.releaseHeading = 1.0;
         }},
        {"standstill-180-left", "a wait at standstill first, then a 180 deg slide to the left",
         [](CarScript& s) { s.standstill = 1.0; }},
        {"stick-90-left", "analogue stick, a moderate approach and about 90 deg to the left",
         [](CarScript& s) {
             s.launchThrottle = 0.6;
             s.turnTime = 1.0;
             s.releaseHeading = 1.2;
         }},
        {"keyboard-90-right", "keyboard keys tapped for part throttle, about 90 deg to the right",
         [](CarScript& s) {
             s.keyboard = true;
             s.direction = -1.0;
             s.launchThrottle = 0.6;
             s.turnTime = 1.0;
             s.releaseHeading = 1.2;
         }},
        {"fast-180-right", "a long, fast approach on full throttle, 180 deg to the right",
         [](CarScript& s) {
             s.direction = -1.0;
             s.launchThrottle = 1.0;
             s.turnTime = 1.8;
             s.releaseHeading = 1.2;
         }},
        {"slow-90-left", "a long, slow approach, about 90 deg to the left",
         [](CarScript& s) {
             s.launchThrottle = 0.5;
             s.turnTime = 1.8;
             s.releaseHeading = 1.0;
         }},
        {"blip-180-left", "a throttle blip in the slide, 180 deg to the left",
         [](CarScript& s) {
             s.blipThrottle = 0.5;
             s.blipDelay = 0.25;
             s.blipDuration = 0.15;
         }},
        {"jitter-180-right", "a shaking hand on both sticks, 180 deg to the right",
         [](CarScript& s) {
             s.direction = -1.0;
             s.stickJitter = 0.06;
         }},
        {"coast-90-right", "throttle off early, coasting into a 90 deg slide to the right",
         [](CarScript& s) {
             s.direction = -1.0;
             s.turnTime = 1.0;
             s.coastTime = 0.4;
             s.releaseHeading = 1.2;
         }},
    };
    return styles;
}

const std::vector<ArmStyle>& armStyles() {
    static const std::vector<ArmStyle> styles = {
        {"swing-medium", "a swing growing to about 50 deg at the shoulder (the classic)",
         [](ArmScript&) {}},
        {"swing-small", "a gentle swing of about 25 deg",
         [](ArmScript& s) {
             s.shoulderAmplitude = 0.45;
             s.elbowAmplitude = 0.3;
         }},
        {"swing-large", "a large swing of about 75 deg, grown quickly",
         [](ArmScript& s) {
             s.shoulderAmplitude = 1.35;
             s.elbowAmplitude = 0.9;
             s.growTime = 4.0;
         }},
        {"swing-fast", "a faster swing (2.4 s period) with a stiffer hand",
         [](ArmScript& s) {
             s.period = 2.4;
             s.shoulderStiffness = 30.0;
             s.elbowStiffness = 15.0;
         }},
    };
    return styles;
}

const std::vector<PilotStyle>& pilotStyles() {
    static const std::vector<PilotStyle> styles = {
        {"s-turn", "a left and a right half circle (the classic)", [](PilotScript&) {}},
        {"circle", "one full circle to the left",
         [](PilotScript& s) {
             s.turns = {2.0 * kPi};
             s.finalStraight = 4.0;
         }},
        {"figure-eight", "a full circle to the left, then one to the right (climb-free)",
         [](PilotScript& s) {
             s.turns = {2.0 * kPi, -2.0 * kPi};
             s.middleStraight = 1.0;
             s.maxDuration = 60.0;
         }},
        {"s-turn-wide", "a gentle S-turn with less rudder and longer straights",
         [](PilotScript& s) {
             s.turnRudder = 0.45;
             s.firstStraight = 4.0;
             s.middleStraight = 4.0;
             s.maxDuration = 60.0;
         }},
    };
    return styles;
}

template <class Style>
std::vector<DemonstrationStyle> describe(const std::vector<Style>& styles) {
    std::vector<DemonstrationStyle> out;
    for (const Style& s : styles) {
        out.push_back({QString::fromLatin1(s.name), QString::fromLatin1(s.description)});
    }
    return out;
}

template <class Style>
const Style* find(const std::vector<Style>& styles, const QString& name) {
    for (const Style& s : styles) {
        if (name == QLatin1String(s.name)) {
            return &s;
        }
    }
    return nullptr;
}

// An unknown style of a plant, named with the plant's styles.
template <class Style>
[[noreturn]] void unknownStyle(const std::vector<Style>& styles, const QString& plant,
                               const QString& style) {
    QStringList known;
    for (const Style& s : styles) {
        known << QString::fromLatin1(s.name);
    }
    throw std::invalid_argument(QStringLiteral("unknown %1 style '%2' (one of: %3)")
                                    .arg(plant, style, known.join(QLatin1Char(' ')))
                                    .toStdString());
}

}  // namespace

namespace {

// The script of a style, recorded by its plant's demonstrator.
template <class Demonstrator, class Script, class Typed>
core::Demonstration recordStyle(const std::vector<Style<Script>>& styles, const QString& plant,
                                const QString& style, std::uint64_t seed,
                                const SimulationTiming& timing,
                                const RecordingConditions& conditions,
                                Typed (*typed)(const PlantParameters&)) {
    const Style<Script>* s = find(styles, style);
    if (!s) {
        unknownStyle(styles, plant, style);
    }
    Script script;
    s->adjust(script);
    return Demonstrator::record(seed, script, timing,
                                conditions.parameters ? typed(*conditions.parameters) : Typed{},
                                conditions.perturbation);
}

}  // namespace

StyleSet slideCarStyles() {
    return {[] { return describe(carStyles()); },
            [](const QString& style, std::uint64_t seed, const SimulationTiming& timing,
               const RecordingConditions& conditions) {
                return recordStyle<SlideCarDemonstrator>(carStyles(), QStringLiteral("slidecar"),
                                                         style, seed, timing, conditions,
                                                         &slideCarParameters);
            }};
}

StyleSet acrobotStyles() {
    return {[] { return describe(armStyles()); },
            [](const QString& style, std::uint64_t seed, const SimulationTiming& timing,
               const RecordingConditions& conditions) {
                return recordStyle<AcrobotDemonstrator>(armStyles(), QStringLiteral("acrobot"),
                                                        style, seed, timing, conditions,
                                                        &acrobotParameters);
            }};
}

StyleSet aircraftStyles() {
    return {[] { return describe(pilotStyles()); },
            [](const QString& style, std::uint64_t seed, const SimulationTiming& timing,
               const RecordingConditions& conditions) {
                return recordStyle<AircraftDemonstrator>(pilotStyles(), QStringLiteral("aircraft"),
                                                         style, seed, timing, conditions,
                                                         &aircraftParameters);
            }};
}

}  // namespace prisca::sim
