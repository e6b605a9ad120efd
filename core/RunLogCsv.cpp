#include "RunLogCsv.h"

namespace prisca::core {

QByteArray formatRunLogCsv(const RunLog& log, QString* problem) {
    if (log.columns.size() != log.rows.cols() || log.units.size() != log.columns.size()) {
        if (problem) {
            *problem = QStringLiteral("%1 columns, %2 units and %3 values per row disagree")
                           .arg(log.columns.size())
                           .arg(log.units.size())
                           .arg(log.rows.cols());
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
