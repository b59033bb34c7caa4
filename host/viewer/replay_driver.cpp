// SPDX-License-Identifier: Apache-2.0
#include "viewer/replay_driver.hpp"

#include <SDL2/SDL.h>
#include <fmt/format.h>

#include <stdexcept>
#include <string>

#include "scene/formulas/formulas.hpp"
#include "scene/parameters.hpp"

namespace fgr::viewer {
namespace {

SDL_Scancode scancode_named(const std::string& name) {
    return SDL_GetScancodeFromName(name.c_str());
}

bool is_key_event(ReplayAction action) {
    return action == ReplayAction::KeyDown || action == ReplayAction::KeyUp ||
           action == ReplayAction::KeyPress;
}

void check_keys_and_formulas(const std::vector<ReplayEvent>& events, const std::string& file) {
    for (const ReplayEvent& event : events) {
        if (is_key_event(event.action) && scancode_named(event.key) == SDL_SCANCODE_UNKNOWN) {
            throw UsageError(
                fmt::format("{}:{}: unknown key '{}' (SDL key names: W, F12, "
                            "PageDown, Left_Shift...)",
                            file, event.line, event.key));
        }
        if (event.action == ReplayAction::HybridAdd && find_formula(event.text) == nullptr) {
            throw UsageError(
                fmt::format("{}:{}: unknown formula '{}' (`fgr list --formulas` "
                            "names them)",
                            file, event.line, event.text));
        }
    }
}

}  // namespace

std::vector<ReplayEvent> ReplayDriver::load(const std::filesystem::path& file) {
    std::vector<ReplayEvent> events;
    try {
        events = load_replay(file);
    } catch (const std::runtime_error& error) {
        throw UsageError(error.what());
    }
    check_keys_and_formulas(events, file.string());
    return events;
}

ReplayDriver::ReplayDriver(std::vector<ReplayEvent> events, ReplayHost host)
    : clock_(std::move(events)), host_(std::move(host)) {}

void ReplayDriver::feed(double now_seconds) {
    if (clock_.waiting()) {
        if (still_waiting()) return;
        thumbnails_awaited_ = false;
        awaited_changes_.reset();
        awaited_samples_.reset();
        awaited_frames_.reset();
        window_size_.reset();
        clock_.resume(now_seconds);
    }
    for (const ReplayEvent& event : clock_.due(now_seconds)) push(event);
}

bool ReplayDriver::window_size_pending() const {
    return window_size_ && host_.window_size() != *window_size_;
}

bool ReplayDriver::still_waiting() const {
    if (thumbnails_awaited_) return !host_.thumbnails_done();
    if (awaited_changes_) return host_.changes_handled() <= *awaited_changes_;
    if (awaited_samples_) return host_.full_size_samples() < *awaited_samples_;
    if (awaited_frames_) return host_.frames_shown() < *awaited_frames_;
    return !host_.view_idle();
}

void ReplayDriver::push(const ReplayEvent& event) {
    switch (event.action) {
        case ReplayAction::KeyDown:
        case ReplayAction::KeyUp:
        case ReplayAction::KeyPress:
            push_key(event);
            break;
        case ReplayAction::MouseDown:
        case ReplayAction::MouseUp:
        case ReplayAction::MouseMove:
        case ReplayAction::Wheel:
            push_mouse(event);
            break;
        case ReplayAction::Resize:
            host_.resize_window(event.x, event.y);
            window_size_ = {event.x, event.y};
            break;
        case ReplayAction::WaitIdle:
            break;  // the clock holds the script until the view is idle
        case ReplayAction::WaitReload:
            awaited_changes_ = host_.changes_handled();
            break;
        case ReplayAction::WaitThumbnails:
            thumbnails_awaited_ = true;
            break;
        case ReplayAction::WaitSamples:
            awaited_samples_ = event.count;
            break;
        case ReplayAction::WaitFrames:
            awaited_frames_ = host_.frames_shown() + event.count;
            break;
        case ReplayAction::Quit:
            host_.quit();
            break;
        case ReplayAction::BrowserSearch:
        case ReplayAction::BrowserPick:
            host_.browser_event(event);
            break;
        case ReplayAction::HybridAdd:
        case ReplayAction::HybridRemove:
        case ReplayAction::HybridMove:
        case ReplayAction::HybridRepeat:
        case ReplayAction::HybridSave:
            host_.editor_event(event);
            break;
        case ReplayAction::SetParameter:
            host_.set_parameter(event.text);
            break;
    }
}

void ReplayDriver::push_key(const ReplayEvent& event) {
    const SDL_Scancode code = scancode_named(event.key);
    SDL_Event sdl{};
    sdl.key.windowID = host_.window_id();
    sdl.key.keysym.scancode = code;
    sdl.key.keysym.sym = SDL_GetKeyFromScancode(code);
    if (event.action != ReplayAction::KeyUp) {
        sdl.type = SDL_KEYDOWN;
        sdl.key.state = SDL_PRESSED;
        SDL_PushEvent(&sdl);
    }
    if (event.action != ReplayAction::KeyDown) {
        sdl.type = SDL_KEYUP;
        sdl.key.state = SDL_RELEASED;
        SDL_PushEvent(&sdl);
    }
}

// Buttons without a position and motion happen at the window's centre.
void ReplayDriver::push_mouse(const ReplayEvent& event) {
    const auto [width, height] = host_.window_size();
    const uint32_t window_id = host_.window_id();
    SDL_Event sdl{};
    switch (event.action) {
        case ReplayAction::MouseDown:
        case ReplayAction::MouseUp: {
            const bool down = event.action == ReplayAction::MouseDown;
            sdl.type = down ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
            sdl.button.windowID = window_id;
            sdl.button.button = static_cast<Uint8>(event.button);
            sdl.button.state = down ? SDL_PRESSED : SDL_RELEASED;
            sdl.button.clicks = 1;
            sdl.button.x = event.has_position ? event.x : width / 2;
            sdl.button.y = event.has_position ? event.y : height / 2;
            break;
        }
        case ReplayAction::MouseMove:
            sdl.type = SDL_MOUSEMOTION;
            sdl.motion.windowID = window_id;
            sdl.motion.x = width / 2;
            sdl.motion.y = height / 2;
            sdl.motion.xrel = event.x;
            sdl.motion.yrel = event.y;
            break;
        case ReplayAction::Wheel:
            sdl.type = SDL_MOUSEWHEEL;
            sdl.wheel.windowID = window_id;
            sdl.wheel.y = event.wheel;
            sdl.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
            break;
        default:
            return;
    }
    SDL_PushEvent(&sdl);
}

}  // namespace fgr::viewer
