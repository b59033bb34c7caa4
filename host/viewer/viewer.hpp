// SPDX-License-Identifier: Apache-2.0
#pragma once
// `fgr view`: the interactive window. Rendering runs on its own thread, so input and the panel
// never wait on a slow frame; see docs/tutorial/viewer.md for the controls.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/projection.hpp"
#include "camera/view_override.hpp"
#include "render/environment.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "scene/render_mode.hpp"
#include "view_file/view_file.hpp"

namespace fgr::viewer {

// The most samples per pixel the viewer accumulates on a still view and renders F12 with.
inline constexpr int kMaxSampleCap = 1024;

struct ViewerOptions {
    // Id or scene file path (scene/scene_argument.hpp) to open first; empty: mandelbulb, else the
    // first found.
    std::string scene;
    int width = 1280;  // window size in pixels
    int height = 720;
    bool fullscreen = false;
    double target_ms = 33.0;  // frame time to hold while the view changes
    int sample_cap = 16;      // samples per pixel while still; F12's and saved views' too
    int device = -1;          // OpenCL device index, -1: first GPU, else first device
    int packet_width = 0;     // 0: the device's preference
    Precision precision = Precision::Auto;  // float, double or per view; the panel changes it
    std::optional<RenderMode> mode;         // shaded or path; default: each scene's own
    PathSettings path;                      // path mode's settings (its environment unset)
    bool denoise =
        false;  // path mode's accumulating image shown denoised; the panel and N toggle it
    EnvironmentChoice environment;         // what lights path-traced scenes; the panel changes it
    std::vector<std::string> assignments;  // --set id=value for the first scene
    std::string effect_changes;            // --effects for the first scene
    std::optional<std::filesystem::path> camera_path_file;  // load (and list) a recorded path
    std::string path_name;  // --path: the first scene's path P plays (default: its first)
    std::optional<ViewOverride> start_view;  // --eye, --target, --up, --fov: the first view
    Projection projection;                   // --projection and its settings; the panel changes it
    std::filesystem::path output_dir = ".";  // screenshots, saved views and camera paths
    // `fgr view VIEW.fgrview.json`: the view opened, whose settings are in the options above; the
    // viewer says when its scene is another or has changed since the view was saved.
    std::optional<ViewFile> opened_view;
    // Set by run_viewer for a scene opened by path: its file (absolute), which views of it
    // record, so `fgr render VIEW` finds it again.
    std::string opened_scene_file{};
    std::optional<std::filesystem::path> replay;  // scripted input (see replay.hpp)
    std::optional<double> exit_after_seconds;
    bool print_stats = false;  // frame-time statistics and the final camera on stdout
    bool dev = false;          // also watch scenes' .cl sources and reload them on change
};

// Runs the viewer until the window is closed, Escape, --exit-after or the replay's quit.
// Returns the process exit code. Throws fgr::UsageError for bad options (exit code 2) and
// std::runtime_error for failures (no display, no OpenCL device...).
int run_viewer(const ViewerOptions& options);

// The viewer is also fgr's module libfgr_viewer.so (scene/modules.hpp), which `fgr view` loads:
// SDL, OpenGL and the ~50 libraries they pull in are loaded only by the process that opens a
// window. Its entry point kViewerModuleEntry returns this table.
struct ViewerModule {
    int version;  // kViewerModuleVersion of the tree the module was built from
    int (*run)(const ViewerOptions& options);
};
inline constexpr int kViewerModuleVersion = 2;
inline constexpr const char* kViewerModuleName = "libfgr_viewer.so";
inline constexpr const char* kViewerModuleEntry = "fgr_viewer_module";

}  // namespace fgr::viewer
