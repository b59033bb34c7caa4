// SPDX-License-Identifier: Apache-2.0
// fgr bench: the benchmark protocol along a camera path (the accuracy sweep, `fgr bench accuracy`,
// is in bench_accuracy.cpp; time to quality, `fgr bench quality` and `fgr bench compare`, in
// bench_quality.cpp).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "cli/progress.hpp"
#include "commands.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"

namespace fgr {
namespace {

// The bench's progress over all its runs on `progress`, with the run and the pace in frames a
// second. It is called before each frame of a run and once at its end: every call but a run's
// first ends a frame.
BenchProgress bench_progress(DelayedProgress& progress, int runs) {
    return [&progress, runs, frames = 0L, current = -1, clock = PaceClock()](int run,
                                                                             double done) mutable {
        if (run == current) ++frames;
        current = run;
        const double seconds = clock.seconds();
        const auto permille = std::lround(1000.0 * (run + std::clamp(done, 0.0, 1.0)) / runs);
        progress.update(permille, 1000, seconds,
                        fmt::format("run {}/{} | {:.1f} fps", run + 1, runs,
                                    seconds > 0.0 ? double(frames) / seconds : 0.0));
    };
}

// The scene with, first among its paths, one that holds the view the options give over its
// default camera (two equal keyframes a second apart): bench plays it like any path. `path_name`
// is set to it.
Scene with_still_path(const Scene& scene, const ViewOverrideText& view_override,
                      std::string& path_name) {
    const CameraView view = overridden_view(scene.cameras.front().view, view_override);
    CameraPath still;
    still.name = "command-line-view";
    still.keyframes = {Keyframe{0.0f, view}, Keyframe{1.0f, view}};
    Scene copy = scene;
    copy.camera_paths.insert(copy.camera_paths.begin(), still);
    path_name = still.name;
    return copy;
}

}  // namespace

void add_bench_command(CLI::App& app, BenchOptions& options) {
    CLI::App* bench = app.add_subcommand(
        "bench", "benchmark protocol: play the scene's benchmark camera path, record frame times");
    bench->add_option("scene", options.scene, "scene id (see `fgr list`) or scene file");
    bench->add_option("--width", options.settings.width, "image width (default 1280)")
        ->check(CLI::Range(1, kMaxImageSide));
    bench->add_option("--height", options.settings.height, "image height (default 720)")
        ->check(CLI::Range(1, kMaxImageSide));
    auto* duration = bench
                         ->add_option("--duration", options.settings.duration_seconds,
                                      "seconds per run, the path played in real time (default 10)")
                         ->check(CLI::Range(0.1, 3600.0));
    bench
        ->add_option("--frames", options.frames,
                     "a fixed number of frames per run, spread evenly over the path (default: "
                     "as many as --duration allows)")
        ->check(CLI::Range(1, 100000))
        ->excludes(duration);
    bench->add_option("--runs", options.settings.runs, "repeat and average (default 1)")
        ->check(CLI::Range(1, 100));
    bench->add_option("--path", options.settings.path,
                      "camera path (default: 'benchmark' if the scene has it, else its first)");
    bench->add_option("--spp", options.settings.samples, "samples per pixel (default 1)")
        ->check(CLI::Range(kMinSamples, kMaxSamples));
    bench->add_option("-o,--output", options.output,
                      "write PREFIX.json and PREFIX.csv (default: bench-SCENE)");
    add_kernel_source_option(bench, options.kernel_source);
    add_view_override_options(bench, options.view_override);
    add_precision_option(bench, options.settings.precision,
                         "for the frames of the path finer than float resolves");
    add_device_options(bench, options.device, options.settings.packet_width);
    add_mode_options(bench, options.mode);
    add_bench_accuracy_command(*bench, options);
    add_bench_quality_commands(*bench, options);
}

int command_bench(BenchOptions& options) {
    if (options.accuracy_command->parsed()) {
        return command_bench_accuracy(options.accuracy, options.device);
    }
    if (options.quality_command->parsed()) return command_bench_quality(options.quality);
    if (options.compare_command->parsed()) return command_bench_compare(options.compare);
    if (options.scene.empty()) throw UsageError("bench needs a SCENE (see `fgr list`)");
    if (!options.view_override.empty() && !options.settings.path.empty()) {
        throw UsageError(
            "--path plays a camera path, --eye, --target, --up and --fov hold a still "
            "view: give one or the other");
    }
    parsed_view_override(options.view_override);  // a malformed vector fails before any loading
    const Scene found_scene = scene_from_argument(options.scene);
    const Scene scene = with_kernel_source(
        options.view_override.empty()
            ? found_scene
            : with_still_path(found_scene, options.view_override, options.settings.path),
        options.kernel_source);
    if (options.frames > 0) options.settings.frames = options.frames;
    try {
        bench_path(scene, options.settings.path);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    options.settings.render_mode = chosen_mode(options.mode, scene);
    if (options.settings.render_mode == RenderMode::Path) {
        options.settings.path_tracing = chosen_path_settings(options.mode, scene);
    }
    const std::string prefix = options.output.empty() ? "bench-" + scene.id : options.output;
    const std::filesystem::path json_file = prefix + ".json", csv_file = prefix + ".csv";
    check_output_directory(json_file);
    const ComputeDevice device = open_requested_device(options.device);
    ProgramCache cache(ProgramCache::default_directory());
    spdlog::info("benchmarking '{}' at {}x{} in {} mode on {}", scene.id, options.settings.width,
                 options.settings.height, render_mode_name(options.settings.render_mode),
                 device.info.name);
    DelayedProgress progress("bench", ProgressShows::Percent);
    const BenchReport report = run_benchmark(scene, device, cache, options.settings,
                                             bench_progress(progress, options.settings.runs));
    progress.finish();
    fmt::print("{}", bench_table(report));
    write_output(json_file, bench_json(report));
    write_output(csv_file, bench_csv(report));
    fmt::print("wrote {} and {}\n", json_file.string(), csv_file.string());
    return 0;
}

}  // namespace fgr
