// prisca-cli simulate: replay actions (or none) on a plant from a given state, so anyone can
// check the physics against their own model.
#include "app/cli/ActionTable.h"
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "sim/PlantCatalog.h"
#include "sim/demonstrations/DemonstrationRecorder.h"

#include <QJsonArray>

namespace prisca::app::cli {

namespace {
// What one simulation may take. A row of states and actions is kept for every control step:
// a million rows of a 10-number plant is 80 MB. The physics: 2 x 10^6 steps took 2.6 s
// (aircraft), 2.7 s (slide-car) and 5.2 s (acrobot) on one core of the lab's 2-core machine
// while a build ran on the other, so 2 x 10^7 stays under a minute.
constexpr int kMaxSteps = 1'000'000;
constexpr long long kMaxPhysicsSteps = 20'000'000;
constexpr int kMaxPhysicsSeconds = 60;
}  // namespace

int simulateCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("simulate"),
        QStringLiteral("Simulate a plant from an initial state under given actions and "
                       "write the states (demonstration CSV format)."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addValue("initial",
                  "Initial state, comma separated, in the plant's state order and SI "
                  "units (default: the plant's nominal start).",
                  "values");
    line.addValue("actions",
                  "CSV whose header names the plant's actions; row k is applied at "
                  "step k.",
                  "file");
    line.addFlag("zero-action", "Apply zero action throughout (instead of --actions).");
    line.addValue("duration", "Simulated time [s] (default: one step per action row).", "seconds");
    line.addValue("dt", "Control period [s].", "seconds", "0.025");
    line.addValue("substeps", "Physics steps per control period.", "count", "10");
    addPlantParametersOption(line);
    line.addValue("out", "Output CSV of states and applied actions.", "file");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out"});
    const QString plantName = checkedPlant(line.required("plant"));
    const QString out = line.required("out");
    sim::SimulationTiming timing;
    timing.controlPeriod = line.number("dt", 1e-4, 1.0);
    timing.physicsSubsteps = static_cast<int>(line.integer("substeps", 1, 1000));
    const auto parameters = plantParametersOption(line, plantName);
    auto plant = parameters ? sim::PlantCatalog::create(*parameters, timing)
                            : sim::PlantCatalog::create(plantName, timing);
    const sim::PlantInfo& info = plant->info();
    const int n = info.stateDimension();
    const int m = info.actionDimension();

    if (line.isSet("actions") == line.isSet("zero-action")) {
        throw UsageError(QStringLiteral("give exactly one of --actions FILE and --zero-action"));
    }
    Eigen::MatrixXd actions;
    int steps = 0;
    if (line.isSet("actions")) {
        actions = readActionTable(line.value("actions"), info.actionNames);
        steps = static_cast<int>(actions.rows());
    }
    if (line.isSet("duration")) {
        steps =
            static_cast<int>(line.number("duration", 0.0, 86400.0) / timing.controlPeriod + 0.5);
        if (actions.rows() > 0 && steps > actions.rows()) {
            throw UsageError(QStringLiteral("%1 has %2 action rows, %3 s needs %4")
                                 .arg(line.value("actions"))
                                 .arg(actions.rows())
                                 .arg(line.value("duration"))
                                 .arg(steps));
        }
    } else if (line.isSet("zero-action")) {
        throw UsageError(QStringLiteral("--zero-action needs --duration"));
    }
    if (steps < 1) {
        throw UsageError(
            QStringLiteral("nothing to simulate: the duration is under one control period"));
    }
    // The work bounded before it starts (as lemma41's grid): rows kept in memory and written,
    // and physics steps taken.
    if (steps > kMaxSteps) {
        throw UsageError(QStringLiteral("%1 control steps (--duration / --dt) is more than the %2 "
                                        "a simulation may take (%3 MB of rows): a longer "
                                        "--dt or a shorter --duration")
                             .arg(steps)
                             .arg(kMaxSteps)
                             .arg(kMaxSteps * (n + m + 1) * 8 / 1000000));
    }
    if (static_cast<long long>(steps) * timing.physicsSubsteps > kMaxPhysicsSteps) {
        throw UsageError(QStringLiteral("%1 control steps of %2 physics substeps is more than the "
                                        "%3 physics steps a simulation may take (about %4 s on "
                                        "one core): fewer --substeps or a shorter --duration")
                             .arg(steps)
                             .arg(timing.physicsSubsteps)
                             .arg(kMaxPhysicsSteps)
                             .arg(kMaxPhysicsSeconds));
    }

    Eigen::VectorXd state;
    if (line.isSet("initial")) {
        const QStringList fields = line.value("initial").split(QLatin1Char(','));
        if (fields.size() != n) {
            throw UsageError(QStringLiteral("--initial has %1 values, the %2 state has %3 (%4)")
                                 .arg(fields.size())
                                 .arg(plantName)
                                 .arg(n)
                                 .arg(info.stateNames.join(", ")));
        }
        state.resize(n);
        for (int i = 0; i < n; ++i) {
            bool ok = false;
            state[i] = fields[i].trimmed().toDouble(&ok);
            if (!ok || !std::isfinite(state[i])) {
                throw UsageError(
                    QStringLiteral("--initial value %1 ('%2', for %3) is not a finite number")
                        .arg(i + 1)
                        .arg(fields[i].trimmed(), info.stateNames[i]));
            }
        }
        // Within the plant's bounds (sim::PlantInfo::stateProblem), before the physics sees it.
        if (const QString problem = info.stateProblem(state); !problem.isEmpty()) {
            throw UsageError(QStringLiteral("--initial: %1").arg(problem));
        }
        state = plant->resetTo(state);
    } else {
        state = plant->reset(0, sim::Perturbation::none());
    }

    sim::DemonstrationRecorder recorder(info, timing.controlPeriod);
    Eigen::VectorXd action = Eigen::VectorXd::Zero(m);
    for (int k = 0; k < steps; ++k) {
        if (actions.rows() > 0) {
            action = actions.row(k).transpose();
        }
        recorder.record(state, action);
        state = plant->step(action);
    }
    recorder.record(state, action);  // the final state; its action is the last one, held
    core::Demonstration result = recorder.demonstration();
    result.metadata.insert(QStringLiteral("source"), QStringLiteral("prisca-cli simulate"));
    result.metadata.insert(QStringLiteral("note"),
                           QStringLiteral("the last row's action repeats the one before it"));
    writeDemonstration(result, out);

    if (line.format() == QLatin1String("json")) {
        QJsonArray finalState;
        for (int i = 0; i < n; ++i) {
            finalState.append(state[i]);
        }
        printJson({{"plant", plantName},
                   {"steps", steps},
                   {"duration", steps * timing.controlPeriod},
                   {"finalState", finalState},
                   {"out", out}});
    } else {
        QStringList parts;
        for (int i = 0; i < n; ++i) {
            parts << QStringLiteral("%1 = %2 %3")
                         .arg(info.stateNames[i])
                         .arg(state[i], 0, 'g', 6)
                         .arg(info.stateUnits[i]);
        }
        printText(QStringLiteral("simulated %1 for %2 s (%3 steps); final state: %4\nwrote %5\n")
                      .arg(plantName)
                      .arg(steps * timing.controlPeriod)
                      .arg(steps)
                      .arg(parts.join(", "), out));
    }
    return 0;
}

}  // namespace prisca::app::cli
