// SPDX-License-Identifier: Apache-2.0
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <string>
#include <vector>

#include "commands.hpp"
#include "device/program_cache.hpp"
#include "distributed/cluster.hpp"
#include "render/renderer.hpp"
#include "scene/scene_argument.hpp"
#include "scene/scene_index.hpp"
#include "scene/scene_source.hpp"
#include "util/atomic_file.hpp"
#include "util/strings.hpp"

namespace fgr {
Discovery discover() { return discover_scenes(plugin_search_path(executable_dir())); }

Scene scene_from_argument(const std::string& argument) {
    const std::filesystem::path cache = ProgramCache::default_directory();
    return find_scene_argument(argument, plugin_search_path(executable_dir()),
                               cache.empty() ? cache : cache / kSceneIndexName);
}

std::future<Scene> scene_from_argument_meanwhile(const std::string& argument) {
    return std::async(std::launch::async, [argument] { return scene_from_argument(argument); });
}

const Scene& find_scene(const Discovery& found, const std::string& id) {
    for (const auto& scene : found.scenes) {
        if (scene.id == id) return scene;
    }
    throw UsageError(unknown_scene_message(found, id));
}

void add_kernel_source_option(CLI::App* command, std::string& file) {
    command->add_option(
        "--kernel-source", file,
        "FILE.cl: the scene with this OpenCL source instead of its own (try or time "
        "a variant of its DE without rebuilding the plugin)");
}

Scene with_kernel_source(Scene scene, const std::string& file) {
    if (file.empty()) return scene;
    try {
        scene = with_source_file(scene, std::filesystem::absolute(file));
    } catch (const std::runtime_error& error) {
        throw UsageError(fmt::format("--kernel-source: {}", error.what()));
    }
    if (scene.source.empty()) throw UsageError(fmt::format("--kernel-source: {} is empty", file));
    return scene;
}

Scene scene_as_used(const Scene& scene, bool dev) {
    if (!dev) {
        if (const std::string stale = stale_source_warning(scene); !stale.empty()) {
            spdlog::warn("{}", stale);
        }
        return scene;
    }
    try {
        return with_source_from_disk(scene);
    } catch (const std::runtime_error& error) {
        throw UsageError(error.what());
    }
}

ComputeDevice open_requested_device(int index) {
    const std::vector<DeviceInfo> devices = list_devices();
    if (index >= static_cast<int>(devices.size())) {
        throw UsageError(fmt::format("no OpenCL device {} (see `fgr info`)", index));
    }
    const Cluster& cluster = Cluster::current();
    if (index < 0 && !cluster.alone()) {
        // One device a rank where a node has several of the default's kind (GPUs, say): the
        // ranks on a node take them in turn by their local rank.
        std::vector<int> candidates;
        const bool any_gpu = std::any_of(devices.begin(), devices.end(),
                                         [](const DeviceInfo& d) { return d.is_gpu; });
        for (const DeviceInfo& device : devices) {
            if (device.is_gpu == any_gpu) candidates.push_back(device.index);
        }
        if (!candidates.empty()) {
            index = candidates[size_t(cluster.local_rank()) % candidates.size()];
            spdlog::debug("{} renders on OpenCL device {}", cluster.name(), index);
        }
    }
    return open_device(index);
}

DeviceOpenedAhead::DeviceOpenedAhead(int index) {
    try {
        device_ = open_requested_device(index);
    } catch (...) {
        failure_ = std::current_exception();
    }
}

ComputeDevice DeviceOpenedAhead::take() {
    if (failure_) std::rethrow_exception(failure_);
    return std::move(*device_);
}

std::future<Discovery> discover_meanwhile() {
    return std::async(std::launch::async, [] { return discover(); });
}

void print_mpi_figures(const Cluster& cluster, const FarmOutcome& outcome) {
    fmt::print("mpi_ranks {}\n", cluster.size());
    fmt::print("mpi_tasks_by_rank {}\n", tasks_by_rank_text(outcome));
    fmt::print("mpi_traffic {} messages, {} bytes\n", cluster.traffic().messages,
               cluster.traffic().bytes);
}

void add_device_options(CLI::App* command, int& device, int& packet_width) {
    command
        ->add_option("--device", device,
                     "OpenCL device index (see `fgr info`); default: the first GPU, else device 0")
        ->check(CLI::NonNegativeNumber);
    command
        ->add_option("--packet-width", packet_width,
                     "rays per work-item (default: 16 on CPUs, 1 on GPUs)")
        ->check(CLI::IsMember({1, 4, 8, 16}));
}

void add_precision_option(CLI::App* command, Precision& precision, const std::string& auto_means) {
    std::vector<std::string> names;
    for (Precision choice : {Precision::Float, Precision::Double, Precision::Auto}) {
        names.emplace_back(precision_name(choice));
    }
    const auto choose = [&precision](const std::string& name) {
        precision = parse_precision(name);
    };
    command
        ->add_option_function<std::string>("--precision", choose,
                                           "float, double, or auto (default): double " + auto_means)
        ->check(CLI::IsMember(names));
}

void add_prepass_option(CLI::App* command, bool& prepass) {
    const auto choose = [&prepass](const std::string& value) { prepass = value == "on"; };
    command
        ->add_option_function<std::string>(
            "--prepass", choose,
            "on (default) or off: start camera rays where a cone marched for their 8x8 block of "
            "pixels came near the surface, instead of at the eye (same image, fewer DE "
            "evaluations; no effect with depth of field, glow, IFS scenes or --mode brute)")
        ->check(CLI::IsMember({"on", "off"}));
}

void add_mode_options(CLI::App* command, ModeOptions& options) {
    std::vector<std::string> names;
    for (const RenderModeInfo& info : render_modes()) names.emplace_back(info.name);
    command
        ->add_option("--mode", options.mode,
                     "render mode: shaded (Blinn-Phong and effects), path (path tracing) or "
                     "brute (brute-force inside tests, for scenes with no distance estimator); "
                     "default: the scene's own")
        ->check(CLI::IsMember(names));
    const std::string path = "Path tracing (--mode path)";
    command
        ->add_option("--environment", options.environment,
                     "what lights the scene besides its own lights: sky, studio, "
                     "uniform[:RADIANCE or R,G,B] or an equirectangular .hdr/.exr file; default: "
                     "the scene's own environment, else sky. Under the sky its sun takes the place "
                     "of the scene's key light (its first directional light)")
        ->group(path);
    command
        ->add_option("--environment-rotation", options.environment_rotation,
                     "turn the environment about the up axis, degrees")
        ->group(path);
    command
        ->add_option("--environment-intensity", options.environment_intensity,
                     "scale the environment's radiance")
        ->check(CLI::NonNegativeNumber)
        ->group(path);
    command->add_option("--turbidity", options.turbidity, "sky haze, 2 (clear) to 10 (hazy)")
        ->check(CLI::Range(1.7f, 10.0f))
        ->group(path);
    command
        ->add_option("--sun-elevation", options.sun_elevation,
                     "sun above the horizon, degrees (default: the scene's key light)")
        ->check(CLI::Range(-10.0f, 90.0f))
        ->group(path);
    command
        ->add_option("--sun-azimuth", options.sun_azimuth,
                     "sun's compass angle, degrees (default: the scene's key light)")
        ->group(path);
    command->add_option("--bounces", options.bounces, "scattering events per path at most")
        ->check(CLI::Range(0, kMaxBounces))
        ->group(path);
    command
        ->add_option("--roulette-depth", options.roulette_depth,
                     "Russian roulette from this bounce on (unbiased); 0: never")
        ->check(CLI::Range(0, kMaxBounces))
        ->group(path);
    command
        ->add_option("--clamp", options.radiance_clamp,
                     "clamp each sample's radiance to this (removes fireflies, biased); 0: off")
        ->check(CLI::NonNegativeNumber)
        ->group(path);
    command
        ->add_flag("--no-light-sampling", options.no_light_sampling,
                   "find lights by BSDF sampling alone (no next-event estimation)")
        ->group(path);
    command
        ->add_flag("--no-mis", options.no_mis,
                   "no multiple importance sampling between light and BSDF sampling")
        ->group(path);
    command
        ->add_flag("--no-scene-lights", options.no_scene_lights,
                   "light the scene by the environment alone (the sky keeps its sun): what a "
                   "furnace test with --environment uniform wants")
        ->group(path);
    command->add_option("--seed", options.seed, "noise pattern of the path tracer")->group(path);
    command
        ->add_option("--noise-threshold", options.noise_threshold,
                     "adaptive sampling: each pixel stops once the relative standard error of its "
                     "estimate is about this (e.g. 0.01), --spp being the most it takes; 0: off "
                     "(every pixel takes --spp samples)")
        ->check(CLI::Range(0.0f, 1.0f))
        ->group(path);
    command
        ->add_option("--min-spp", options.min_samples,
                     "adaptive sampling: samples every pixel takes before any stops (default: "
                     "--spp / 32, at least 4)")
        ->check(CLI::Range(2, 1 << 20))
        ->group(path);
    command
        ->add_flag("--no-regroup", options.no_regroup,
                   "one sample a launch, each lane tracing its own pixel's path to its end (the "
                   "same image, slower: to measure what regrouping the lanes buys)")
        ->group(path);
}

void add_denoise_option(CLI::App* command, bool& denoise, const std::string& what) {
    command->add_flag("--denoise", denoise, what)->group("Path tracing (--mode path)");
}

void check_denoise(RenderMode mode, int samples) {
    if (mode != RenderMode::Path) {
        throw UsageError(fmt::format(
            "--denoise is for the path tracer (--mode path): the {} mode's image has no noise "
            "to filter",
            render_mode_name(mode)));
    }
    if (samples < 2) {
        throw UsageError("--denoise needs at least 2 samples per pixel (--spp 2 or more)");
    }
}

RenderMode chosen_mode(const ModeOptions& options, const Scene& scene) {
    RenderMode mode = scene.default_mode;
    if (options.mode) {
        try {
            mode = parse_render_mode(*options.mode);
            check_mode_supported(scene, mode);  // before any kernel is built for it
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    if (mode != RenderMode::Path && (options.noise_threshold > 0.0f || options.min_samples > 0)) {
        throw UsageError(fmt::format(
            "--noise-threshold and --min-spp are for --mode path (the {} mode takes the same "
            "samples everywhere)",
            render_mode_name(mode)));
    }
    return mode;
}

PathSettings path_settings_from(const ModeOptions& options) {
    PathSettings settings;
    settings.max_bounces = options.bounces;
    settings.roulette_depth = options.roulette_depth;
    settings.radiance_clamp = options.radiance_clamp;
    settings.light_sampling = !options.no_light_sampling;
    settings.mis = !options.no_mis;
    settings.scene_lights = !options.no_scene_lights;
    settings.seed = options.seed;
    settings.noise_threshold = options.noise_threshold;
    settings.min_samples = options.min_samples;
    settings.regroup = !options.no_regroup;
    try {
        check_path_settings(settings);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    return settings;
}

EnvironmentChoice environment_choice_from(const ModeOptions& options) {
    EnvironmentChoice choice;
    if (options.environment) {
        try {
            choice = parse_environment(*options.environment);
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    choice.rotation_degrees = options.environment_rotation;
    choice.intensity = options.environment_intensity;
    if (options.turbidity) choice.sky.turbidity = *options.turbidity;
    // Settings of the sky name it, as --environment sky does.
    if (options.turbidity || options.sun_elevation || options.sun_azimuth) choice.given = true;
    if (options.sun_elevation || options.sun_azimuth) {
        choice.sun_from_scene = false;
        if (options.sun_elevation) choice.sky.sun_elevation_degrees = *options.sun_elevation;
        if (options.sun_azimuth) choice.sky.sun_azimuth_degrees = *options.sun_azimuth;
    }
    if (choice.kind != EnvironmentKind::Sky &&
        (options.turbidity || options.sun_elevation || options.sun_azimuth)) {
        throw UsageError("--turbidity, --sun-elevation and --sun-azimuth need --environment sky");
    }
    return choice;
}

PathSettings chosen_path_settings(const ModeOptions& options, const Scene& scene) {
    PathSettings settings = path_settings_from(options);
    const EnvironmentChoice choice =
        with_scene_environment(environment_choice_from(options), scene);
    try {
        settings.environment = prepare_environment(choice, scene);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    spdlog::info("environment: {}{}; lit by {}", settings.environment->description,
                 choice.given || scene.environment.empty() ? "" : " (the scene's own)",
                 path_lights_text(choice, scene, settings.scene_lights));
    return settings;
}

void add_view_override_options(CLI::App* command, ViewOverrideText& text) {
    const std::string group = "Viewpoint (over the scene's camera; no camera path file needed)";
    command->add_option("--eye", text.eye, "camera position X,Y,Z (default: the camera's)")
        ->group(group);
    command->add_option("--target", text.target, "point looked at X,Y,Z (default: the camera's)")
        ->group(group);
    command->add_option("--up", text.up, "up direction X,Y,Z (default: the camera's)")
        ->group(group);
    command->add_option("--fov", text.fov, "horizontal field of view, degrees in (0, 180)")
        ->group(group);
}

void add_projection_options(CLI::App* command, ProjectionOptions& options) {
    const std::string group = "Projection (panoramas, fisheye, stereo pairs)";
    command
        ->add_option("--projection", options.projection,
                     "pinhole (default), equirectangular (alias panorama: the whole sphere, "
                     "best at 2:1), fisheye (equidistant), stereo-sbs or stereo-tb (a stereo "
                     "pair side by side, left eye left, or top/bottom, left eye on top)")
        ->group(group);
    command
        ->add_option("--stereo", options.stereo,
                     "sbs or tb: a stereo pair, the same as --projection stereo-sbs/stereo-tb")
        ->group(group);
    command
        ->add_option("--fisheye-fov", options.fisheye_fov,
                     "fisheye field of view across the image circle, degrees in (0, 360] "
                     "(default 180)")
        ->group(group);
    command
        ->add_option("--eye-separation", options.eye_separation,
                     "stereo: distance between the eyes, >= 0 (default: 1/30 of the distance "
                     "to the target)")
        ->group(group);
    command
        ->add_option("--convergence", options.convergence,
                     "stereo: distance to the zero-parallax plane, > 0 (default: the distance "
                     "to the target)")
        ->group(group);
}

Projection chosen_projection(const ProjectionOptions& options) {
    Projection projection;
    try {
        if (options.projection && options.stereo) {
            throw std::invalid_argument("give --projection or --stereo, not both");
        }
        if (options.projection) projection.kind = parse_projection_kind(*options.projection);
        if (options.stereo) {
            if (*options.stereo != "sbs" && *options.stereo != "tb") {
                throw std::invalid_argument(
                    fmt::format("unknown --stereo '{}': expected sbs or tb", *options.stereo));
            }
            projection.kind = *options.stereo == "sbs" ? ProjectionKind::StereoSideBySide
                                                       : ProjectionKind::StereoTopBottom;
        }
        if (options.fisheye_fov) projection.fisheye_fov_degrees = *options.fisheye_fov;
        projection.eye_separation = options.eye_separation;
        projection.convergence = options.convergence;
        check_projection(projection);
        if (options.fisheye_fov && projection.kind != ProjectionKind::Fisheye) {
            throw std::invalid_argument("--fisheye-fov needs --projection fisheye");
        }
        if ((options.eye_separation || options.convergence) && !is_stereo(projection.kind)) {
            throw std::invalid_argument(
                "--eye-separation and --convergence need a stereo projection (--stereo sbs|tb)");
        }
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    return projection;
}

ViewOverride parsed_view_override(const ViewOverrideText& text) {
    try {
        return parse_view_override(text);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
}

CameraView overridden_view(const CameraView& base, const ViewOverrideText& text) {
    try {
        return apply_view_override(base, parsed_view_override(text));
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
}

void check_output_directory(const std::filesystem::path& file) {
    const auto directory = file.has_parent_path() ? file.parent_path() : ".";
    if (std::error_code error; !std::filesystem::is_directory(directory, error)) {
        throw UsageError(fmt::format("cannot write {}: directory {} does not exist", quoted(file),
                                     quoted(directory)));
    }
}

void write_output(const std::filesystem::path& file, const std::string& text) {
    try {
        write_text_file_atomically(file, text);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
}

}  // namespace fgr
