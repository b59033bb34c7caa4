#include "fgr/cli.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <map>
#include <tuple>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "fgr/accuracy.hpp"
#include "fgr/atomic_file.hpp"
#include "fgr/bench.hpp"
#include "fgr/camera.hpp"
#include "fgr/camera_path_file.hpp"
#include "fgr/discovery.hpp"
#include "fgr/image_io.hpp"
#include "fgr/opencl_device.hpp"
#include "fgr/parameters.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/precision.hpp"
#include "fgr/renderer.hpp"
#include "fgr/scaffold.hpp"
#include "fgr/still_image.hpp"
#include "fgr/viewer/viewer.hpp"

namespace fgr {
namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

// A failure while running (not the user's typing): exit code 1.
struct RuntimeFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct RenderOptions {
    std::string scene;
    std::string output;
    int width = 640;
    int height = 480;
    std::vector<std::string> assignments;
    std::optional<std::string> camera;
    std::optional<std::string> camera_path;
    std::optional<float> time;
    int device = -1;
    int samples = 1;       // per pixel, jittered (anti-aliasing, depth of field)
    int bit_depth = 8;     // 8: tone-mapped sRGB; 16: linear
    int packet_width = 0;  // 0: the device's preference
    bool all = false;      // every scene's default view into the directory `output`
    bool stats = false;    // print the primary rays' work: steps, DE evaluations, out of steps
    Precision precision = Precision::Auto;
    std::string effect_changes;  // "+shadows,-ambient_occlusion": over the scene's own effects
};

Discovery discover() { return discover_scenes(plugin_search_path(executable_dir())); }

std::string scene_ids(const std::vector<Scene>& scenes) {
    std::string ids;
    for (const auto& scene : scenes) ids += (ids.empty() ? "" : ", ") + scene.id;
    return ids.empty() ? "none found" : ids;
}

const Scene& find_scene(const Discovery& found, const std::string& id) {
    for (const auto& scene : found.scenes) {
        if (scene.id == id) return scene;
    }
    throw UsageError(fmt::format("unknown scene '{}' (available: {})", id, scene_ids(found.scenes)));
}

std::string range_text(const ParamInfo& param) {
    if (param.type == ParamType::Bool) return "true|false";
    if (!param.choices.empty()) {
        std::string names;
        for (const auto& choice : param.choices) names += (names.empty() ? "" : "|") + choice;
        return names;
    }
    return fmt::format("[{}, {}]", param.min_value, param.max_value);
}

std::string default_text(const ParamInfo& param) {
    const auto& value = param.default_value;
    if (param_components(param.type) == 3) return fmt::format("{},{},{}", value[0], value[1], value[2]);
    if (!param.choices.empty()) {
        return param.choices.at(static_cast<size_t>(value[0] - param.min_value));
    }
    if (param.type == ParamType::Bool) return value[0] != 0.0f ? "true" : "false";
    return fmt::format("{}", value[0]);
}

void print_scene(const Scene& scene) {
    fmt::print("{}  {} - {}\n", scene.id, scene.name, scene.description);
    fmt::print("  plugin: {}\n", scene.plugin_file.string());
    fmt::print("  parameters:\n");
    for (const auto& param : scene.params) {
        fmt::print("    {:<20} {:<7} {:<30} default {:<16} {} ({})\n", param.id,
                   param_type_name(param.type), range_text(param), default_text(param),
                   param.label, param.group);
    }
    std::string cameras;
    for (const auto& camera : scene.cameras) cameras += (cameras.empty() ? "" : ", ") + camera.name;
    fmt::print("  cameras: {} (default: {})\n", cameras, scene.cameras.front().name);
    std::string paths;
    for (const auto& path : scene.camera_paths) {
        paths += fmt::format("{}{} ({}-{} s, {} keyframes)", paths.empty() ? "" : ", ", path.name,
                             path.keyframes.front().time, path.keyframes.back().time,
                             path.keyframes.size());
    }
    fmt::print("  camera paths: {}\n", paths.empty() ? "none" : paths);
    fmt::print("  effects: {}\n", effect_names(scene.effects));
}

int command_list() {
    const Discovery found = discover();
    if (found.scenes.empty()) {
        fmt::print("no scenes found; searched:\n");
        for (const auto& dir : plugin_search_path(executable_dir())) fmt::print("  {}\n", dir.string());
        return 0;
    }
    for (size_t i = 0; i < found.scenes.size(); ++i) {
        if (i > 0) fmt::print("\n");
        print_scene(found.scenes[i]);
    }
    return 0;
}

int command_info() {
    const auto devices = list_devices();
    if (devices.empty()) {
        throw RuntimeFailure("no OpenCL device found (install an OpenCL driver, e.g. pocl-opencl-icd)");
    }
    for (const auto& device : devices) {
        fmt::print("device {}: {}\n", device.index, device.name);
        fmt::print("  platform:       {}\n", device.platform);
        fmt::print("  type:           {}\n", device.is_gpu ? "GPU" : device.is_cpu ? "CPU" : "other");
        fmt::print("  version:        {} (driver {}, {})\n", device.version, device.driver_version,
                   device.opencl_c_version);
        fmt::print("  compute units:  {}\n", device.compute_units);
        fmt::print("  global memory:  {} MiB\n", device.global_memory_bytes >> 20);
        fmt::print("  double:         {}\n", device.has_fp64 ? "yes (cl_khr_fp64)" : "no");
        fmt::print("  packet width:   {} rays per work-item\n", preferred_packet_width(device));
    }
    return 0;
}

// A camera path given by name (one of the scene's) or as a JSON file the viewer saved.
CameraPath find_camera_path(const Scene& scene, const std::string& argument) {
    if (looks_like_camera_path_file(argument)) {
        CameraPathFile file;
        try {
            file = read_camera_path_file(argument);
        } catch (const std::runtime_error& error) {
            throw UsageError(error.what());
        }
        if (!file.scene.empty() && file.scene != scene.id) {
            spdlog::warn("camera path '{}' was recorded in scene '{}', rendering it in '{}'",
                         argument, file.scene, scene.id);
        }
        return file.path;
    }
    const CameraPath* path = scene.find_camera_path(argument);
    if (!path) {
        throw UsageError(fmt::format("scene '{}' has no camera path '{}' (see `fgr list`)",
                                     scene.id, argument));
    }
    return *path;
}

CameraView choose_view(const Scene& scene, const RenderOptions& options) {
    if (options.camera_path) {
        const CameraPath path = find_camera_path(scene, *options.camera_path);
        const float first = path.keyframes.front().time, last = path.keyframes.back().time;
        if (!(*options.time >= first && *options.time <= last)) {
            throw UsageError(fmt::format("--time {} is outside camera path '{}' [{}, {}]",
                                         *options.time, path.name, first, last));
        }
        return evaluate_camera_path(path, *options.time);
    }
    if (options.camera) {
        const NamedCamera* camera = scene.find_camera(*options.camera);
        if (!camera) {
            throw UsageError(fmt::format("scene '{}' has no camera '{}' (see `fgr list`)", scene.id,
                                         *options.camera));
        }
        return camera->view;
    }
    return scene.cameras.front().view;
}

void check_output_path(const std::filesystem::path& output) {
    std::string extension = output.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png") {
        throw UsageError(fmt::format("output '{}' must be a .png file", output.string()));
    }
    const auto directory = output.has_parent_path() ? output.parent_path() : ".";
    std::error_code error;
    if (!std::filesystem::is_directory(directory, error)) {
        throw RuntimeFailure(fmt::format("cannot write '{}': directory '{}' does not exist",
                                         output.string(), directory.string()));
    }
}

