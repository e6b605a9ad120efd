#pragma once

#include <QObject>
#include <QStringList>
#include <QVector>

#include <memory>

class QTimer;

namespace prisca::app {

class GamepadInput;

/// A game controller's button as E-STOP (SDL2's game-controller API, which names the buttons of
/// common pads alike: "b" is the red one on the common layout). Polled every 20 ms on the GUI
/// thread whatever the window shows (a dialog, a menu); a pad plugged in later is found within
/// a second. The buttons come from the "estop/gamepadButtons" setting (default "b"); none: the
/// pad is not read at all.
class GamepadEmergencyButton : public QObject {
    Q_OBJECT
  public:
    static constexpr int kPollMs = 20;
    explicit GamepadEmergencyButton(QObject* parent = nullptr);
    ~GamepadEmergencyButton() override;

    /// SDL's button names; unknown ones are left out (knownButton() tells). Empty: off.
    void setButtons(const QStringList& names);
    const QStringList& buttons() const { return names_; }
    static bool knownButton(const QString& name);
    /// A pad is open (and a button set).
    bool padFound() const;

  signals:
    /// A button was pressed (once per press): "gamepad button b".
    void pressed(const QString& what);

  private:
    void poll();

    QTimer* timer_;
    std::unique_ptr<GamepadInput> pad_;
    QStringList names_;
    QVector<int> buttons_;
    QVector<bool> wasDown_;
};

}  // namespace prisca::app
