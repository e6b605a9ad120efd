// prisca-cli identify: a plant's parameters fitted to a demonstration (and trial bundles) by
// multiple shooting; writes the identified plant file and says what the data determined.
#include "app/cli/CliSupport.h"
#include "app/cli/Commands.h"
#include "app/cli/TaskSetup.h"
#include "rig/TrialBundle.h"
#include "sim/PlantCatalog.h"
#include "sim/planning/Identification.h"
#include "sim/planning/IdentificationReport.h"
#include "sim/plants/PlantParameters.h"

#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace prisca::app::cli {

namespace {

// The report printed with --format json: the one the plant file keeps, where it went and what
// it came from.
QJsonObject reportJson(const sim::IdentificationResult& result, const QString& out,
                       const QStringList& sources) {
    QJsonObject report = sim::identificationReportJson(result);
    report.insert(QStringLiteral("out"), out);
    report.insert(QStringLiteral("sources"), QJsonArray::fromStringList(sources));
    return report;
}

QString reportText(const sim::IdentificationResult& result, const QString& out) {
    QString text = QStringLiteral(
                       "%1 identified from %2 segments: pose error %3 cm, %4 deg RMS "
                       "per segment (the prior: %5 cm); wrote %6\n")
                       .arg(result.parameters.plant)
                       .arg(result.segments.size())
                       .arg(100.0 * result.positionRms, 0, 'f', 2)
                       .arg(result.headingRms * 180.0 / M_PI, 0, 'f', 2)
                       .arg(100.0 * result.priorPositionRms, 0, 'f', 2)
                       .arg(out);
    int width = 0;
    for (const sim::IdentifiedParameter& p : result.table) {
        width = std::max(width, static_cast<int>(p.key.size()));
    }
    for (const sim::IdentifiedParameter& p : result.table) {
        if (!p.fitted) {
            continue;
        }
        const QString unit = p.unit == QLatin1String("1") ? QString() : QLatin1Char(' ') + p.unit;
        text += QStringLiteral("  %1  %2 +- %3%4  %5 (prior %6)\n")
                    .arg(p.key, -width)
                    .arg(p.value, 9, 'g', 4)
                    .arg(p.std, -8, 'g', 2)
                    .arg(unit, -8)
                    .arg(p.identified      ? QStringLiteral("identified")
                         : p.heldAtPrior() ? QStringLiteral("held at its prior")
                                           : QStringLiteral("not determined (fitted value)"))
                    .arg(p.prior, 0, 'g', 4);
    }
    QStringList held;
    for (const sim::IdentifiedParameter& p : result.table) {
        if (!p.fitted) {
            held << p.key;
        }
    }
    text +=
        QStringLiteral("  not fitted (from the prior): %1\n").arg(held.join(QStringLiteral(", ")));
    text += QStringLiteral("segments (run, start s: position cm, heading deg RMS):");
    for (const sim::SegmentFit& s : result.segments) {
        text += QStringLiteral(" %1@%2: %3, %4;")
                    .arg(s.run + 1)
                    .arg(s.start, 0, 'f', 1)
                    .arg(100.0 * s.positionRms, 0, 'f', 2)
                    .arg(s.headingRms * 180.0 / M_PI, 0, 'f', 2);
    }
    text.chop(1);
    return text + QLatin1Char('\n');
}

}  // namespace

