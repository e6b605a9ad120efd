// prisca-cli fit: the action mapping B_v of eq. 8 from a demonstration.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "sim/PlantCatalog.h"

#include <QJsonArray>

#include <algorithm>

namespace prisca::app::cli {

namespace {

QJsonArray matrixJson(const Eigen::MatrixXd& matrix) {
    QJsonArray rows;
    for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
        QJsonArray row;
        for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
            row.append(matrix(r, c));
        }
        rows.append(row);
    }
    return rows;
}

std::vector<int> columns(const QString& option, const QString& text, int n) {
    std::vector<int> out;
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        bool ok = false;
        const int c = part.trimmed().toInt(&ok);
        if (!ok || c < 0 || c >= n) {
            throw UsageError(QStringLiteral("--%1: '%2' is not a state column 0..%3")
                                 .arg(option, part.trimmed())
                                 .arg(n - 1));
        }
        out.push_back(c);
    }
    return out;
}

// The demonstration and its fit: a catalogued plant's checks and B~ by default; a robot outside
// the catalog needs its B~ (--mask) and, if it has angles or a planar pose, says which columns.
Task fitTask(const CommandLine& line, const QString& demoPath,
             const core::ActionMappingFitOptions& options) {
    const QString plant = line.value("plant");
    core::Demonstration demonstration = readDemonstration(demoPath);
    if (actionsNeverChange(demonstration)) {
        throw UsageError(QStringLiteral("%1: the actions never change; B_v is fitted from how "
                                        "the state answers changes of the actions, so there is "
                                        "nothing to fit")
                             .arg(demoPath));
    }
    const QString named = plant.isEmpty() ? demonstration.plant : plant;
    if (sim::PlantCatalog::contains(named) && !line.isSet("angles") && !line.isSet("pose")) {
        return loadTask(plant, demoPath, line.value("mask"), options);
    }
    if (!line.isSet("mask")) {
        throw UsageError(QStringLiteral("%1: '%2' is not a catalogued plant (%3): give its "
                                        "intuitive mapping B~ with --mask")
                             .arg(demoPath, named.isEmpty() ? QStringLiteral("?") : named,
                                  sim::PlantCatalog::names().join(' ')));
    }
    const int n = demonstration.stateDimension();
    const int m = demonstration.actionDimension();
    QString error;
    const auto mapping = core::IntuitiveMapping::parse(line.value("mask"), &error);
    if (!mapping) {
        throw UsageError(QStringLiteral("--mask: %1").arg(error));
    }
    if (mapping->controls() != m || mapping->states() != n) {
        throw UsageError(
            QStringLiteral("--mask has %1 x %2 signs; %3 has %4 controls and %5 states")
                .arg(mapping->controls())
                .arg(mapping->states())
                .arg(demoPath)
                .arg(m)
                .arg(n));
    }
    core::DeviationModel deviation = core::DeviationModel::euclidean(n);
    deviation.angleIndices = columns(QStringLiteral("angles"), line.value("angles"), n);
    if (line.isSet("pose")) {
        const std::vector<int> pose = columns(QStringLiteral("pose"), line.value("pose"), n);
        if (pose.size() != 3) {
            throw UsageError(QStringLiteral("--pose needs three columns: x,y,heading"));
        }
        deviation.pose = core::PlanarPoseIndices{pose[0], pose[1], pose[2]};
        if (std::find(deviation.angleIndices.begin(), deviation.angleIndices.end(), pose[2]) ==
            deviation.angleIndices.end()) {
            deviation.angleIndices.push_back(pose[2]);
        }
    }
    const QString problem = deviation.validate();
    if (!problem.isEmpty()) {
        throw UsageError(problem);
    }
    Task task;
    task.plant = named;
    task.profile.mapping = *mapping;
    try {
        task.fit = core::fitActionMapping(demonstration, *mapping, deviation, options);
    } catch (const std::invalid_argument& e) {
        throw UsageError(QStringLiteral("%1: %2").arg(demoPath, QString::fromStdString(e.what())));
    }
    task.demonstration = std::make_shared<const core::Demonstration>(std::move(demonstration));
    return task;
}

}  // namespace

int fitCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("fit"),
                     QStringLiteral("Fit the action mapping B_v (eq. 8) to a demonstration of any "
                                    "robot (a catalogued plant, or any other given --mask) and "
                                    "report R^2, residuals and warnings."));
    line.addValue("demo", "Demonstration CSV.", "file");
    line.addValue("plant", "Plant (default: the demonstration's).", "name");
    line.addValue("mask",
                  "Intuitive mapping B~: rows = controls separated by ';', entries "
                  "-1, 0 or 1 per state separated by ',' (default: the plant's).",
                  "signs");
    line.addValue("latency", "Latency shift d [steps]: pairs ds_{k+1+d} with du_k.", "steps", "0");
    line.addValue("response",
                  "Response horizon R [steps] of the rate target (see ActionMapping.h).", "steps",
                  "1");
    line.addValue("target",
                  "'rate' (change of the state change, default) or 'state' (eq. 8 "
                  "read literally).",
                  "target", "rate");
    line.addFlag("allow-negative", "Do not constrain B_v >= 0.");
    line.addFlag("drift",
                 "eq. 5 in full: identify the drift A (regressors dt ds_k) together with B "
                 "(rate target, response 1).");
    line.addValue("angles",
                  "For a robot outside the catalog: state columns (0-based, comma-separated) "
                  "that are angles, wrapped to (-pi, pi].",
                  "list");
    line.addValue("pose",
                  "For a robot outside the catalog: the columns 'x,y,heading' of a planar "
                  "pose, whose error is taken in the robot's own frame.",
                  "list");
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    core::ActionMappingFitOptions options;
    options.latency = static_cast<int>(line.integer("latency", 0, 1000));
    options.responseSteps = static_cast<int>(line.integer("response", 1, 1000));
    const QString target = line.value("target");
    if (target == QLatin1String("state")) {
        options.target = core::ActionMappingFitOptions::Target::StateChange;
    } else if (target != QLatin1String("rate")) {
        throw UsageError(
            QStringLiteral("--target must be 'rate' or 'state', got '%1'").arg(target));
    }
    options.nonNegative = !line.isSet("allow-negative");
    options.drift = line.isSet("drift");
    if (options.drift && (options.target != core::ActionMappingFitOptions::Target::RateChange ||
                          options.responseSteps != 1)) {
        throw UsageError(QStringLiteral("--drift needs --target rate and --response 1"));
    }
    const QString demoPath = line.required("demo");
    const Task task = fitTask(line, demoPath, options);
    const core::ActionMappingFit& fit = task.fit;
    const core::Demonstration& demo = *task.demonstration;

    if (line.format() == QLatin1String("json")) {
        // R^2 of the states the fit explains, by name; a state no control acts on (its mask
        // column is all zeros) has none and is listed as such, never as null.
        QJsonObject r2;
        QJsonArray unexplained, rms, conflicts, unexcited, warnings;
        for (int c = 0; c < demo.stateDimension(); ++c) {
            if (std::isfinite(fit.rSquared[c])) {
                r2.insert(demo.stateNames[c], fit.rSquared[c]);
            } else {
                unexplained.append(demo.stateNames[c]);
            }
            rms.append(fit.residualRms[c]);
        }
        for (const auto& [l, c] : fit.signConflicts) {
            conflicts.append(
                QJsonObject{{"control", demo.actionNames[l]}, {"state", demo.stateNames[c]}});
        }
        for (int l : fit.unexcitedChannels) {
            unexcited.append(demo.actionNames[l]);
        }
        for (const QString& w : fit.warnings) {
            warnings.append(w);
        }
        printJson({{"plant", task.plant},
                   {"mask", task.profile.mapping.toString()},
                   {"states", QJsonArray::fromStringList(demo.stateNames)},
                   {"controls", QJsonArray::fromStringList(demo.actionNames)},
                   {"samples", fit.samples},
                   {"latency", options.latency},
                   {"Bv", matrixJson(fit.bv)},
                   {"B", matrixJson(fit.b)},
                   {"unconstrainedBv", matrixJson(fit.unconstrainedBv)},
                   {"drift", options.drift},
                   {"A", matrixJson(fit.a)},
                   {"rSquared", r2},
                   {"statesNoControlActsOn", unexplained},
                   {"residualRms", rms},
                   {"signConflicts", conflicts},
                   {"unexcitedControls", unexcited},
                   {"warnings", warnings}});
        return 0;
    }
    QString text = QStringLiteral("B = B_v (.) B~ fitted on %1 samples (mask %2, latency %3):\n")
                       .arg(fit.samples)
                       .arg(task.profile.mapping.toString())
                       .arg(options.latency);
    text += QStringLiteral("%1").arg(QString(), -12);
    for (int c = 0; c < demo.stateDimension(); ++c) {
        text += QStringLiteral("%1").arg(demo.stateNames[c], 12);
    }
    text += QLatin1Char('\n');
    for (int l = 0; l < demo.actionDimension(); ++l) {
        text += QStringLiteral("%1").arg(demo.actionNames[l], -12);
        for (int c = 0; c < demo.stateDimension(); ++c) {
            text += QStringLiteral("%1").arg(fit.b(l, c), 12, 'g', 4);
        }
        text += QLatin1Char('\n');
    }
    text += QStringLiteral("%1").arg(QStringLiteral("R^2"), -12);
    for (int c = 0; c < demo.stateDimension(); ++c) {
        text += std::isfinite(fit.rSquared[c])
                    ? QStringLiteral("%1").arg(fit.rSquared[c], 12, 'f', 3)
                    : QStringLiteral("%1").arg(QStringLiteral("-"), 12);
    }
    text += QLatin1Char('\n');
    text += QStringLiteral("%1").arg(QStringLiteral("residual"), -12);
    for (int c = 0; c < demo.stateDimension(); ++c) {
        text += QStringLiteral("%1").arg(fit.residualRms[c], 12, 'g', 3);
    }
    text += QLatin1Char('\n');
    if (options.drift) {
        text += QStringLiteral(
            "drift A (row: state's one-step change; column: the previous "
            "one-step change of) [1/s]:\n");
        for (int r = 0; r < demo.stateDimension(); ++r) {
            text += QStringLiteral("%1").arg(demo.stateNames[r], -12);
            for (int c = 0; c < demo.stateDimension(); ++c) {
                text += QStringLiteral("%1").arg(fit.a(r, c), 12, 'g', 4);
            }
            text += QLatin1Char('\n');
        }
    }
    for (const QString& w : fit.warnings) {
        text += QStringLiteral("warning: %1\n").arg(w);
    }
    printText(text);
    return 0;
}

}  // namespace prisca::app::cli
