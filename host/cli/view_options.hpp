// SPDX-License-Identifier: Apache-2.0
#pragma once
// View files on the command line (view_file/view_file.hpp): reading one as the start of a render
// under the options typed, and writing the view of a render.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "commands.hpp"
#include "view_file/view_file.hpp"

namespace fgr {

// --view FILE and --save-view FILE (render and video).
void add_view_file_options(CLI::App* command, RenderOptions& options);

// Fills `typed` with the long names of the options given on `command`'s line, once it is parsed:
// a view file fills in only what the user did not type.
void record_typed_options(CLI::App* command, TypedOptions& typed);

// The view the options start from: --view, or a SCENE that is a view file; none otherwise.
std::optional<std::string> view_argument(const RenderOptions& options);
// The view file `argument` names (UsageError naming the file and the key for a bad one).
ViewFile load_view_argument(const std::string& argument);

// The options with the view's settings in place of every one the user did not type: scene, size,
// output depth and layers, samples, mode and the path tracer's settings, effects (the view's set,
// then --effects over it), precision, prepass, parameters (the view's, then --set), camera (unless
// --camera or --camera-path was typed; --eye, --target, --up and --fov each replace the view's)
// and projection.
void apply_view(RenderOptions& options, const ViewFile& view);

// `fgr view VIEW` and `fgr view --view VIEW`: the viewer opens the view's scene with its camera
// (--eye, --target, --up and --fov each replace the view's), parameters (then --set), effects
// (then --effects), mode and path tracer's settings, projection, precision and samples (the sample
// cap, what F12 renders with), each unless typed; the window keeps its own size.
void apply_view(ViewCommandOptions& options, const ViewFile& view);

// Warns when `scene` is not the one the view was saved with (another id, or changed since).
void warn_if_scene_changed(const ViewFile& view, const Scene& scene);

// The view of a render: `request` (size, camera, parameters, projection) of `scene` with the
// options' mode, samples, effects and output settings.
ViewFile view_of_render(const Scene& scene, const FrameRequest& request,
                        const RenderOptions& options);

// Writes the view to --save-view's file when one was given (RuntimeFailure when it cannot).
void save_view_if_asked(const RenderOptions& options, const ViewFile& view);

}  // namespace fgr
