#include "Table1Protocol.h"

#include "DemonstrationStyles.h"

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
    result.cells.resize(settings.table.methods.size());
    const int cellCount = static_cast<int>(settings.styles.size() * settings.seedSets.size());
    int cell = 0;
    for (const QString& style : settings.styles) {
        for (std::uint64_t set : settings.seedSets) {
            if (settings.table.cancelled && settings.table.cancelled()) {
                result.cancelled = true;
                break;
            }
            ++cell;
            if (settings.table.progress) {
                settings.table.progress(QStringLiteral("table1: cell %1/%2 (%3, seed set %4)")
                                            .arg(cell)
                                            .arg(cellCount)
                                            .arg(style)
                                            .arg(set));
            }
            const Task task = makeTask(profile,
                                       std::make_shared<core::Demonstration>(
                                           DemonstrationStyles::record(plant, style, set)),
                                       settings.fit);
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
                result.cells[m].push_back({style, set, rows[m]});
            }
        }
        if (result.cancelled) {
            break;
        }
    }
    result.summary = core::summarizeProtocol(settings.table.methods, settings.styles,
                                             settings.seedSets, result.cells);
    return result;
}

}  // namespace prisca::sim