// Checks that do not need a scene: option combinations and the output location.
void check_render_options(const RenderOptions& options) {
    try {
        apply_effect_changes(0, options.effect_changes);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    if (options.all) {
        if (!options.scene.empty()) throw UsageError("give a SCENE or --all, not both");
        if (!options.assignments.empty() || options.camera || options.camera_path || options.time) {
            throw UsageError("--all renders each scene's default view: no --set, --camera or --time");
        }
        return;
    }
    if (options.scene.empty()) throw UsageError("render needs a SCENE (see `fgr list`) or --all");
    if (options.time && !options.camera_path) throw UsageError("--time needs --camera-path");
    if (options.camera_path && !options.time) throw UsageError("--camera-path needs --time");
    check_output_path(options.output);
}

ComputeDevice open_requested_device(const RenderOptions& options) {
    if (options.device >= static_cast<int>(list_devices().size())) {
        throw UsageError(fmt::format("no OpenCL device {} (see `fgr info`)", options.device));
    }
    return open_device(options.device);
}

// Renders `request` (render_still: the kernel, float or double), writes the PNG, prints the
// figures.
void render_to_file(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                    ProgramCache& cache, const RenderOptions& options,
                    const std::filesystem::path& output) {
    StillSettings settings;
    settings.packet_width = options.packet_width;
    settings.effects = apply_effect_changes(scene.effects, options.effect_changes);
    settings.stats = options.stats;
    settings.precision = options.precision;
    FrameRequest reported = request;
    if (request.samples >= 8) {
        // Long multi-sample renders say how far they are, about every tenth of the way.
        reported.on_sample = [step = std::max(1, request.samples / 10)](int done, int total) {
            if (done % step == 0 || done == total) spdlog::info("sample {}/{}", done, total);
        };
    }
    const Frame frame = render_still(scene, reported, device, cache, settings);
    fmt::print("render_ms {:.1f}\n", frame.render_ms);
    fmt::print("hits {}\n", frame.hits);
    if (frame.stats) {
        const MarchStats& stats = *frame.stats;
        fmt::print("steps_per_pixel {:.2f} (max {})\n", stats.mean_steps, stats.max_steps);
        fmt::print("de_evaluations {} ({:.2f} per pixel: primary march and normals)\n",
                   stats.de_evaluations, double(stats.de_evaluations) / double(stats.pixels));
        fmt::print("out_of_steps {:.3f}% ({} of {} pixels)\n", stats.out_of_steps_percent(),
                   stats.out_of_steps, stats.pixels);
    }
    try {
        write_still(output, frame, options.bit_depth,
                    param_value(scene, request.params, "exposure"));
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    fmt::print("wrote {} ({}x{})\n", output.string(), frame.image.width, frame.image.height);
}

FrameRequest default_request(const Scene& scene, const RenderOptions& options) {
    FrameRequest request;
    request.width = options.width;
    request.height = options.height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    request.samples = options.samples;
    return request;
}

int render_all(const RenderOptions& options) {
    const std::filesystem::path directory = options.output;
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error || !std::filesystem::is_directory(directory)) {
        throw RuntimeFailure(fmt::format("cannot create directory '{}'", directory.string()));
    }
    const Discovery found = discover();
    if (found.scenes.empty()) throw RuntimeFailure("no scenes found (see `fgr list`)");
    const ComputeDevice device = open_requested_device(options);
    ProgramCache cache(ProgramCache::default_directory());
    for (size_t i = 0; i < found.scenes.size(); ++i) {
        const Scene& scene = found.scenes[i];
        fmt::print("scene {} ({}/{})\n", scene.id, i + 1, found.scenes.size());
        render_to_file(scene, default_request(scene, options), device, cache, options,
                       directory / (scene.id + ".png"));
    }
    return 0;
}

int command_render(const RenderOptions& options) {
    check_render_options(options);
    if (options.all) return render_all(options);
    const Discovery found = discover();
    const Scene& scene = find_scene(found, options.scene);
    FrameRequest request = default_request(scene, options);
    for (const auto& assignment : options.assignments) {
        set_param_from_text(scene, request.params, assignment);
    }
    request.view = choose_view(scene, options);
    const ComputeDevice device = open_requested_device(options);
    ProgramCache cache(ProgramCache::default_directory());
    render_to_file(scene, request, device, cache, options, options.output);
    return 0;
}

// --device and --packet-width, shared by the commands that render.
void add_device_options(CLI::App* command, int& device, int& packet_width) {
    command->add_option("--device", device, "OpenCL device index (see `fgr info`)")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--packet-width", packet_width,
                        "rays per work-item (default: 16 on CPUs, 1 on GPUs)")
        ->check(CLI::IsMember({1, 4, 8, 16}));
}

