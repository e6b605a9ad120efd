// The demonstration CSV writer: the checks a demonstration must pass to be written, the header,
// the rows, the atomic write.
#include "DemonstrationCsv.h"

#include "DemonstrationCsvText.h"

namespace prisca::core {

using namespace csvtext;

namespace {

void appendList(QByteArray& out, const char* key, const QStringList& names,
                const QStringList& units) {
    out += "# ";
    out += key;
    out += ':';
    for (int i = 0; i < names.size(); ++i) {
        out += i == 0 ? " " : ", ";
        out += names[i].toUtf8();
        out += '[';
        out += units[i].toUtf8();
        out += ']';
    }
    out += '\n';
}

}  // namespace

QString checkDemonstrationForCsv(const Demonstration& demo) {
    const QString invalid = demo.validate();
    if (!invalid.isEmpty()) {
        return invalid;
    }
    QStringList seen;
    const auto checkChannels = [&seen](const QString& kind, const QStringList& names,
                                       const QStringList& units) -> QString {
        for (int i = 0; i < names.size(); ++i) {
            const QString nameWhy = stateOrActionNameProblem(names[i]);
            if (!nameWhy.isEmpty()) {
                return QStringLiteral("%1 name %2 %3").arg(kind, quoted(names[i]), nameWhy);
            }
            if (seen.contains(names[i])) {
                return QStringLiteral("%1 name %2 is used twice; column names must be unique")
                    .arg(kind, quoted(names[i]));
            }
            seen.append(names[i]);
            const QString unitWhy = unitProblem(units[i]);
            if (!unitWhy.isEmpty()) {
                return QStringLiteral("unit %1 of %2 %3 %4")
                    .arg(quoted(units[i]), kind, quoted(names[i]), unitWhy);
            }
        }
        return {};
    };
    QString problem = checkChannels(QStringLiteral("state"), demo.stateNames, demo.stateUnits);
    if (problem.isEmpty()) {
        problem = checkChannels(QStringLiteral("action"), demo.actionNames, demo.actionUnits);
    }
    if (!problem.isEmpty()) {
        return problem;
    }
    if (hasLineBreak(demo.plant)) {
        return QStringLiteral("the plant name %1 contains a line break").arg(quoted(demo.plant));
    }
    for (auto it = demo.metadata.cbegin(); it != demo.metadata.cend(); ++it) {
        if (const QString problem = metadataProblem(it.key(), it.value()); !problem.isEmpty()) {
            return problem;
        }
    }
    return {};
}

void appendDemonstrationCsvRow(QByteArray& out, double time, const Eigen::VectorXd& state,
                               const Eigen::VectorXd& action) {
    appendNumber(out, time);
    for (Eigen::Index c = 0; c < state.size(); ++c) {
        out += ',';
        appendNumber(out, state[c]);
    }
    for (Eigen::Index c = 0; c < action.size(); ++c) {
        out += ',';
        appendNumber(out, action[c]);
    }
    out += '\n';
}

QByteArray formatDemonstrationCsvHeader(const Demonstration& demo) {
    QByteArray out;
    out += kMagicLine;
    out += '\n';
    if (!demo.plant.isEmpty()) {
        out += "# plant: " + demo.plant.toUtf8() + '\n';
    }
    out += "# dt: ";
    appendNumber(out, demo.dt);
    out += '\n';
    appendList(out, "states", demo.stateNames, demo.stateUnits);
    appendList(out, "actions", demo.actionNames, demo.actionUnits);
    for (auto it = demo.metadata.cbegin(); it != demo.metadata.cend(); ++it) {
        out += "# " + it.key().toUtf8() + ':';
        if (!it.value().isEmpty()) {
            out += ' ' + it.value().toUtf8();
        }
        out += '\n';
    }
    out += 't';
    for (const QString& name : demo.stateNames + demo.actionNames) {
        out += ',' + name.toUtf8();
    }
    out += '\n';
    return out;
}

QByteArray formatDemonstrationCsv(const Demonstration& demo, QString* problem) {
    try {
        const QString why = checkDemonstrationForCsv(demo);
        if (!why.isEmpty()) {
            if (problem) {
                *problem = why;
            }
            return {};
        }
        const int rows = demo.length();
        const int n = demo.stateDimension();
        const int m = demo.actionDimension();
        QByteArray out;
        // About 12 characters per number; one allocation for the usual case.
        out.reserve(qsizetype(rows) * (1 + n + m) * 12 + 1024);
        out += formatDemonstrationCsvHeader(demo);
        for (int k = 0; k < rows; ++k) {
            appendDemonstrationCsvRow(out, demo.time[k], demo.states.row(k).transpose(),
                                      demo.actions.row(k).transpose());
        }
        return out;
    } catch (const std::bad_alloc&) {
        if (problem) {
            *problem = QStringLiteral("not enough memory to format the demonstration");
        }
        return {};
    }
}

bool writeDemonstrationCsv(const Demonstration& demo, const QString& path, FileError* error) {
    const auto fail = [&](const QString& message) {
        if (error) {
            *error = FileError{path, 0, 0, message};
        }
        return false;
    };
    if (path.isEmpty()) {
        return fail(QStringLiteral("no file name given"));
    }
    QString problem;
    const QByteArray text = formatDemonstrationCsv(demo, &problem);
    if (text.isEmpty()) {
        return fail(QStringLiteral("cannot write this demonstration: %1").arg(problem));
    }
    return writeFileAtomically(path, text, error);
}

}  // namespace prisca::core
