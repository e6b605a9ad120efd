#pragma once

#include <Eigen/Core>

#include <QString>
#include <QStringList>

namespace prisca::app::cli {

/// Reads the actions to replay from a CSV: '#' lines and blank lines are skipped, the first
/// other line is a header naming the columns, and every action name must be among them (other
/// columns, such as t or states, are ignored, so a demonstration file works too). Row k is the
/// action of control step k. Throws UsageError "file:line:column: message" on bad input.
Eigen::MatrixXd readActionTable(const QString& path, const QStringList& actionNames);

}  // namespace prisca::app::cli