int identifyCommand(const QStringList& arguments) {
    CommandLine line(
        QStringLiteral("identify"),
        QStringLiteral("Fits a plant's physical parameters to a demonstration (and the trials of "
                       "trial bundles) by multiple shooting over short segments, and writes the "
                       "identified plant file. It says which parameters the data determined "
                       "(each with its standard deviation), which it held at their prior, and "
                       "the fit per segment. Data that cannot identify (too short, no slide, a "
                       "constant command, a gap in the poses) is refused with exit 2."));
    line.addValue("plant", "Plant: " + sim::PlantCatalog::names().join(", ") + ".", "name");
    line.addValue("demo", "The demonstration CSV to identify from.", "file");
    line.addValue("bundle", "A trial bundle whose trial is data too (may be given several times).",
                  "folder");
    addPlantParametersOption(line);
    line.addValue("out", "The identified plant file to write (JSON).", "file");
    // The window's Model step identifies with these same defaults.
    const sim::IdentificationSettings defaults;
    line.addValue("segment",
                  QStringLiteral("Segment length [s] (default %1).").arg(defaults.segmentSeconds),
                  "seconds", QString::number(defaults.segmentSeconds));
    line.addValue("restarts",
                  QStringLiteral("Further local searches from perturbed starts (default %1).")
                      .arg(defaults.restarts),
                  "N", QString::number(defaults.restarts));
    line.addValue("evaluations",
                  QStringLiteral("Model runs per local search (default %1).")
                      .arg(defaults.evaluationsPerStart),
                  "N", QString::number(defaults.evaluationsPerStart));
    line.addFormat({"text", "json"});
    if (!line.parse(arguments)) {
        return 0;
    }
    checkOutputs(line, {"out"});
    const QString plant = checkedPlant(line.required("plant"));
    const QString out = line.required("out");
    std::vector<core::Demonstration> runs;
    QStringList sources;
    const QString demoPath = line.required("demo");
    runs.push_back(readDemonstration(demoPath));
    runs.back().metadata.insert(QStringLiteral("source"), demoPath);
    sources << demoPath;
    for (const QString& folder : line.values("bundle")) {
        QString error;
        const auto bundle = rig::TrialBundle::load(folder, &error);
        if (!bundle) {
            throw UsageError(error);
        }
        const std::vector<core::Demonstration> parts = rig::recordedRuns(*bundle);
        if (parts.empty()) {
            throw UsageError(QStringLiteral("%1: no stretch of 10 samples with a pose and a "
                                            "command to identify from")
                                 .arg(folder));
        }
        runs.insert(runs.end(), parts.begin(), parts.end());
        sources << folder;
    }
    const auto prior = plantParametersOption(line, plant);
    sim::IdentificationSettings settings;
    settings.segmentSeconds = line.number("segment", 0.2, 10.0);
    settings.restarts = static_cast<int>(line.integer("restarts", 0, 20));
    settings.evaluationsPerStart = static_cast<int>(line.integer("evaluations", 20, 1000000));
    installInterruptHandler();
    QElapsedTimer clock;
    clock.start();
    qint64 lastShown = 0;
    const sim::IdentificationResult result = sim::identifyPlant(
        runs, prior ? *prior : sim::defaultPlantParameters(plant), settings,
        [&](long long done, long long total) {
            if (clock.elapsed() - lastShown > 1000) {
                lastShown = clock.elapsed();
                printProgress(QStringLiteral("identify: %1 of about %2 model runs, %3 s")
                                  .arg(done)
                                  .arg(total)
                                  .arg(clock.elapsed() / 1000));
            }
            return !interrupted();
        });
    printProgress(QString());
    if (!result.refusal.isEmpty()) {
        throw UsageError(
            QStringLiteral("cannot identify the %1 from this data: %2").arg(plant, result.refusal));
    }
    if (result.cancelled) {
        printText(QStringLiteral("identify: interrupted by %1; nothing written\n")
                      .arg(interruptionName()));
        return interruptedExitCode();
    }
    const QJsonObject report = reportJson(result, out, sources);
    // The plant file, with the identification's report kept beside the values.
    writeOutput(
        out,
        sim::identifiedPlantFile(
            result, QStringLiteral("identified from %1").arg(sources.join(QStringLiteral(", "))),
            sources),
        true);
    if (line.format() == QLatin1String("json")) {
        printJson(report);
    } else {
        printText(reportText(result, out));
    }
    return 0;
}

}  // namespace prisca::app::cli
