// SPDX-License-Identifier: Apache-2.0
#pragma once
// The `fgr` executable's commands, one file each (list.cpp, info.cpp, render.cpp, video.cpp,
// merge.cpp, view.cpp, check.cpp, bench.cpp, bench_accuracy.cpp, new_scene.cpp, cache.cpp), and
// what they share (common.cpp).
// run_cli (cli.cpp) registers each command's options with CLI11 and runs the one given. A command
// returns the exit code, throws UsageError for bad input (exit 2) and anything else for failures
// while running (exit 1).

#include <CLI/CLI.hpp>
#include <exception>
#include <filesystem>
#include <future>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "camera/projection.hpp"
#include "camera/view_override.hpp"
#include "device/opencl_device.hpp"
#include "diagnostics/accuracy.hpp"
#include "diagnostics/bench.hpp"
#include "distributed/cluster.hpp"
#include "distributed/task_farm.hpp"
#include "output/still_image.hpp"
#include "render/environment.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "scene/discovery.hpp"
#include "scene/parameters.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"
#include "viewer/viewer.hpp"

namespace fgr {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;

// A failure while running (not the user's typing): exit code 1.
struct RuntimeFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// --- Shared (common.cpp) -------------------------------------------------------------------------

// The scenes in the plugin search path beside this executable.
Discovery discover();
// The scene a command's scene argument names (scene/scene_argument.hpp): a scene file by path
// (a plugin, an IFS, formula or text scene file), loaded alone, or a scene id, found through the
// scene index in the kernel cache. UsageError, one line, naming the refused file, or the scenes
// there are.
Scene scene_from_argument(const std::string& argument);
// scene_from_argument on a thread of its own (see DeviceOpenedAhead).
std::future<Scene> scene_from_argument_meanwhile(const std::string& argument);
// The scene with that id among those found; throws UsageError naming the scenes there are.
const Scene& find_scene(const Discovery& found, const std::string& id);
// --kernel-source FILE.cl on `command`; with_kernel_source gives the scene with that file's text
// as its source (the scene as it is when `file` is empty).
void add_kernel_source_option(CLI::App* command, std::string& file);
Scene with_kernel_source(Scene scene, const std::string& file);

// Device `index` (-1: the default); throws UsageError for an index `fgr info` does not list.
ComputeDevice open_requested_device(int index);
// For a command that finds its scenes while its device opens: opening the first device loads the
// OpenCL driver (PoCL: LLVM, about a quarter of a small `fgr render`), which finding the scenes
// need not wait for. The device opens on the calling (main) thread, because the thread that first
// loads LLVM gets an alternate signal stack of LLVM's, which AddressSanitizer fails to unmap when
// such a thread ends; the scenes are found on another (scene_from_argument_meanwhile,
// discover_meanwhile). A failure to open
// is kept until take(), so that the command's scene errors come first, as they did when the
// device opened after them.
class DeviceOpenedAhead {
public:
    explicit DeviceOpenedAhead(int index);
    // The device, or throws what open_requested_device threw.
    ComputeDevice take();

private:
    std::optional<ComputeDevice> device_;
    std::exception_ptr failure_;
};
// discover() on a thread of its own.
std::future<Discovery> discover_meanwhile();
// --device and --packet-width, for the commands that render.
void add_device_options(CLI::App* command, int& device, int& packet_width);
// --precision, for the commands that render; `auto_means` ends its help text.
void add_precision_option(CLI::App* command, Precision& precision, const std::string& auto_means);
// --prepass on|off (the cone-marched depth prepass; on by default).
void add_prepass_option(CLI::App* command, bool& prepass);
// --mode and the path tracer's options, shared by render, view and bench.
struct ModeOptions {
    std::optional<std::string> mode;  // default: the scene's (Scene::default_mode)
    // sky, studio, uniform[:RADIANCE] or an .hdr/.exr file; unset: the scene's own, else the sky
    std::optional<std::string> environment;
    float environment_rotation = 0.0f;  // degrees about the up axis
    float environment_intensity = 1.0f;
    std::optional<float> turbidity;
    std::optional<float> sun_elevation;  // degrees above the horizon
    std::optional<float> sun_azimuth;    // degrees
    int bounces = PathSettings{}.max_bounces;
    int roulette_depth = PathSettings{}.roulette_depth;
    float radiance_clamp = 0.0f;
    bool no_light_sampling = false;
    bool no_mis = false;
    bool no_scene_lights = false;
    bool no_regroup = false;
    uint32_t seed = 0;
    bool denoise = false;          // --denoise (render, video; the viewer's toggle starts on)
    float noise_threshold = 0.0f;  // adaptive sampling's relative error; 0: off
    int min_samples = 0;           // adaptive sampling's first round; 0: automatic
};
void add_mode_options(CLI::App* command, ModeOptions& options);
// --denoise, in the path tracer's group (render, video and view).
void add_denoise_option(CLI::App* command, bool& denoise, const std::string& what);
// UsageError unless `mode` is the path tracer's (--denoise filters its noise, and no other mode
// has any) and `samples` per pixel are at least 2 (the noise is measured from two halves).
void check_denoise(RenderMode mode, int samples);
// The mode to render `scene` in: --mode, else the scene's own; UsageError for an unknown name or
// a mode the scene cannot render in (check_mode_supported).
RenderMode chosen_mode(const ModeOptions& options, const Scene& scene);
// The path settings the options ask for, the environment loaded or generated (UsageError for
// bad values, RuntimeFailure for an environment file that cannot be read).
PathSettings chosen_path_settings(const ModeOptions& options, const Scene& scene);
// The same without an environment, and the environment asked for (UsageError for bad values),
// `given` when the options name one (--environment, or the sky's --turbidity or --sun-*).
PathSettings path_settings_from(const ModeOptions& options);
EnvironmentChoice environment_choice_from(const ModeOptions& options);

// --eye, --target, --up and --fov, for the commands that render (render, view, bench).
void add_view_override_options(CLI::App* command, ViewOverrideText& text);
// The options parsed (UsageError naming a malformed one).
ViewOverride parsed_view_override(const ViewOverrideText& text);
// `base` with the options' fields laid over it (UsageError when that view cannot be rendered).
CameraView overridden_view(const CameraView& base, const ViewOverrideText& text);

// --projection, --stereo, --fisheye-fov, --eye-separation, --convergence (render and view).
struct ProjectionOptions {
    std::optional<std::string> projection;  // a name or alias (camera/projection.hpp)
    std::optional<std::string> stereo;      // sbs or tb: the same as --projection stereo-sbs/tb
    std::optional<float> fisheye_fov;       // degrees in (0, 360]
    std::optional<double> eye_separation;   // world units >= 0
    std::optional<double> convergence;      // world units > 0
};
void add_projection_options(CLI::App* command, ProjectionOptions& options);
// The projection the options ask for (UsageError, one line, for a bad name, a value out of range
// or a setting the chosen projection does not use).
Projection chosen_projection(const ProjectionOptions& options);

// Under MPI, rank 0's figures of a distributed command: ranks, the tasks each rendered, and the
// messages and bytes rank 0 exchanged.
void print_mpi_figures(const Cluster& cluster, const FarmOutcome& outcome);

// Throws UsageError unless the directory `file` would be written into exists.
void check_output_directory(const std::filesystem::path& file);
// The scene as a command uses it: with --dev (`dev`), its source read from its recorded .cl file
// (UsageError when it records none); without, as loaded, after a warning when that file changed
// after the plugin was built (scene/scene_source.hpp).
Scene scene_as_used(const Scene& scene, bool dev);

// Writes `text` to `file` atomically; a failure is a RuntimeFailure.
void write_output(const std::filesystem::path& file, const std::string& text);

// --- fgr list, fgr info --------------------------------------------------------------------------

struct ListOptions {
    std::string scene;      // an id or a scene file: that scene in full
    bool formulas = false;  // the formula library instead
    bool ids = false;       // the ids alone, one a line (for scripts and shell completion)
};
void add_list_command(CLI::App& app, ListOptions& options);
// `fgr list`: the scenes found, a line each (id, kind, name and description); one scene in full.
int command_list(const ListOptions& options);
// `fgr list SCENE`, `fgr info SCENE`: the scene an id or scene file names, in full: its file,
// parameters (each described), cameras, camera paths, effects and modes.
int command_list_scene(const std::string& argument);
// With `math_check`, each device's math self-test verdict per precision and packet width.
int command_info(bool math_check);
// `fgr info FILE`: the view an image file carries (image/embedded_view.hpp), printed as indented
// JSON; a RuntimeFailure naming the file when it carries none.
int command_info_file(const std::filesystem::path& file);
// `fgr info ARGUMENT`: a view file, an image (by its name) or a folder is command_info_file's;
// anything else is a scene, command_list_scene's.
int command_info_argument(const std::string& argument);

// --- fgr render ----------------------------------------------------------------------------------

// The long names of the options typed on a command's line (view_options.hpp records them).
struct TypedOptions {
    std::set<std::string> names;
    bool has(std::string_view long_name) const;
};

struct RenderOptions {
    std::string scene;
    std::string output;
    int width = 640;
    int height = 480;
    std::vector<std::string> assignments;
    std::optional<std::string> colour;  // --colour: the scene's colour_mode, by name
    std::optional<std::string> camera;
    std::optional<std::string> camera_path;
    ViewOverrideText view_override;  // --eye, --target, --up, --fov over the camera
    std::optional<float> time;
    int device = -1;
    std::optional<int> samples;  // per pixel, jittered; default 1 (shaded), 64 (path)
    std::string kernel_source;   // OpenCL source instead of the scene's own; empty: its own
    int bit_depth = 8;           // 8: tone-mapped sRGB; 16: linear (PNG only)
    int packet_width = 0;        // 0: the device's preference
    bool all = false;            // every scene's default view into the directory `output`
    bool stats = false;  // print the primary rays' work: steps, DE evaluations, out of steps
    Precision precision = Precision::Auto;
    std::string effect_changes;  // "+shadows,-ambient_occlusion": over the scene's own effects
    ModeOptions mode;
    std::optional<double> time_limit;  // seconds: stop adding samples after this long
    bool no_cost_limit = false;  // render even what the estimate says takes hours (render_cost)
    std::string aovs;            // "albedo,normal,depth,alpha": EXR layers beside the image
    bool alpha = false;  // coverage as alpha: RGBA PNG (straight), EXR A (premultiplied colour)
    bool dev = false;    // read the scene's .cl file from disk, not the plugin's embedded copy
    std::optional<int> tile_size;  // render in tiles of about this side (also implied by size)
    bool resume = false;           // continue an interrupted tiled render from its tile store
    ProjectionOptions projection;
    bool part = false;  // write a part for `fgr merge` (output/parts/render_parts.hpp)
    std::optional<std::string> tile;  // "I/N": the part is rows of tile I of N (implies --part)
    bool prepass = true;  // --prepass on|off: the cone-marched depth prepass (FrameRequest)
    std::optional<std::string> view;       // --view: a view file, or an image carrying its view
    std::optional<std::string> save_view;  // --save-view: write the render's view to this file
    TypedOptions typed;                    // what was typed, over a view's settings
    std::string embedded_view;             // not typed: the view the images carry (view_file_text)
};

void add_render_command(CLI::App& app, RenderOptions& options);
int command_render(const RenderOptions& options);

// What `fgr render` and `fgr video` share, so a video frame is the still of the same options:
// the options that say how a frame is rendered (size, --set, --colour, --spp, --bit-depth, --aov,
// --mode and the path tracer's, --effects, --precision, --kernel-source, --dev, --device);
// (--width and --height up to max_side: a still renders in tiles past kMaxImageSide)
void add_frame_options(CLI::App* command, RenderOptions& options, int max_side = kMaxImageSide);
// their checks that need no scene (UsageError);
void check_frame_options(const RenderOptions& options);
// the request with the scene's defaults, --set and --colour applied (the scene's default view);
FrameRequest scene_request(const Scene& scene, const RenderOptions& options);
// and the settings, samples and path settings render_still gets for `request`.
struct StillJob {
    StillSettings settings;
    FrameRequest request;
    Aovs aovs;
};
StillJob still_job(const Scene& scene, const FrameRequest& request, const RenderOptions& options);
// Refuses (UsageError, one line: the estimate, what is costly, what to change and the override)
// `frames` frames of `job` whose estimated time on `device` (shared by `devices` of them) is over
// the limit, or an IFS scene whose rays would stop unfinished (render/render_cost.hpp), unless
// --no-cost-limit. A render under --time-limit is bounded by it and checked for the second only.
void check_render_cost(const Scene& scene, const StillJob& job, const RenderOptions& options,
                       const DeviceInfo& device, double frames = 1.0, double devices = 1.0);
// A camera path given by name (one of the scene's) or as a JSON file the viewer saved
// (UsageError when there is no such path or the file cannot be read).
CameraPath find_camera_path(const Scene& scene, const std::string& argument);

// --- fgr video -----------------------------------------------------------------------------------

struct VideoOptions {
    // Scene, --camera-path and how each frame renders, as `fgr render` takes them (output, time,
    // camera and view overrides unused).
    RenderOptions frame;
    std::string output;            // .mp4, .mkv, .webm, .gif, .webp, .apng; "" with --frames alone
    std::string frames_directory;  // frame_00000.png ...; "" for none
    std::string frames_format = "png";  // png or exr
    double fps = 30.0;
    std::optional<double> start;     // path time of the first frame (default: first keyframe)
    std::optional<double> duration;  // seconds of path time (default: to the last keyframe)
    std::string codec;               // FFmpeg encoder name; "": the container's default
    std::optional<int> crf;  // constant quality (x264, x265, VP9, AV1); default: the codec's
    std::optional<std::string> frame_range;  // "A:B": render frames A..B only (0-based, inclusive)
};

void add_video_command(CLI::App& app, VideoOptions& options);
int command_video(const VideoOptions& options);

// --- fgr merge -----------------------------------------------------------------------------------

struct MergeOptions {
    std::vector<std::string> parts;  // part files (fgr render --part, --tile)
    std::string output;              // .png, .tif, .exr; or a video file with --frames
    int bit_depth = 8;
    bool alpha = false;
    std::string aovs;
    std::string frames_directory;  // frame_00000.png ... to encode into a video
    double fps = 30.0;
    std::string codec;
    std::optional<int> crf;
};

void add_merge_command(CLI::App& app, MergeOptions& options);
int command_merge(const MergeOptions& options);

// --- fgr view ------------------------------------------------------------------------------------

struct ViewCommandOptions {
    viewer::ViewerOptions viewer;
    ModeOptions mode;
    std::string preset;
    std::string camera_path_file;
    ViewOverrideText view_override;  // the first scene's start view
    std::string replay;
    double exit_after = 0.0;
    ProjectionOptions projection;     // the viewer's starting projection
    std::optional<std::string> view;  // --view: a view file to open (or give it as the scene)
    TypedOptions typed;               // what was typed, over a view's settings
};

void add_view_command(CLI::App& app, ViewCommandOptions& options);
int command_view(ViewCommandOptions& options);

// --- fgr bench, fgr bench accuracy, fgr bench quality, fgr bench compare ------------------------

struct AccuracyOptions {
    std::string scene;
    AccuracySettings settings;
    ModeOptions mode;    // --mode path sweeps the path tracer's noise knobs instead
    std::string output;  // prefix of the .csv, .gp and .png files
};

// fgr bench quality: a time-to-quality CSV summarised (diagnostics/time_to_quality.hpp).
struct QualityOptions {
    std::string measurements;  // the CSV bench/time_to_quality.sh writes
    double threshold = 0.005;  // the 1 - SSIM each configuration must reach
    std::string baseline;      // the configuration speed-ups are measured against; "": the first
    std::string output;        // prefix of the .md, .gp and .png files
};

// fgr bench compare: one image's error against a reference.
struct CompareOptions {
    std::string image;
    std::string reference;
};

struct BenchOptions {
    std::string scene;
    BenchSettings settings;
    int frames = 0;
    std::string output;         // prefix of the .json and .csv files
    std::string kernel_source;  // OpenCL source to time instead of the scene's own; empty: its own
    int device = -1;
    ModeOptions mode;
    ViewOverrideText view_override;  // a still view to bench instead of a camera path
    AccuracyOptions accuracy;
    CLI::App* accuracy_command = nullptr;
    QualityOptions quality;
    CLI::App* quality_command = nullptr;
    CompareOptions compare;
    CLI::App* compare_command = nullptr;
};

// Adds `bench` and its subcommand `accuracy` (bench_accuracy.cpp adds the latter's options).
void add_bench_command(CLI::App& app, BenchOptions& options);
void add_bench_accuracy_command(CLI::App& bench, BenchOptions& options);
int command_bench(BenchOptions& options);
int command_bench_accuracy(const AccuracyOptions& options, int device_index);
// Adds `bench quality` and `bench compare` (bench_quality.cpp).
void add_bench_quality_commands(CLI::App& bench, BenchOptions& options);
int command_bench_quality(const QualityOptions& options);
int command_bench_compare(const CompareOptions& options);
// Runs gnuplot on `script` beside it (so the script's relative names resolve), making `png`, and
// says what was written (`data` and `script`); without gnuplot, says how to get the plot later.
void plot_with_gnuplot(const std::filesystem::path& data, const std::filesystem::path& script,
                       const std::filesystem::path& png);

// --- fgr check -----------------------------------------------------------------------------------

struct CheckOptions {
    std::string scene;  // an id, or a scene file by path
    bool compile_only = false;
    std::optional<std::string> only;       // one check, by name (scene_check_names)
    std::vector<std::string> assignments;  // --set id=value: the values the checks run at
    bool dev = false;
    int device = -1;
    int packet_width = 0;  // 0: the device's preference
};

void add_check_command(CLI::App& app, CheckOptions& options);
// Exit 0 when every check passed (or, with --compile, the kernel compiled), 1 otherwise.
int command_check(const CheckOptions& options);

// --- fgr new-scene -------------------------------------------------------------------------------

struct NewSceneOptions {
    std::string name;
    std::string directory;  // default: ./NAME (--text: .)
    bool text = false;      // one text scene file NAME.cl instead of a plugin project
};

void add_new_scene_command(CLI::App& app, NewSceneOptions& options);
int command_new_scene(const NewSceneOptions& options);

// --- fgr cache size, fgr cache clear -------------------------------------------------------------

struct CacheOptions {
    CLI::App* size = nullptr;
    CLI::App* clear = nullptr;
};

void add_cache_command(CLI::App& app, CacheOptions& options);
int command_cache(const CacheOptions& options);

// --- fgr environment ----------------------------------------------------------------------------

struct EnvironmentOptions {
    std::string kind;    // studio or sky
    std::string output;  // .hdr or .exr
    int width = 1024;    // the map is width x width/2
    float turbidity = SkySettings{}.turbidity;
    float sun_elevation = SkySettings{}.sun_elevation_degrees;
    float sun_azimuth = SkySettings{}.sun_azimuth_degrees;
};
void add_environment_command(CLI::App& app, EnvironmentOptions& options);
int command_environment(const EnvironmentOptions& options);

}  // namespace fgr
