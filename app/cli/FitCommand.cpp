// prisca-cli fit: the action mapping B_v of eq. 8 from a demonstration.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"

#include <QJsonArray>

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

QJsonValue finiteOrNull(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

}  // namespace

int fitCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("fit"),
                     QStringLiteral("Fit the action mapping B_v (eq. 8) to a demonstration and "
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
    const Task task =
        loadTask(line.value("plant"), line.required("demo"), line.value("mask"), options);
    const core::ActionMappingFit& fit = task.fit;
    const core::Demonstration& demo = *task.demonstration;

    if (line.format() == QLatin1String("json")) {
        QJsonArray r2, rms, conflicts, unexcited, warnings;
        for (int c = 0; c < demo.stateDimension(); ++c) {
            r2.append(finiteOrNull(fit.rSquared[c]));
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
                   {"rSquared", r2},
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
    for (const QString& w : fit.warnings) {
        text += QStringLiteral("warning: %1\n").arg(w);
    }
    printText(text);
    return 0;
}

}  // namespace prisca::app::cli