// --precision, shared by the commands that render.
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

void add_render_command(CLI::App& app, RenderOptions& options) {
    CLI::App* render = app.add_subcommand(
        "render", "render one image of a scene to a PNG file, or every scene's default view");
    render->add_option("scene", options.scene, "scene id (see `fgr list`)");
    render->add_flag("--all", options.all, "render every scene's default view into the directory -o");
    render->add_option("-o,--output", options.output, "output PNG file (a directory with --all)")
        ->required();
    render->add_option("--width", options.width, "image width in pixels")
        ->check(CLI::Range(1, kMaxImageSide));
    render->add_option("--height", options.height, "image height in pixels")
        ->check(CLI::Range(1, kMaxImageSide));
    render->add_option("--set", options.assignments, "set a parameter: id=value (repeatable)")
        ->allow_extra_args(false);
    auto* camera = render->add_option("--camera", options.camera, "named camera of the scene");
    auto* path = render->add_option("--camera-path", options.camera_path,
                                    "camera path of the scene, or a .json file saved by `fgr view`");
    path->excludes(camera);
    render->add_option("--time", options.time, "time along the camera path, in seconds");
    render->add_option("--spp", options.samples,
                       "samples per pixel, jittered and averaged: anti-aliasing, depth of field")
        ->check(CLI::Range(1, kMaxSamples));
    render->add_option("--bit-depth", options.bit_depth,
                       "8: tone-mapped sRGB PNG (default); 16: linear 16-bit PNG (exposure only)")
        ->check(CLI::IsMember({8, 16}));
    render->add_option("--effects", options.effect_changes,
                       "change the scene's effects, e.g. +shadows,-ambient_occlusion");
    add_precision_option(render, options.precision,
                         "when a pixel is finer than float resolves (deep zooms)");
    render->add_flag("--stats", options.stats,
                     "print steps per pixel, DE evaluations and rays that ran out of steps");
    add_device_options(render, options.device, options.packet_width);
}

