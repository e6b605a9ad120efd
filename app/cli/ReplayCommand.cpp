// prisca-cli replay: a trial bundle's summary and scores.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "rig/TrialBundle.h"

#include <QJsonArray>
#include <QJsonObject>

namespace prisca::app::cli {

int replayCommand(const QStringList& arguments) {
    CommandLine line(QStringLiteral("replay"),
                     QStringLiteral("A trial bundle (rig --bundle-dir, or the window's trials): "
                                    "what ran, its samples and frames, and its scores. A bundle "
                                    "whose writer was killed reads up to its last second."));
    line.addPositional(QStringLiteral("BUNDLE"), QStringLiteral("The trial bundle's folder."));
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    const QStringList positional = line.positionalArguments();
    if (positional.size() != 1) {
        throw UsageError(
            QStringLiteral("replay needs one bundle folder, %1 given").arg(positional.size()));
    }
    QString error;
    const auto bundle = rig::TrialBundle::load(positional.front(), &error);
    if (!bundle) {
        throw UsageError(error);
    }
    const QJsonObject summary = rig::summarizeBundle(*bundle);
    if (line.format() == QLatin1String("json")) {
        printJson(summary);
        return 0;
    }
    QString text = QStringLiteral(
                       "%1 trial, %2, %3 s: %4 samples (%5 with a pose, %6 in "
                       "failsafe), %7 frames%8\n")
                       .arg(summary.value("kind").toString(), summary.value("method").toString())
                       .arg(summary.value("seconds").toDouble(), 0, 'f', 2)
                       .arg(summary.value("samples").toInt())
                       .arg(summary.value("samplesWithPose").toInt())
                       .arg(summary.value("samplesInFailsafe").toInt())
                       .arg(summary.value("frames").toInt())
                       .arg(bundle->complete() ? QString()
                                               : QStringLiteral(" (incomplete: the writer "
                                                                "stopped before the trial ended)"));
    if (summary.contains("finalPositionErrorCm")) {
        text += QStringLiteral("last pose %1 cm and %2 deg from the lot\n")
                    .arg(summary.value("finalPositionErrorCm").toDouble(), 0, 'f', 1)
                    .arg(summary.value("finalHeadingErrorDeg").toDouble(), 0, 'f', 1);
    }
    const QJsonObject result = summary.value("result").toObject();
    if (result.value("failsafe").toBool()) {
        text += QStringLiteral("ended in failsafe: %1\n").arg(result.value("reason").toString());
    }
    printText(text);
    return 0;
}

}  // namespace prisca::app::cli
