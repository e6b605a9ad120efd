#pragma once

#include <Eigen/Core>
#include <QString>

#include <optional>

namespace prisca::app {

/// A game controller for driving during a recording (SDL2's game-controller API, which maps
/// common pads to one layout). Optional at run time: without SDL's controller support or with no
/// pad plugged in, available() is false and the keyboard drives. A pad plugged in later is found
/// on a later poll. GUI thread only.
class GamepadInput {
  public:
    GamepadInput();
    ~GamepadInput();
    GamepadInput(const GamepadInput&) = delete;
    GamepadInput& operator=(const GamepadInput&) = delete;

    /// Reads the pad: [0] the left stick pushed forward (first control, e.g. throttle), [1] the
    /// right stick pushed left (second control, e.g. steering left), each in [-1, 1] with a
    /// small dead zone. Empty when no pad is open.
    std::optional<Eigen::Vector2d> poll();
    /// Whether the button (an SDL_GameControllerButton) is held now, read afresh; empty when no
    /// pad is open. A pad plugged in later is found as by poll().
    std::optional<bool> buttonDown(int button);
    /// The SDL_GameControllerButton named `name` in SDL's mapping names ("a", "b", "back",
    /// "start", "leftshoulder", "paddle1", ...); -1 when there is none of that name.
    static int buttonFromName(const QString& name);
    /// A pad is open.
    bool available() const { return controller_ != nullptr; }
    /// The open pad's name (empty when none).
    QString name() const;

  private:
    void tryOpen();
    /// Reads the pad's state now (events are not used: nothing drains SDL's queue, so it is
    /// emptied here); the open pad, or null.
    void* update();

    bool initialised_ = false;
    void* controller_ = nullptr;  ///< SDL_GameController*
    int pollsSinceSearch_ = 0;
};

}  // namespace prisca::app
