#include "app/PlantText.h"

#include <QCoreApplication>

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

QStringList controlNames(const QStringList& names) {
    QStringList shown;
    for (const QString& name : names) {
        shown << controlName(name);
    }
    return shown;
}

}  // namespace prisca::app
