#pragma once

#include <QString>
#include <QStringList>

namespace prisca::app {

/// A plant's control as the window names it, in the interface language ("throttle", "steering",
/// "left wheel"); symbols (tau1) and names it does not know stay as the plant gives them. Files
/// (run logs, chart exports) keep the plant's own names.
QString controlName(const QString& name);
/// Every control of a plant, named as above.
QStringList controlNames(const QStringList& names);

}  // namespace prisca::app