// Window sizes offered by --preset and in the viewer's panel.
const std::map<std::string, std::pair<int, int>>& window_presets() {
    static const std::map<std::string, std::pair<int, int>> presets = {
        {"1366x768", {1366, 768}},
        {"1920x1080", {1920, 1080}},
        {"2560x1440", {2560, 1440}},
        {"3840x2160", {3840, 2160}}};
    return presets;
}

struct ViewCommandOptions {
    viewer::ViewerOptions viewer;
    std::string preset;
    std::string camera_path_file;
    std::string replay;
    double exit_after = 0.0;
};

void add_view_command(CLI::App& app, ViewCommandOptions& options) {
    CLI::App* view = app.add_subcommand(
        "view", "open the interactive viewer (press H in it for the key bindings)");
    viewer::ViewerOptions& viewer = options.viewer;
    view->add_option("scene", viewer.scene, "scene to open first (default: mandelbulb)");
    view->add_option("--width", viewer.width, "window width in pixels (default 1280)")
        ->check(CLI::Range(64, kMaxImageSide));
    view->add_option("--height", viewer.height, "window height in pixels (default 720)")
        ->check(CLI::Range(64, kMaxImageSide));
    std::vector<std::string> names;
    for (const auto& [name, size] : window_presets()) names.push_back(name);
    view->add_option("--preset", options.preset, "window size preset")
        ->check(CLI::IsMember(names));
    view->add_flag("--fullscreen", viewer.fullscreen, "start fullscreen (F11 toggles)");
    view->add_option("--target-ms", viewer.target_ms,
                     "frame time to hold while moving, in ms (default 33)")
        ->check(CLI::Range(5.0, 1000.0));
    view->add_option("--samples", viewer.sample_cap,
                     "samples per pixel accumulated when still and for screenshots (default 16)")
        ->check(CLI::Range(1, 1024));
    view->add_option("--set", viewer.assignments, "set a parameter of the first scene: id=value")
        ->allow_extra_args(false);
    view->add_option("--effects", viewer.effect_changes,
                     "change the first scene's effects, e.g. +shadows,-ambient_occlusion");
    view->add_option("--camera-path", options.camera_path_file,
                     "a .json camera path saved by the viewer, to play with P");
    view->add_option("--output-dir", viewer.output_dir,
                     "where F12 screenshots and saved camera paths go (default: .)");
    view->add_option("--replay", options.replay, "feed timed input events from a file");
    view->add_option("--exit-after", options.exit_after, "quit after this many seconds")
        ->check(CLI::PositiveNumber);
    view->add_flag("--dev", viewer.dev,
                   "scene development: reload a scene when its .cl source file is saved");
    view->add_flag("--stats", viewer.print_stats,
                   "print frame-time statistics and the final camera on exit");
    add_precision_option(view, viewer.precision,
                         "while the view is finer than float resolves (flying in deep), per frame");
    add_device_options(view, viewer.device, viewer.packet_width);
}

