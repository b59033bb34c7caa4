#include "tiled_render.hpp"

#include <sys/resource.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <regex>
#include <utility>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "fgr/parameters.hpp"
#include "fgr/precision.hpp"
#include "fgr/progress.hpp"
#include "fgr/render_parts.hpp"
#include "fgr/still_layers.hpp"
#include "fgr/streaming_image.hpp"
#include "fgr/tiled_still.hpp"

namespace fgr {
namespace {

volatile std::sig_atomic_t interrupt_signal = 0;

void note_interrupt(int signal) { interrupt_signal = signal; }

// Catches Ctrl-C (and SIGTERM) while it lives, so a render stops between tiles and cleans up
// instead of dying with a partial file; the previous handlers come back after.
class InterruptCatcher {
public:
    InterruptCatcher() {
        interrupt_signal = 0;
        struct sigaction action {};
        action.sa_handler = note_interrupt;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &previous_int_);
        sigaction(SIGTERM, &action, &previous_term_);
    }
    ~InterruptCatcher() {
        sigaction(SIGINT, &previous_int_, nullptr);
        sigaction(SIGTERM, &previous_term_, nullptr);
    }
    InterruptCatcher(const InterruptCatcher&) = delete;
    InterruptCatcher& operator=(const InterruptCatcher&) = delete;
    static bool caught() { return interrupt_signal != 0; }

private:
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
};

double peak_memory_mib() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_maxrss) / 1024.0;  // kilobytes on Linux
}

// --tile I/N as (I, N); UsageError when it is not two numbers with a slash between.
std::pair<int, int> part_tile(const RenderOptions& options) {
    const std::string& text = *options.tile;
    const std::regex form(R"((\d{1,9})/(\d{1,9}))");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw UsageError(fmt::format("--tile '{}' must be I/N, e.g. 3/16: tile I of N", text));
    }
    const int index = std::stoi(match[1]), count = std::stoi(match[2]);
    if (index < 1 || index > count || count > options.height) {
        throw UsageError(fmt::format("--tile {} must be I/N with 1 <= I <= N <= the image height "
                                     "({})", text, options.height));
    }
    return {index, count};
}

}  // namespace

bool tiled_render_wanted(const RenderOptions& options) {
    if (options.all) return false;
    return options.tile_size || options.resume ||
           image_format_of(options.output) == ImageFormat::Tiff ||
           options.width > kMaxImageSide || options.height > kMaxImageSide ||
           long(options.width) * long(options.height) > kTiledFromPixels;
}

void check_tiled_options(const RenderOptions& options) {
    if (options.stats) {
        throw UsageError("--stats is for untiled renders (at most 16384 a side and 16 Mpx, no "
                         "--tile-size, PNG or EXR)");
    }
    if (options.time_limit) {
        throw UsageError("a tiled render takes the same samples in every tile: give --spp, not "
                         "--time-limit");
    }
}

int render_tiled(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                 ProgramCache& cache, const RenderOptions& options) {
    const StillJob job = still_job(scene, request, options);
    const StillSettings& settings = job.settings;
    const FrameRequest& whole = job.request;
    PrecisionRenderers renderers(device, cache, scene, still_switches(device, settings));
    Renderer& renderer = choose_still_renderer(renderers, scene, whole, device, settings);

    TiledOutput output;
    output.path = options.output;
    output.format = image_format_of(output.path);
    output.bit_depth = options.bit_depth;
    output.aovs = job.aovs;
    output.alpha = options.alpha;
    if (output.format == ImageFormat::Exr) output.aovs.alpha = output.aovs.alpha || options.alpha;
    output.display = display_transform(scene, whole.params);

    InterruptCatcher catcher;
    ProgressLine progress("tiles");
    TiledSettings tiled;
    tiled.tile_size = options.tile_size.value_or(kDefaultTileSize);
    tiled.resume = options.resume;
    tiled.interrupted = [] { return InterruptCatcher::caught(); };
    tiled.on_progress = [&](const TiledProgress& p) {
        progress.update(p.tiles_done, p.tiles_total, p.tiles_done - p.tiles_resumed, p.seconds,
                        format_rate(p.rays_per_second) + "rays/s");
    };
    TiledResult result;
    try {
        result = render_tiled_still(renderer, whole, output, tiled);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const std::runtime_error& error) {
        progress.finish();
        throw RuntimeFailure(error.what());
    }
    progress.finish();
    if (result.interrupted) {
        spdlog::error("interrupted: nothing written to '{}'; the finished bands are kept in '{}': "
                      "run the same command with --resume to continue",
                      options.output, result.store.string());
        return 130;
    }
    fmt::print("render_ms {:.1f}\n", result.render_ms);
    fmt::print("hits {}\n", result.hits);
    fmt::print("samples_per_pixel {}\n", result.samples);
    fmt::print("tiles {} ({} from an earlier run; {} rows a band, {} columns a tile, {} padding)\n",
               result.tiles, result.tiles_resumed, result.plan.band_rows, result.plan.tile_width,
               result.plan.padding);
    fmt::print("peak_memory_mib {:.1f}\n", peak_memory_mib());
    fmt::print("wrote {} ({}x{})\n", options.output, whole.width, whole.height);
    return 0;
}

