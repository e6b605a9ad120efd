// The plant file: read (checked key by key, with its unit and range) and written, and shown as a
// table.
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

const QString kFormat = QStringLiteral("prisca-plant-parameters");

}  // namespace

std::optional<PlantParameters> parsePlantParameters(const QByteArray& json,
                                                    const QString& sourceName, const QString& plant,
                                                    QString* error) {
    auto fail = [&](const QString& why) -> std::optional<PlantParameters> {
        if (error) {
            *error = QStringLiteral("%1: %2").arg(sourceName, why);
        }
        return std::nullopt;
    };
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        return fail(QStringLiteral("not valid JSON at byte %1 (%2)")
                        .arg(parseError.offset)
                        .arg(parseError.errorString()));
    }
    if (!document.isObject()) {
        return fail(
            QStringLiteral("valid JSON, but not a plant file (an object with \"plant\" "
                           "and \"parameters\" is expected)"));
    }
    const QJsonObject root = document.object();
    for (auto it = root.begin(); it != root.end(); ++it) {
        const QString key = it.key();
        if (key != QLatin1String("plant") && key != QLatin1String("parameters") &&
            key != QLatin1String("unmodelled") && key != QLatin1String("format") &&
            key != QLatin1String("version") && key != QLatin1String("description") &&
            key != QLatin1String("identification")) {
            return fail(QStringLiteral("unknown key \"%1\" (a plant file has \"plant\", "
                                       "\"parameters\" and optionally \"unmodelled\", "
                                       "\"format\", \"version\", \"description\", "
                                       "\"identification\")")
                            .arg(key));
        }
    }
    if (root.contains(QLatin1String("format")) &&
        root.value(QLatin1String("format")).toString() != kFormat) {
        return fail(QStringLiteral("\"format\" is \"%1\", not \"%2\"")
                        .arg(root.value(QLatin1String("format")).toString(), kFormat));
    }
    if (root.contains(QLatin1String("version"))) {
        const QJsonValue version = root.value(QLatin1String("version"));
        if (!version.isDouble()) {
            // "1" is text: the version is the number 1.
            return fail(QStringLiteral("\"version\" must be the number 1, not %1")
                            .arg(version.isString()
                                     ? QStringLiteral("the text \"%1\"").arg(version.toString())
                                     : QStringLiteral("a JSON %1")
                                           .arg(version.isBool() ? QStringLiteral("true or false")
                                                : version.isArray()  ? QStringLiteral("list")
                                                : version.isObject() ? QStringLiteral("object")
                                                                     : QStringLiteral("null"))));
        }
        if (version.toDouble() != 1.0) {
            return fail(
                QStringLiteral("version %1 is not one this build reads (it reads version 1)")
                    .arg(version.toDouble()));
        }
    }
    const QJsonValue plantValue = root.value(QLatin1String("plant"));
    if (!plantValue.isString()) {
        return fail(QStringLiteral("\"plant\" is missing (one of: %1)")
                        .arg(plantParameterPlants().join(QStringLiteral(", "))));
    }
    const QString filePlant = plantValue.toString();
    if (!plantParameterPlants().contains(filePlant)) {
        return fail(QStringLiteral("unknown plant \"%1\" (one of: %2)")
                        .arg(filePlant, plantParameterPlants().join(QStringLiteral(", "))));
    }
    if (!plant.isEmpty() && filePlant != plant) {
        return fail(QStringLiteral("is a plant file for the %1, not the %2").arg(filePlant, plant));
    }
    const QJsonValue parametersValue = root.value(QLatin1String("parameters"));
    if (!parametersValue.isObject()) {
        return fail(QStringLiteral("\"parameters\" is missing or not an object"));
    }
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(filePlant);
    PlantParameters result = defaultPlantParameters(filePlant);
    result.source = sourceName;
    const QJsonValue unmodelledValue = root.value(QLatin1String("unmodelled"));
    if (!unmodelledValue.isUndefined() && !unmodelledValue.isObject()) {
        return fail(QStringLiteral("\"unmodelled\" is not an object"));
    }
    // The model's parameters and the effects it leaves out, each in its own group (a file may
    // also give an unmodelled effect among the parameters).
    QJsonObject parameters = parametersValue.toObject();
    const QJsonObject unmodelled = unmodelledValue.toObject();
    for (auto it = unmodelled.begin(); it != unmodelled.end(); ++it) {
        bool isUnmodelled = false;
        for (const PlantParameterSpec& spec : specs) {
            isUnmodelled = isUnmodelled || (spec.key == it.key() && spec.unmodelled);
        }
        if (!isUnmodelled) {
            QStringList known;
            for (const PlantParameterSpec& spec : specs) {
                if (spec.unmodelled) {
                    known << spec.key;
                }
            }
            return fail(QStringLiteral("\"%1\" is not an unmodelled effect of the %2 (%3)")
                            .arg(it.key(), filePlant,
                                 known.isEmpty() ? QStringLiteral("it has none")
                                                 : QStringLiteral("those are: ") +
                                                       known.join(QStringLiteral(", "))));
        }
        if (parameters.contains(it.key())) {
            return fail(QStringLiteral("%1 is given twice, in \"parameters\" and in "
                                       "\"unmodelled\"")
                            .arg(it.key()));
        }
        parameters.insert(it.key(), it.value());
    }
    for (auto it = parameters.begin(); it != parameters.end(); ++it) {
        int index = -1;
        for (size_t i = 0; i < specs.size(); ++i) {
            if (specs[i].key == it.key()) {
                index = static_cast<int>(i);
            }
        }
        if (index < 0) {
            QStringList known;
            for (const PlantParameterSpec& s : specs) {
                known << s.key;
            }
            return fail(QStringLiteral("unknown %1 parameter \"%2\" (known: %3)")
                            .arg(filePlant, it.key(), known.join(QStringLiteral(", "))));
        }
        const PlantParameterSpec& spec = specs[static_cast<size_t>(index)];
        QJsonValue value = it.value();
        if (value.isObject()) {
            const QJsonObject entry = value.toObject();
            if (entry.contains(QLatin1String("unit")) &&
                entry.value(QLatin1String("unit")).toString() != spec.unit) {
                return fail(
                    QStringLiteral("%1 is given in \"%2\"; its unit is \"%3\"")
                        .arg(spec.key, entry.value(QLatin1String("unit")).toString(), spec.unit));
            }
            value = entry.value(QLatin1String("value"));
        }
        if (!value.isDouble()) {
            return fail(QStringLiteral("%1 is not a number").arg(spec.key));
        }
        result.values[static_cast<size_t>(index)] = value.toDouble();
    }
    if (const QString problem = plantParametersProblem(filePlant, result.values);
        !problem.isEmpty()) {
        return fail(problem);
    }
    return result;
}