int command_view(ViewCommandOptions& options) {
    viewer::ViewerOptions& viewer = options.viewer;
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
    if (!options.replay.empty()) viewer.replay = options.replay;
    if (options.exit_after > 0.0) viewer.exit_after_seconds = options.exit_after;
    std::error_code error;
    if (!std::filesystem::is_directory(viewer.output_dir, error)) {
        throw UsageError(fmt::format("--output-dir '{}' is not a directory",
                                     viewer.output_dir.string()));
    }
    return viewer::run_viewer(viewer);
}

struct AccuracyOptions {
    std::string scene;
    AccuracySettings settings;
    std::string output;  // prefix of the .csv, .gp and .png files
};

struct BenchOptions {
    std::string scene;
    BenchSettings settings;
    int frames = 0;
    std::string output;  // prefix of the .json and .csv files
    int device = -1;
    AccuracyOptions accuracy;
    CLI::App* accuracy_command = nullptr;
};

void add_bench_command(CLI::App& app, BenchOptions& options) {
    CLI::App* bench = app.add_subcommand(
        "bench", "benchmark protocol: play the scene's benchmark camera path, record frame times");
    bench->add_option("scene", options.scene, "scene id (see `fgr list`)");
    bench->add_option("--width", options.settings.width, "image width (default 1280)")
        ->check(CLI::Range(1, kMaxImageSide));
    bench->add_option("--height", options.settings.height, "image height (default 720)")
        ->check(CLI::Range(1, kMaxImageSide));
    auto* duration = bench->add_option("--duration", options.settings.duration_seconds,
                                       "seconds per run, the path played in real time (default 10)")
                         ->check(CLI::Range(0.1, 3600.0));
    bench->add_option("--frames", options.frames,
                      "a fixed number of frames per run, spread evenly over the path")
        ->check(CLI::Range(1, 100000))
        ->excludes(duration);
    bench->add_option("--runs", options.settings.runs, "repeat and average (default 1)")
        ->check(CLI::Range(1, 100));
    bench->add_option("--path", options.settings.path,
                      "camera path (default: 'benchmark' if the scene has it, else its first)");
    bench->add_option("--spp", options.settings.samples, "samples per pixel (default 1)")
        ->check(CLI::Range(1, kMaxSamples));
    bench->add_option("-o,--output", options.output,
                      "write PREFIX.json and PREFIX.csv (default: bench-SCENE)");
    add_precision_option(bench, options.settings.precision,
                         "for the frames of the path finer than float resolves");
    add_device_options(bench, options.device, options.settings.packet_width);

    CLI::App* accuracy = bench->add_subcommand(
        "accuracy", "sweep the knobs that trade accuracy for time against a reference render");
    options.accuracy_command = accuracy;
    AccuracyOptions& sweep = options.accuracy;
    accuracy->add_option("scene", sweep.scene, "scene id (see `fgr list`)")->required();
    accuracy->add_option("--width", sweep.settings.width, "image width (default 320)")
        ->check(CLI::Range(8, 4096));
    accuracy->add_option("--height", sweep.settings.height, "image height (default 240)")
        ->check(CLI::Range(8, 4096));
    accuracy->add_option("--reference-spp", sweep.settings.reference_samples,
                         "samples per pixel of the reference (default 16)")
        ->check(CLI::Range(1, kMaxSamples));
    accuracy->add_option("--repeats", sweep.settings.repeats,
                         "timing rounds over all settings (alternating); each setting's fastest "
                         "render counts (default 5)")
        ->check(CLI::Range(1, 20));
    accuracy->add_option("-o,--output", sweep.output,
                         "write PREFIX.csv, PREFIX.gp and PREFIX.png (default: accuracy-SCENE)");
}

