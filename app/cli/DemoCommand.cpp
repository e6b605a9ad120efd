// prisca-cli demo: a scripted, human-like demonstration of a plant, in one of its styles.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "sim/DemonstrationStyles.h"
#include "sim/PlantCatalog.h"

#include <QJsonArray>

namespace prisca::app::cli {

int demoCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("demo"),
                     QStringLiteral("Record a scripted demonstration of a simulated plant, in one "
                                    "of the operator styles of that plant (--list-styles)."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addValue("style", "Operator style (default: the plant's classic one).", "name");
    line.addFlag("list-styles", "Print the plant's styles, one name a line, and exit.");
    line.addValue("seed", "Seed of the operator's hand variation.", "N", "1");
    line.addValue("rate",
                  "Control rate of the recording [Hz]: one sample per control step, as a camera "
                  "take at this frame rate gives (default 40).",
                  "Hz", "40");
    addPlantParametersOption(line);
    line.addValue("day",
                  "Record on a lab-session day's car: the mismatch that day N's trials meet under "
                  "the session perturbation model (run, table1 and curve with --seed N). Default: "
                  "the nominal car.",
                  "N");
    line.addValue("out", "Output demonstration CSV.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out"});
    const QString plantName = checkedPlant(line.required("plant"));
    if (line.isSet("list-styles")) {
        const std::vector<sim::DemonstrationStyle> styles = sim::DemonstrationStyles::of(plantName);
        if (line.format() == QLatin1String("json")) {
            QJsonArray list;
            for (const sim::DemonstrationStyle& style : styles) {
                list.append(QJsonObject{{"name", style.name}, {"description", style.description}});
            }
            printJson({{"plant", plantName}, {"styles", list}});
        } else {
            QString text;
            for (const sim::DemonstrationStyle& style : styles) {
                text += style.name + QLatin1Char('\n');
            }
            printText(text);
        }
        return 0;
    }
    const QString style =
        line.isSet("style") ? line.value("style") : sim::DemonstrationStyles::classic(plantName);
    if (!sim::DemonstrationStyles::contains(plantName, style)) {
        throw UsageError(
            QStringLiteral("--style: unknown %1 style '%2' (one of: %3)")
                .arg(plantName, style,
                     sim::DemonstrationStyles::names(plantName).join(QLatin1Char(' '))));
    }
    const QString out = line.required("out");
    const auto seed =
        static_cast<std::uint64_t>(line.integer("seed", 0, std::numeric_limits<long long>::max()));
    sim::SimulationTiming timing;
    const double rate = line.number("rate", 5.0, 1000.0);
    timing.controlPeriod = 1.0 / rate;
    const auto parameters = plantParametersOption(line, plantName);
    sim::RecordingConditions conditions;
    conditions.parameters = parameters.get();
    if (line.isSet("day")) {
        conditions.perturbation =
            sim::Perturbation::dayOf(static_cast<std::uint64_t>(line.integer("day", 0, 1LL << 62)));
    }
    core::Demonstration demonstration =
        sim::DemonstrationStyles::record(plantName, style, seed, timing, conditions);
    demonstration.metadata.insert(
        QStringLiteral("source"),
        QStringLiteral("prisca-cli demo, style %1, seed %2, %3 Hz").arg(style).arg(seed).arg(rate));
    if (parameters) {
        demonstration.metadata.insert(QStringLiteral("plant-parameters"), parameters->source);
    }
    if (line.isSet("day")) {
        demonstration.metadata.insert(QStringLiteral("day"), line.value("day"));
    }
    // A plant file inside its ranges can still make the scripted manoeuvre leave the numbers:
    // that is the plant's doing, not the output file's.
    if (const QString invalid = demonstration.validate(); !invalid.isEmpty()) {
        throw UsageError(QStringLiteral("the %1 demonstration on %2 left the numbers a "
                                        "demonstration holds (%3): %4; nothing was written to %5")
                             .arg(style,
                                  parameters
                                      ? QStringLiteral("the plant file %1").arg(parameters->source)
                                      : QStringLiteral("the catalog %1").arg(plantName),
                                  invalid,
                                  parameters ? QStringLiteral("its parameters do not make a plant "
                                                              "this manoeuvre can drive")
                                             : QStringLiteral("the manoeuvre diverged"),
                                  out));
    }
    writeDemonstration(demonstration, out);
    const int T = demonstration.length();
    if (line.format() == QLatin1String("json")) {
        QJsonObject end;
        for (int i = 0; i < demonstration.stateDimension(); ++i) {
            end.insert(demonstration.stateNames[i], demonstration.states(T - 1, i));
        }
        printJson({{"plant", plantName},
                   {"style", style},
                   {"seed", static_cast<double>(seed)},
                   {"samples", T},
                   {"duration", T * demonstration.dt},
                   {"dt", demonstration.dt},
                   {"final", end},
                   {"out", out}});
    } else {
        printText(QStringLiteral("%1 demonstration (%2, seed %3): %4 samples, %5 s; wrote %6\n")
                      .arg(plantName, style)
                      .arg(seed)
                      .arg(T)
                      .arg(T * demonstration.dt)
                      .arg(out));
    }
    return 0;
}

}  // namespace prisca::app::cli
