#include "app/OperatorText.h"

#include <QCoreApplication>

#include <algorithm>

namespace prisca::app {

namespace {
// The plants' control names (sim/*.cpp, PlantInfo::actionNames), for the translators.
[[maybe_unused]] const char* const kControlNames[] = {
    QT_TRANSLATE_NOOP("PlantControl", "throttle"),
    QT_TRANSLATE_NOOP("PlantControl", "steering"),
    QT_TRANSLATE_NOOP("PlantControl", "rudder"),
    QT_TRANSLATE_NOOP("PlantControl", "left wheel"),
    QT_TRANSLATE_NOOP("PlantControl", "right wheel"),
};
}  // namespace

QString controlName(const QString& name) {
    return QCoreApplication::translate("PlantControl", name.toUtf8().constData());
}

QString duration(qint64 milliseconds) {
    const qint64 s = (std::max<qint64>(milliseconds, 0) + 500) / 1000;
    if (s < 60) {
        return QCoreApplication::translate("OperatorText", "%1 s").arg(s);
    }
    if (s < 3600) {
        return QCoreApplication::translate("OperatorText", "%1 min %2 s")
            .arg(s / 60)
            .arg(s % 60, 2, 10, QLatin1Char('0'));
    }
    return QCoreApplication::translate("OperatorText", "%1 h %2 min")
        .arg(s / 3600)
        .arg((s % 3600) / 60, 2, 10, QLatin1Char('0'));
}

QString progressTime(qint64 elapsedMs, int done, int total) {
    // The rate so far, over what is left (the parts are alike; the first may include training).
    const QString left =
        done > 0 && total >= done
            ? QCoreApplication::translate("OperatorText", "about %1 left")
                  .arg(duration(elapsedMs * (total - done) / done))
            : QCoreApplication::translate("OperatorText", "estimating the time left");
    return QCoreApplication::translate("OperatorText", "%1 so far · %2")
        .arg(duration(elapsedMs), left);
}

QStringList controlNames(const QStringList& names) {
    QStringList shown;
    for (const QString& name : names) {
        shown << controlName(name);
    }
    return shown;
}

}  // namespace prisca::app