// Writes `text` to `file` atomically; a failure is a runtime failure.
void write_output(const std::filesystem::path& file, const std::string& text) {
    try {
        write_text_file_atomically(file, text);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
}

void check_output_directory(const std::filesystem::path& file) {
    const auto directory = file.has_parent_path() ? file.parent_path() : ".";
    if (std::error_code error; !std::filesystem::is_directory(directory, error)) {
        throw UsageError(fmt::format("cannot write '{}': directory '{}' does not exist",
                                     file.string(), directory.string()));
    }
}

int command_bench_accuracy(const AccuracyOptions& options, int device_index) {
    const Discovery found = discover();
    const Scene& scene = find_scene(found, options.scene);
    const std::string prefix = options.output.empty() ? "accuracy-" + scene.id : options.output;
    const std::filesystem::path csv = prefix + ".csv", script = prefix + ".gp", png = prefix + ".png";
    check_output_directory(csv);
    RenderOptions device_choice;
    device_choice.device = device_index;
    const ComputeDevice device = open_requested_device(device_choice);
    ProgramCache cache(ProgramCache::default_directory());
    const AccuracyReport report = run_accuracy_sweep(
        scene, device, cache, options.settings, [](int done, int total, const std::string& what) {
            if (done < total) spdlog::info("[{}/{}] {}", done + 1, total, what);
        });
    fmt::print("reference ({}): {:.0f} ms\n", report.reference_settings, report.reference_ms);
    fmt::print("{:<15} {:>8} {:>10} {:>9} {:>8} {:>8} {:>10} {:>12} {}\n", "knob", "value",
               "render ms", "steps/px", "rmse", "psnr dB", "hit diff %", "depth error", "pareto");
    for (const AccuracyPoint& point : report.points) {
        fmt::print("{:<15} {:>8} {:>10.1f} {:>9.2f} {:>8.3f} {:>8.2f} {:>10.3f} {:>12.3g} {}\n",
                   point.knob, point.value, point.render_ms, point.steps_per_pixel,
                   point.error.rmse, point.error.psnr, point.error.hit_mismatch_percent,
                   point.error.mean_depth_error, point.pareto ? "*" : "");
    }
    write_output(csv, accuracy_csv(report));
    write_output(script, accuracy_gnuplot(report, scene.id, csv.filename().string(),
                                          png.filename().string()));
    fmt::print("wrote {} and {}\n", csv.string(), script.string());
    // gnuplot runs beside the files, so the script's relative names resolve.
    const std::string directory = csv.has_parent_path() ? csv.parent_path().string() : ".";
    const std::string command = fmt::format("cd '{}' && gnuplot '{}' 2>&1", directory,
                                            script.filename().string());
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        spdlog::warn("gnuplot not found: no plot (apt-get install gnuplot-nox, then gnuplot {})",
                     script.string());
        return 0;
    }
    if (std::system(command.c_str()) != 0 || !std::filesystem::exists(png)) {
        throw RuntimeFailure(fmt::format("gnuplot failed on {}", script.string()));
    }
    fmt::print("wrote {}\n", png.string());
    return 0;
}

// A bar on a terminal, a line every quarter otherwise (logs, CI).
BenchProgress bench_progress(int runs) {
    const bool terminal = isatty(fileno(stderr)) != 0;
    return [terminal, runs, last_quarter = -1, last_run = -1](int run, double done) mutable {
        if (terminal) {
            const int filled = static_cast<int>(done * 30.0);
            std::fprintf(stderr, "\rrun %d/%d [%s%s] %3.0f%%", run + 1, runs,
                         std::string(static_cast<size_t>(filled), '#').c_str(),
                         std::string(static_cast<size_t>(30 - filled), '.').c_str(), done * 100.0);
            if (done >= 1.0) std::fputc('\n', stderr);
            return;
        }
        const int quarter = static_cast<int>(done * 4.0);
        if (run != last_run || quarter != last_quarter) {
            spdlog::info("run {}/{}: {:.0f}%", run + 1, runs, quarter * 25.0);
            last_run = run;
            last_quarter = quarter;
        }
    };
}

