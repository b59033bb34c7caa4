// SPDX-License-Identifier: Apache-2.0
#pragma once
// `fgr bench SCENE`: the benchmark protocol. A scene's benchmark camera path is played at a fixed
// resolution, either in real time for a fixed duration (the camera at each frame is where the
// path is at that moment, as in an interactive session) or as a fixed number of frames spread
// evenly over the path. Frame times, frame rates, the kernel build time and the system are
// recorded; several runs are averaged. Results are written as JSON and CSV. Each frame is rendered
// in float or double as `precision` decides for its view (see precision.hpp); the double kernel is
// built the first time a frame needs it, the run's clock stopped meanwhile.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/path_settings.hpp"
#include "render/precision.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"

namespace fgr {

struct BenchSettings {
    int width = 1280;
    int height = 720;
    double duration_seconds = 10.0;  // per run, when frames is not set
    std::optional<int> frames;       // a fixed frame count per run instead
    int runs = 1;
    int samples = 1;       // per pixel
    int packet_width = 0;  // 0: the device's preference
    Precision precision = Precision::Auto;
    RenderMode render_mode = RenderMode::Shaded;
    PathSettings path_tracing;  // render_mode Path: bounces, strategies, environment
    std::string path;  // camera path; empty: "benchmark" if the scene has it, else the first
    // Called after every frame with the view rendered, its time on the camera path (in the
    // keyframes' seconds) and its render time in ms, when set: what was played, for tests.
    std::function<void(const CameraView&, float, double)> on_frame{};
};

struct RunFigures {
    int frames = 0;
    double seconds = 0.0;  // wall time of the run
    double min_ms = 0.0, max_ms = 0.0, mean_ms = 0.0;
    double mean_fps = 0.0;            // frames / seconds
    double min_fps = 0.0;             // 1000 / max_ms
    double max_fps = 0.0;             // 1000 / min_ms
    int double_frames = 0;            // frames rendered in double
    double samples_per_second = 0.0;  // pixel samples (frames x spp x pixels) per second
};

struct SystemInfo {
    std::string os;       // e.g. "Debian GNU/Linux 12 (bookworm), Linux 6.1.0"
    std::string cpu;      // model name
    int cpu_threads = 0;  // logical CPUs
    uint64_t memory_bytes = 0;
    DeviceInfo device;
};

struct BenchReport {
    std::string scene;
    std::string path;
    double path_seconds = 0.0;
    BenchSettings settings;
    double build_ms = 0.0;     // float kernel build (or cache load) and warm-up; 0 if never needed
    std::string build_origin;  // "compiled", "disk cache" or "memory cache"; empty if never built
    double double_build_ms = 0.0;  // the same for the double kernel
    std::string double_build_origin;
    std::vector<RunFigures> runs;
    RunFigures average;  // each figure averaged over the runs
    SystemInfo system;
};

// Summarises one run's frame times (ms) over `seconds` of wall time.
RunFigures summarise_run(const std::vector<double>& frame_ms, double seconds);

// The mean of each figure over `runs` (frame counts rounded to the nearest integer).
RunFigures average_runs(const std::vector<RunFigures>& runs);

// The camera path the protocol plays; throws std::invalid_argument naming the scene's paths
// when there is none or `name` is not one of them.
const CameraPath& bench_path(const Scene& scene, const std::string& name);

SystemInfo system_info(const DeviceInfo& device);

// Called after every frame with (run index from 0, fraction of the run done in [0, 1]).
using BenchProgress = std::function<void(int, double)>;

// Runs the protocol. Throws KernelBuildError, std::invalid_argument (bad path or settings),
// std::runtime_error (precision Double on a device without it).
BenchReport run_benchmark(const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
                          const BenchSettings& settings, const BenchProgress& progress = {});

std::string bench_json(const BenchReport& report);
// A header line, then one line per run and one for the average.
std::string bench_csv(const BenchReport& report);
// The human-readable table `fgr bench` prints.
std::string bench_table(const BenchReport& report);

}  // namespace fgr
