// SPDX-License-Identifier: Apache-2.0
#pragma once
// RAII over the viewer's SDL, OpenGL and Dear ImGui handles, each releasing what it made.
// Private to fgr_viewer.

#include <SDL2/SDL.h>
#include <SDL2/SDL_opengl.h>
#include <backends/imgui_impl_opengl2.h>
#include <backends/imgui_impl_sdl.h>
#include <fmt/format.h>
#include <imgui.h>

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "image/image_io.hpp"

namespace fgr::viewer {

struct SdlSession {
    SdlSession() {
        if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
            throw std::runtime_error(fmt::format(
                "cannot open a window: {} (no display? run under xvfb-run for headless use)",
                SDL_GetError()));
        }
        // With no display SDL falls back to drivers that show nothing; a viewer nobody can see
        // is an error unless that is what the user asked for.
        const std::string driver = SDL_GetCurrentVideoDriver();
        if ((driver == "offscreen" || driver == "dummy") && !SDL_getenv("SDL_VIDEODRIVER")) {
            SDL_Quit();
            throw std::runtime_error(
                "cannot open a window: no display found (set DISPLAY, run under xvfb-run, or set "
                "SDL_VIDEODRIVER=offscreen to run without showing anything)");
        }
    }
    ~SdlSession() { SDL_Quit(); }
    SdlSession(const SdlSession&) = delete;
    SdlSession& operator=(const SdlSession&) = delete;
};

struct WindowDeleter {
    void operator()(SDL_Window* window) const { SDL_DestroyWindow(window); }
};
using WindowHandle = std::unique_ptr<SDL_Window, WindowDeleter>;

struct GlContextDeleter {
    void operator()(void* context) const { SDL_GL_DeleteContext(context); }
};
using GlContextHandle = std::unique_ptr<void, GlContextDeleter>;

class ImGuiSession {
public:
    ImGuiSession(SDL_Window* window, void* gl_context) {
        IMGUI_CHECKVERSION();
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's directory
        ImGui::StyleColorsDark();
        ImGui_ImplSDL2_InitForOpenGL(window, gl_context);
        ImGui_ImplOpenGL2_Init();
    }
    ~ImGuiSession() {
        ImGui_ImplOpenGL2_Shutdown();
        ImGui_ImplSDL2_Shutdown();
        ImGui::DestroyContext();
    }
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The texture the rendered image is drawn from.
class ImageTexture {
public:
    ImageTexture() {
        glGenTextures(1, &id_);
        glBindTexture(GL_TEXTURE_2D, id_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    }
    ~ImageTexture() { glDeleteTextures(1, &id_); }
    ImageTexture(const ImageTexture&) = delete;
    ImageTexture& operator=(const ImageTexture&) = delete;

    void upload(const Image8& image) {
        glBindTexture(GL_TEXTURE_2D, id_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        if (image.width != width_ || image.height != height_) {
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, image.width, image.height, 0, GL_RGB,
                         GL_UNSIGNED_BYTE, image.rgb.data());
            width_ = image.width;
            height_ = image.height;
        } else {
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE,
                            image.rgb.data());
        }
    }
    bool empty() const { return width_ == 0; }
    ImTextureID id() const { return reinterpret_cast<ImTextureID>(static_cast<intptr_t>(id_)); }

private:
    GLuint id_ = 0;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace fgr::viewer
