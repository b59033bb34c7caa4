// SPDX-License-Identifier: Apache-2.0
// fgr view: the interactive viewer (fgr_viewer) with the command line's options.
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "commands.hpp"
#include "device/kernel_assembly.hpp"
#include "image/hdr_io.hpp"
#include "render/renderer.hpp"
#include "scene/modules.hpp"
#include "view_options.hpp"

namespace fgr {
namespace {

// Window sizes offered by --preset and in the viewer's panel.
const std::map<std::string, std::pair<int, int>>& window_presets() {
    static const std::map<std::string, std::pair<int, int>> presets = {{"1366x768", {1366, 768}},
                                                                       {"1920x1080", {1920, 1080}},
                                                                       {"2560x1440", {2560, 1440}},
                                                                       {"3840x2160", {3840, 2160}}};
    return presets;
}

}  // namespace

void add_view_command(CLI::App& app, ViewCommandOptions& options) {
    CLI::App* view = app.add_subcommand(
        "view", "open the interactive viewer (press H in it for the key bindings)");
    viewer::ViewerOptions& viewer = options.viewer;
    view->add_option("scene", viewer.scene,
                     "scene to open first, by id or as a scene file: .so, .ifs.json, "
                     ".formula.json, .cl (default: mandelbulb); or a view file (.fgrview.json)");
    view->add_option("--width", viewer.width, "window width in pixels (default 1280)")
        ->check(CLI::Range(64, kMaxImageSide));
    view->add_option("--height", viewer.height, "window height in pixels (default 720)")
        ->check(CLI::Range(64, kMaxImageSide));
    std::vector<std::string> names;
    for (const auto& [name, size] : window_presets()) names.push_back(name);
    view->add_option("--preset", options.preset, "window size preset")->check(CLI::IsMember(names));
    view->add_flag("--fullscreen", viewer.fullscreen, "start fullscreen (F11 toggles)");
    view->add_option("--target-ms", viewer.target_ms,
                     "frame time to hold while moving, in ms (default 33)")
        ->check(CLI::Range(5.0, 1000.0));
    view->add_option("--samples", viewer.sample_cap,
                     "samples per pixel accumulated when still and for screenshots (default 16)")
        ->check(CLI::Range(1, viewer::kMaxSampleCap));
    view->add_option("--set", viewer.assignments, "set a parameter of the first scene: id=value")
        ->allow_extra_args(false);
    view->add_option_function<std::string>(
        "--colour",
        [&viewer](const std::string& mode) { viewer.assignments.push_back("colour_mode=" + mode); },
        "colour mode of the first scene (point, planes, axes, iterations: those it offers, see "
        "`fgr list SCENE`); the same as --set colour_mode=MODE");
    view->add_option("--effects", viewer.effect_changes,
                     "change the first scene's effects, e.g. +shadows,-ambient_occlusion");
    view->add_option("--camera-path", options.camera_path_file,
                     "a .json camera path saved by the viewer, to play with P");
    view->add_option("--path", viewer.path_name,
                     "the first scene's camera path P plays (default: its first; `fgr list SCENE` "
                     "shows them), e.g. --path dive");
    add_view_override_options(view, options.view_override);
    add_projection_options(view, options.projection);
    view->add_option("--output-dir", viewer.output_dir,
                     "where F12 screenshots and saved camera paths go (default: .)");
    view->add_option("--replay", options.replay, "feed timed input events from a file");
    view->add_option("--exit-after", options.exit_after,
                     "quit after this many seconds (default: never)")
        ->check(CLI::PositiveNumber);
    view->add_flag("--dev", viewer.dev,
                   "scene development: reload a scene when its .cl source file is saved");
    view->add_flag("--stats", viewer.print_stats,
                   "print frame-time statistics and the final camera on exit");
    add_precision_option(view, viewer.precision,
                         "while the view is finer than float resolves (flying in deep), per frame");
    add_device_options(view, viewer.device, viewer.packet_width);
    add_mode_options(view, options.mode);
    view->add_option("--view", options.view,
                     "open a view: a .fgrview.json file (as Ctrl+S saves it) or an image fgr "
                     "wrote (it carries its view): its scene, camera, parameters, effects, mode "
                     "and settings; any option typed overrides the view's");
    record_typed_options(view, options.typed);
}

int command_view(ViewCommandOptions& options) {
    viewer::ViewerOptions& viewer = options.viewer;
    if (options.view || is_view_file_name(viewer.scene)) {
        apply_view(options, load_view_argument(options.view.value_or(viewer.scene)));
    }
    if (!options.preset.empty()) {
        std::tie(viewer.width, viewer.height) = window_presets().at(options.preset);
    }
    try {
        apply_effect_changes(0, viewer.effect_changes);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    if (!options.camera_path_file.empty()) {
        if (!looks_like_camera_path_file(options.camera_path_file)) {
            throw UsageError("--camera-path must name a .json file saved by the viewer");
        }
        viewer.camera_path_file = options.camera_path_file;
    }
    viewer.projection = chosen_projection(options.projection);
    if (!options.view_override.empty()) {
        viewer.start_view = parsed_view_override(options.view_override);
    }
    if (options.mode.mode) {
        try {
            viewer.mode = parse_render_mode(*options.mode.mode);
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    viewer.path = path_settings_from(options.mode);
    viewer.environment = environment_choice_from(options.mode);
    if (viewer.environment.kind == EnvironmentKind::File) {
        // A bad file is refused before a window opens.
        try {
            read_hdr_image(viewer.environment.file);
        } catch (const std::runtime_error& error) {
            throw RuntimeFailure(error.what());
        }
    }
    if (!options.replay.empty()) viewer.replay = options.replay;
    if (options.exit_after > 0.0) viewer.exit_after_seconds = options.exit_after;
    std::error_code error;
    if (!std::filesystem::is_directory(viewer.output_dir, error)) {
        throw UsageError(
            fmt::format("--output-dir '{}' is not a directory", viewer.output_dir.string()));
    }
    // The viewer module (viewer/viewer.hpp), loaded now that a window is wanted.
    const auto& module =
        module_table<viewer::ViewerModule>(viewer::kViewerModuleName, viewer::kViewerModuleEntry,
                                           viewer::kViewerModuleVersion, "the viewer");
    return module.run(viewer);
}

}  // namespace fgr
