#include "app/EmergencyStop.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcEmergency, "prisca.app.estop")

namespace prisca::app {

QString EmergencyStop::refusal() const {
    return tr("E-STOP is latched (pressed at %1 by %2): press Reset E-STOP first.")
        .arg(engagedAt_.toString(QStringLiteral("HH:mm:ss")), pressedBy_);
}

void EmergencyStop::engage(const QString& pressedBy) {
    const bool wasLatched = latched_;
    latched_ = true;
    if (!wasLatched) {
        engagedAt_ = QTime::currentTime();
        pressedBy_ = pressedBy;
        qCWarning(lcEmergency).noquote() << "E-STOP pressed by" << pressedBy;
    }
    // Every job is told first, whatever shows the latch afterwards.
    emit engaged();
    if (!wasLatched) {
        emit latchChanged(true);
    }
}

void EmergencyStop::reset() {
    if (!latched_) {
        return;
    }
    latched_ = false;
    emit released();
    emit latchChanged(false);
}

}  // namespace prisca::app
