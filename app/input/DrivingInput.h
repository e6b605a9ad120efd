#pragma once

#include <Eigen/Core>
#include <QObject>
#include <QString>

#include <memory>

namespace prisca::app {

class GamepadInput;

/// What the operator's hands ask for while driving: the keyboard (arrows or WASD) with a
/// proportional ramp (a held key pushes its control towards full at 2 per second; released, it
/// returns to neutral at 3 per second), and a gamepad's sticks where pushed. Controls in
/// [-1, 1]: [0] up/down (throttle), [1] left/right (steering, left positive). While active, the
/// driving keys are taken from whatever widget has the focus. GUI thread only.
class DrivingInput : public QObject {
    Q_OBJECT
  public:
    explicit DrivingInput(QObject* parent = nullptr);
    ~DrivingInput() override;

    /// Starts listening (neutral input); stop() releases the keys and returns to neutral.
    void start(int controls);
    void stop();
    /// Advances the ramp by dt [s] and reads the gamepad; returns the input.
    const Eigen::VectorXd& advance(double dt);
    const Eigen::VectorXd& input() const { return input_; }
    /// Neutral at once, every key released (E-STOP).
    void neutral();

    bool gamepadAvailable() const;
    QString gamepadName() const;

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    std::unique_ptr<GamepadInput> gamepad_;
    bool active_ = false;
    bool held_[4] = {false, false, false, false};  ///< up, down, left, right
    Eigen::VectorXd input_ = Eigen::VectorXd::Zero(2);
};

}  // namespace prisca::app
