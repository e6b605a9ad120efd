#include "sim/plants/PlantParameters.h"
#include "sim/plants/PlantParameters_p.h"

#include "core/FileIo.h"
#include "sim/plants/Acrobot.h"
#include "sim/plants/DiffDrive.h"
#include "sim/plants/PlanarAircraft.h"
#include "sim/plants/SlideCar.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace prisca::sim {

using parameters::number;
using parameters::withUnit;

namespace {

// One declared parameter of a plant's typed parameters struct P.
template <class P>
struct Field {
    const char* key;
    const char* unit;
    double lower;
    double upper;
    const char* description;
    double& (*ref)(P&);
    /// An effect the identification model leaves out: in the file's "unmodelled" group, with
    /// the value a real plant of this size has and where that value comes from.
    bool unmodelled = false;
    double realistic = 0.0;
    const char* realisticSource = "";
};

// The slide-car's parameters: a 1:10 to 1:8 car. The ranges keep the model physical (positive
// masses and lengths, a friction below 2) and Box2D's single-precision body well conditioned.
const std::vector<Field<SlideCarParameters>>& slideCarFields() {
    using P = SlideCarParameters;
    static const std::vector<Field<P>> fields = {
        {"mass", "kg", 0.3, 10.0, "mass of the car, battery included",
         [](P& p) -> double& { return p.mass; }},
        {"yawInertia", "kg m^2", 0.0, 2.0,
         "moment of inertia about the vertical axis through the centre of mass (0: a uniform box "
         "of the body's length and width)",
         [](P& p) -> double& { return p.yawInertia; }},
        {"length", "m", 0.1, 1.0, "body length (drawing, the uniform-box inertia)",
         [](P& p) -> double& { return p.length; }},
        {"width", "m", 0.05, 0.6, "body width, about the track (drawing, the uniform-box inertia)",
         [](P& p) -> double& { return p.width; }},
        {"wheelbase", "m", 0.08, 0.8, "front to rear axle",
         [](P& p) -> double& { return p.wheelbase; }},
        {"cgForward", "m", -0.3, 0.3,
         "centre of mass ahead of the wheelbase's midpoint (negative: behind it)",
         [](P& p) -> double& { return p.cgForward; }},
        {"cgHeight", "m", 0.0, 0.3, "centre of mass above the floor (load transfer)",
         [](P& p) -> double& { return p.cgHeight; }},
        {"staticFriction", "1", 0.05, 2.0, "front tyres' static friction coefficient",
         [](P& p) -> double& { return p.staticFriction; }},
        {"kineticFriction", "1", 0.05, 2.0, "front tyres' sliding friction coefficient",
         [](P& p) -> double& { return p.kineticFriction; }},
        {"rearStaticGrip", "1", 0.2, 2.0, "rear tyres' static friction as a share of the front's",
         [](P& p) -> double& { return p.rearGripRatio; }},
        {"rearKineticGrip", "1", 0.2, 2.0, "rear tyres' sliding friction as a share of the front's",
         [](P& p) -> double& { return p.rearKineticGripRatio; }},
        {"maxDriveForce", "N", 0.5, 100.0,
         "traction of all four wheels at standstill and full throttle",
         [](P& p) -> double& { return p.maxDriveForce; }},
        {"topSpeed", "m/s", 0.5, 40.0, "speed at which full throttle gives no more force",
         [](P& p) -> double& { return p.topSpeed; }},
        {"maxSteeringAngle", "rad", 0.05, 1.0, "front-wheel angle at full steering (steering lock)",
         [](P& p) -> double& { return p.maxSteeringAngle; }},
        {"servoRate", "rad/s", 0.5, 50.0, "slew rate of the front-wheel angle",
         [](P& p) -> double& { return p.servoRate; }},
        {"servoDelay", "s", 0.0, 0.2, "dead time of steering commands",
         [](P& p) -> double& { return p.servoDelay; }},
        {"throttleDelay", "s", 0.0, 0.2, "dead time of the speed controller",
         [](P& p) -> double& { return p.throttleDelay; }},
        {"rollingResistance", "1", 0.0, 0.5, "coefficient of rolling resistance",
         [](P& p) -> double& { return p.rollingResistance; }},
        {"drivelineDrag", "N s/m", 0.0, 10.0, "viscous drag of motor and gears when coasting",
         [](P& p) -> double& { return p.drivelineDrag; }},
        // The reality gap (docs/architecture.md "Plants"): each off at its catalog value.
        {"tyreStiffness", "1/rad", 0.0, 40.0,
         "tyres on a saturating Magic Formula curve coupling drive and side slip: cornering "
         "stiffness per unit load (0: Coulomb stick-slip)",
         [](P& p) -> double& { return p.tyreStiffness; }, true, 8.0,
         "rubber tyres' cornering stiffness is 5-20 per rad per unit load; small, soft, "
         "low-pressure tyres sit low in that range"},
        {"servoBacklash", "rad", 0.0, 0.2,
         "play in the steering linkage the servo must take up before the wheels turn (0: none)",
         [](P& p) -> double& { return p.servoBacklash; }, true, 0.035,
         "a hobby servo's dead band with a plastic linkage and ball joints leaves 1-3 deg of "
         "wheel angle"},
        {"motorStallRatio", "1", 1.0, 5.0,
         "the brushed motor's stall force as a multiple of the ESC's current limit: flat, then "
         "falling steeply with speed (1: the linear law)",
         [](P& p) -> double& { return p.motorStallRatio; }, true, 2.0,
         "a 540-size brushed motor stalls at 40-80 A; hobby car ESCs limit the current to 20-40 "
         "A"},
        {"escDeadband", "1", 0.0, 0.3,
         "the ESC's neutral band as a share of full throttle (0: none)",
         [](P& p) -> double& { return p.escDeadband; }, true, 0.05,
         "hobby car ESCs ship with a neutral range of 3-8 % of full throttle"},
        {"patchFriction", "1", 0.3, 1.5,
         "grip of every other square of floor as a share of the rest (1: an even floor)",
         [](P& p) -> double& { return p.patchFriction; }, true, 0.85,
         "a lab floor's friction varies 10-20 % between clean and dusty areas, tape and mats"},
        {"patchSize", "m", 0.05, 5.0, "side of the floor's squares of other grip",
         [](P& p) -> double& { return p.patchSize; }, true, 0.5,
         "floor tiles and mats are 0.3-1 m across"},
    };
    return fields;
}

// The acrobot's arm: the book's constants by default.
const std::vector<Field<AcrobotParameters>>& acrobotFields() {
    using P = AcrobotParameters;
    static const std::vector<Field<P>> fields = {
        {"m1", "kg", 0.05, 20.0, "mass of link 1", [](P& p) -> double& { return p.links.m1; }},
        {"m2", "kg", 0.05, 20.0, "mass of link 2", [](P& p) -> double& { return p.links.m2; }},
        {"l1", "m", 0.1, 5.0, "length of link 1, shoulder to elbow",
         [](P& p) -> double& { return p.links.l1; }},
        {"l2", "m", 0.1, 5.0, "length of link 2, elbow to tip",
         [](P& p) -> double& { return p.links.l2; }},
        {"lc1", "m", 0.01, 5.0, "shoulder to link 1's centre of mass",
         [](P& p) -> double& { return p.links.lc1; }},
        {"lc2", "m", 0.01, 5.0, "elbow to link 2's centre of mass",
         [](P& p) -> double& { return p.links.lc2; }},
        {"I1", "kg m^2", 0.001, 50.0, "link 1's moment of inertia about its centre of mass",
         [](P& p) -> double& { return p.links.I1; }},
        {"I2", "kg m^2", 0.001, 50.0, "link 2's moment of inertia about its centre of mass",
         [](P& p) -> double& { return p.links.I2; }},
        {"torqueLimit", "N m", 0.1, 200.0, "limit on each joint's torque",
         [](P& p) -> double& { return p.torqueLimit; }},
        {"jointDamping", "N m s/rad", 0.0, 10.0, "viscous friction in each joint",
         [](P& p) -> double& { return p.jointDamping; }},
    };
    return fields;
}

// The aircraft: a small fixed-wing UAV.
const std::vector<Field<PlanarAircraftParameters>>& aircraftFields() {
    using P = PlanarAircraftParameters;
    static const std::vector<Field<P>> fields = {
        {"mass", "kg", 0.2, 50.0, "mass", [](P& p) -> double& { return p.mass; }},
        {"yawInertia", "kg m^2", 0.005, 20.0, "moment of inertia about the vertical axis",
         [](P& p) -> double& { return p.yawInertia; }},
        {"wingArea", "m^2", 0.02, 5.0, "reference wing area S",
         [](P& p) -> double& { return p.wingArea; }},
        {"wingSpan", "m", 0.2, 10.0, "reference span b",
         [](P& p) -> double& { return p.wingSpan; }},
        {"airDensity", "kg/m^3", 0.5, 1.5, "air density rho",
         [](P& p) -> double& { return p.airDensity; }},
        {"zeroLiftDrag", "1", 0.005, 0.3, "zero-lift drag coefficient CD0",
         [](P& p) -> double& { return p.zeroLiftDrag; }},
        {"oswaldEfficiency", "1", 0.3, 1.0, "Oswald efficiency e (induced drag)",
         [](P& p) -> double& { return p.oswaldEfficiency; }},
        {"maxLiftCoefficient", "1", 0.3, 3.0, "lift coefficient cap below the stall speed",
         [](P& p) -> double& { return p.maxLiftCoefficient; }},
        {"sideslipDrag", "1", 0.0, 2.0, "extra drag coefficient per rad^2 of sideslip",
         [](P& p) -> double& { return p.sideslipDrag; }},
        {"sideForceSideslip", "1/rad", -5.0, -0.01, "side force from sideslip CY_beta (< 0)",
         [](P& p) -> double& { return p.sideForceSideslip; }},
        {"sideForceRudder", "1/rad", -2.0, 0.0, "side force from the rudder CY_delta_r",
         [](P& p) -> double& { return p.sideForceRudder; }},
        {"yawMomentSideslip", "1/rad", 0.0, 1.0, "weathercock stability Cn_beta (> 0)",
         [](P& p) -> double& { return p.yawMomentSideslip; }},
        {"yawMomentRudder", "1/rad", 0.001, 1.0, "rudder authority Cn_delta_r (> 0)",
         [](P& p) -> double& { return p.yawMomentRudder; }},
        {"yawDamping", "1", -5.0, 0.0, "yaw damping Cn_r (< 0)",
         [](P& p) -> double& { return p.yawDamping; }},
        {"maxRudderDeflection", "rad", 0.05, 1.0, "rudder angle at full deflection",
         [](P& p) -> double& { return p.maxRudderDeflection; }},
        {"staticThrust", "N", 0.5, 500.0, "thrust at full throttle and zero airspeed",
         [](P& p) -> double& { return p.staticThrust; }},
        {"propellerPitchSpeed", "m/s", 5.0, 150.0, "airspeed at which the thrust has fallen to 0",
         [](P& p) -> double& { return p.propellerPitchSpeed; }},
    };
    return fields;
}

// The differential-drive robot.
const std::vector<Field<DiffDriveParameters>>& diffDriveFields() {
    using P = DiffDriveParameters;
    static const std::vector<Field<P>> fields = {
        {"mass", "kg", 0.2, 50.0, "mass", [](P& p) -> double& { return p.mass; }},
        {"yawInertia", "kg m^2", 0.0005, 10.0, "moment of inertia about the centre",
         [](P& p) -> double& { return p.yawInertia; }},
        {"length", "m", 0.05, 2.0, "body length", [](P& p) -> double& { return p.length; }},
        {"width", "m", 0.05, 2.0, "body width", [](P& p) -> double& { return p.width; }},
        {"track", "m", 0.05, 2.0, "distance between the two wheels",
         [](P& p) -> double& { return p.track; }},
        {"maxWheelSpeed", "m/s", 0.05, 10.0, "wheel rim speed at a command of 1",
         [](P& p) -> double& { return p.maxWheelSpeed; }},
        {"motorTimeConstant", "s", 0.005, 2.0, "first-order lag of each wheel's speed",
         [](P& p) -> double& { return p.motorTimeConstant; }},
        {"friction", "1", 0.05, 2.0, "tyre-floor friction coefficient",
         [](P& p) -> double& { return p.friction; }},
        {"tractionStiffness", "1", 0.01, 1.0, "share of the slip a wheel removes per physics step",
         [](P& p) -> double& { return p.tractionStiffness; }},
        {"casterDrag", "N s/m", 0.0, 20.0, "viscous drag of the caster",
         [](P& p) -> double& { return p.casterDrag; }},
    };
    return fields;
}

template <class P>
std::vector<PlantParameterSpec> specsOf(const std::vector<Field<P>>& fields) {
    std::vector<PlantParameterSpec> specs;
    P defaults{};
    for (const Field<P>& f : fields) {
        PlantParameterSpec spec;
        spec.key = QString::fromLatin1(f.key);
        spec.unit = QString::fromUtf8(f.unit);
        spec.lower = f.lower;
        spec.upper = f.upper;
        spec.value = f.ref(defaults);
        spec.description = QString::fromUtf8(f.description);
        spec.unmodelled = f.unmodelled;
        spec.realistic = f.unmodelled ? f.realistic : f.ref(defaults);
        spec.realisticSource = QString::fromUtf8(f.realisticSource);
        specs.push_back(spec);
    }
    return specs;
}

template <class P>
P typedFrom(const std::vector<Field<P>>& fields, const PlantParameters& parameters,
            const char* plant) {
    if (parameters.plant != QLatin1String(plant) || parameters.values.size() != fields.size()) {
        throw std::invalid_argument(
            QStringLiteral("plant parameters of '%1' (%2 values) given to the %3")
                .arg(parameters.plant)
                .arg(parameters.values.size())
                .arg(QLatin1String(plant))
                .toStdString());
    }
    P typed{};
    for (size_t i = 0; i < fields.size(); ++i) {
        fields[i].ref(typed) = parameters.values[i];
    }
    return typed;
}

int indexOf(const std::vector<PlantParameterSpec>& specs, const char* key) {
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].key == QLatin1String(key)) {
            return static_cast<int>(i);
        }
    }
    throw std::logic_error("plant parameter not declared");
}

