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
    /// A pad is open.
    bool available() const { return controller_ != nullptr; }
    /// The open pad's name (empty when none).
    QString name() const;

  private:
    void tryOpen();

    bool initialised_ = false;
    void* controller_ = nullptr;  ///< SDL_GameController*
    int pollsSinceSearch_ = 0;
};

}  // namespace prisca::app
