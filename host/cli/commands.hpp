#pragma once
// The `fgr` executable's commands, one file each (list.cpp, info.cpp, render.cpp, view.cpp,
// bench.cpp, bench_accuracy.cpp, new_scene.cpp, cache.cpp), and what they share (common.cpp).
// run_cli (cli.cpp) registers each command's options with CLI11 and runs the one given. A command
// returns the exit code, throws UsageError for bad input (exit 2) and anything else for failures
// while running (exit 1).

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fgr/accuracy.hpp"
#include "fgr/bench.hpp"
#include "fgr/discovery.hpp"
#include "fgr/opencl_device.hpp"
#include "fgr/parameters.hpp"
#include "fgr/precision.hpp"
#include "fgr/scene.hpp"
#include "fgr/viewer/viewer.hpp"

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
// The scene with that id; throws UsageError naming the scenes there are.
const Scene& find_scene(const Discovery& found, const std::string& id);
// Device `index` (-1: the default); throws UsageError for an index `fgr info` does not list.
ComputeDevice open_requested_device(int index);
// --device and --packet-width, for the commands that render.
void add_device_options(CLI::App* command, int& device, int& packet_width);
// --precision, for the commands that render; `auto_means` ends its help text.
void add_precision_option(CLI::App* command, Precision& precision, const std::string& auto_means);
// Throws UsageError unless the directory `file` would be written into exists.
void check_output_directory(const std::filesystem::path& file);
// Writes `text` to `file` atomically; a failure is a RuntimeFailure.
void write_output(const std::filesystem::path& file, const std::string& text);

// --- fgr list, fgr info --------------------------------------------------------------------------

int command_list();
// With `math_check`, each device's math self-test verdict per precision and packet width.
int command_info(bool math_check);

// --- fgr render ----------------------------------------------------------------------------------

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

void add_render_command(CLI::App& app, RenderOptions& options);
int command_render(const RenderOptions& options);

// --- fgr view ------------------------------------------------------------------------------------

struct ViewCommandOptions {
    viewer::ViewerOptions viewer;
    std::string preset;
    std::string camera_path_file;
    std::string replay;
    double exit_after = 0.0;
};

void add_view_command(CLI::App& app, ViewCommandOptions& options);
int command_view(ViewCommandOptions& options);

// --- fgr bench, fgr bench accuracy ---------------------------------------------------------------

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

// Adds `bench` and its subcommand `accuracy` (bench_accuracy.cpp adds the latter's options).
void add_bench_command(CLI::App& app, BenchOptions& options);
void add_bench_accuracy_command(CLI::App& bench, BenchOptions& options);
int command_bench(BenchOptions& options);
int command_bench_accuracy(const AccuracyOptions& options, int device_index);

// --- fgr new-scene -------------------------------------------------------------------------------

struct NewSceneOptions {
    std::string name;
    std::string directory;  // default: ./NAME
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

}  // namespace fgr
