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
/// A duration in the operator's words: "40 s", "2 min 05 s", "1 h 20 min".
QString duration(qint64 milliseconds);
/// How far a job of `total` equal parts is and about how long is left, from the time the
/// `done` parts took: "2 min 05 s so far · about 10 min left" (no estimate before the first).
QString progressTime(qint64 elapsedMs, int done, int total);

}  // namespace prisca::app
