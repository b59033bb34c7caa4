// SPDX-License-Identifier: Apache-2.0
// fgr bench accuracy: the accuracy-for-time knobs swept against a reference render, with a plot.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli/progress.hpp"
#include "commands.hpp"
#include "device/program_cache.hpp"
#include "diagnostics/brute_accuracy.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"

namespace fgr {

void add_bench_accuracy_command(CLI::App& bench, BenchOptions& options) {
    CLI::App* accuracy = bench.add_subcommand(
        "accuracy", "sweep the knobs that trade accuracy for time against a reference render");
    options.accuracy_command = accuracy;
    AccuracyOptions& sweep = options.accuracy;
    accuracy->add_option("scene", sweep.scene, "scene id (see `fgr list`) or scene file")
        ->required();
    // SSIM's window needs 11x11 pixels.
    accuracy->add_option("--width", sweep.settings.width, "image width (default 320)")
        ->check(CLI::Range(16, 4096));
    accuracy->add_option("--height", sweep.settings.height, "image height (default 240)")
        ->check(CLI::Range(16, 4096));
    accuracy
        ->add_option("--reference-spp", sweep.settings.reference_samples,
                     "samples per pixel of the samples reference, the one the spp points "
                     "are measured against (default 64)")
        ->check(CLI::Range(kMinSamples, kMaxSamples));
    accuracy
        ->add_option("--repeats", sweep.settings.repeats,
                     "timing rounds over all settings (alternating); each setting's fastest "
                     "render counts (default 5)")
        ->check(CLI::Range(1, 20));
    accuracy->add_option("-o,--output", sweep.output,
                         "write PREFIX.csv, PREFIX.gp and PREFIX.png (default: accuracy-SCENE)");
    // --mode path sweeps samples, bounces, roulette and sampling strategies instead, against a
    // path reference of --reference-spp (at least 256) samples per pixel; --mode brute the
    // brute-force passes, against the sphere tracer's depth (or 1024 passes without a DE).
    add_mode_options(accuracy, sweep.mode);
}

void plot_with_gnuplot(const std::filesystem::path& csv, const std::filesystem::path& script,
                       const std::filesystem::path& png) {
    fmt::print("wrote {} and {}\n", csv.string(), script.string());
    const std::string directory = csv.has_parent_path() ? csv.parent_path().string() : ".";
    const std::string command =
        fmt::format("cd '{}' && gnuplot '{}' 2>&1", directory, script.filename().string());
    if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
        spdlog::warn("gnuplot not found: no plot (apt-get install gnuplot-nox, then gnuplot {})",
                     script.string());
        return;
    }
    if (std::system(command.c_str()) != 0 || !std::filesystem::exists(png)) {
        throw RuntimeFailure(fmt::format("gnuplot failed on {}", script.string()));
    }
    fmt::print("wrote {}\n", png.string());
}

namespace {

// The sweep's progress on `progress`: renders done of all, what renders now and the pace.
AccuracyProgress accuracy_progress(DelayedProgress& progress) {
    return [&progress, clock = PaceClock()](int done, int total, const std::string& what) mutable {
        const double seconds = clock.seconds();
        progress.update(done, total, seconds,
                        fmt::format("{} | {:.2g} renders/s", what,
                                    seconds > 0.0 ? double(done) / seconds : 0.0));
    };
}

// --mode brute: the depth's convergence over passes (diagnostics/brute_accuracy.hpp).
void brute_accuracy(const Scene& scene, const AccuracySettings& settings,
                    const ComputeDevice& device, ProgramCache& cache,
                    const std::filesystem::path& csv, const std::filesystem::path& script,
                    const std::filesystem::path& png) {
    BruteConvergenceSettings brute;
    brute.width = settings.width;
    brute.height = settings.height;
    brute.repeats = settings.repeats;
    DelayedProgress progress("renders");
    const BruteConvergence result =
        run_brute_convergence(scene, device, cache, brute, accuracy_progress(progress));
    progress.finish();
    fmt::print("reference: {} ({:.0f} ms)\n", result.reference, result.reference_ms);
    // Times against the sphere tracer's say what brute force costs; against a long brute-force
    // render they would say nothing.
    const auto against_reference = [&](double ms) {
        return result.sphere_traced ? fmt::format("{:.1f}", ms / result.reference_ms)
                                    : std::string("-");
    };
    fmt::print("{:>6} {:>10} {:>10} {:>8} {:>12} {:>8} {:>10}\n", "passes", "render ms", "x ref",
               "tests/px", "disagree %", "IoU", "err (fp)");
    for (const BrutePoint& point : result.points) {
        fmt::print("{:>6} {:>10.1f} {:>10} {:>8.1f} {:>12.3f} {:>8.4f} {:>10.3f}\n", point.passes,
                   point.render_ms, against_reference(point.render_ms),
                   point.inside_tests_per_pixel, point.agreement.disagreeing_percent(),
                   point.agreement.iou(), point.agreement.mean_footprints);
    }
    // The headline: the first pass count whose depth agrees on 98% of the pixels (the brute
    // mode's test), and what it costs against the reference.
    const auto agreed = std::find_if(result.points.begin(), result.points.end(), [](const auto& p) {
        return p.agreement.disagreeing_percent() <= 2.0;
    });
    if (agreed != result.points.end()) {
        fmt::print("98% agreement after {} passes: {:.0f} ms{}\n", agreed->passes,
                   agreed->render_ms,
                   result.sphere_traced ? fmt::format(", {:.1f}x the sphere tracer",
                                                      agreed->render_ms / result.reference_ms)
                                        : std::string());
    } else {
        fmt::print("98% agreement not reached in {} passes\n", result.points.back().passes);
    }
    write_output(csv, brute_convergence_csv(result));
    write_output(script, brute_convergence_gnuplot(result, scene.id, csv.filename().string(),
                                                   png.filename().string()));
    plot_with_gnuplot(csv, script, png);
}

}  // namespace

int command_bench_accuracy(const AccuracyOptions& options, int device_index) {
    const Scene scene = scene_from_argument(options.scene);
    const std::string prefix = options.output.empty() ? "accuracy-" + scene.id : options.output;
    const std::filesystem::path csv = prefix + ".csv", script = prefix + ".gp",
                                png = prefix + ".png";
    check_output_directory(csv);
    const ComputeDevice device = open_requested_device(device_index);
    ProgramCache cache(ProgramCache::default_directory());
    const RenderMode mode = chosen_mode(options.mode, scene);
    if (mode == RenderMode::Brute) {
        brute_accuracy(scene, options.settings, device, cache, csv, script, png);
        return 0;
    }
    DelayedProgress shown("renders");
    const AccuracyProgress progress = accuracy_progress(shown);
    const AccuracyReport report =
        mode == RenderMode::Path
            ? run_path_accuracy_sweep(scene, device, cache, options.settings,
                                      chosen_path_settings(options.mode, scene), progress)
            : run_accuracy_sweep(scene, device, cache, options.settings, progress);
    shown.finish();
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
                   point.knob, point.value, point.reference, point.render_ms, point.steps_per_pixel,
                   point.error.rmse, point.error.one_minus_ssim, point.error.hit_mismatch_percent,
                   point.error.mean_depth_error, front);
    }
    write_output(csv, accuracy_csv(report));
    write_output(script, accuracy_gnuplot(report, scene.id, csv.filename().string(),
                                          png.filename().string()));
    plot_with_gnuplot(csv, script, png);
    return 0;
}

}  // namespace fgr
