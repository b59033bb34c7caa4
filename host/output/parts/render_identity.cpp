// SPDX-License-Identifier: Apache-2.0
#include "output/parts/render_identity.hpp"

#include <fmt/format.h>

#include <cstdint>

#include "camera/projection.hpp"
#include "device/kernel_assembly.hpp"
#include "scene/render_mode.hpp"

namespace fgr {
namespace {

// FNV-1a: a stable fingerprint of the kernel source (std::hash may differ between builds).
std::string fingerprint(const std::string& text) {
    uint64_t hash = 14695981039346656037ull;
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return fmt::format("{:016x}", hash);
}

std::string view_text(const CameraView& view) {
    return fmt::format(
        "eye {:.17g} {:.17g} {:.17g} target {:.17g} {:.17g} {:.17g} up {:.9g} "
        "{:.9g} {:.9g} fov {:.9g}",
        view.position.x, view.position.y, view.position.z, view.target.x, view.target.y,
        view.target.z, view.up.x, view.up.y, view.up.z, view.fov_degrees);
}

std::string projection_text(const Projection& projection) {
    return fmt::format(
        "{} fisheye {:.9g} separation {} convergence {}", projection_name(projection.kind),
        projection.fisheye_fov_degrees,
        projection.eye_separation ? fmt::format("{:.17g}", *projection.eye_separation) : "auto",
        projection.convergence ? fmt::format("{:.17g}", *projection.convergence) : "auto");
}

// Without the seed: parts of one image may differ in it (independent samples of each pixel).
std::string path_text(const PathSettings& path) {
    std::string text = fmt::format(
        "bounces {} roulette {} clamp {:.9g} light {} mis {} "
        "importance {} lights {} stratified {}",
        path.max_bounces, path.roulette_depth, path.radiance_clamp, path.light_sampling, path.mis,
        path.environment_importance, path.scene_lights, path.stratified);
    if (path.environment) {
        text += fmt::format(" environment '{}' rotation {:.9g} intensity {:.9g}",
                            path.environment->description, path.environment->rotation_degrees,
                            path.environment->intensity);
    }
    return text;
}

// The kernel as built, but for the packet width (and the stats counters, which change no pixel).
std::string kernel_text(const Renderer& renderer) {
    KernelSwitches switches = renderer.switches();
    switches.packet_width = 1;
    switches.stats = false;
    const AssembledProgram program = assemble_program(renderer.scene(), switches);
    return fingerprint(program.source + "\n" + program.options);
}

}  // namespace

std::string size_identity(int width, int height) { return fmt::format("{}x{}", width, height); }

std::string display_identity(const DisplayTransform& display) {
    return fmt::format("exposure {:.9g} tone map {}", display.exposure,
                       static_cast<int>(display.tone_map));
}

std::string layers_identity(bool layers) {
    return layers ? "colour, depth, albedo, normal, alpha, foreground" : "colour, depth";
}

IdentityFields image_identity(const Renderer& renderer, const FrameRequest& request,
                              const DisplayTransform& display) {
    const KernelSwitches& switches = renderer.switches();
    std::string params;
    for (float value : request.params)
        params += fmt::format("{}{:.9g}", params.empty() ? "" : " ", value);
    return {
        {"scene", renderer.scene().id},
        {"size", size_identity(request.width, request.height)},
        {"mode", std::string(render_mode_name(switches.mode))},
        {"effects", effect_names(switches.effects)},
        {"precision", switches.double_precision ? "double" : "float"},
        {"projection", projection_text(request.projection)},
        {"view", view_text(request.view)},
        {"parameters", params},
        {"path tracing", switches.mode == RenderMode::Path ? path_text(request.path) : "none"},
        {"display", display_identity(display)},
        {"layers", layers_identity(switches.aovs)},
        {"kernel", kernel_text(renderer)},
    };
}

}  // namespace fgr
