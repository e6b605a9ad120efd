#include "app/input/DrivingInput.h"

#include "app/input/GamepadInput.h"

#include <QApplication>
#include <QKeyEvent>

#include <algorithm>
#include <iterator>

namespace prisca::app {

namespace {
constexpr double kRampUp = 2.0;    // input units per second while a key is held
constexpr double kRampDown = 3.0;  // back to neutral per second once released

// Which key means what: 0 up, 1 down, 2 left, 3 right; -1 not a driving key.
int drivingKey(int key) {
    switch (key) {
        case Qt::Key_Up:
        case Qt::Key_W:
            return 0;
        case Qt::Key_Down:
        case Qt::Key_S:
            return 1;
        case Qt::Key_Left:
        case Qt::Key_A:
            return 2;
        case Qt::Key_Right:
        case Qt::Key_D:
            return 3;
        default:
            return -1;
    }
}
}  // namespace

DrivingInput::DrivingInput(QObject* parent)
    : QObject(parent), gamepad_(std::make_unique<GamepadInput>()) {}

DrivingInput::~DrivingInput() {
    stop();
}

void DrivingInput::start(int controls) {
    input_ = Eigen::VectorXd::Zero(controls);
    std::fill(std::begin(held_), std::end(held_), false);
    if (!active_) {
        qApp->installEventFilter(this);
        active_ = true;
    }
}

void DrivingInput::stop() {
    if (active_) {
        qApp->removeEventFilter(this);
        active_ = false;
    }
    neutral();
}

void DrivingInput::neutral() {
    std::fill(std::begin(held_), std::end(held_), false);
    input_.setZero();
}

const Eigen::VectorXd& DrivingInput::advance(double dt) {
    for (int channel = 0; channel < std::min<int>(2, static_cast<int>(input_.size())); ++channel) {
        const bool plus = held_[channel == 0 ? 0 : 2];
        const bool minus = held_[channel == 0 ? 1 : 3];
        double& u = input_[channel];
        if (plus != minus) {
            u = std::clamp(u + (plus ? 1.0 : -1.0) * kRampUp * dt, -1.0, 1.0);
        } else if (u > 0.0) {
            u = std::max(0.0, u - kRampDown * dt);
        } else {
            u = std::min(0.0, u + kRampDown * dt);
        }
    }
    // A gamepad's sticks, where pushed, drive their control directly (proportional).
    if (const std::optional<Eigen::Vector2d> pad = gamepad_->poll()) {
        for (int channel = 0; channel < std::min<int>(2, static_cast<int>(input_.size()));
             ++channel) {
            if ((*pad)[channel] != 0.0) {
                input_[channel] = (*pad)[channel];
            }
        }
    }
    return input_;
}

bool DrivingInput::gamepadAvailable() const {
    return gamepad_->available();
}

QString DrivingInput::gamepadName() const {
    return gamepad_->name();
}

bool DrivingInput::eventFilter(QObject* watched, QEvent* event) {
    if (active_ && (event->type() == QEvent::KeyPress || event->type() == QEvent::KeyRelease)) {
        auto* key = static_cast<QKeyEvent*>(event);
        const int index = drivingKey(key->key());
        if (index >= 0) {
            if (!key->isAutoRepeat()) {
                held_[index] = event->type() == QEvent::KeyPress;
            }
            return true;  // driving keys never move spin boxes or focus while driving
        }
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace prisca::app
