#include "app/input/GamepadEmergencyButton.h"

#include "app/input/GamepadInput.h"

#include <QTimer>

namespace prisca::app {

GamepadEmergencyButton::GamepadEmergencyButton(QObject* parent)
    : QObject(parent), timer_(new QTimer(this)) {
    timer_->setInterval(kPollMs);
    connect(timer_, &QTimer::timeout, this, &GamepadEmergencyButton::poll);
}

GamepadEmergencyButton::~GamepadEmergencyButton() = default;

bool GamepadEmergencyButton::knownButton(const QString& name) {
    return GamepadInput::buttonFromName(name) >= 0;
}

void GamepadEmergencyButton::setButtons(const QStringList& names) {
    names_.clear();
    buttons_.clear();
    for (const QString& name : names) {
        const int button = GamepadInput::buttonFromName(name);
        if (button >= 0 && !buttons_.contains(button)) {
            names_ << name.trimmed().toLower();
            buttons_ << button;
        }
    }
    wasDown_ = QVector<bool>(buttons_.size(), false);  // held when first read: pressed
    if (buttons_.isEmpty()) {
        timer_->stop();
        pad_.reset();  // SDL's controller subsystem only while it is used
        return;
    }
    if (!pad_) {
        pad_ = std::make_unique<GamepadInput>();
    }
    timer_->start();
}

bool GamepadEmergencyButton::padFound() const {
    return pad_ && pad_->available();
}

void GamepadEmergencyButton::poll() {
    for (int i = 0; i < buttons_.size(); ++i) {
        const std::optional<bool> down = pad_->buttonDown(buttons_[i]);
        if (!down) {
            wasDown_.fill(false);  // no pad: a button held when one comes is a press
            return;
        }
        if (*down && !wasDown_[i]) {
            emit pressed(tr("gamepad button %1").arg(names_[i]));
        }
        wasDown_[i] = *down;
    }
}

}  // namespace prisca::app
