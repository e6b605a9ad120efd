#include "sim/experiments/Table1Protocol.h"

#include "sim/DemonstrationStyles.h"

#include <QFileInfo>

#include <cmath>
#include <memory>
#include <stdexcept>

namespace prisca::sim {

std::vector<std::uint64_t> consecutiveSeedSets(std::uint64_t first, int count) {
    std::vector<std::uint64_t> sets;
    for (int i = 0; i < count; ++i) {
        sets.push_back(first + static_cast<std::uint64_t>(i));
    }
    return sets;
}

QString variantName(const PlantParameters* parameters) {
    if (!parameters || parameters->source.isEmpty()) {
        return QStringLiteral("catalog");
    }
    return QFileInfo(parameters->source).completeBaseName();
}

Table1ProtocolResult runTable1Protocol(const Table1ProtocolSettings& settings,
                                       const MethodTuning& profile) {
    const QString& plant = profile.info.name;
    if (const QString unknown = DemonstrationStyles::unknownStyleIn(plant, settings.styles);
        !unknown.isEmpty()) {
        throw std::invalid_argument(unknown.toStdString());
    }
    if (settings.styles.isEmpty() || settings.seedSets.empty()) {
        throw std::invalid_argument("the protocol needs at least one style and one seed set");
    }
    Table1ProtocolResult result;
    const size_t methods = static_cast<size_t>(settings.table.methods.size());
    result.cells.resize(methods);
    result.curves.resize(methods);
    for (size_t m = 0; m < methods; ++m) {
        result.curves[m].method = settings.table.methods[static_cast<int>(m)];
    }
    std::vector<std::shared_ptr<const PlantParameters>> variants = settings.variants;
    const bool byVariant = !variants.empty();
    if (!byVariant) {
        variants.push_back(settings.plantParameters);
    }
    QStringList variantNames;
    for (const auto& variant : variants) {
        if (variant && variant->plant != plant) {
            throw std::invalid_argument(QStringLiteral("the variant %1 is a %2, not a %3")
                                            .arg(variant->source, variant->plant, plant)
                                            .toStdString());
        }
        variantNames << variantName(variant.get());
    }
    const int cellCount =
        static_cast<int>(variants.size() * settings.styles.size() * settings.seedSets.size());
    int cell = 0;
    for (size_t v = 0; v < variants.size() && !result.cancelled; ++v) {
        for (const QString& style : settings.styles) {
            for (std::uint64_t set : settings.seedSets) {
                if (settings.table.cancelled && settings.table.cancelled()) {
                    result.cancelled = true;
                    break;
                }
                ++cell;
                if (settings.table.progress) {
                    settings.table.progress(
                        QStringLiteral("table1: cell %1/%2 (%3%4, seed set %5)")
                            .arg(cell)
                            .arg(cellCount)
                            .arg(byVariant ? variantNames[static_cast<int>(v)] + QLatin1Char(' ')
                                           : QString())
                            .arg(style)
                            .arg(set));
                }
                // The demonstration is recorded on the day's car (session model: its mismatch).
                const Task task =
                    makeTask(profile,
                             std::make_shared<core::Demonstration>(DemonstrationStyles::record(
                                 plant, style, set, {},
                                 demonstrationConditions(settings.table.run, profile,
                                                         variants[v].get(), set))),
                             settings.fit, variants[v]);
                Table1Settings table = settings.table;
                table.run.seed = set;
                table.keepPaths = false;
                const Table1Result run = runTable1(table, task);
                int finished = 0;
                const std::vector<core::Table1Row> rows = table1Rows(run, &finished);
                result.finishedTrials += finished;
                if (run.cancelled) {
                    // A cell cut short is left out: its means would not be comparable.
                    result.cancelled = true;
                    break;
                }
                for (size_t m = 0; m < rows.size(); ++m) {
                    result.cells[m].push_back(
                        {byVariant ? variantNames[static_cast<int>(v)] : style, set, rows[m],
                         byVariant ? style : QString()});
                    // The trials by their place in the day, training first.
                    const MethodTrials& trials = run.methods[m];
                    TrialCurve& curve = result.curves[m];
                    curve.trainingTrials = static_cast<int>(trials.training.size());
                    std::vector<const TrialSummary*> day;
                    for (const TrialSummary& t : trials.training) {
                        day.push_back(&t);
                    }
                    for (size_t t = 0; t < trials.trials.size(); ++t) {
                        day.push_back(trials.completed[t] ? &trials.trials[t] : nullptr);
                    }
                    if (curve.position.size() < day.size()) {
                        curve.position.resize(day.size());
                        curve.orientation.resize(day.size());
                    }
                    for (size_t i = 0; i < day.size(); ++i) {
                        if (day[i]) {
                            curve.position[i].push_back(day[i]->finalPositionError * 100.0);
                            curve.orientation[i].push_back(day[i]->finalHeadingError * 180.0 /
                                                           M_PI);
                        }
                    }
                }
            }
            if (result.cancelled) {
                break;
            }
        }
    }
    result.summary =
        core::summarizeProtocol(settings.table.methods, byVariant ? variantNames : settings.styles,
                                settings.seedSets, result.cells);
    result.summary.byVariant = byVariant;
    return result;
}

}  // namespace prisca::sim
