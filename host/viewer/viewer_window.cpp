// SPDX-License-Identifier: Apache-2.0
#include "viewer/viewer_window.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace fgr::viewer {

void ViewerWindow::open(int width, int height, bool fullscreen) {
    fullscreen_ = fullscreen;
    sdl_ = std::make_unique<SdlSession>();
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI;
    if (fullscreen_) flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
    window_.reset(SDL_CreateWindow("fgr", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, width,
                                   height, flags));
    if (!window_) throw std::runtime_error(fmt::format("cannot open a window: {}", SDL_GetError()));
    gl_context_.reset(SDL_GL_CreateContext(window_.get()));
    if (!gl_context_) {
        throw std::runtime_error(
            fmt::format("cannot create an OpenGL context: {}", SDL_GetError()));
    }
    SDL_GL_SetSwapInterval(1);
    imgui_ = std::make_unique<ImGuiSession>(window_.get(), gl_context_.get());
}

std::pair<int, int> ViewerWindow::size() const {
    int width = 0, height = 0;
    SDL_GetWindowSize(window_.get(), &width, &height);
    return {width, height};
}

std::pair<int, int> ViewerWindow::drawable_size() const {
    int width = 0, height = 0;
    SDL_GL_GetDrawableSize(window_.get(), &width, &height);
    return {width, height};
}

void ViewerWindow::begin_frame() {
    ImGui_ImplOpenGL2_NewFrame();
    ImGui_ImplSDL2_NewFrame();
    ImGui::NewFrame();
}

void ViewerWindow::end_frame() {
    ImGui::Render();
    const auto [width, height] = drawable_size();
    glViewport(0, 0, width, height);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    SDL_GL_SwapWindow(window_.get());
}

void ViewerWindow::toggle_fullscreen() {
    fullscreen_ = !fullscreen_;
    SDL_SetWindowFullscreen(window_.get(), fullscreen_ ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
}

void ViewerWindow::set_size(int width, int height) {
    if (fullscreen_) toggle_fullscreen();
    SDL_SetWindowSize(window_.get(), width, height);
}

}  // namespace fgr::viewer
