// SPDX-License-Identifier: Apache-2.0
// fgr render: one image of a scene to a PNG file, or every scene's default view (--all).
#include <fmt/format.h>
#include <fnmatch.h>  // POSIX: the shell's wildcards for --all's scene pattern
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "camera/camera_path_file.hpp"
#include "camera/view_validation.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "device/kernel_assembly.hpp"
#include "device/program_cache.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_farm.hpp"
#include "distributed/seed_split.hpp"
#include "output/denoised_frame.hpp"
#include "output/still_image.hpp"
#include "output/tiled/streaming_image.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/adaptive_sampling.hpp"
#include "render/render_cost.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"
#include "scene/ifs/ifs.hpp"
#include "tiled_render.hpp"
#include "util/interruption.hpp"
#include "util/strings.hpp"
#include "util/suggest.hpp"
#include "util/timing.hpp"
#include "view_options.hpp"

namespace fgr {

CameraPath find_camera_path(const Scene& scene, const std::string& argument) {
    if (looks_like_camera_path_file(argument)) {
        CameraPathFile file;
        try {
            file = read_camera_path_file(argument);
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
        if (!file.scene.empty() && file.scene != scene.id) {
            spdlog::warn("camera path {} was recorded in scene '{}', rendering it in '{}'",
                         quoted(std::filesystem::path(argument)), printable_text(file.scene),
                         scene.id);
        }
        return file.path;
    }
    const CameraPath* path = scene.find_camera_path(argument);
    if (!path) {
        std::vector<std::string> names;
        for (const CameraPath& known : scene.camera_paths) names.push_back(known.name);
        throw UsageError(unknown_name_message(
            fmt::format("scene '{}' has no camera path '{}'", scene.id, argument), argument, names,
            fmt::format(" (`fgr list {}` lists its camera paths)", scene.id)));
    }
    return *path;
}

namespace {

CameraView choose_view(const Scene& scene, const RenderOptions& options) {
    if (options.camera_path) {
        const CameraPath path = find_camera_path(scene, *options.camera_path);
        const float first = path.keyframes.front().time, last = path.keyframes.back().time;
        if (!(*options.time >= first && *options.time <= last)) {
            throw UsageError(fmt::format("--time {} is outside camera path '{}' [{}, {}]",
                                         *options.time, path.name, first, last));
        }
        const CameraView view = evaluate_camera_path(path, *options.time);
        // Every keyframe was checked, but an interpolated moment can still be degenerate (a path
        // whose camera passes through its target).
        if (const std::string problem = computed_view_problem(view); !problem.empty()) {
            throw UsageError(fmt::format("camera path '{}' at time {}: {}", *options.camera_path,
                                         *options.time, problem));
        }
        return view;
    }
    if (options.camera) {
        const NamedCamera* camera = scene.find_camera(*options.camera);
        if (!camera) {
            std::vector<std::string> names;
            for (const NamedCamera& known : scene.cameras) names.push_back(known.name);
            throw UsageError(unknown_name_message(
                fmt::format("scene '{}' has no camera '{}'", scene.id, *options.camera),
                *options.camera, names,
                fmt::format(" (`fgr list {}` lists its cameras)", scene.id)));
        }
        return overridden_view(camera->view, options.view_override);
    }
    return overridden_view(scene.cameras.front().view, options.view_override);
}

void check_output_path(const std::filesystem::path& output) {
    try {
        image_format_of(output);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    const auto directory = output.has_parent_path() ? output.parent_path() : ".";
    std::error_code error;
    if (!std::filesystem::is_directory(directory, error)) {
        throw RuntimeFailure(fmt::format("cannot write {}: directory {} does not exist",
                                         quoted(output), quoted(directory)));
    }
}

// Checks that do not need a scene: option combinations and the output location.
void check_render_options(const RenderOptions& options) {
    chosen_projection(options.projection);  // bad values fail before anything is loaded
    if (options.all) {
        if (!Cluster::current().alone()) {
            throw UsageError("--all renders the scenes one after another: run it without mpirun");
        }
        try {
            apply_effect_changes(0, options.effect_changes);
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
        if (options.dev) throw UsageError("--dev is for one scene: give a SCENE, not --all");
        if (!options.assignments.empty() || options.colour || options.camera ||
            options.camera_path || options.time || !options.view_override.empty()) {
            throw UsageError(
                "--all renders each scene's default view: no --set, --colour, "
                "--camera, --eye... or --time");
        }
        if (!options.kernel_source.empty())
            throw UsageError("--kernel-source is for one SCENE, not --all");
        if (part_render_wanted(options)) {
            throw UsageError("--part and --tile are for one SCENE, not --all");
        }
        if (options.mode.denoise) throw UsageError("--denoise is for one SCENE, not --all");
        return;
    }
    if (options.scene.empty()) throw UsageError("render needs a SCENE (see `fgr list`) or --all");
    check_frame_options(options);
    if (options.time && !options.camera_path) throw UsageError("--time needs --camera-path");
    if (options.camera_path && !options.time) throw UsageError("--camera-path needs --time");
    if (options.camera_path && !options.view_override.empty()) {
        throw UsageError(
            "--eye, --target, --up and --fov set a still view: not with --camera-path "
            "(they change --camera, or the scene's default camera)");
    }
    parsed_view_override(options.view_override);  // a malformed vector fails before any loading
    check_output_path(options.output);
    if (options.mode.noise_threshold > 0.0f &&
        (part_render_wanted(options) || tiled_render_wanted(options))) {
        throw UsageError(
            "--noise-threshold decides each pixel's samples from the whole image's rounds: not "
            "with --part, --tile or a tiled render (give --spp)");
    }
    if (part_render_wanted(options)) {
        check_part_options(options);
    }
    const bool exr = image_format_of(options.output) == ImageFormat::Exr;
    if (!options.aovs.empty() && !exr) throw UsageError("--aov needs an .exr output");
    if (exr && options.bit_depth != 8) throw UsageError("--bit-depth is for PNG and TIFF output");
    if (!part_render_wanted(options) && tiled_render_wanted(options)) check_tiled_options(options);
    if (options.mode.denoise && (part_render_wanted(options) || tiled_render_wanted(options))) {
        throw UsageError(
            "--denoise filters the whole image at once: not with a tiled render (--tile-size, "
            "over 16 Mpx), --part or --tile (denoise the merged image's EXR instead)");
    }
    const Aovs aovs = parse_aovs(options.aovs);
    if ((aovs.samples || aovs.variance) &&
        (part_render_wanted(options) || tiled_render_wanted(options))) {
        throw UsageError(
            "--aov samples and variance are written by a render of the whole image in one "
            "process: not with --part, --tile or a tiled render");
    }
}

FrameRequest default_request(const Scene& scene, const RenderOptions& options) {
    FrameRequest request;
    request.width = options.width;
    request.height = options.height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    request.projection = chosen_projection(options.projection);
    request.prepass.enabled = options.prepass;
    return request;
}

}  // namespace

void check_frame_options(const RenderOptions& options) {
    chosen_projection(options.projection);
    try {
        apply_effect_changes(0, options.effect_changes);
        parse_aovs(options.aovs);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    if (options.dev && !options.kernel_source.empty()) {
        throw UsageError("--dev reads the scene's own .cl file, --kernel-source another: give one");
    }
}

FrameRequest scene_request(const Scene& scene, const RenderOptions& options) {
    FrameRequest request = default_request(scene, options);
    for (const auto& assignment : options.assignments) {
        set_param_from_text(scene, request.params, assignment);
    }
    if (options.colour) {
        if (scene.find_param("colour_mode") == nullptr) {
            throw UsageError(fmt::format(
                "scene '{}' has no colour modes (no colour_mode parameter; see `fgr list {}`)",
                scene.id, scene.id));
        }
        set_param_from_text(scene, request.params, "colour_mode=" + *options.colour);
    }
    return request;
}

StillJob still_job(const Scene& scene, const FrameRequest& request, const RenderOptions& options) {
    StillSettings settings;
    settings.packet_width = options.packet_width;
    settings.effects = apply_effect_changes(scene.effects, options.effect_changes);
    settings.stats = options.stats;
    settings.precision = options.precision;
    settings.mode = chosen_mode(options.mode, scene);
    const Aovs aovs = parse_aovs(options.aovs);
    if ((aovs.samples || aovs.variance) && settings.mode != RenderMode::Path) {
        throw UsageError(fmt::format(
            "--aov samples and variance are the path mode's (the {} mode estimates no variance)",
            render_mode_name(settings.mode)));
    }
    // Every mode renders every layer; the kernel writes alpha and layers only when asked.
    settings.aovs = options.alpha || aovs.need_aov_planes();
    if (settings.mode == RenderMode::Brute) {
        if (const uint64_t ignored = settings.effects & ~kBruteModeEffects) {
            spdlog::info("the brute mode shades in screen space and ignores {}",
                         effect_names(ignored));
        }
    }
    FrameRequest reported = request;
    try {
        reported.samples = still_samples(settings.mode, options.samples);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    if (settings.mode == RenderMode::Path) {
        reported.path = chosen_path_settings(options.mode, scene);
        if (reported.path.radiance_clamp > 0.0f) {
            spdlog::warn(
                "radiance clamped to {:g} per sample: fireflies go, and so does some "
                "energy (the image is biased)",
                reported.path.radiance_clamp);
        }
    }
    return StillJob{settings, reported, aovs};
}

void check_render_cost(const Scene& scene, const StillJob& job, const RenderOptions& options,
                       const DeviceInfo& device, double frames, double devices) {
    if (options.no_cost_limit) return;
    const RenderCost cost = estimate_render_cost(scene, job.request, job.settings.mode);
    const double limit = options.time_limit ? INFINITY : kCostLimitSeconds;
    const std::string refusal =
        cost_refusal(cost, frames, estimated_pace(device) * std::max(devices, 1.0), limit,
                     "pass --no-cost-limit to render it anyway");
    if (!refusal.empty()) throw UsageError(refusal);
}

namespace {

// Prints the figures of a rendered still and writes it to `output`; `samples_asked` per pixel, of
// which the frame holds those the time limit left time for.
void report_and_write(const Scene& scene, const FrameRequest& request, int samples_asked,
                      const RenderOptions& options, const Aovs& aovs, const Frame& frame,
                      const std::filesystem::path& output) {
    fmt::print("render_ms {:.1f}\n", frame.render_ms);
    fmt::print("hits {}\n", frame.hits);
    fmt::print("samples_per_pixel {}\n", frame.samples);
    if (frame.adaptive) {
        spdlog::info("{}", adaptive_summary(*frame.adaptive));
        fmt::print("adaptive_converged_share {:.4f}\n", frame.adaptive->share_converged);
        fmt::print("adaptive_mean_error {:.5f}\n", frame.adaptive->mean_error);
        fmt::print("adaptive_error_p95 {:.5f}\n", frame.adaptive->error_p95);
        fmt::print("adaptive_spp_min_mean_max {:g} {:.2f} {:g}\n", frame.adaptive->min_spp,
                   frame.adaptive->mean_spp, frame.adaptive->max_spp);
        fmt::print("adaptive_samples_saved {:.4f}\n", frame.adaptive->saved());
    }
    if (options.time_limit && frame.samples < samples_asked && !frame.adaptive) {
        spdlog::info("--time-limit {:g} s reached after {} of {} samples per pixel",
                     *options.time_limit, frame.samples, samples_asked);
    }
    const double mean_samples = frame.adaptive ? frame.adaptive->mean_spp : double(frame.samples);
    fmt::print("samples_per_second {:.0f}\n", mean_samples * request.width * request.height /
                                                  std::max(frame.render_ms / 1000.0, 1e-9));
    if (frame.lane_stats) {
        fmt::print("lane_utilisation {:.3f} ({} rays per work-item)\n",
                   frame.lane_stats->utilisation(), frame.lane_stats->packet_width);
    }
    if (frame.inside_tests_per_pixel) {
        fmt::print("inside_tests_per_pixel {:.1f} ({:.1f} per pass)\n",
                   *frame.inside_tests_per_pixel,
                   *frame.inside_tests_per_pixel / std::max(frame.samples, 1));
    }
    if (frame.ifs_levels) {
        fmt::print("ifs_depth_reached {} (mean {:.2f} over the hits; the slider allows {})\n",
                   frame.ifs_levels->deepest, frame.ifs_levels->mean,
                   static_cast<int>(param_value(scene, request.params, "ifs_depth")));
    }
    if (frame.stats && scene.ifs) {
        // IFS scenes trace nodes, not march steps.
        const MarchStats& stats = *frame.stats;
        fmt::print("ifs_nodes_per_ray {:.2f} (max {})\n", stats.mean_steps, stats.max_steps);
        fmt::print("ifs_heap_peak {} of {} (rays traced depth first after a full heap: {})\n",
                   stats.heap_peak, kIfsHeapCapacity, stats.heap_overflows);
        fmt::print("secondary_nodes {} ({:.2f} per pixel: shadow and reflection rays)\n",
                   stats.secondary_de_evaluations,
                   double(stats.secondary_de_evaluations) / double(stats.pixels));
    } else if (frame.stats) {
        const MarchStats& stats = *frame.stats;
        fmt::print("steps_per_pixel {:.2f} (max {})\n", stats.mean_steps, stats.max_steps);
        fmt::print(
            "de_evaluations {} ({:.2f} per pixel: cone prepass, primary march and "
            "normals)\n",
            stats.de_evaluations, double(stats.de_evaluations) / double(stats.pixels));
        fmt::print("prepass_de_evaluations {} ({:.3f} per pixel)\n", stats.prepass_de_evaluations,
                   double(stats.prepass_de_evaluations) / double(stats.pixels));
        if (stats.packet_steps > 0) {
            fmt::print(
                "primary_lane_utilisation {:.1f}% ({} lane steps in {} packet steps of {} "
                "lanes)\n",
                100.0 * double(stats.lane_steps) /
                    (double(stats.packet_steps) * stats.packet_width),
                stats.lane_steps, stats.packet_steps, stats.packet_width);
        }
        if (stats.secondary_packet_steps > 0) {
            fmt::print("secondary_lane_utilisation {:.1f}% ({} lane steps in {} packet steps)\n",
                       100.0 * double(stats.secondary_de_evaluations) /
                           (double(stats.secondary_packet_steps) * stats.packet_width),
                       stats.secondary_de_evaluations, stats.secondary_packet_steps);
        }
        fmt::print("out_of_steps {:.3f}% ({} of {} pixels)\n", stats.out_of_steps_percent(),
                   stats.out_of_steps, stats.pixels);
        fmt::print(
            "secondary_de_evaluations {} ({:.2f} per pixel: shadow, reflection and "
            "refraction rays)\n",
            stats.secondary_de_evaluations,
            double(stats.secondary_de_evaluations) / double(stats.pixels));
    }
    try {
        write_still(output, frame,
                    StillOutput{options.bit_depth, display_transform(scene, request.params),
                                options.alpha, aovs, options.embedded_view});
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    fmt::print("wrote {} ({}x{})\n", printable_path(output), frame.image.width, frame.image.height);
}

// A still's Renderer progress, drawn on `progress` with the rate in pixel samples a second.
std::function<void(long, long)> still_progress(DelayedProgress& progress,
                                               const FrameRequest& request) {
    const double pixel_samples = double(request.width) * request.height * request.samples;
    return [&progress, pixel_samples, start = std::chrono::steady_clock::time_point{}](
               long done, long total) mutable {
        // From the first launch: the kernel's build is no part of the render's pace.
        if (done == 0) start = std::chrono::steady_clock::now();
        const double seconds = seconds_since(start);
        const double rate =
            seconds > 0.0 ? pixel_samples * double(done) / double(total) / seconds : 0.0;
        progress.update(done, total, seconds, format_rate(rate) + "samples/s");
    };
}

// `request` rendered as render_still renders it, in two halves of its samples for the variance
// the denoiser needs (render_with_variance), then denoised (denoise_frame; its time is part of
// render_ms and printed as denoise_ms).
Frame render_denoised(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                      ProgramCache& cache, const StillSettings& settings) {
    check_denoise(settings.mode, request.samples);
    PrecisionRenderers renderers(device, cache, scene, still_switches(device, settings));
    Frame frame = render_with_variance(request, [&](const FrameRequest& half) {
        Frame rendered =
            choose_still_renderer(renderers, scene, half, device, settings).render(half);
        check_finite_frame(scene, rendered);
        return rendered;
    });
    const auto started = std::chrono::steady_clock::now();
    denoise_frame(frame, display_transform(scene, request.params), DenoiseSettings{});
    const double denoise_ms = elapsed_ms(started);
    frame.render_ms += denoise_ms;
    fmt::print("denoise_ms {:.1f} ({})\n", denoise_ms,
               denoise_method_name(DenoiseSettings{}.method));
    return frame;
}

// Renders `request` (render_still: the kernel, float or double), writes the file, prints the
// figures; a render of more than a moment shows its progress on stderr.
void render_to_file(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                    ProgramCache& cache, const RenderOptions& options,
                    const std::filesystem::path& output) {
    StillJob job = still_job(scene, request, options);
    FrameRequest& reported = job.request;
    if (options.time_limit) reported.enough = deadline_after(*options.time_limit);
    DelayedProgress progress("render", ProgressShows::Percent);
    reported.on_progress = still_progress(progress, reported);
    Frame frame;
    try {
        frame = options.mode.denoise ? render_denoised(scene, reported, device, cache, job.settings)
                                     : render_still(scene, reported, device, cache, job.settings);
    } catch (...) {
        progress.finish();
        throw;
    }
    progress.finish();
    report_and_write(scene, reported, reported.samples, options, job.aovs, frame, output);
}

// A still whose samples differ with the seed, under MPI: shared out by seed, a task a rank
// (distributed/seed_split.hpp).
int render_samples_across_ranks(Cluster& cluster, const Scene& scene, const FrameRequest& request,
                                const ComputeDevice& device, ProgramCache& cache,
                                const RenderOptions& options) {
    const StillJob job = still_job(scene, request, options);
    const SeedSplit split = split_by_seed(job.request, job.settings.mode, cluster.size());
    const auto render = [&](FrameRequest part) {
        if (options.time_limit) part.enough = deadline_after(*options.time_limit);
        return render_still(scene, part, device, cache, job.settings);
    };
    FarmFrameDispatch dispatch(cluster);
    const auto started = std::chrono::steady_clock::now();
    std::optional<Frame> merged = render_by_seed(split, job.request, render, dispatch);
    if (!merged) return 0;
    merged->render_ms = elapsed_ms(started);
    merged->image = display_image(scene, request.params, merged->linear, merged->image.width,
                                  merged->image.height);
    fmt::print("seeds {} to {} (one a rank)\n", split.first_seed, split.last_seed());
    report_and_write(scene, job.request, split.samples(), options, job.aovs, *merged,
                     options.output);
    print_mpi_figures(cluster, dispatch.outcome());
    return 0;
}

// `fgr render` under mpirun: stills whose samples differ with the seed (path-traced ones) by seed,
// everything else in tiles.
int render_across_ranks(Cluster& cluster, const Scene& scene, const FrameRequest& request,
                        const ComputeDevice& device, ProgramCache& cache,
                        const RenderOptions& options) {
    if (const Aovs aovs = parse_aovs(options.aovs); aovs.samples || aovs.variance) {
        throw UsageError(
            "--aov samples and variance are for renders of one process: under mpirun the ranks' "
            "sums carry neither");
    }
    if (options.mode.noise_threshold > 0.0f) {
        throw UsageError(
            "--noise-threshold decides each pixel's samples from its own rounds: under mpirun the "
            "ranks sum fixed samples with their own seeds (give --spp)");
    }
    if (sample_budget(chosen_mode(options.mode, scene)).seeded && !tiled_render_wanted(options)) {
        if (options.stats)
            throw UsageError("--stats is for renders of one process (without mpirun)");
        return render_samples_across_ranks(cluster, scene, request, device, cache, options);
    }
    if (options.stats || options.time_limit) {
        throw UsageError(
            "under mpirun a shaded or brute-force still is shared out in tiles: no "
            "--stats or --time-limit (those are for one process, or --mode path)");
    }
    return render_tiled(scene, request, device, cache, options);
}

// The scenes whose ids match PATTERN, a shell wildcard ('mandel*', 'quaternion-?ulia'); every
// scene when it is empty.
std::vector<Scene> scenes_matching(const Discovery& found, const std::string& pattern) {
    if (found.scenes.empty()) throw RuntimeFailure("no scenes found (see `fgr list`)");
    std::vector<Scene> matching;
    for (const Scene& scene : found.scenes) {
        if (pattern.empty() || fnmatch(pattern.c_str(), scene.id.c_str(), 0) == 0) {
            matching.push_back(scene);
        }
    }
    if (matching.empty()) {
        throw UsageError(fmt::format("no scene id matches '{}' (see `fgr list`)", pattern));
    }
    return matching;
}

// `code`, after writing the view to --save-view's file when the render succeeded (on the rank
// that writes files).
int saved_view_after(int code, const RenderOptions& options, const ViewFile& view,
                     bool writes_files = true) {
    if (code == 0 && writes_files) save_view_if_asked(options, view);
    return code;
}

void check_save_view_option(const RenderOptions& options) {
    if (!options.save_view) return;
    if (options.all) throw UsageError("--save-view is for one scene, not --all");
    if (!is_view_file_name(*options.save_view)) {
        throw UsageError(fmt::format("--save-view {}: a view file's name ends in {}",
                                     *options.save_view, kViewFileSuffix));
    }
    check_output_directory(*options.save_view);
}

int render_all(const RenderOptions& options) {
    std::future<Discovery> finding = discover_meanwhile();
    DeviceOpenedAhead device_opening(options.device);
    const std::vector<Scene> scenes = scenes_matching(finding.get(), options.scene);
    const std::filesystem::path directory = options.output;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory)) {
        throw RuntimeFailure(fmt::format("cannot create directory {}", quoted(directory)));
    }
    const ComputeDevice device = device_opening.take();
    ProgramCache cache(ProgramCache::default_directory());
    for (size_t i = 0; i < scenes.size(); ++i) {
        const Scene scene = scene_as_used(scenes[i], false);
        fmt::print("scene {} ({}/{})\n", scene.id, i + 1, scenes.size());
        const FrameRequest request = default_request(scene, options);
        RenderOptions scene_options = options;
        scene_options.embedded_view = view_file_text(view_of_render(scene, request, options));
        render_to_file(scene, request, device, cache, scene_options,
                       directory / (scene.id + ".png"));
    }
    return 0;
}

}  // namespace

void add_frame_options(CLI::App* command, RenderOptions& options, int max_side) {
    const std::string tiled =
        max_side > kMaxImageSide ? " (over 16384 a side or 16 Mpx in all: rendered in tiles)" : "";
    // A view file's size stands in for the defaults (view_options.hpp).
    command
        ->add_option("--width", options.width,
                     fmt::format("image width in pixels{} (default: {}, or the view's with --view)",
                                 tiled, RenderOptions{}.width))
        ->check(CLI::Range(1, max_side));
    command
        ->add_option("--height", options.height,
                     fmt::format("image height in pixels (default: {}, or the view's with --view)",
                                 RenderOptions{}.height))
        ->check(CLI::Range(1, max_side));
    command->add_option("--set", options.assignments, "set a parameter: id=value (repeatable)")
        ->allow_extra_args(false);
    command->add_option("--colour", options.colour,
                        "colour mode: point, planes, axes or iterations, those the scene offers "
                        "(see `fgr list SCENE`); the same as --set colour_mode=MODE");
    command
        ->add_option("--spp", options.samples,
                     fmt::format("samples per pixel, jittered and averaged: anti-aliasing, depth "
                                 "of field, and the path tracer's estimate (default {}; {} with "
                                 "--mode path); with --mode brute, {} of sampling along each "
                                 "ray (default {})",
                                 sample_budget(RenderMode::Shaded).still,
                                 sample_budget(RenderMode::Path).still,
                                 sample_budget(RenderMode::Brute).unit,
                                 sample_budget(RenderMode::Brute).still))
        ->check(CLI::Range(kMinSamples, kMaxSamples));
    command
        ->add_option("--bit-depth", options.bit_depth,
                     "8: tone-mapped sRGB PNG (default); 16: linear 16-bit PNG (exposure only)")
        ->check(CLI::IsMember({8, 16}));
    command->add_option("--aov", options.aovs,
                        "EXR layers beside the linear image, in every mode: albedo,normal,depth,"
                        "alpha (alpha: as --alpha); in path mode also samples (per pixel) and "
                        "variance (of each pixel's estimate)");
    command->add_flag("--alpha", options.alpha,
                      "coverage as alpha with the background removed: an RGBA PNG (straight "
                      "alpha), or an EXR's A channel (colour premultiplied)");
    add_mode_options(command, options.mode);
    add_denoise_option(command, options.mode.denoise,
                       "denoise the path-traced image, guided by its albedo, normal and depth "
                       "(--mode path; the samples are rendered in two halves to measure the "
                       "noise); an EXR keeps the raw image as the layer raw.R/G/B");
    add_prepass_option(command, options.prepass);
    command->add_option("--effects", options.effect_changes,
                        "change the scene's effects, e.g. +shadows,-ambient_occlusion");
    add_precision_option(command, options.precision,
                         "when a pixel is finer than float resolves (deep zooms)");
    add_kernel_source_option(command, options.kernel_source);
    command->add_flag("--dev", options.dev,
                      "read the scene's .cl file from disk instead of the copy its plugin embeds "
                      "(as `fgr view --dev`): try an edit without rebuilding the plugin");
    add_device_options(command, options.device, options.packet_width);
    add_projection_options(command, options.projection);
    command->add_flag("--no-cost-limit", options.no_cost_limit,
                      "render even when the estimate says it takes over an hour, or that an IFS "
                      "scene's rays would stop unfinished (refused otherwise, saying what to "
                      "change)");
}

void add_render_command(CLI::App& app, RenderOptions& options) {
    CLI::App* render = app.add_subcommand(
        "render",
        "render one image of a scene to a PNG, EXR or TIFF file, or every scene's default view");
    render->add_option("scene", options.scene,
                       "scene id (see `fgr list`), scene file (.so, .ifs.json, .formula.json, "
                       ".cl) or view file (.fgrview.json); with --all, a wildcard pattern of ids "
                       "(e.g. 'mandel*')");
    render->add_flag("--all", options.all,
                     "render every scene's default view (or those the scene pattern matches) into "
                     "the directory -o");
    render
        ->add_option(
            "-o,--output", options.output,
            "output .png or .tif (tone-mapped) or .exr (linear) file; a directory with --all")
        ->required();
    render
        ->add_option("--tile-size", options.tile_size,
                     "render in tiles of about this many pixels a side, streaming the file a "
                     "band of rows at a time (default for images over 16 Mpx: 512)")
        ->check(CLI::Range(16, 8192));
    render->add_flag("--resume", options.resume,
                     "continue an interrupted tiled render from the tiles it finished (kept in "
                     "OUTPUT.fgr-tiles)");
    auto* camera = render->add_option("--camera", options.camera, "named camera of the scene");
    auto* path =
        render->add_option("--camera-path", options.camera_path,
                           "camera path of the scene, or a .json file saved by `fgr view`");
    path->excludes(camera);
    render->add_option("--time", options.time, "time along the camera path, in seconds");
    add_view_override_options(render, options.view_override);
    render->add_flag("--part", options.part,
                     "write a part for `fgr merge`: an .exr of the raw planes, recording the "
                     "render, its rows, samples and --seed (render parts on many machines, merge "
                     "them into one image)");
    render->add_option("--tile", options.tile,
                       "I/N: render rows floor((I-1)*H/N) .. floor(I*H/N)-1 of the image as a part "
                       "(implies --part); `fgr merge` joins the N tiles");
    render
        ->add_option("--time-limit", options.time_limit,
                     "stop adding samples after this many seconds and write what is done")
        ->check(CLI::PositiveNumber);
    render->add_flag("--stats", options.stats,
                     "print steps per pixel, DE evaluations and rays that ran out of steps");
    add_frame_options(render, options, kMaxTiledImageSide);
    add_view_file_options(render, options);
    record_typed_options(render, options.typed);
}

int command_render(const RenderOptions& typed_options) {
    // A signal removes the temporary of any file being written (tiled renders and parts stop
    // cleanly between tiles instead).
    install_interrupt_handlers();
    RenderOptions options = typed_options;
    std::optional<ViewFile> view;
    if (const std::optional<std::string> argument = view_argument(options)) {
        if (options.all) throw UsageError("--view is for one scene, not --all");
        view = load_view_argument(*argument);
        apply_view(options, *view);
    }
    check_save_view_option(options);
    check_render_options(options);
    if (options.all) return render_all(options);
    std::future<Scene> finding = scene_from_argument_meanwhile(options.scene);
    DeviceOpenedAhead device_opening(options.device);
    const Scene scene =
        with_kernel_source(scene_as_used(finding.get(), options.dev), options.kernel_source);
    if (view) warn_if_scene_changed(*view, scene);
    FrameRequest request = scene_request(scene, options);
    request.view = choose_view(scene, options);
    if (options.mode.denoise) {
        const RenderMode mode = chosen_mode(options.mode, scene);
        check_denoise(mode, still_samples(mode, options.samples));
    }
    const ViewFile rendered_view = view_of_render(scene, request, options);
    options.embedded_view = view_file_text(rendered_view);
    const ComputeDevice device = device_opening.take();
    if (!part_render_wanted(options)) {  // a part checks its own rows (render_part_file)
        check_render_cost(scene, still_job(scene, request, options), options, device.info, 1.0,
                          static_cast<double>(Cluster::current().size()));
    }
    ProgramCache cache(ProgramCache::default_directory());
    if (part_render_wanted(options)) {
        if (!Cluster::current().alone()) {
            throw UsageError(
                "--part and --tile make one part a process, for a scheduler: run "
                "them without mpirun");
        }
        return saved_view_after(render_part_file(scene, request, device, cache, options), options,
                                rendered_view);
    }
    if (Cluster& cluster = Cluster::current(); !cluster.alone()) {
        if (options.mode.denoise) {
            throw UsageError("--denoise is for renders of one process (without mpirun)");
        }
        return saved_view_after(
            render_across_ranks(cluster, scene, request, device, cache, options), options,
            rendered_view, cluster.coordinator());
    }
    if (tiled_render_wanted(options)) {
        return saved_view_after(render_tiled(scene, request, device, cache, options), options,
                                rendered_view);
    }
    render_to_file(scene, request, device, cache, options, options.output);
    return saved_view_after(0, options, rendered_view);
}

}  // namespace fgr
