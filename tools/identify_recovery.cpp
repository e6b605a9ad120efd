// Developer tool (not installed): how well identification recovers cars of known parameters.
// For each plant file given, records the style's demonstration on that car (nominal: no day's
// mismatch, no unmodelled effect added; STYLE may name several, comma-separated, one
// demonstration each), identifies from the demonstrations alone, starting from
// the prior an operator has (sim::measuredPrior: the car's measured mass and geometry, the
// catalog's values for everything fitted), and prints each fitted parameter's error against the
// car's true value. Identification's own defaults (IdentificationSettings{}), as `prisca-cli
// identify` and the Model step use (IR_RESTARTS, IR_EVALUATIONS, IR_SEGMENT in ms: development
// overrides).
//   identify_recovery STYLE SEED CAR.json [CAR.json ...]
// Exit 0 when every parameter reported identified on every car is within 10 % of its true value.
#include "sim/DemonstrationStyles.h"
#include "sim/planning/Identification.h"
#include "sim/plants/PlantParameters.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace prisca;
using namespace prisca::sim;

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    if (argc < 4) {
        std::fprintf(stderr, "usage: identify_recovery STYLE SEED CAR.json [CAR.json ...]\n");
        return 2;
    }
    const QString style = QString::fromLocal8Bit(argv[1]);
    const std::uint64_t seed = std::stoull(argv[2]);
    IdentificationSettings settings;
    // Development overrides.
    if (qEnvironmentVariableIsSet("IR_RESTARTS"))
        settings.restarts = qEnvironmentVariableIntValue("IR_RESTARTS");
    if (qEnvironmentVariableIsSet("IR_EVALUATIONS"))
        settings.evaluationsPerStart = qEnvironmentVariableIntValue("IR_EVALUATIONS");
    if (qEnvironmentVariableIsSet("IR_SEGMENT"))
        settings.segmentSeconds = qEnvironmentVariableIntValue("IR_SEGMENT") / 1000.0;
    for (const QString& one : style.split(QLatin1Char(','))) {
        if (!DemonstrationStyles::contains(QStringLiteral("slidecar"), one)) {
            std::fprintf(
                stderr, "unknown slidecar style '%s' (one of: %s)\n", qPrintable(one),
                qPrintable(
                    DemonstrationStyles::names(QStringLiteral("slidecar")).join(QLatin1Char(' '))));
            return 2;
        }
    }
    double worstError = 0.0;
    QString worstKey;
    int failures = 0;
    for (int i = 3; i < argc; ++i) {
        const QString file = QString::fromLocal8Bit(argv[i]);
        QString error;
        const auto car = readPlantParameters(file, QStringLiteral("slidecar"), &error);
        if (!car) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 2;
        }
        RecordingConditions conditions;
        conditions.parameters = &*car;
        std::vector<core::Demonstration> demonstrations;
        for (const QString& one : style.split(QLatin1Char(','))) {
            demonstrations.push_back(DemonstrationStyles::record(
                QStringLiteral("slidecar"), one, seed, SimulationTiming{}, conditions));
        }
        const IdentificationResult result =
            identifyPlant(demonstrations, measuredPrior(*car), settings);
        const QString name = QFileInfo(file).completeBaseName();
        if (!result.ok()) {
            std::printf("%-14s refused: %s\n", qPrintable(name), qPrintable(result.refusal));
            ++failures;
            continue;
        }
        // The true car's own fit on the same segments: where the fit found is better, the
        // model's restarts, not the search, keep the truth from being the best fit.
        std::printf("%-14s fit %.2f cm (prior %.2f cm, the true car %.2f cm)\n", qPrintable(name),
                    100.0 * result.positionRms, 100.0 * result.priorPositionRms,
                    100.0 * modelPositionRms(demonstrations, *car, settings));
        for (const IdentifiedParameter& p : result.table) {
            if (!p.fitted) {
                continue;
            }
            const double truth = car->value(p.key);
            const double relative = truth != 0.0 ? (p.value - truth) / std::abs(truth)
                                                 : (p.value == 0.0 ? 0.0 : INFINITY);
            const bool within = std::abs(relative) <= 0.10;
            std::printf("  %-18s %-10s %9.4g  true %9.4g  prior %9.4g  %+7.1f %%  std %.2g%s\n",
                        qPrintable(p.key),
                        p.identified      ? "identified"
                        : p.heldAtPrior() ? "held"
                                          : "undetermined",
                        p.value, truth, p.prior, 100.0 * relative, p.std,
                        p.identified && !within ? "  OUTSIDE 10 %" : "");
            if (p.identified) {
                failures += within ? 0 : 1;
                if (std::abs(relative) > worstError) {
                    worstError = std::abs(relative);
                    worstKey = name + QLatin1Char('/') + p.key;
                }
            }
        }
        std::fflush(stdout);
    }
    std::printf("worst identified parameter: %s %.1f %%; outside 10 %% or refused: %d\n",
                qPrintable(worstKey), 100.0 * worstError, failures);
    return failures == 0 ? 0 : 1;
}
