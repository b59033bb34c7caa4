// SPDX-License-Identifier: Apache-2.0
#include "diagnostics/bench.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/utsname.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "camera/camera.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

using nlohmann::json;

// The value after "key" and a separator (':' or '=') on the first line starting with `key` in
// `file`, trimmed; empty when absent.
std::string file_field(const std::string& file, const std::string& key) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind(key, 0) != 0) continue;
        const auto separator = line.find_first_of(":=", key.size());
        if (separator == std::string::npos) continue;
        std::string value = line.substr(separator + 1);
        value.erase(0, value.find_first_not_of(" \t\""));
        value.erase(value.find_last_not_of(" \t\"") + 1);
        return value;
    }
    return {};
}

std::string operating_system() {
    std::string name = file_field("/etc/os-release", "PRETTY_NAME");
    utsname uts{};
    if (uname(&uts) == 0) {
        name += fmt::format("{}{} {} {}", name.empty() ? "" : ", ", uts.sysname, uts.release,
                            uts.machine);
    }
    return name.empty() ? "unknown" : name;
}

json figures_json(const RunFigures& run) {
    return {{"frames", run.frames},
            {"seconds", run.seconds},
            {"min_ms", run.min_ms},
            {"max_ms", run.max_ms},
            {"mean_ms", run.mean_ms},
            {"mean_fps", run.mean_fps},
            {"min_fps", run.min_fps},
            {"max_fps", run.max_fps},
            {"double_frames", run.double_frames},
            {"samples_per_second", run.samples_per_second}};
}

std::string csv_row(const std::string& label, const BenchReport& report, const RunFigures& run) {
    return fmt::format(
        "{},{},{},{},{},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.3f},{:.1f},{},{},{:.1f},{},"
        "{:.0f}\n",
        report.scene, label, report.settings.width, report.settings.height, run.frames, run.seconds,
        run.min_ms, run.max_ms, run.mean_ms, run.mean_fps, run.min_fps, run.max_fps,
        report.build_ms, precision_name(report.settings.precision), run.double_frames,
        report.double_build_ms, render_mode_name(report.settings.render_mode),
        run.samples_per_second);
}

std::string origin_name(BuildReport::Origin origin) {
    switch (origin) {
        case BuildReport::Origin::Compiled:
            return "compiled";
        case BuildReport::Origin::Disk:
            return "disk cache";
        case BuildReport::Origin::Memory:
            break;
    }
    return "memory cache";
}

// What a benchmark builds: its frames all render the scene's defaults, so the parameters the scene
// lets the host compile in are compiled in, as `fgr render` does.
KernelSwitches bench_switches(const Scene& scene, const ComputeDevice& device,
                              const BenchSettings& settings) {
    KernelSwitches switches{
        settings.packet_width ? settings.packet_width : preferred_packet_width(device.info),
        scene.effects, false, false, settings.render_mode};
    switches.specialised = specialisation_for(scene, default_param_values(scene));
    return switches;
}

// A benchmark's float and double renderers, each built when a frame first needs it, and the
// choice between them frame by frame.
struct BenchRenderers {
    BenchRenderers(const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
                   const BenchSettings& settings)
        : renderers(device, cache, scene, bench_switches(scene, device, settings)),
          chooser(device.info, [](const std::string& warning) { spdlog::warn("{}", warning); }) {}

    PrecisionRenderers renderers;
    PrecisionChooser chooser;
};

// Builds the renderer in that precision and records its build in `report`.
Renderer& build_renderer(PrecisionRenderers& renderers, bool double_precision,
                         BenchReport& report) {
    Renderer& renderer = renderers.get(double_precision);
    const BuildReport& build = renderer.build_report();
    (double_precision ? report.double_build_ms : report.build_ms) = build.build_ms;
    (double_precision ? report.double_build_origin : report.build_origin) =
        origin_name(build.origin);
    return renderer;
}

using Clock = std::chrono::steady_clock;

