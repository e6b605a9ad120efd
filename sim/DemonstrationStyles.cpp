#include "sim/DemonstrationStyles.h"

#include "sim/PlantCatalog.h"

#include <stdexcept>

namespace prisca::sim {

namespace {

[[noreturn]] void unknownStyle(const QString& plant, const QString& style) {
    const QStringList known = DemonstrationStyles::names(plant);
    if (known.isEmpty()) {
        throw std::invalid_argument(
            QStringLiteral("no demonstration styles for plant '%1'").arg(plant).toStdString());
    }
    throw std::invalid_argument(QStringLiteral("unknown %1 style '%2' (one of: %3)")
                                    .arg(plant, style, known.join(QLatin1Char(' ')))
                                    .toStdString());
}

}  // namespace

std::vector<DemonstrationStyle> DemonstrationStyles::of(const QString& plant) {
    const PlantEntry* entry = PlantCatalog::find(plant);
    return entry && entry->styles.list ? entry->styles.list() : std::vector<DemonstrationStyle>{};
}

QStringList DemonstrationStyles::names(const QString& plant) {
    QStringList names;
    for (const DemonstrationStyle& s : of(plant)) {
        names << s.name;
    }
    return names;
}

QString DemonstrationStyles::unknownStyleIn(const QString& plant, const QStringList& styles) {
    for (const QString& style : styles) {
        if (!contains(plant, style)) {
            return QStringLiteral("unknown %1 style '%2' (one of: %3)")
                .arg(plant, style, names(plant).join(QLatin1Char(' ')));
        }
    }
    return {};
}

QString DemonstrationStyles::classic(const QString& plant) {
    const QStringList all = names(plant);
    return all.isEmpty() ? QString() : all.front();
}

core::Demonstration DemonstrationStyles::record(const QString& plant, const QString& style,
                                                std::uint64_t seed, const SimulationTiming& timing,
                                                const RecordingConditions& conditions) {
    const PlantEntry* entry = PlantCatalog::find(plant);
    if (!entry || !entry->styles.record) {
        unknownStyle(plant, style);
    }
    if (conditions.parameters && conditions.parameters->plant != plant) {
        throw std::invalid_argument(QStringLiteral("a %1 demonstration recorded with %2 parameters")
                                        .arg(plant, conditions.parameters->plant)
                                        .toStdString());
    }
    return recordInStyle(entry->styles, style, seed, timing, conditions);
}

}  // namespace prisca::sim
