// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's input: the window's events (handed to Dear ImGui first), the key bindings, looking
// around with the right mouse button, the wheel's speed factor, and flying the camera by the held
// keys. Private to fgr_viewer.

#include <SDL2/SDL.h>

#include <functional>
#include <optional>
#include <set>

#include "viewer/fly_camera.hpp"

namespace fgr::viewer {

// What a key (or the window's close button) asks of the viewer; the help window lists the keys.
enum class ViewerCommand {
    Quit,
    ResetCamera,
    NextCamera,
    PreviousScene,
    NextScene,
    TogglePlayback,
    RecordKeyframe,
    SaveRecordedPath,
    Screenshot,
    SaveView,
    ToggleHelp,
    TogglePanel,
    ToggleFullscreen,
    ToggleBrowser,
    ToggleDenoise,
};

// The command bound to pressing `key` (`ctrl`: with Ctrl held); none for unbound keys and for the
// flying keys, which act while held.
std::optional<ViewerCommand> command_for_key(SDL_Scancode key, bool ctrl);

// What the input asks of the viewer.
struct InputHost {
    std::function<void(ViewerCommand)> run;
    std::function<bool(int x, int y)> over_panel;  // a window point lies on the panel
    std::function<FlyCamera&()> camera;            // the camera the user flies and turns
    std::function<void()> took_camera;             // the user moved the camera: playback stops
};

class InputHandler {
public:
    explicit InputHandler(InputHost host);

    // Hands the window's pending events to ImGui, then acts on them; whether there were any.
    bool pump_events();
    // Flies the camera `dt` seconds by the held keys (W A S D Q E; Shift: faster; not while Ctrl is
    // held, so that Ctrl+S does not fly backwards), at a speed that follows the distance to the
    // surface, `de_at_camera` (negative while unknown).
    void fly(double dt, float de_at_camera);

    float speed_factor() const { return speed_factor_; }
    void set_speed_factor(float factor) { speed_factor_ = factor; }

private:
    void handle_event(const SDL_Event& event);
    void handle_key_down(SDL_Scancode key, bool repeat);
    void handle_mouse_button(const SDL_MouseButtonEvent& button, bool down);

    InputHost host_;
    std::set<SDL_Scancode> held_keys_;
    bool looking_ = false;       // the right button is down: motion turns the camera
    float speed_factor_ = 1.0f;  // on the flying speed; the wheel and the panel change it
};

}  // namespace fgr::viewer