// One run along `path`: its frames, timed, and how many of them rendered in double.
RunFigures bench_run(const CameraPath& path, const Scene& scene, const BenchSettings& settings,
                     BenchRenderers& renderers, BenchReport& report,
                     const std::function<void(double)>& progress) {
    FrameRequest request;
    request.width = settings.width;
    request.height = settings.height;
    request.params = default_param_values(scene);
    request.samples = settings.samples;
    request.path = settings.path_tracing;
    const float start_time = path.keyframes.front().time;
    std::vector<double> frame_ms;
    int double_frames = 0;
    auto start = Clock::now();
    for (;;) {
        const double elapsed = seconds_since(start);
        double fraction = 0.0;
        float time = start_time;
        if (settings.frames) {
            fraction = double(frame_ms.size()) / *settings.frames;
            if (frame_ms.size() >= size_t(*settings.frames)) break;
            // Frames spread evenly over the path, the last one on its end.
            const int last = std::max(1, *settings.frames - 1);
            time += path.duration() * float(frame_ms.size()) / float(last);
        } else {
            fraction = std::min(1.0, elapsed / settings.duration_seconds);
            if (elapsed >= settings.duration_seconds) break;
            // Real time: where the path is now (looping), as an interactive session sees it.
            time += path.duration() > 0.0f ? std::fmod(static_cast<float>(elapsed), path.duration())
                                           : 0.0f;
        }
        progress(fraction);
        request.view = evaluate_camera_path(path, time);
        const auto renderer_in = [&](bool double_precision) -> Renderer& {
            Renderer* renderer = renderers.renderers.built(double_precision);
            if (renderer == nullptr) {
                // The run's clock stops while a kernel builds: builds are reported on their own.
                const auto build_start = Clock::now();
                renderer = &build_renderer(renderers.renderers, double_precision, report);
                start += Clock::now() - build_start;
            }
            return *renderer;
        };
        // The auto rule's DE at the camera comes from the float kernel, as in fgr render and view.
        const bool in_double = renderers.chooser.in_double(
            settings.precision, request.view, settings.width,
            [&] { return surface_distance(renderer_in(false), request.view, request.params); });
        frame_ms.push_back(renderer_in(in_double).render(request).render_ms);
        double_frames += in_double;
        if (settings.on_frame) settings.on_frame(request.view, time, frame_ms.back());
    }
    RunFigures run = summarise_run(frame_ms, seconds_since(start));
    run.double_frames = double_frames;
    run.samples_per_second = run.seconds > 0.0 ? double(run.frames) * settings.samples *
                                                     settings.width * settings.height / run.seconds
                                               : 0.0;
    return run;
}

}  // namespace

RunFigures summarise_run(const std::vector<double>& frame_ms, double seconds) {
    RunFigures run;
    run.frames = static_cast<int>(frame_ms.size());
    run.seconds = seconds;
    if (frame_ms.empty()) return run;
    const auto [low, high] = std::minmax_element(frame_ms.begin(), frame_ms.end());
    run.min_ms = *low;
    run.max_ms = *high;
    run.mean_ms = std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0) / run.frames;
    run.mean_fps = seconds > 0.0 ? run.frames / seconds : 0.0;
    run.min_fps = run.max_ms > 0.0 ? 1000.0 / run.max_ms : 0.0;
    run.max_fps = run.min_ms > 0.0 ? 1000.0 / run.min_ms : 0.0;
    return run;
}

RunFigures average_runs(const std::vector<RunFigures>& runs) {
    RunFigures mean;
    if (runs.empty()) return mean;
    const double n = static_cast<double>(runs.size());
    double frames = 0.0, double_frames = 0.0;
    for (const RunFigures& run : runs) {
        frames += run.frames;
        double_frames += run.double_frames;
        mean.seconds += run.seconds / n;
        mean.min_ms += run.min_ms / n;
        mean.max_ms += run.max_ms / n;
        mean.mean_ms += run.mean_ms / n;
        mean.mean_fps += run.mean_fps / n;
        mean.samples_per_second += run.samples_per_second / n;
        mean.min_fps += run.min_fps / n;
        mean.max_fps += run.max_fps / n;
    }
    mean.frames = static_cast<int>(std::lround(frames / n));
    mean.double_frames = static_cast<int>(std::lround(double_frames / n));
    return mean;
}

const CameraPath& bench_path(const Scene& scene, const std::string& name) {
    std::string names;
    for (const CameraPath& path : scene.camera_paths)
        names += (names.empty() ? "" : ", ") + path.name;
    if (scene.camera_paths.empty()) {
        throw std::invalid_argument(
            fmt::format("scene '{}' has no camera path to benchmark along", scene.id));
    }
    const std::string wanted = name.empty() ? "benchmark" : name;
    if (const CameraPath* path = scene.find_camera_path(wanted)) return *path;
    if (name.empty()) return scene.camera_paths.front();
    throw std::invalid_argument(
        fmt::format("scene '{}' has no camera path '{}' (paths: {})", scene.id, name, names));
}

SystemInfo system_info(const DeviceInfo& device) {
    SystemInfo info;
    info.os = operating_system();
    info.cpu = file_field("/proc/cpuinfo", "model name");
    if (info.cpu.empty()) info.cpu = "unknown";
    info.cpu_threads = static_cast<int>(std::thread::hardware_concurrency());
    const std::string memory = file_field("/proc/meminfo", "MemTotal");  // "24000000 kB"
    info.memory_bytes = memory.empty() ? 0 : std::stoull(memory) * 1024;
    info.device = device;
    return info;
}

BenchReport run_benchmark(const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
                          const BenchSettings& settings, const BenchProgress& progress) {
    if (settings.runs < 1) throw std::invalid_argument("--runs must be at least 1");
    if (settings.frames && *settings.frames < 1) {
        throw std::invalid_argument("--frames must be at least 1");
    }
    if (!settings.frames && !(settings.duration_seconds > 0.0)) {
        throw std::invalid_argument("--duration must be positive");
    }
    const CameraPath& path = bench_path(scene, settings.path);
    BenchReport report;
    report.scene = scene.id;
    report.path = path.name;
    report.path_seconds = path.duration();
    report.settings = settings;
    report.system = system_info(device.info);

    BenchRenderers renderers(scene, device, cache, settings);
    for (int run = 0; run < settings.runs; ++run) {
        report.runs.push_back(bench_run(path, scene, settings, renderers, report, [&](double done) {
            if (progress) progress(run, done);
        }));
        if (progress) progress(run, 1.0);
    }
    report.average = average_runs(report.runs);
    return report;
}

