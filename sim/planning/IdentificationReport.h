#pragma once

#include "sim/planning/Identification.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <optional>

namespace prisca::sim {

/// What an identification found, as the identified plant file keeps it beside the values
/// (`prisca-cli identify` writes it; the window's session keeps the same): per parameter its
/// value, unit, prior, whether it was fitted and identified and its standard deviation (null
/// where there is none); the fit per segment; the position and heading RMS, the prior's
/// position RMS and the model runs used.
QJsonObject identificationReportJson(const IdentificationResult& result);

/// The identified plant file: the plant file of result.parameters (plantParametersJson), a
/// "description" and the report above as "identification", with the data it came from as its
/// "sources" (files, or words). readPlantParameters reads it as a plant file (`run --model`);
/// readIdentifiedPlantFile reads it whole.
QByteArray identifiedPlantFile(const IdentificationResult& result, const QString& description,
                               const QStringList& sources);

/// An identification read back from an identified plant file's text: the parameters checked
/// as every plant file's (parsePlantParameters, of `plant` when non-empty), and the table, fit
/// per segment and figures from its "identification". On failure nullopt, and *error says what
/// is wrong (a plant file without an "identification" is one).
std::optional<IdentificationResult> readIdentifiedPlantFile(const QByteArray& json,
                                                            const QString& sourceName,
                                                            const QString& plant, QString* error);

}  // namespace prisca::sim
