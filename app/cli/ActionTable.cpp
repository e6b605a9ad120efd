#include "app/cli/ActionTable.h"

#include "app/cli/CliSupport.h"

#include "core/FileIo.h"

#include <QList>

#include <cmath>
#include <vector>

namespace prisca::app::cli {

Eigen::MatrixXd readActionTable(const QString& path, const QStringList& actionNames) {
    core::FileError error;
    constexpr qint64 kMaxBytes = qint64(256) << 20;
    const std::optional<QByteArray> text = core::readFileBounded(path, kMaxBytes, &error);
    if (!text) {
        throw UsageError(error.toString());
    }
    const QList<QByteArray> lines = text->split('\n');
    std::vector<int> columnOf;
    int fieldCount = 0;
    std::vector<Eigen::VectorXd> rows;
    int lineNumber = 0;
    for (const QByteArray& bytes : lines) {
        ++lineNumber;
        const QString line = QString::fromUtf8(bytes).trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#'))) {
            continue;
        }
        const QStringList fields = line.split(QLatin1Char(','));
        if (columnOf.empty()) {
            QStringList names;
            for (const QString& f : fields) {
                names << f.trimmed();
            }
            for (const QString& action : actionNames) {
                const int at = static_cast<int>(names.indexOf(action));
                if (at < 0) {
                    throw UsageError(
                        QStringLiteral("%1:%2: the header has no column '%3' (it needs: %4)")
                            .arg(path)
                            .arg(lineNumber)
                            .arg(action, actionNames.join(QStringLiteral(", "))));
                }
                columnOf.push_back(at);
            }
            fieldCount = static_cast<int>(fields.size());
            continue;
        }
        if (fields.size() != fieldCount) {
            throw UsageError(QStringLiteral("%1:%2: %3 fields, the header has %4")
                                 .arg(path)
                                 .arg(lineNumber)
                                 .arg(fields.size())
                                 .arg(fieldCount));
        }
        Eigen::VectorXd action(static_cast<Eigen::Index>(columnOf.size()));
        for (size_t a = 0; a < columnOf.size(); ++a) {
            bool ok = false;
            const QString text = fields[columnOf[a]].trimmed();
            const double value = text.toDouble(&ok);
            if (!ok || !std::isfinite(value)) {
                throw UsageError(
                    QStringLiteral("%1:%2:%3: '%4' in column '%5' is not a finite number")
                        .arg(path)
                        .arg(lineNumber)
                        .arg(columnOf[a] + 1)
                        .arg(text, actionNames[static_cast<int>(a)]));
            }
            if (std::abs(value) > core::Demonstration::kMaxAbsValue) {
                throw UsageError(QStringLiteral("%1:%2:%3: '%4' in column '%5' is beyond the "
                                                "+-%6 an action may be")
                                     .arg(path)
                                     .arg(lineNumber)
                                     .arg(columnOf[a] + 1)
                                     .arg(text, actionNames[static_cast<int>(a)])
                                     .arg(core::Demonstration::kMaxAbsValue));
            }
            action[static_cast<Eigen::Index>(a)] = value;
        }
        rows.push_back(action);
    }
    if (columnOf.empty()) {
        throw UsageError(QStringLiteral("%1: no header row").arg(path));
    }
    if (rows.empty()) {
        throw UsageError(QStringLiteral("%1: no action rows after the header").arg(path));
    }
    Eigen::MatrixXd table(static_cast<Eigen::Index>(rows.size()), actionNames.size());
    for (size_t k = 0; k < rows.size(); ++k) {
        table.row(static_cast<Eigen::Index>(k)) = rows[k].transpose();
    }
    return table;
}

}  // namespace prisca::app::cli
