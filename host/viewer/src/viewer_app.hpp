#pragma once
// The viewer application shared by its source files: viewer_app.cpp (window, input, camera,
// actions), viewer_panel.cpp (the Dear ImGui panel), viewer_reload.cpp (hot reload) and
// viewer_formulas.cpp (the formula browser and the hybrid editor). Private to fgr_viewer.

#include <SDL2/SDL.h>
#include <SDL2/SDL_opengl.h>
#include <backends/imgui_impl_opengl2.h>
#include <backends/imgui_impl_sdl.h>
#include <fmt/format.h>
#include <imgui.h>

#include <chrono>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera_paths.hpp"
#include "fgr/camera_path_file.hpp"
#include "fgr/formulas.hpp"
#include "fgr/image_io.hpp"
#include "fgr/precision.hpp"
#include "fgr/scene.hpp"
#include "fgr/viewer/adaptive_quality.hpp"
#include "fgr/viewer/file_watcher.hpp"
#include "fgr/viewer/fly_camera.hpp"
#include "fgr/viewer/frame_stats.hpp"
#include "fgr/viewer/render_worker.hpp"
#include "fgr/viewer/replay.hpp"
#include "fgr/viewer/scene_search.hpp"
#include "fgr/viewer/thumbnails.hpp"
#include "fgr/viewer/viewer.hpp"
#include "formula_browser.hpp"
#include "gl_handles.hpp"
#include "hot_reloader.hpp"
#include "hybrid_editor.hpp"
#include "input_handler.hpp"
#include "render_choices.hpp"
#include "replay_driver.hpp"
#include "scene_set.hpp"
#include "view_tracker.hpp"
#include "viewer_panel.hpp"
#include "viewer_statistics.hpp"
#include "viewer_util.hpp"
#include "viewer_window.hpp"

namespace fgr::viewer {

inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --- The application ---------------------------------------------------------------------

class ViewerApp {
public:
    ViewerApp(const ViewerOptions& options, std::vector<Scene> scenes);
    int run();

private:
    // Setup.
    void prepare_first_scene();

    // Input.
    void run_command(ViewerCommand command);
    InputHost input_host();
    ReplayHost replay_host();

    // Per-frame updates.
    void submit_view();
    void receive_frame();
    bool view_idle() const;
    void log_refined_view();  // once each time the view becomes fully refined (debug level)

    // Hot reload.
    ReloadHost reload_host();
    void adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene);

    // The hybrid editor.
    HybridHost hybrid_host();

    // The formula browser.
    BrowserHost browser_host();

    // Actions.
    void switch_scene(int index);
    void reset_camera(int camera_index);
    void take_screenshot();
    void add_message(std::string message);

    // The panel.
    PanelHost panel_host();
    void draw_frame();

    const Scene& scene() const { return scenes_.current(); }
    SceneSession& session() { return scenes_.session(); }
    const SceneSession& session() const { return scenes_.session(); }
    void print_stats();

    ViewerOptions options_;
    // Opened in run(); declared before everything that holds a texture, so that the OpenGL context
    // outlives them.
    ViewerWindow window_;
    std::unique_ptr<ImageTexture> texture_;
    std::unique_ptr<RenderWorker> worker_;

    SceneSet scenes_;
    RenderChoices choices_;
    SceneEnvironments environments_;
    CameraPaths paths_;
    InputHandler input_;
    HotReloader reloader_;
    HybridEditor hybrid_;
    FormulaBrowser browser_;
    ViewerPanel panel_;
    std::optional<ReplayDriver> replay_;  // with --replay

    std::chrono::steady_clock::time_point start_;
    bool quit_ = false;

    ViewTracker view_;
    WorkerStatus status_;
    bool was_idle_ = false;
    std::optional<DisplayFrame> shown_;  // image data lives in the texture; this keeps its facts
    std::deque<std::string> messages_;
    std::set<std::filesystem::path> screenshot_files_;

    ViewerStatistics stats_;
    // The window is drawn again only when something may have changed it (an input event, a new
    // frame: redraws_pending_ counts the draws still owed, ImGui settling over two) and at least
    // every kMaxUndrawnSeconds for the status line: redrawing an unchanged window 60 times a
    // second costs a software rasteriser (Xvfb, a laptop without a GPU driver) the CPU time the
    // render thread needs.
    int redraws_pending_ = 2;
    std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace fgr::viewer
