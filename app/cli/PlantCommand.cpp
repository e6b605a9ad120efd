// prisca-cli plant: a plant's physical parameters (every key with its unit, allowed range and
// value), printed or written as a plant file to edit, and a plant file checked.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "sim/PlantCatalog.h"
#include "sim/plants/PlantParameters.h"

#include <QJsonDocument>

namespace prisca::app::cli {

int plantCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("plant"),
                     QStringLiteral("A plant's physical parameters: --print-params lists every "
                                    "key with its unit, allowed range and value (the catalog's, "
                                    "or a plant file's with --plant-params); --format json gives "
                                    "a plant file to edit and load with --plant-params."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addFlag("print-params", "Print the parameters.");
    addPlantParametersOption(line);
    line.addValue("out", "Write the parameters to this file instead of standard output.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString plant = checkedPlant(line.required("plant"));
    const auto fromFile = plantParametersOption(line, plant);
    if (!line.isSet("print-params") && !fromFile) {
        throw UsageError(
            QStringLiteral("give --print-params (the catalog's parameters) or --plant-params FILE "
                           "(checked, then printed)"));
    }
    const sim::PlantParameters parameters =
        fromFile ? *fromFile : sim::defaultPlantParameters(plant);
    const QByteArray bytes = line.format() == QLatin1String("json")
                                 ? sim::plantParametersJson(parameters)
                                 : sim::plantParametersText(parameters).toUtf8();
    if (line.isSet("out")) {
        writeOutput(line.value("out"), bytes, true);
    } else {
        printText(QString::fromUtf8(bytes));
    }
    return 0;
}

}  // namespace prisca::app::cli
