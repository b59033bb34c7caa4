// SPDX-License-Identifier: Apache-2.0
// fgr bench quality: the time each configuration of the path tracer takes to reach an error
// threshold, from the measurements bench/time_to_quality.sh makes; fgr bench compare: one image's
// error against a reference, the measurement the script takes of each render.
#include <fmt/format.h>

#include <filesystem>
#include <string>

#include "commands.hpp"
#include "diagnostics/image_metrics.hpp"
#include "diagnostics/time_to_quality.hpp"
#include "image/hdr_io.hpp"
#include "util/files.hpp"

namespace fgr {
namespace {

constexpr std::uintmax_t kMaxMeasurementBytes = std::uintmax_t{16} << 20;

// An image as linear RGB: .png decoded from sRGB, anything else read as .exr or .hdr (the first
// part's default layer: a denoised render's beauty).
HdrImage linear_image(const std::string& file) {
    const std::filesystem::path path(file);
    try {
        if (path.extension() == ".png") return linear_rgb(read_png(path));
        return read_hdr_image(path);
    } catch (const std::exception& error) {
        throw RuntimeFailure(error.what());
    }
}

}  // namespace

void add_bench_quality_commands(CLI::App& bench, BenchOptions& options) {
    CLI::App* quality = bench.add_subcommand(
        "quality",
        "time to quality: when each path-tracing configuration reaches an error threshold, "
        "from the measurements bench/time_to_quality.sh writes");
    options.quality_command = quality;
    QualityOptions& q = options.quality;
    quality
        ->add_option("measurements", q.measurements,
                     "CSV with the columns scene, configuration, budget, render_ms and "
                     "one_minus_ssim, a configuration's rows in order of growing budget")
        ->required();
    quality
        ->add_option("--threshold", q.threshold,
                     "the 1 - SSIM each configuration must reach (default 0.005)")
        ->check(CLI::Range(1e-9, 1.0));
    quality->add_option("--baseline", q.baseline,
                        "the configuration speed-ups are measured against (default: the first "
                        "in the CSV)");
    quality->add_option("-o,--output", q.output,
                        "write PREFIX.md, PREFIX.gp and PREFIX.png (default: the CSV's name "
                        "without .csv)");

    CLI::App* compare = bench.add_subcommand(
        "compare", "one image's error against a reference: 1 - SSIM of the display luma and RMSE");
    options.compare_command = compare;
    compare->add_option("image", options.compare.image, "the image (.exr, .hdr or .png)")
        ->required();
    compare->add_option("reference", options.compare.reference, "the reference, the same size")
        ->required();
}

int command_bench_quality(const QualityOptions& options) {
    std::string text;
    const std::string reason = read_file_bytes(options.measurements, text, kMaxMeasurementBytes);
    if (!reason.empty()) {
        throw RuntimeFailure(fmt::format("cannot read '{}': {}", options.measurements, reason));
    }
    std::vector<QualityPoint> points;
    try {
        points = parse_quality_csv(text, options.measurements);
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    if (points.empty()) {
        throw RuntimeFailure(fmt::format("{}: no measurements", options.measurements));
    }
    if (!options.baseline.empty() &&
        std::none_of(points.begin(), points.end(), [&](const QualityPoint& point) {
            return point.configuration == options.baseline;
        })) {
        throw UsageError(fmt::format("--baseline '{}': no such configuration in {}",
                                     options.baseline, options.measurements));
    }
    std::string prefix = options.output;
    if (prefix.empty()) {
        const std::filesystem::path csv(options.measurements);
        prefix = (csv.parent_path() / csv.stem()).string();
    }
    const std::filesystem::path markdown = prefix + ".md", script = prefix + ".gp",
                                png = prefix + ".png";
    check_output_directory(markdown);
    const std::vector<QualitySummaryRow> rows =
        summarise_quality(points, options.threshold, options.baseline);
    const std::string table = quality_table_markdown(rows, options.threshold);
    fmt::print("{}", table);
    write_output(markdown, table);
    write_output(script, quality_gnuplot(points, options.threshold, png.filename().string()));
    plot_with_gnuplot(markdown, script, png);
    return 0;
}

int command_bench_compare(const CompareOptions& options) {
    const HdrImage image = linear_image(options.image);
    const HdrImage reference = linear_image(options.reference);
    if (image.width != reference.width || image.height != reference.height) {
        throw RuntimeFailure(fmt::format("'{}' is {}x{} and '{}' {}x{}: not the same size",
                                         options.image, image.width, image.height,
                                         options.reference, reference.width, reference.height));
    }
    if (image.width < kSsimWindow || image.height < kSsimWindow) {
        throw RuntimeFailure(fmt::format("'{}' is smaller than SSIM's {}x{} window", options.image,
                                         kSsimWindow, kSsimWindow));
    }
    fmt::print("one_minus_ssim {:.6g}\n", 1.0 - ssim(image, reference));
    fmt::print("rmse {:.6g}\n", rmse(image, reference));
    return 0;
}

}  // namespace fgr
