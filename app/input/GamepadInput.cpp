#include "app/input/GamepadInput.h"

#include <SDL.h>

#include <algorithm>
#include <cmath>

namespace prisca::app {

namespace {
constexpr double kDeadZone = 0.08;         // of full stick travel
constexpr int kPollsBetweenSearches = 40;  // about once a second at the recording's 40 Hz

double axis(SDL_GameController* pad, SDL_GameControllerAxis which) {
    const double v = SDL_GameControllerGetAxis(pad, which) / 32767.0;
    if (std::abs(v) < kDeadZone) {
        return 0.0;
    }
    // Rescale so the input starts from 0 at the edge of the dead zone.
    return std::clamp((std::abs(v) - kDeadZone) / (1.0 - kDeadZone), 0.0, 1.0) * (v < 0 ? -1 : 1);
}
}  // namespace

GamepadInput::GamepadInput() {
    // SDL must not take over Ctrl-C, and the pad must be read while the window is in front or not.
    SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    initialised_ = SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) == 0;
    tryOpen();
}

GamepadInput::~GamepadInput() {
    if (controller_) {
        SDL_GameControllerClose(static_cast<SDL_GameController*>(controller_));
    }
    if (initialised_) {
        SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
    }
}

void GamepadInput::tryOpen() {
    if (!initialised_ || controller_) {
        return;
    }
    for (int i = 0; i < SDL_NumJoysticks(); ++i) {
        if (SDL_IsGameController(i)) {
            controller_ = SDL_GameControllerOpen(i);
            if (controller_) {
                return;
            }
        }
    }
}

void* GamepadInput::update() {
    if (!initialised_) {
        return nullptr;
    }
    SDL_GameControllerUpdate();
    // The state is what is read; the events SDL queues for it would only pile up.
    SDL_FlushEvents(SDL_JOYAXISMOTION, SDL_CONTROLLERSENSORUPDATE);
    auto* pad = static_cast<SDL_GameController*>(controller_);
    if (pad && !SDL_GameControllerGetAttached(pad)) {
        SDL_GameControllerClose(pad);  // unplugged: back to the keyboard
        controller_ = pad = nullptr;
    }
    if (!pad && ++pollsSinceSearch_ >= kPollsBetweenSearches) {
        pollsSinceSearch_ = 0;
        SDL_JoystickUpdate();
        tryOpen();
        pad = static_cast<SDL_GameController*>(controller_);
    }
    return pad;
}

std::optional<Eigen::Vector2d> GamepadInput::poll() {
    auto* pad = static_cast<SDL_GameController*>(update());
    if (!pad) {
        return std::nullopt;
    }
    // Stick up is negative in SDL; steering left is the right stick pushed left (negative x).
    return Eigen::Vector2d(-axis(pad, SDL_CONTROLLER_AXIS_LEFTY),
                           -axis(pad, SDL_CONTROLLER_AXIS_RIGHTX));
}

std::optional<bool> GamepadInput::buttonDown(int button) {
    auto* pad = static_cast<SDL_GameController*>(update());
    if (!pad) {
        return std::nullopt;
    }
    return SDL_GameControllerGetButton(pad, static_cast<SDL_GameControllerButton>(button)) != 0;
}

int GamepadInput::buttonFromName(const QString& name) {
    const SDL_GameControllerButton button =
        SDL_GameControllerGetButtonFromString(name.trimmed().toLower().toUtf8().constData());
    return button == SDL_CONTROLLER_BUTTON_INVALID ? -1 : static_cast<int>(button);
}

QString GamepadInput::name() const {
    if (!controller_) {
        return {};
    }
    const char* n = SDL_GameControllerName(static_cast<SDL_GameController*>(controller_));
    return n ? QString::fromUtf8(n) : QStringLiteral("game controller");
}

}  // namespace prisca::app
