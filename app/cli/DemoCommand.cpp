// prisca-cli demo: the plant's scripted, human-like demonstration.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "sim/PlantCatalog.h"

namespace prisca::app::cli {

int demoCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("demo"),
                     QStringLiteral("Record the scripted demonstration of a simulated plant."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addValue("seed", "Seed of the operator's hand variation.", "N", "1");
    line.addValue("out", "Output demonstration CSV.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QString plantName = checkedPlant(line.required("plant"));
    const QString out = line.required("out");
    const auto seed =
        static_cast<std::uint64_t>(line.integer("seed", 0, std::numeric_limits<long long>::max()));
    core::Demonstration demonstration = sim::PlantCatalog::demonstrate(plantName, seed);
    demonstration.metadata.insert(QStringLiteral("source"),
                                  QStringLiteral("prisca-cli demo, seed %1").arg(seed));
    writeDemonstration(demonstration, out);
    const int T = demonstration.length();
    if (line.format() == QLatin1String("json")) {
        QJsonObject end;
        for (int i = 0; i < demonstration.stateDimension(); ++i) {
            end.insert(demonstration.stateNames[i], demonstration.states(T - 1, i));
        }
        printJson({{"plant", plantName},
                   {"seed", static_cast<double>(seed)},
                   {"samples", T},
                   {"duration", T * demonstration.dt},
                   {"dt", demonstration.dt},
                   {"final", end},
                   {"out", out}});
    } else {
        printText(QStringLiteral("%1 demonstration (seed %2): %3 samples, %4 s; wrote %5\n")
                      .arg(plantName)
                      .arg(seed)
                      .arg(T)
                      .arg(T * demonstration.dt)
                      .arg(out));
    }
    return 0;
}

}  // namespace prisca::app::cli
