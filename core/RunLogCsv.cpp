#include "RunLogCsv.h"

#include "DemonstrationCsvText.h"

namespace prisca::core {

namespace {

// Why a "# key: value" line's text would not survive, or empty if it would.
QString lineProblem(const QString& text) {
    for (const QChar c : text) {
        if (c.unicode() < 0x20 || c.unicode() == 0x7f) {
            return QStringLiteral("contains a control character");
        }
    }
    return {};
}

// The first reason the log cannot be written as the format says, or empty.
QString logProblem(const RunLog& log) {
    if (log.columns.size() != log.rows.cols() || log.units.size() != log.columns.size()) {
        return QStringLiteral("%1 columns, %2 units and %3 values per row disagree")
            .arg(log.columns.size())
            .arg(log.units.size())
            .arg(log.rows.cols());
    }
    using csvtext::quoted;
    for (const auto& [what, text] : {std::pair{"plant", log.plant}, {"method", log.method}}) {
        if (const QString why = lineProblem(text); !why.isEmpty()) {
            return QStringLiteral("the %1 %2 %3").arg(what, quoted(text), why);
        }
    }
    for (auto it = log.metadata.cbegin(); it != log.metadata.cend(); ++it) {
        QString why = lineProblem(it.key() + it.value());
        if (why.isEmpty() && (it.key().isEmpty() || it.key().contains(QLatin1Char(':')))) {
            why = QStringLiteral("needs a key without ':'");
        }
        if (!why.isEmpty()) {
            return QStringLiteral("the metadata line %1 %2").arg(quoted(it.key()), why);
        }
    }
    for (int c = 0; c < log.columns.size(); ++c) {
        if (const QString why = csvtext::nameProblem(log.columns[c]); !why.isEmpty()) {
            return QStringLiteral("column %1 %2 %3").arg(c + 1).arg(quoted(log.columns[c]), why);
        }
        if (const QString why = csvtext::unitProblem(log.units[c]); !why.isEmpty()) {
            return QStringLiteral("the unit %1 of column %2 %3")
                .arg(quoted(log.units[c]), quoted(log.columns[c]), why);
        }
    }
    return {};
}

}  // namespace

QByteArray formatRunLogCsv(const RunLog& log, QString* problem) {
    if (const QString why = logProblem(log); !why.isEmpty()) {
        if (problem) {
            *problem = why;
        }
        return {};
    }
    QByteArray out("# prisca-run-log 1\n");
    out += "# plant: " + log.plant.toUtf8() + '\n';
    out += "# method: " + log.method.toUtf8() + '\n';
    out += "# dt: ";
    appendCsvNumber(out, log.dt);
    out += '\n';
    for (auto it = log.metadata.cbegin(); it != log.metadata.cend(); ++it) {
        out += "# " + it.key().toUtf8() + ": " + it.value().toUtf8() + '\n';
    }
    QStringList declared;
    for (int c = 0; c < log.columns.size(); ++c) {
        declared << QStringLiteral("%1[%2]").arg(log.columns[c], log.units[c]);
    }
    out += "# columns: " + declared.join(QStringLiteral(", ")).toUtf8() + '\n';
    out += log.columns.join(QLatin1Char(',')).toUtf8() + '\n';
    for (Eigen::Index r = 0; r < log.rows.rows(); ++r) {
        for (Eigen::Index c = 0; c < log.rows.cols(); ++c) {
            if (c > 0) {
                out += ',';
            }
            appendCsvNumber(out, log.rows(r, c));
        }
        out += '\n';
    }
    return out;
}

bool writeRunLogCsv(const RunLog& log, const QString& path, FileError* error) {
    QString problem;
    const QByteArray text = formatRunLogCsv(log, &problem);
    if (text.isEmpty()) {
        if (error) {
            *error =
                FileError{path, 0, 0, QStringLiteral("cannot write this run log: %1").arg(problem)};
        }
        return false;
    }
    return writeFileAtomically(path, text, error);
}

}  // namespace prisca::core
