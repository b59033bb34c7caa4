// SPDX-License-Identifier: Apache-2.0
#pragma once
// One still image of a scene, as `fgr render` makes it: the scene's kernel built with the
// requested switches and render mode, float or double chosen for the view, the frame rendered and
// written as PNG or EXR.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "output/still_layers.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

struct StillSettings {
    int packet_width = 0;  // rays per work-item; 0: the device's preference
    uint64_t effects = 0;  // fgr_effect_flag bits compiled in
    bool stats = false;    // count the primary rays' work (Frame::stats)
    Precision precision = Precision::Auto;
    RenderMode mode = RenderMode::Shaded;
    bool aovs = false;  // also render alpha, albedo and normal (KernelSwitches::aovs)
};

// "albedo,normal,depth,alpha" (any subset, any order; "" for none). Throws std::invalid_argument
// naming an unknown layer.
Aovs parse_aovs(std::string_view list);

// The kernel switches a still renders with, in float (the precision is chosen per view).
KernelSwitches still_switches(const ComputeDevice& device, const StillSettings& settings);

// The renderer of `renderers` (made with still_switches) in `double_precision`, built now if it
// was not yet, logging what it builds and how long that took.
Renderer& build_still_renderer(PrecisionRenderers& renderers, const Scene& scene,
                               const ComputeDevice& device, const StillSettings& settings,
                               bool double_precision);

// The renderer of `renderers` (made with still_switches) in the precision `settings` and the
// view call for (as render_still chooses it), built now if need be, logging what it builds.
// Throws as render_still does for a view or effects it cannot render.
Renderer& choose_still_renderer(PrecisionRenderers& renderers, const Scene& scene,
                                const FrameRequest& request, const ComputeDevice& device,
                                const StillSettings& settings);

// Builds the scene's kernel (logging what it builds and how long it took) and renders `request`.
// Float or double as PrecisionChooser decides for the view (Auto: auto_wants_double, with the DE
// at the camera from the float kernel when the target alone does not call for double). Throws
// KernelBuildError when the scene does not compile, std::runtime_error when double was asked of a
// device without it, and std::runtime_error when a pixel's colour or depth came out NaN or
// infinite (non_finite_pixels): an image that could not be computed is an error, never a file.
Frame render_still(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                   ProgramCache& cache, const StillSettings& settings);

// Pixels of `frame` whose linear colour or depth is NaN or infinite.
long non_finite_pixels(const Frame& frame);
// Throws std::runtime_error naming `scene` when `frame` has non-finite pixels (render_still's
// check).
void check_finite_frame(const Scene& scene, const Frame& frame);

// How a still is written (see still_layers.hpp for what alpha does to the colour).
struct StillOutput {
    int bit_depth = 8;         // PNG: 8, tone-mapped sRGB; 16, linear colour times the exposure
    DisplayTransform display;  // the 8-bit image's (its exposure also scales the 16-bit one)
    bool alpha = false;        // PNG: RGBA, straight alpha; EXR: A, premultiplied colour
    Aovs aovs;                 // EXR layers beside the colour
    // The document the file carries (image/embedded_view.hpp: the view that made it); "": none.
    std::string embedded_view{};
};

// Writes `frame` by the file's extension. PNG: bit_depth 8, the tone-mapped sRGB image; 16, its
// linear colour times the exposure in a linear 16-bit PNG; RGBA with output.alpha. EXR: the
// linear colour as rendered (scene-referred: no exposure, no tone mapping) in 32-bit float
// channels R, G, B, plus the layers output.aovs asks for (albedo.R/G/B, normal.X/Y/Z, depth.Z,
// A; A also with output.alpha). Either carries output.embedded_view. Atomic; throws
// std::runtime_error (and std::invalid_argument for a layer the frame does not have: alpha, albedo
// and normal need StillSettings::aovs; or a document check_embedded_view refuses).
void write_still(const std::filesystem::path& path, const Frame& frame, const StillOutput& output);

}  // namespace fgr