// The relations between a plant's values that no single range can say.
QString relationProblem(const QString& plant, const std::vector<PlantParameterSpec>& specs,
                        const std::vector<double>& v) {
    auto at = [&](const char* key) { return v[static_cast<size_t>(indexOf(specs, key))]; };
    if (plant == QLatin1String("slidecar")) {
        if (at("kineticFriction") > at("staticFriction")) {
            return QStringLiteral(
                       "kineticFriction = %1 is above staticFriction = %2 (a sliding "
                       "tyre grips less than a rolling one)")
                .arg(number(at("kineticFriction")), number(at("staticFriction")));
        }
        const double rearStatic = at("staticFriction") * at("rearStaticGrip");
        const double rearKinetic = at("kineticFriction") * at("rearKineticGrip");
        if (rearKinetic > rearStatic) {
            return QStringLiteral(
                       "the rear tyres' sliding friction (kineticFriction x "
                       "rearKineticGrip = %1) is above their static friction "
                       "(staticFriction x rearStaticGrip = %2): a sliding tyre grips "
                       "less than a rolling one")
                .arg(number(rearKinetic), number(rearStatic));
        }
        if (std::abs(at("cgForward")) >= 0.45 * at("wheelbase")) {
            return QStringLiteral(
                       "cgForward = %1 m puts the centre of mass over an axle of the "
                       "%2 m wheelbase (|cgForward| must stay below 0.45 wheelbase)")
                .arg(number(at("cgForward")), number(at("wheelbase")));
        }
        if (at("wheelbase") > at("length")) {
            return QStringLiteral("wheelbase = %1 m is longer than the body (length = %2 m)")
                .arg(number(at("wheelbase")), number(at("length")));
        }
    } else if (plant == QLatin1String("acrobot")) {
        if (at("lc1") > at("l1")) {
            return QStringLiteral("lc1 = %1 m lies beyond link 1 (l1 = %2 m)")
                .arg(number(at("lc1")), number(at("l1")));
        }
        if (at("lc2") > at("l2")) {
            return QStringLiteral("lc2 = %1 m lies beyond link 2 (l2 = %2 m)")
                .arg(number(at("lc2")), number(at("l2")));
        }
    } else if (plant == QLatin1String("diffdrive")) {
        if (at("track") > at("width") * 1.5) {
            return QStringLiteral("track = %1 m is far wider than the body (width = %2 m)")
                .arg(number(at("track")), number(at("width")));
        }
    }
    return {};
}

}  // namespace