std::optional<PlantParameters> readPlantParameters(const QString& path, const QString& plant,
                                                   QString* error) {
    core::FileError fileError;
    // A plant file is a few kilobytes; a megabyte is far beyond any.
    const std::optional<QByteArray> bytes = core::readFileBounded(path, 1 << 20, &fileError);
    if (!bytes) {
        if (error) {
            *error = fileError.toString();
        }
        return std::nullopt;
    }
    return parsePlantParameters(*bytes, path, plant, error);
}

QByteArray plantParametersJson(const PlantParameters& parameters) {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(parameters.plant);
    QJsonObject values;
    QJsonObject unmodelled;
    for (size_t i = 0; i < specs.size() && i < parameters.values.size(); ++i) {
        const PlantParameterSpec& s = specs[i];
        QJsonObject entry{{"value", parameters.values[i]},
                          {"unit", s.unit},
                          {"min", s.lower},
                          {"max", s.upper},
                          {"description", s.description}};
        if (s.unmodelled) {
            entry.insert(QStringLiteral("off"), s.value);
            entry.insert(QStringLiteral("realistic"), s.realistic);
            entry.insert(QStringLiteral("realisticSource"), s.realisticSource);
            unmodelled.insert(s.key, entry);
        } else {
            values.insert(s.key, entry);
        }
    }
    QJsonObject root{
        {"format", kFormat}, {"version", 1}, {"plant", parameters.plant}, {"parameters", values}};
    if (!unmodelled.isEmpty()) {
        root.insert(QStringLiteral("unmodelled"), unmodelled);
    }
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString plantParametersText(const PlantParameters& parameters) {
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(parameters.plant);
    int width = 0;
    int rangeWidth = 0;
    for (const PlantParameterSpec& s : specs) {
        width = std::max(width, static_cast<int>(s.key.size()));
        rangeWidth = std::max(
            rangeWidth, static_cast<int>(number(s.lower).size() + number(s.upper).size() + 4));
    }
    QString text =
        QStringLiteral("%1 parameters%2\n")
            .arg(parameters.plant, parameters.source.isEmpty()
                                       ? QStringLiteral(" (the catalog's)")
                                       : QStringLiteral(" from %1").arg(parameters.source));
    bool groupShown = false;
    for (size_t i = 0; i < specs.size() && i < parameters.values.size(); ++i) {
        const PlantParameterSpec& s = specs[i];
        if (s.unmodelled && !groupShown) {
            text += QStringLiteral(
                "unmodelled (effects identification leaves out; off at the "
                "catalog's values):\n");
            groupShown = true;
        }
        text +=
            QStringLiteral("  %1  %2  %3  %4\n")
                .arg(s.key, -width)
                .arg(withUnit(parameters.values[i], s.unit), -16)
                .arg(QStringLiteral("[%1, %2]").arg(number(s.lower), number(s.upper)), -rangeWidth)
                .arg(s.description);
    }
    return text;
}

}  // namespace prisca::sim