std::string bench_json(const BenchReport& report) {
    const DeviceInfo& device = report.system.device;
    json runs = json::array();
    for (const RunFigures& run : report.runs) runs.push_back(figures_json(run));
    const json document = {
        {"scene", report.scene},
        {"camera_path", report.path},
        {"camera_path_seconds", report.path_seconds},
        {"settings",
         {{"width", report.settings.width},
          {"height", report.settings.height},
          {"mode", report.settings.frames ? "frames" : "duration"},
          {"frames", report.settings.frames ? *report.settings.frames : 0},
          {"duration_seconds", report.settings.frames ? 0.0 : report.settings.duration_seconds},
          {"runs", report.settings.runs},
          {"samples_per_pixel", report.settings.samples},
          {"render_mode", render_mode_name(report.settings.render_mode)},
          {"precision", precision_name(report.settings.precision)}}},
        {"kernel_build_ms", report.build_ms},
        {"kernel_build_origin", report.build_origin},
        {"double_kernel_build_ms", report.double_build_ms},
        {"double_kernel_build_origin", report.double_build_origin},
        {"runs", runs},
        {"average", figures_json(report.average)},
        {"system",
         {{"os", report.system.os},
          {"cpu", report.system.cpu},
          {"cpu_threads", report.system.cpu_threads},
          {"memory_bytes", report.system.memory_bytes},
          {"opencl",
           {{"platform", device.platform},
            {"device", device.name},
            {"version", device.version},
            {"driver_version", device.driver_version},
            {"compute_units", device.compute_units},
            {"global_memory_bytes", device.global_memory_bytes}}}}}};
    return document.dump(2) + "\n";
}

std::string bench_csv(const BenchReport& report) {
    std::string csv =
        "scene,run,width,height,frames,seconds,min_ms,max_ms,mean_ms,mean_fps,min_fps,max_fps,"
        "kernel_build_ms,precision,double_frames,double_kernel_build_ms,render_mode,"
        "samples_per_second\n";
    for (size_t i = 0; i < report.runs.size(); ++i) {
        csv += csv_row(std::to_string(i + 1), report, report.runs[i]);
    }
    csv += csv_row("average", report, report.average);
    return csv;
}

namespace {

// "kernel build 120 ms (compiled), double kernel build 310 ms (disk cache)": the kernels the
// frames needed.
std::string kernel_builds(const BenchReport& report) {
    std::string text;
    if (!report.build_origin.empty()) {
        text = fmt::format("kernel build {:.0f} ms ({})", report.build_ms, report.build_origin);
    }
    if (!report.double_build_origin.empty()) {
        text += fmt::format("{}double kernel build {:.0f} ms ({})", text.empty() ? "" : ", ",
                            report.double_build_ms, report.double_build_origin);
    }
    return text;
}

}  // namespace

std::string bench_table(const BenchReport& report) {
    const SystemInfo& system = report.system;
    std::string table = fmt::format(
        "scene {} along '{}' ({:.1f} s), {}x{}, {} mode, {} spp, precision {}, {}\n"
        "system: {}; {} ({} threads), {:.1f} GiB\n"
        "OpenCL: {} / {} ({}, {} compute units, {} MiB)\n\n",
        report.scene, report.path, report.path_seconds, report.settings.width,
        report.settings.height, render_mode_name(report.settings.render_mode),
        report.settings.samples, precision_name(report.settings.precision), kernel_builds(report),
        system.os, system.cpu, system.cpu_threads, double(system.memory_bytes) / double(1ull << 30),
        system.device.platform, system.device.name, system.device.version,
        system.device.compute_units, system.device.global_memory_bytes >> 20);
    table += fmt::format("{:>8} {:>7} {:>8} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>7} {:>12}\n",
                         "run", "frames", "seconds", "min ms", "mean ms", "max ms", "avg fps",
                         "min fps", "max fps", "double", "samples/s");
    const auto row = [&](const std::string& label, const RunFigures& run) {
        table += fmt::format(
            "{:>8} {:>7} {:>8.2f} {:>9.1f} {:>9.1f} {:>9.1f} {:>8.2f} {:>8.2f} "
            "{:>8.2f} {:>7} {:>12.0f}\n",
            label, run.frames, run.seconds, run.min_ms, run.mean_ms, run.max_ms, run.mean_fps,
            run.min_fps, run.max_fps, run.double_frames, run.samples_per_second);
    };
    for (size_t i = 0; i < report.runs.size(); ++i) row(std::to_string(i + 1), report.runs[i]);
    if (report.runs.size() > 1) row("average", report.average);
    return table;
}

}  // namespace fgr
