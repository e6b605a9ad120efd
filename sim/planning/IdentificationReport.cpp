#include "sim/planning/IdentificationReport.h"

#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>
#include <limits>

namespace prisca::sim {

namespace {

// JSON has no infinity: a deviation the data did not bound is written as null.
QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue();
}

}  // namespace

QJsonObject identificationReportJson(const IdentificationResult& result) {
    QJsonObject parameters;
    for (const IdentifiedParameter& p : result.table) {
        QJsonObject entry{{"value", p.value},
                          {"unit", p.unit},
                          {"prior", p.prior},
                          {"fitted", p.fitted},
                          {"identified", p.identified}};
        entry.insert(QStringLiteral("std"), p.fitted ? finiteOrNull(p.std) : QJsonValue());
        parameters.insert(p.key, entry);
    }
    QJsonArray segments;
    for (const SegmentFit& s : result.segments) {
        segments.append(QJsonObject{{"run", s.run},
                                    {"start", s.start},
                                    {"duration", s.duration},
                                    {"positionRms", s.positionRms},
                                    {"headingRms", s.headingRms}});
    }
    return QJsonObject{{"plant", result.parameters.plant},
                       {"parameters", parameters},
                       {"segments", segments},
                       {"positionRms", result.positionRms},
                       {"headingRms", result.headingRms},
                       {"priorPositionRms", result.priorPositionRms},
                       {"evaluations", static_cast<double>(result.evaluations)}};
}

QByteArray identifiedPlantFile(const IdentificationResult& result, const QString& description,
                               const QStringList& sources) {
    QJsonObject file = QJsonDocument::fromJson(plantParametersJson(result.parameters)).object();
    file.insert(QStringLiteral("description"), description);
    QJsonObject report = identificationReportJson(result);
    report.insert(QStringLiteral("sources"), QJsonArray::fromStringList(sources));
    file.insert(QStringLiteral("identification"), report);
    return QJsonDocument(file).toJson(QJsonDocument::Indented);
}

std::optional<IdentificationResult> readIdentifiedPlantFile(const QByteArray& json,
                                                            const QString& sourceName,
                                                            const QString& plant, QString* error) {
    std::optional<PlantParameters> parameters =
        parsePlantParameters(json, sourceName, plant, error);
    if (!parameters) {
        return std::nullopt;
    }
    const QJsonObject report =
        QJsonDocument::fromJson(json).object().value(QLatin1String("identification")).toObject();
    const auto fail = [&](const QString& what) -> std::optional<IdentificationResult> {
        *error = QStringLiteral("%1: %2").arg(sourceName, what);
        return std::nullopt;
    };
    const auto number = [&](const QJsonObject& object, const char* key, double* out) {
        const QJsonValue v = object.value(QLatin1String(key));
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < 0.0) {
            return false;
        }
        *out = v.toDouble();
        return true;
    };
    IdentificationResult result;
    double evaluations = 0.0;
    if (report.isEmpty() || !number(report, "positionRms", &result.positionRms) ||
        !number(report, "headingRms", &result.headingRms) ||
        !number(report, "priorPositionRms", &result.priorPositionRms) ||
        !number(report, "evaluations", &evaluations)) {
        return fail(
            QStringLiteral("\"identification\" is missing or lacks its fit figures "
                           "(positionRms, headingRms, priorPositionRms, evaluations)"));
    }
    result.evaluations = static_cast<long long>(evaluations);
    result.parameters = std::move(*parameters);
    const QJsonObject reported = report.value(QLatin1String("parameters")).toObject();
    const std::vector<PlantParameterSpec>& specs = plantParameterSpecs(result.parameters.plant);
    for (size_t j = 0; j < specs.size(); ++j) {
        const QJsonObject entry = reported.value(specs[j].key).toObject();
        IdentifiedParameter p;
        p.key = specs[j].key;
        p.unit = specs[j].unit;
        p.value = result.parameters.values[j];
        p.prior = entry.value(QLatin1String("prior")).toDouble(p.value);
        p.fitted = entry.value(QLatin1String("fitted")).toBool(false);
        p.identified = p.fitted && entry.value(QLatin1String("identified")).toBool(false);
        // A fitted parameter without a deviation is one the data did not bound.
        const QJsonValue deviation = entry.value(QLatin1String("std"));
        p.std = !p.fitted              ? 0.0
                : deviation.isDouble() ? deviation.toDouble()
                                       : std::numeric_limits<double>::infinity();
        result.table.push_back(p);
    }
    for (const QJsonValue& value : report.value(QLatin1String("segments")).toArray()) {
        const QJsonObject s = value.toObject();
        SegmentFit fit;
        fit.run = s.value(QLatin1String("run")).toInt();
        fit.start = s.value(QLatin1String("start")).toDouble();
        fit.duration = s.value(QLatin1String("duration")).toDouble();
        fit.positionRms = s.value(QLatin1String("positionRms")).toDouble();
        fit.headingRms = s.value(QLatin1String("headingRms")).toDouble();
        result.segments.push_back(fit);
    }
    return result;
}

}  // namespace prisca::sim