namespace {

/// The plants with a parameter file: their keys and how each is built from checked values. In
/// PlantCatalog's order (a test holds the two lists equal).
struct PlantModel {
    const char* name;
    std::vector<PlantParameterSpec> specs;
    std::unique_ptr<Plant> (*create)(const PlantParameters& parameters,
                                     const SimulationTiming& timing);
};

template <class P, auto typed>
std::unique_ptr<Plant> build(const PlantParameters& parameters, const SimulationTiming& timing) {
    return std::make_unique<P>(typed(parameters), timing);
}

const std::vector<PlantModel>& plantModels() {
    static const std::vector<PlantModel> models = {
        {"slidecar", specsOf(slideCarFields()), &build<SlideCar, &slideCarParameters>},
        {"acrobot", specsOf(acrobotFields()), &build<Acrobot, &acrobotParameters>},
        {"aircraft", specsOf(aircraftFields()), &build<PlanarAircraft, &aircraftParameters>},
        {"diffdrive", specsOf(diffDriveFields()), &build<DiffDrive, &diffDriveParameters>},
    };
    return models;
}

const PlantModel& plantModel(const QString& plant) {
    for (const PlantModel& model : plantModels()) {
        if (plant == QLatin1String(model.name)) {
            return model;
        }
    }
    throw std::invalid_argument(QStringLiteral("unknown plant '%1' (one of: %2)")
                                    .arg(plant, plantParameterPlants().join(QLatin1Char(' ')))
                                    .toStdString());
}

}  // namespace

