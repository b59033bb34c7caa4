// SPDX-License-Identifier: Apache-2.0
// View files on the command line: `fgr render VIEW.fgrview.json`, `--view FILE` (a view file or an
// image that carries one) under any option typed, and `--save-view FILE`.
#include "view_options.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "image/embedded_view.hpp"
#include "render/environment.hpp"
#include "render/sample_budget.hpp"
#include "scene/effects.hpp"
#include "scene/scene.hpp"
#include "scene/scene_limits.hpp"
#include "util/version.hpp"

namespace fgr {
namespace {

std::string vector_text(double x, double y, double z) { return fmt::format("{},{},{}", x, y, z); }

// The file's effects as --effects changes: the whole set, then what was typed over it.
std::string effect_changes_of(const ViewFile& view, const std::string& typed) {
    std::string changes = "none";
    for (const std::string& name : view.effects) changes += ",+" + name;
    if (!typed.empty()) changes += "," + typed;
    return changes;
}

// The view's camera under --eye, --target, --up and --fov, each of which replaces the view's.
void apply_camera(ViewOverrideText& text, const ViewFile& view) {
    const CameraView& camera = view.camera;
    if (!text.eye) text.eye = vector_text(camera.position.x, camera.position.y, camera.position.z);
    if (!text.target) text.target = vector_text(camera.target.x, camera.target.y, camera.target.z);
    if (!text.up) text.up = vector_text(camera.up.x, camera.up.y, camera.up.z);
    if (!text.fov) text.fov = fmt::format("{}", camera.fov_degrees);
}

void apply_projection(ProjectionOptions& projection, const ViewFile& view) {
    if (projection.projection || projection.stereo) return;  // a projection typed is the user's
    projection.projection = projection_name(view.projection.kind);
    if (view.projection.kind == ProjectionKind::Fisheye && !projection.fisheye_fov) {
        projection.fisheye_fov = view.projection.fisheye_fov_degrees;
    }
    if (is_stereo(view.projection.kind)) {
        if (!projection.eye_separation) projection.eye_separation = view.projection.eye_separation;
        if (!projection.convergence) projection.convergence = view.projection.convergence;
    }
}

// The view's mode and path tracer's choices under those typed.
void apply_mode(ModeOptions& mode, const ViewFile& view, const TypedOptions& typed) {
    if (!typed.has("mode")) mode.mode = std::string(render_mode_name(view.mode));
    if (!view.path) return;
    const ViewPathChoices& path = *view.path;
    if (!typed.has("seed")) mode.seed = path.seed;
    if (!typed.has("bounces")) mode.bounces = path.bounces;
    if (!typed.has("roulette-depth")) mode.roulette_depth = path.roulette_depth;
    if (!typed.has("clamp")) mode.radiance_clamp = path.radiance_clamp;
    if (!typed.has("no-light-sampling")) mode.no_light_sampling = !path.light_sampling;
    if (!typed.has("no-mis")) mode.no_mis = !path.mis;
    if (!typed.has("no-scene-lights")) mode.no_scene_lights = !path.scene_lights;
    // The view names what lit it, the scene's own environment included, so it renders the same
    // even where the scene's own has changed since.
    if (!typed.has("environment")) mode.environment = path.environment;
    if (!typed.has("environment-rotation")) mode.environment_rotation = path.environment_rotation;
    if (!typed.has("environment-intensity")) {
        mode.environment_intensity = path.environment_intensity;
    }
    if (!typed.has("turbidity")) mode.turbidity = path.turbidity;
    if (!typed.has("sun-elevation")) mode.sun_elevation = path.sun_elevation;
    if (!typed.has("sun-azimuth")) mode.sun_azimuth = path.sun_azimuth;
    if (!typed.has("denoise")) mode.denoise = path.denoise;
}

// The view's parameters as --set takes them, then those typed, which so win.
std::vector<std::string> assignments_of(const ViewFile& view,
                                        const std::vector<std::string>& typed) {
    std::vector<std::string> assignments;
    for (const ViewParameter& parameter : view.parameters) {
        assignments.push_back(parameter_assignment(parameter));
    }
    assignments.insert(assignments.end(), typed.begin(), typed.end());
    return assignments;
}

}  // namespace

bool TypedOptions::has(std::string_view long_name) const {
    return names.contains(std::string(long_name));
}

void record_typed_options(CLI::App* command, TypedOptions& typed) {
    command->parse_complete_callback([command, &typed] {
        typed.names.clear();
        for (const CLI::Option* option : command->get_options()) {
            if (option->count() == 0) continue;
            for (const std::string& name : option->get_lnames()) typed.names.insert(name);
        }
    });
}

void add_view_file_options(CLI::App* command, RenderOptions& options) {
    command->add_option("--view", options.view,
                        "start from a view: a .fgrview.json file, or an image fgr wrote (it "
                        "carries its view); any option typed overrides the view's");
    command->add_option("--save-view", options.save_view,
                        "also write this render's view to FILE (.fgrview.json): `fgr render FILE` "
                        "renders it again");
}

std::optional<std::string> view_argument(const RenderOptions& options) {
    if (options.view) return options.view;
    if (is_view_file_name(options.scene)) return options.scene;
    return std::nullopt;
}

ViewFile load_view_argument(const std::string& argument) {
    try {
        if (is_view_file_name(argument)) return read_view_file(argument);
        const std::optional<std::string> document = read_embedded_view(argument);
        if (!document) {
            throw UsageError(fmt::format(
                "{}: carries no fgr view (give a .fgrview.json file, or an image fgr wrote)",
                argument));
        }
        return parse_view_file(*document);
    } catch (const UsageError&) {
        throw;
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        // read_view_file names the file; an image's document does not.
        throw UsageError(message.starts_with(argument) ||
                                 message.starts_with("cannot read '" + argument)
                             ? message
                             : fmt::format("{}: the view it carries: {}", argument, message));
    }
}

void apply_view(RenderOptions& options, const ViewFile& view) {
    const TypedOptions& typed = options.typed;
    // A scene typed besides the view renders the view in that scene.
    if (options.scene.empty() || is_view_file_name(options.scene)) {
        options.scene = view.scene_file.empty() ? view.scene_id : view.scene_file;
    }
    if (!typed.has("width")) options.width = view.width;
    if (!typed.has("height")) options.height = view.height;
    if (!typed.has("bit-depth")) options.bit_depth = view.bit_depth;
    if (!typed.has("alpha")) options.alpha = view.alpha;
    if (!typed.has("aov")) options.aovs = view.layers;
    if (!typed.has("spp")) options.samples = view.samples;
    apply_mode(options.mode, view, typed);
    if (!typed.has("precision")) options.precision = view.precision;
    if (!typed.has("prepass")) options.prepass = view.prepass;
    options.effect_changes = effect_changes_of(view, options.effect_changes);
    options.assignments = assignments_of(view, options.assignments);
    // A named camera or a camera path typed replaces the file's camera altogether.
    if (!options.camera && !options.camera_path) apply_camera(options.view_override, view);
    apply_projection(options.projection, view);
}

void apply_view(ViewCommandOptions& options, const ViewFile& view) {
    const TypedOptions& typed = options.typed;
    viewer::ViewerOptions& viewer = options.viewer;
    if (viewer.scene.empty() || is_view_file_name(viewer.scene)) {
        viewer.scene = view.scene_file.empty() ? view.scene_id : view.scene_file;
    }
    // The view's samples are what F12 renders with, as when the viewer saved it.
    if (!typed.has("samples")) {
        viewer.sample_cap = std::clamp(view.samples, 1, viewer::kMaxSampleCap);
    }
    apply_mode(options.mode, view, typed);
    if (!typed.has("precision")) viewer.precision = view.precision;
    viewer.effect_changes = effect_changes_of(view, viewer.effect_changes);
    viewer.assignments = assignments_of(view, viewer.assignments);
    apply_camera(options.view_override, view);
    apply_projection(options.projection, view);
    viewer.opened_view = view;
}

void warn_if_scene_changed(const ViewFile& view, const Scene& scene) {
    if (view.scene_id != scene.id) {
        spdlog::warn("the view was saved in scene '{}': rendering it in '{}'", view.scene_id,
                     scene.id);
        return;
    }
    if (const std::string warning = scene_change_warning(view, scene); !warning.empty()) {
        spdlog::warn("{}", warning);
    }
}

ViewFile view_of_render(const Scene& scene, const FrameRequest& request,
                        const RenderOptions& options) {
    const RenderMode mode = chosen_mode(options.mode, scene);
    uint64_t effects = 0;
    int samples = 1;
    try {
        effects = apply_effect_changes(scene.effects, options.effect_changes);
        samples = still_samples(mode, options.samples);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    ViewFile view;
    view.scene_id = scene.id;
    view.scene_fingerprint = scene_fingerprint(scene);
    std::error_code error;
    if (!options.all && !is_scene_id(options.scene) &&
        std::filesystem::is_regular_file(options.scene, error)) {
        const std::filesystem::path absolute = std::filesystem::absolute(options.scene, error);
        view.scene_file = error ? options.scene : absolute.lexically_normal().string();
    }
    view.fgr_version = fgr_version();
    view.width = request.width;
    view.height = request.height;
    view.bit_depth = options.bit_depth;
    view.alpha = options.alpha;
    view.layers = options.aovs;
    view.camera = request.view;
    view.projection = request.projection;
    view.parameters = changed_parameters(scene, request.params);
    view.mode = mode;
    view.samples = samples;
    for (const EffectSwitch& effect : effect_switches()) {
        if (effects & effect.bit) view.effects.emplace_back(effect.name);
    }
    view.precision = options.precision;
    view.prepass = options.prepass;
    if (mode == RenderMode::Path) {
        const ModeOptions& choices = options.mode;
        ViewPathChoices path;
        path.seed = choices.seed;
        path.bounces = choices.bounces;
        path.roulette_depth = choices.roulette_depth;
        path.radiance_clamp = choices.radiance_clamp;
        path.light_sampling = !choices.no_light_sampling;
        path.mis = !choices.no_mis;
        path.scene_lights = !choices.no_scene_lights;
        // What lit the render, so that the view renders it again: the environment typed, else
        // the sky's settings typed name the sky, else the scene's own, else the sky.
        path.environment = choices.environment ? *choices.environment
                                               : environment_argument(with_scene_environment(
                                                     environment_choice_from(choices), scene));
        path.environment_rotation = choices.environment_rotation;
        path.environment_intensity = choices.environment_intensity;
        path.turbidity = choices.turbidity;
        path.sun_elevation = choices.sun_elevation;
        path.sun_azimuth = choices.sun_azimuth;
        path.denoise = choices.denoise;
        view.path = path;
    }
    return view;
}

void save_view_if_asked(const RenderOptions& options, const ViewFile& view) {
    if (!options.save_view) return;
    try {
        write_view_file(*options.save_view, view);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    fmt::print("wrote {} (the view)\n", *options.save_view);
}

}  // namespace fgr
