// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's Dear ImGui panel (Tab): the status line, scenes, cameras and paths, a widget per
// parameter, effects, render mode, adaptive quality and messages; the help window (H) and the
// windows that say why a build failed. Private to fgr_viewer.

#include <imgui.h>

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "device/opencl_device.hpp"
#include "viewer/camera_paths.hpp"
#include "viewer/render_choices.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/scene_set.hpp"
#include "viewer/viewer_window.hpp"

namespace fgr::viewer {

// What the panel shows of the view this frame.
struct ViewReport {
    const ViewState& view;                     // the last handed to the render thread
    const std::optional<DisplayFrame>& shown;  // the facts of the frame on screen
    const WorkerStatus& status;
    const DeviceInfo& device;
    const std::deque<std::string>& messages;  // the newest last
};

// What the panel asks of the viewer beyond what it edits itself.
struct PanelHost {
    std::function<void(int index)> switch_scene;
    std::function<void(int camera_index)> reset_camera;
    std::function<void()> take_screenshot;
    std::function<void()> save_view;            // Ctrl+S: the view as a .fgrview.json file
    std::function<void()> quality_changed;      // the render thread takes the new settings
    std::function<void()> environment_changed;  // the prepared environments are stale
    std::function<float()> fly_speed;           // the factor on the flying speed
    std::function<void(float)> set_fly_speed;
    std::function<bool()> browser_shown;
    std::function<void()> toggle_browser;
    std::function<void()> draw_formula_sequence;  // the hybrid editor's section
};

class ViewerPanel {
public:
    // The panel edits the sessions, the render choices, the camera paths and the window itself.
    ViewerPanel(SceneSet& scenes, RenderChoices& choices, CameraPaths& paths, ViewerWindow& window,
                PanelHost host);

    // The status line at the top left.
    void draw_overlay(const ViewReport& report);
    // The panel, when shown.
    void draw_panel(const ViewReport& report);
    // Why an update or a build was refused, and the help window.
    void draw_dialogs(const WorkerStatus& status);

    // Whether a window point lies on the panel (the wheel and the right button are the panel's
    // there).
    bool covers(int x, int y) const;
    void toggle_panel() { visible_ = !visible_; }
    void toggle_help() { show_help_ = !show_help_; }
    // The scene list scrolls to the current scene the next time it is drawn.
    void follow_current_scene() { scene_list_follows_ = true; }
    // Shows why an update was refused (summary, compiler log) until the user closes it.
    void show_refused_update(std::string summary, std::string log);
    void clear_refused_update() { refused_update_ = {}; }

private:
    void draw_scene_section();
    void draw_camera_section(const WorkerStatus& status);
    void draw_projection_section();
    void draw_params_section();
    void draw_effects_section(const WorkerStatus& status);
    void draw_mode_section();
    // The environment's controls; true when the choice changed.
    bool draw_environment_controls();
    void draw_quality_section(const ViewReport& report);
    void draw_precision_combo(const ViewReport& report);
    void draw_messages(const std::deque<std::string>& messages);
    void draw_help();
    void draw_build_errors(const WorkerStatus& status);

    SceneSet& scenes_;
    RenderChoices& choices_;
    CameraPaths& paths_;
    ViewerWindow& window_;
    PanelHost host_;
    bool visible_ = true;
    bool show_help_ = false;
    bool scene_list_follows_ = true;  // the scene list scrolls to the current scene
    ImVec2 min_{0, 0}, max_{0, 0};    // the panel's extent when last drawn
    std::pair<std::string, std::string> refused_update_;  // summary, log
};

}  // namespace fgr::viewer