QStringList plantParameterPlants() {
    QStringList names;
    for (const PlantModel& model : plantModels()) {
        names << QString::fromLatin1(model.name);
    }
    return names;
}

const std::vector<PlantParameterSpec>& plantParameterSpecs(const QString& plant) {
    return plantModel(plant).specs;
}

std::unique_ptr<Plant> makePlant(const PlantParameters& parameters,
                                 const SimulationTiming& timing) {
    const PlantModel& model = plantModel(parameters.plant);
    if (const QString problem = plantParametersProblem(parameters.plant, parameters.values);
        !problem.isEmpty()) {
        throw std::invalid_argument(problem.toStdString());
    }
    return model.create(parameters, timing);
}

bool PlantParameters::isCatalogPlant() const {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(plant);
    if (specs.size() != values.size()) {
        return false;
    }
    for (size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].value != values[i]) {
            return false;
        }
    }
    return true;
}

double PlantParameters::value(const QString& key) const {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(plant);
    for (size_t i = 0; i < specs.size() && i < values.size(); ++i) {
        if (specs[i].key == key) {
            return values[i];
        }
    }
    throw std::invalid_argument(
        QStringLiteral("the %1 has no parameter '%2'").arg(plant, key).toStdString());
}

PlantParameters defaultPlantParameters(const QString& plant) {
    PlantParameters p;
    p.plant = plant;
    for (const PlantParameterSpec& spec : plantParameterSpecs(plant)) {
        p.values.push_back(spec.value);
    }
    return p;
}

