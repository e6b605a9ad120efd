#pragma once

#include "sim/plants/Plant.h"

#include <QByteArray>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>
#include <vector>

namespace prisca::sim {

struct SlideCarParameters;
struct AcrobotParameters;
struct PlanarAircraftParameters;
struct DiffDriveParameters;

/// One physical parameter a plant can be given from a file: its key (as the file spells it),
/// unit, allowed range and the catalog plant's value. Plain data.
struct PlantParameterSpec {
    QString key;          ///< e.g. "mass"
    QString unit;         ///< e.g. "kg" ("1" for a pure number)
    double lower = 0.0;   ///< smallest allowed value
    double upper = 0.0;   ///< largest allowed value
    double value = 0.0;   ///< the catalog plant's value
    QString description;  ///< one line for the operator
    /// An effect the identification model leaves out (the reality gap): off at its catalog
    /// value, in the file's "unmodelled" group, and never fitted by identification.
    bool unmodelled = false;
    double realistic = 0.0;   ///< unmodelled: the value a real plant of this size has
    QString realisticSource;  ///< unmodelled: where that value comes from
};

/// A plant's physical parameters: one value per key its catalog entry declares, in that order,
/// and the file they came from. Made by defaultPlantParameters or readPlantParameters, which
/// check every value; plain data.
struct PlantParameters {
    QString plant;               ///< the plant's catalog name
    std::vector<double> values;  ///< one per spec of the plant, in spec order
    QString source;              ///< the file read; empty: the catalog's own plant

    /// Whether every value is the catalog's (whatever the source).
    bool isCatalogPlant() const;
    /// The value of a key; std::invalid_argument for a key the plant does not declare.
    double value(const QString& key) const;
};

/// The parameters of a plant, in the order files and lists show them; std::invalid_argument
/// naming the known plants for an unknown one.
const std::vector<PlantParameterSpec>& plantParameterSpecs(const QString& plant);

/// The plants a parameter file can describe, in the catalog's order ("slidecar", "acrobot", ...).
QStringList plantParameterPlants();

/// The plant these parameters describe, built with them; std::invalid_argument for an unknown
/// plant (naming the known ones) or a value plantParametersProblem refuses.
std::unique_ptr<Plant> makePlant(const PlantParameters& parameters,
                                 const SimulationTiming& timing = {});

/// The catalog plant's parameters.
PlantParameters defaultPlantParameters(const QString& plant);

/// Empty when the values (one per spec) are each finite and in range and agree with each other
/// (the plant's own relations, e.g. a kinetic friction not above the static one); else what is
/// wrong, naming the key, the value and the range ("mass = 50 kg is outside [0.3, 10] kg").
QString plantParametersProblem(const QString& plant, const std::vector<double>& values);

/// Reads a plant file (JSON): {"plant": NAME, "parameters": {KEY: VALUE, ...}, and optionally
/// "unmodelled": {KEY: VALUE, ...} for the effects the identification model leaves out}, a VALUE
/// being a number or an object with "value" (and, if given, a "unit" that must be the declared one;
/// the other fields, as --print-params writes them, are documentation). Keys not in the file keep
/// the catalog's values. With `plant` non-empty the file must be of that plant. On failure
/// returns nullopt and sets *error naming the file and what is wrong: a missing or unreadable
/// file, bad JSON, another plant, an unknown key (with the known ones), a value outside its
/// range (with the range).
std::optional<PlantParameters> readPlantParameters(const QString& path, const QString& plant,
                                                   QString* error);
/// Parses the text of a plant file; `sourceName` names it in messages and becomes `source`.
std::optional<PlantParameters> parsePlantParameters(const QByteArray& json,
                                                    const QString& sourceName, const QString& plant,
                                                    QString* error);

/// The plant file of these parameters, every key with its value, unit, range and description
/// (readPlantParameters reads it back to the same values).
QByteArray plantParametersJson(const PlantParameters& parameters);
/// The same as a text table for the operator: key, value, unit, range, description.
QString plantParametersText(const PlantParameters& parameters);

/// Each plant's typed parameters from checked values; std::invalid_argument if the parameters
/// are another plant's.
SlideCarParameters slideCarParameters(const PlantParameters& parameters);
AcrobotParameters acrobotParameters(const PlantParameters& parameters);
PlanarAircraftParameters aircraftParameters(const PlantParameters& parameters);
DiffDriveParameters diffDriveParameters(const PlantParameters& parameters);

}  // namespace prisca::sim
