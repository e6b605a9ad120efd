#pragma once

#include "FileIo.h"

#include <Eigen/Core>

#include <QMap>
#include <QString>
#include <QStringList>

namespace prisca::core {

/// A run log: one row per control step of one or more trials (docs/architecture.md "File formats"):
///
///     # prisca-run-log 1
///     # plant: slidecar
///     # method: prisca
///     # dt: 0.025
///     # columns: trial[1], t[s], x[m], ...
///     trial,t,x,...
///
/// Plain CSV after the "#" lines, readable by pandas (comment='#') and MATLAB.
struct RunLog {
    QString plant;                    ///< plant name
    QString method;                   ///< controller name
    double dt = 0.025;                ///< control period [s]
    QMap<QString, QString> metadata;  ///< further "# key: value" lines (seed, parameters, ...)
    QStringList columns;              ///< column names
    QStringList units;                ///< one unit per column ("1" when dimensionless)
    Eigen::MatrixXd rows;             ///< N x columns
};

/// The file text of a run log; empty (with *problem set) if names and data disagree.
QByteArray formatRunLogCsv(const RunLog& log, QString* problem = nullptr);
/// Writes the log atomically. False with *error filled on failure.
bool writeRunLogCsv(const RunLog& log, const QString& path, FileError* error);

}  // namespace prisca::core