bool part_render_wanted(const RenderOptions& options) { return options.part || options.tile; }

void check_part_options(const RenderOptions& options) {
    if (image_format_of(options.output) != ImageFormat::Exr) {
        throw UsageError(fmt::format("a part is an OpenEXR file: give -o NAME.exr (got '{}')",
                                     options.output));
    }
    if (options.resume) throw UsageError("--resume is for tiled stills, not parts: rerun the part");
    if (options.stats) throw UsageError("--stats is for untiled renders, not parts");
    if (options.time_limit) {
        throw UsageError("parts take the same samples everywhere: give --spp, not --time-limit");
    }
    if (options.tile) part_tile(options);  // a malformed I/N fails before anything is loaded
}

int render_part_file(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                     ProgramCache& cache, const RenderOptions& options) {
    const StillJob job = still_job(scene, request, options);
    PrecisionRenderers renderers(device, cache, scene, still_switches(device, job.settings));
    Renderer& renderer = choose_still_renderer(renderers, scene, job.request, device, job.settings);
    FrameRequest part = job.request;
    if (options.tile) {
        const auto [index, count] = part_tile(options);
        try {
            part.region = tile_region(part.width, part.height, index, count);
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }

    InterruptCatcher catcher;
    ProgressLine progress("launches");
    PartSettings settings;
    settings.tile_size = options.tile_size.value_or(kDefaultTileSize);
    settings.interrupted = [] { return InterruptCatcher::caught(); };
    const auto start = std::chrono::steady_clock::now();
    const PixelRegion rendered = rendered_region(part);
    const std::string rows =
        fmt::format("rows {}..{}", rendered.y, rendered.y + rendered.height - 1);
    settings.on_progress = [&](long done, long total) {
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        progress.update(done, total, done, seconds.count(), rows);
    };
    PartResult result;
    try {
        result = render_part(renderer, part, display_transform(scene, part.params), options.output,
                             settings);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const std::runtime_error& error) {
        progress.finish();
        throw RuntimeFailure(error.what());
    }
    progress.finish();
    if (result.interrupted) {
        spdlog::error("interrupted: nothing written to '{}'", options.output);
        return 130;
    }
    const PixelRegion& region = result.region;
    fmt::print("render_ms {:.1f}\n", result.render_ms);
    fmt::print("hits {}\n", result.hits);
    fmt::print("samples_per_pixel {}\n", result.samples);
    fmt::print("seed {}\n", part.path.seed);
    fmt::print("part rows {}..{} of {}x{}{}\n", region.y, region.y + region.height - 1, part.width,
               part.height, options.tile ? " (tile " + *options.tile + ")" : "");
    fmt::print("peak_memory_mib {:.1f}\n", peak_memory_mib());
    fmt::print("wrote {} ({}x{} of {}x{})\n", options.output, region.width, region.height,
               part.width, part.height);
    return 0;
}

}  // namespace fgr
