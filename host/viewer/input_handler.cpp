// SPDX-License-Identifier: Apache-2.0
#include "viewer/input_handler.hpp"

#include <backends/imgui_impl_sdl.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <utility>

namespace fgr::viewer {
namespace {

constexpr float kLookRadiansPerPixel = 0.0035f;
constexpr float kShiftSpeedUp = 4.0f;
constexpr float kWheelSpeedStep = 1.25f;

}  // namespace

std::optional<ViewerCommand> command_for_key(SDL_Scancode key, bool ctrl) {
    switch (key) {
        case SDL_SCANCODE_ESCAPE:
            return ViewerCommand::Quit;
        case SDL_SCANCODE_R:
            return ViewerCommand::ResetCamera;
        case SDL_SCANCODE_C:
            return ViewerCommand::NextCamera;
        case SDL_SCANCODE_PAGEUP:
            return ViewerCommand::PreviousScene;
        case SDL_SCANCODE_PAGEDOWN:
            return ViewerCommand::NextScene;
        case SDL_SCANCODE_P:
            return ViewerCommand::TogglePlayback;
        case SDL_SCANCODE_K:
            return ctrl ? ViewerCommand::SaveRecordedPath : ViewerCommand::RecordKeyframe;
        case SDL_SCANCODE_S:  // without Ctrl, S flies backwards
            if (ctrl) return ViewerCommand::SaveView;
            return std::nullopt;
        case SDL_SCANCODE_F12:
            return ViewerCommand::Screenshot;
        case SDL_SCANCODE_H:
        case SDL_SCANCODE_F1:
            return ViewerCommand::ToggleHelp;
        case SDL_SCANCODE_TAB:
            return ViewerCommand::TogglePanel;
        case SDL_SCANCODE_F11:
            return ViewerCommand::ToggleFullscreen;
        case SDL_SCANCODE_B:
            return ViewerCommand::ToggleBrowser;
        case SDL_SCANCODE_N:
            return ViewerCommand::ToggleDenoise;
        default:
            return std::nullopt;
    }
}

InputHandler::InputHandler(InputHost host) : host_(std::move(host)) {}

bool InputHandler::pump_events() {
    bool any = false;
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        ImGui_ImplSDL2_ProcessEvent(&event);
        handle_event(event);
        any = true;
    }
    return any;
}

void InputHandler::handle_event(const SDL_Event& event) {
    switch (event.type) {
        case SDL_QUIT:
            host_.run(ViewerCommand::Quit);
            break;
        case SDL_KEYDOWN:
            if (ImGui::GetIO().WantTextInput) break;  // typing a value into the panel
            held_keys_.insert(event.key.keysym.scancode);
            handle_key_down(event.key.keysym.scancode, event.key.repeat != 0);
            break;
        case SDL_KEYUP:
            held_keys_.erase(event.key.keysym.scancode);
            break;
        case SDL_MOUSEBUTTONDOWN:
            handle_mouse_button(event.button, true);
            break;
        case SDL_MOUSEBUTTONUP:
            handle_mouse_button(event.button, false);
            break;
        case SDL_MOUSEMOTION:
            if (looking_) {
                FlyCamera& camera = host_.camera();
                const float fov_scale = camera.fov_degrees / 60.0f;
                camera.turn(
                    static_cast<float>(event.motion.xrel) * kLookRadiansPerPixel * fov_scale,
                    -static_cast<float>(event.motion.yrel) * kLookRadiansPerPixel * fov_scale);
                host_.took_camera();
            }
            break;
        case SDL_MOUSEWHEEL: {
            int x = 0, y = 0;
            SDL_GetMouseState(&x, &y);
            if (!looking_ && host_.over_panel(x, y)) break;
            speed_factor_ = std::clamp(
                speed_factor_ * std::pow(kWheelSpeedStep, static_cast<float>(event.wheel.y)), 1e-3f,
                1e3f);
            break;
        }
        default:
            break;
    }
}

void InputHandler::handle_mouse_button(const SDL_MouseButtonEvent& button, bool down) {
    if (button.button != SDL_BUTTON_RIGHT) return;
    if (down && host_.over_panel(button.x, button.y)) return;
    looking_ = down;
    // Relative mode hides the pointer and reports unbounded motion; some X servers refuse it,
    // and motion still arrives then, only bounded by the window.
    SDL_SetRelativeMouseMode(down ? SDL_TRUE : SDL_FALSE);
}

void InputHandler::handle_key_down(SDL_Scancode key, bool repeat) {
    if (repeat) return;
    const bool ctrl = held_keys_.count(SDL_SCANCODE_LCTRL) || held_keys_.count(SDL_SCANCODE_RCTRL);
    if (const std::optional<ViewerCommand> command = command_for_key(key, ctrl)) {
        host_.run(*command);
    }
}

void InputHandler::fly(double dt, float de_at_camera) {
    const auto held = [&](SDL_Scancode key) { return held_keys_.count(key) ? 1.0f : 0.0f; };
    if (held(SDL_SCANCODE_LCTRL) + held(SDL_SCANCODE_RCTRL) > 0.0f) return;
    const glm::vec3 local(held(SDL_SCANCODE_D) - held(SDL_SCANCODE_A),
                          held(SDL_SCANCODE_W) - held(SDL_SCANCODE_S),
                          held(SDL_SCANCODE_E) - held(SDL_SCANCODE_Q));
    if (local == glm::vec3(0.0f)) return;
    host_.took_camera();
    FlyCamera& camera = host_.camera();
    // Until the render thread has measured the distance to the surface, move relative to the
    // distance to the target.
    const double de = de_at_camera >= 0.0f ? double(de_at_camera) : 0.25 * camera.target_distance;
    const bool shift = held(SDL_SCANCODE_LSHIFT) + held(SDL_SCANCODE_RSHIFT) > 0.0f;
    const double speed = travel_speed(de, speed_factor_ * (shift ? kShiftSpeedUp : 1.0f));
    camera.move(local, limit_step(speed * dt, de));
}

}  // namespace fgr::viewer