int command_bench(BenchOptions& options) {
    if (options.accuracy_command->parsed()) {
        return command_bench_accuracy(options.accuracy, options.device);
    }
    if (options.scene.empty()) throw UsageError("bench needs a SCENE (see `fgr list`)");
    const Discovery found = discover();
    const Scene& scene = find_scene(found, options.scene);
    if (options.frames > 0) options.settings.frames = options.frames;
    try {
        bench_path(scene, options.settings.path);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    const std::string prefix = options.output.empty() ? "bench-" + scene.id : options.output;
    const std::filesystem::path json_file = prefix + ".json", csv_file = prefix + ".csv";
    check_output_directory(json_file);
    RenderOptions device_choice;
    device_choice.device = options.device;
    const ComputeDevice device = open_requested_device(device_choice);
    ProgramCache cache(ProgramCache::default_directory());
    spdlog::info("benchmarking '{}' at {}x{} on {}", scene.id, options.settings.width,
                 options.settings.height, device.info.name);
    const BenchReport report = run_benchmark(scene, device, cache, options.settings,
                                             bench_progress(options.settings.runs));
    fmt::print("{}", bench_table(report));
    write_output(json_file, bench_json(report));
    write_output(csv_file, bench_csv(report));
    fmt::print("wrote {} and {}\n", json_file.string(), csv_file.string());
    return 0;
}

struct NewSceneOptions {
    std::string name;
    std::string directory;  // default: ./NAME
};

void add_new_scene_command(CLI::App& app, NewSceneOptions& options) {
    CLI::App* command = app.add_subcommand(
        "new-scene", "create a scene plugin project from the SDK template, ready to build");
    command->add_option("name", options.name, "scene id, e.g. my-kifs")->required();
    command->add_option("--dir", options.directory, "project directory (default: ./NAME)");
}

int command_new_scene(const NewSceneOptions& options) {
    const std::filesystem::path directory =
        std::filesystem::path(options.directory.empty() ? options.name : options.directory);
    const std::filesystem::path prefix = executable_dir().parent_path();
    const std::vector<std::filesystem::path> files = scaffold_scene(options.name, directory, prefix);
    fmt::print("created scene '{}' in {}:\n", options.name, directory.string());
    for (const auto& file : files) fmt::print("  {}\n", file.string());
    const std::string dir = directory.string();
    fmt::print("next:\n"
               "  cmake -S {0} -B {0}/build && cmake --build {0}/build\n"
               "  mkdir -p ~/.local/share/fgr/plugins && cp {0}/build/{1}.so "
               "~/.local/share/fgr/plugins/\n"
               "  fgr render {1} -o {1}.png\n",
               dir, options.name);
    return 0;
}

void configure_logging(bool verbose) {
    auto logger = spdlog::stderr_color_mt("fgr");
    logger->set_pattern("fgr: %^%l%$: %v");
    spdlog::set_default_logger(logger);
    spdlog::set_level(verbose ? spdlog::level::debug : spdlog::level::info);
}

int report_error(const std::string& message, int code) {
    // Errors are one line: keep only the first line of messages that carry more.
    std::fprintf(stderr, "fgr: error: %s\n", message.substr(0, message.find('\n')).c_str());
    return code;
}

}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"fgr: real-time ray marching of 3D fractals"};
    app.require_subcommand(1);
    bool verbose = false;
    app.add_flag("-v,--verbose", verbose, "debug logging");
    app.add_subcommand("list", "list the scenes found, with parameters, cameras and camera paths");
    app.add_subcommand("info", "list OpenCL platforms and devices");
    RenderOptions render_options;
    add_render_command(app, render_options);
    ViewCommandOptions view_options;
    add_view_command(app, view_options);
    NewSceneOptions new_scene_options;
    add_new_scene_command(app, new_scene_options);
    BenchOptions bench_options;
    add_bench_command(app, bench_options);
    if (argc < 2) {
        std::fputs(app.help().c_str(), stdout);
        return report_error("no command given (commands: list, info, render, view, new-scene, bench)", kExitUsage);
    }
    if (const std::string first = argv[1]; !first.empty() && first.front() != '-' &&
        first != "list" && first != "info" && first != "render" && first != "view" &&
        first != "new-scene" && first != "bench") {
        return report_error(
            fmt::format(
                "unknown command '{}' (commands: list, info, render, view, new-scene, bench)",
                first),
                            kExitUsage);
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        return report_error(error.what(), kExitUsage);
    }
    configure_logging(verbose);
    try {
        const std::string command = app.get_subcommands().front()->get_name();
        if (command == "list") return command_list();
        if (command == "info") return command_info();
        if (command == "view") return command_view(view_options);
        if (command == "new-scene") return command_new_scene(new_scene_options);
        if (command == "bench") return command_bench(bench_options);
        return command_render(render_options);
    } catch (const UsageError& error) {
        return report_error(error.what(), kExitUsage);
    } catch (const KernelBuildError& error) {
        std::fprintf(stderr, "%s\n", error.build_log().c_str());
        return report_error(error.what(), kExitFailure);
    } catch (const std::exception& error) {
        return report_error(error.what(), kExitFailure);
    }
}

}  // namespace fgr
