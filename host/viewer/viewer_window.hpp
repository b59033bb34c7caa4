// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's window: SDL, the window, its OpenGL context and Dear ImGui on it, opened together
// and closed in reverse order. Private to fgr_viewer.

#include <memory>
#include <utility>

#include "viewer/gl_handles.hpp"

namespace fgr::viewer {

class ViewerWindow {
public:
    // Throws std::runtime_error when there is no display or no OpenGL.
    void open(int width, int height, bool fullscreen);

    SDL_Window* get() const { return window_.get(); }
    Uint32 id() const { return SDL_GetWindowID(window_.get()); }
    // In screen coordinates, as events and replay scripts give positions.
    std::pair<int, int> size() const;
    // In pixels: the size the image renders at.
    std::pair<int, int> drawable_size() const;
    // A Dear ImGui frame: begin it, build its windows, then end it, which draws and shows it.
    void begin_frame();
    void end_frame();

    bool fullscreen() const { return fullscreen_; }
    void toggle_fullscreen();
    // Leaves fullscreen first, which would keep the display's size.
    void set_size(int width, int height);

private:
    std::unique_ptr<SdlSession> sdl_;
    WindowHandle window_;
    GlContextHandle gl_context_;
    std::unique_ptr<ImGuiSession> imgui_;
    bool fullscreen_ = false;
};

}  // namespace fgr::viewer