QString plantParametersProblem(const QString& plant, const std::vector<double>& values) {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(plant);
    if (values.size() != specs.size()) {
        return QStringLiteral("the %1 has %2 parameters, %3 given")
            .arg(plant)
            .arg(specs.size())
            .arg(values.size());
    }
    for (size_t i = 0; i < specs.size(); ++i) {
        const PlantParameterSpec& s = specs[i];
        if (!std::isfinite(values[i]) || values[i] < s.lower || values[i] > s.upper) {
            return QStringLiteral("%1 = %2 is outside [%3, %4]%5")
                .arg(s.key, withUnit(values[i], s.unit), number(s.lower), number(s.upper),
                     s.unit == QLatin1String("1") ? QString() : QLatin1Char(' ') + s.unit);
        }
    }
    return relationProblem(plant, specs, values);
}

SlideCarParameters slideCarParameters(const PlantParameters& parameters) {
    return typedFrom(slideCarFields(), parameters, "slidecar");
}

AcrobotParameters acrobotParameters(const PlantParameters& parameters) {
    return typedFrom(acrobotFields(), parameters, "acrobot");
}

PlanarAircraftParameters aircraftParameters(const PlantParameters& parameters) {
    return typedFrom(aircraftFields(), parameters, "aircraft");
}

DiffDriveParameters diffDriveParameters(const PlantParameters& parameters) {
    return typedFrom(diffDriveFields(), parameters, "diffdrive");
}

}  // namespace prisca::sim
