// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer application: it owns the window, the render worker and the viewer's parts, hands
// each part what it asks for through the part's host (a struct of callbacks), and runs the window
// thread's loop. Private to fgr_viewer.

#include <chrono>
#include <cstddef>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "viewer/camera_paths.hpp"
#include "viewer/formula_browser.hpp"
#include "viewer/gl_handles.hpp"
#include "viewer/hot_reloader.hpp"
#include "viewer/hybrid_editor.hpp"
#include "viewer/input_handler.hpp"
#include "viewer/render_choices.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/replay_driver.hpp"
#include "viewer/scene_set.hpp"
#include "viewer/view_tracker.hpp"
#include "viewer/viewer.hpp"
#include "viewer/viewer_panel.hpp"
#include "viewer/viewer_statistics.hpp"
#include "viewer/viewer_window.hpp"

namespace fgr::viewer {

class ViewerApp {
public:
    // Throws UsageError for bad options: an unknown scene, path, key or formula in a replay
    // script, an unreadable camera path file.
    ViewerApp(const ViewerOptions& options, std::vector<Scene> scenes);
    int run();

private:
    // The scene, camera, parameters, effects and path the command line asks for first.
    void prepare_first_scene();
    void start();
    // One pass of the window thread's loop, `dt` seconds after the last.
    void update(double dt);
    void draw_frame();
    void finish();

    // Everything that decides the image as the viewer shows it now, at the window's size.
    ViewState current_state();
    void submit_view();
    void receive_frame();
    // The render thread has refined the view, at the size a replayed resize asked for.
    bool view_idle() const;
    void log_refined_view();  // once each time the view becomes fully refined (debug level)

    // What the parts ask of the viewer.
    InputHost input_host();
    ReloadHost reload_host();
    HybridHost hybrid_host();
    BrowserHost browser_host();
    PanelHost panel_host();
    ReplayHost replay_host();
    void run_command(ViewerCommand command);
    void switch_scene(int index);
    void reset_camera(int camera_index);
    void take_screenshot();
    // Writes the view as fgr-SCENE-TIME.fgrview.json with a thumbnail beside it (view_still.hpp).
    void save_view();
    // The view of `state` as Ctrl+S saves it and F12 renders it.
    ViewFile current_view(const ViewState& state) const;
    // A replayed `set ID=VALUE`: the parameter of the scene shown, as --set takes it.
    void set_parameter(const std::string& assignment);
    // A new version of scene `index` (reloaded, or an edit of its sequence) takes its place.
    void adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene);
    void add_message(std::string message);
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
    std::optional<DisplayFrame> shown_;  // the frame on screen (a saved view's thumbnail)
    std::deque<std::string> messages_;
    std::set<std::filesystem::path> written_files_;  // screenshots and views asked for

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
