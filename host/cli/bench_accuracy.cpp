// fgr bench accuracy: the accuracy-for-time knobs swept against a reference render, with a plot.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/renderer.hpp"

namespace fgr {

void add_bench_accuracy_command(CLI::App& bench, BenchOptions& options) {
    CLI::App* accuracy = bench.add_subcommand(
        "accuracy", "sweep the knobs that trade accuracy for time against a reference render");
    options.accuracy_command = accuracy;
    AccuracyOptions& sweep = options.accuracy;
    accuracy->add_option("scene", sweep.scene, "scene id (see `fgr list`)")->required();
    // SSIM's window needs 11x11 pixels.
    accuracy->add_option("--width", sweep.settings.width, "image width (default 320)")
        ->check(CLI::Range(16, 4096));
    accuracy->add_option("--height", sweep.settings.height, "image height (default 240)")
        ->check(CLI::Range(16, 4096));
    accuracy->add_option("--reference-spp", sweep.settings.reference_samples,
                         "samples per pixel of the samples reference, the one the spp points "
                         "are measured against (default 64)")
        ->check(CLI::Range(1, kMaxSamples));
    accuracy->add_option("--repeats", sweep.settings.repeats,
                         "timing rounds over all settings (alternating); each setting's fastest "
                         "render counts (default 5)")
        ->check(CLI::Range(1, 20));
    accuracy->add_option("-o,--output", sweep.output,
                         "write PREFIX.csv, PREFIX.gp and PREFIX.png (default: accuracy-SCENE)");
    // --mode path sweeps samples, bounces, roulette and sampling strategies instead, against a
    // path reference of --reference-spp (at least 256) samples per pixel.
    add_mode_options(accuracy, sweep.mode);
}

int command_bench_accuracy(const AccuracyOptions& options, int device_index) {
    const Discovery found = discover();
    const Scene& scene = find_scene(found, options.scene);
    const std::string prefix = options.output.empty() ? "accuracy-" + scene.id : options.output;
    const std::filesystem::path csv = prefix + ".csv", script = prefix + ".gp", png = prefix + ".png";
    check_output_directory(csv);
    const ComputeDevice device = open_requested_device(device_index);
    ProgramCache cache(ProgramCache::default_directory());
    const auto progress = [](int done, int total, const std::string& what) {
        if (done < total) spdlog::info("[{}/{}] {}", done + 1, total, what);
    };
    const AccuracyReport report =
        chosen_mode(options.mode, scene) == RenderMode::Path
            ? run_path_accuracy_sweep(scene, device, cache, options.settings,
                                      chosen_path_settings(options.mode, scene), progress)
            : run_accuracy_sweep(scene, device, cache, options.settings, progress);
    for (const AccuracyReference& reference : report.references) {
        fmt::print("{} reference ({}): {:.0f} ms\n", reference.name, reference.settings,
                   reference.render_ms);
    }
    // PSNR and the relative depth error are in the CSV; the front column marks the RMSE front
    // (r) and the 1 - SSIM front (s) among the points of one reference.
    fmt::print("{:<15} {:>19} {:>8} {:>9} {:>8} {:>8} {:>8} {:>6} {:>9} {}\n", "knob", "value",
               "ref", "render ms", "steps/px", "rmse", "1-ssim", "hit %", "depth err", "front");
    for (const AccuracyPoint& point : report.points) {
        const std::string front = std::string(point.pareto || point.pareto_ssim ? " " : "") +
                                  (point.pareto ? "r" : "") + (point.pareto_ssim ? "s" : "");
        fmt::print("{:<15} {:>19} {:>8} {:>9.1f} {:>8.2f} {:>8.3f} {:>8.4f} {:>6.2f} {:>9.3g}{}\n",
                   point.knob, point.value, point.reference, point.render_ms,
                   point.steps_per_pixel, point.error.rmse, point.error.one_minus_ssim,
                   point.error.hit_mismatch_percent, point.error.mean_depth_error, front);
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

}  // namespace fgr
