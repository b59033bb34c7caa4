// SPDX-License-Identifier: Apache-2.0
#include "tiled_render.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>
#include <regex>
#include <utility>

#include "cli/progress.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_wire.hpp"
#include "distributed/task_farm.hpp"
#include "output/parts/render_parts.hpp"
#include "output/tiled/streaming_image.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "util/interruption.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

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
        throw UsageError(
            fmt::format("--tile {} must be I/N with 1 <= I <= N <= the image height "
                        "({})",
                        text, options.height));
    }
    return {index, count};
}

}  // namespace

bool tiled_render_wanted(const RenderOptions& options) {
    if (options.all) return false;
    return options.tile_size || options.resume ||
           renders_in_tiles(options.width, options.height, image_format_of(options.output));
}

void check_tiled_options(const RenderOptions& options) {
    if (options.stats) {
        throw UsageError(
            "--stats is for untiled renders (at most 16384 a side and 16 Mpx, no "
            "--tile-size, PNG or EXR)");
    }
    if (options.time_limit) {
        throw UsageError(
            "a tiled render takes the same samples in every tile: give --spp, not "
            "--time-limit");
    }
}

namespace {

// Under MPI the tiles are the unit of work (tile_size_for_ranks), unless --tile-size says.
int tile_size_for(const RenderOptions& options, int ranks) {
    if (options.tile_size) return *options.tile_size;
    return tile_size_for_ranks(options.width, options.height, ranks);
}

// Rank 0 (or the one process): hands the tiles out (distributed/task_farm.hpp), places them
// as they come back and streams the file, with a progress line.
int write_tiles(Cluster& cluster, const TiledRender& render, const TaskWork& work,
                const TiledOutput& output, const RenderOptions& options) {
    std::optional<TiledFile> file;
    try {
        file.emplace(render, output, options.resume);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    } catch (const std::runtime_error& error) {
        throw RuntimeFailure(error.what());
    }
    const TilePlan& plan = render.plan();
    const long resumed = file->tiles_resumed();
    ProgressLine progress("tiles");
    const auto start = std::chrono::steady_clock::now();
    long done = resumed, rays = 0;
    const ResultSink place = [&](int64_t index, std::vector<uint8_t>&& bytes) {
        file->add(index, tile_from_bytes(bytes));
        rays += plan.tile(index).pixels() * render.request().samples;
        ++done;
        const double seconds = seconds_since(start);
        progress.update(done, plan.tiles(), done - resumed, seconds,
                        format_rate(seconds > 0.0 ? double(rays) / seconds : 0.0) + "rays/s");
    };
    FarmSettings farm;
    farm.interrupted = interrupted;
    std::vector<int64_t> tiles(file->tiles_to_render().begin(), file->tiles_to_render().end());
    FarmOutcome outcome;
    try {
        outcome = run_farm(cluster, tiles, work, place, farm);
        if (outcome.finished) file->finish();
    } catch (const std::runtime_error& error) {
        // Ctrl-C reaches every rank: a tile abandoned for it is no failure of that rank. A rank
        // that died is, even when mpirun stopped this one for it.
        progress.finish();
        if (!interrupted() || dynamic_cast<const RankLost*>(&error) != nullptr) {
            if (file->keep_store_if_useful()) {
                spdlog::info("the finished bands are kept in '{}' for --resume",
                             file->store_path().string());
            }
            throw RuntimeFailure(error.what());
        }
    }
    progress.finish();
    if (!outcome.finished || interrupted()) {
        const std::filesystem::path store = file->store_path();
        const bool kept = file->keep_store_if_useful();
        file.reset();  // removes the unfinished file
        if (kept) {
            spdlog::error(
                "interrupted: nothing written to '{}'; the finished bands are kept in '{}': "
                "run the same command with --resume to continue",
                options.output, store.string());
        } else {
            spdlog::error("interrupted: nothing written to '{}' (no band was finished yet)",
                          options.output);
        }
        return interrupted_exit_code();
    }
    const double seconds = seconds_since(start);
    fmt::print("render_ms {:.1f}\n", seconds * 1000.0);
    fmt::print("hits {}\n", file->hits());
    fmt::print("samples_per_pixel {}\n", render.request().samples);
    fmt::print("tiles {} ({} from an earlier run; {} rows a band, {} columns a tile, {} padding)\n",
               plan.tiles(), resumed, plan.band_rows, plan.tile_width, plan.padding);
    if (!cluster.alone()) print_mpi_figures(cluster, outcome);
    fmt::print("peak_memory_mib {:.1f}\n", peak_memory_mib());
    fmt::print("wrote {} ({}x{})\n", options.output, plan.width, plan.height);
    return 0;
}

}  // namespace

int render_tiled(const Scene& scene, const FrameRequest& request, const ComputeDevice& device,
                 ProgramCache& cache, const RenderOptions& options) {
    Cluster& cluster = Cluster::current();
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
    output.embedded_view = options.embedded_view;

    // Ctrl-C or SIGTERM stops between tiles (and within them), keeping the finished bands.
    const InterruptScope interrupt_scope;
    FrameRequest tile_request = whole;
    tile_request.cancel = interrupted;
    tile_request.cancel_response = CancelResponse::Batch;
    const TiledRender render = [&] {
        try {
            return TiledRender(renderer, tile_request, output,
                               tile_size_for(options, cluster.size()));
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }();
    const TaskWork work = [&](int64_t index) {
        std::optional<EncodedTile> tile = render.render(index);
        if (!tile) throw RuntimeFailure("interrupted");
        return tile_to_bytes(*tile);
    };
    if (!cluster.coordinator()) {
        run_farm(cluster, {}, work, {});
        return 0;
    }
    return write_tiles(cluster, render, work, output, options);
}

bool part_render_wanted(const RenderOptions& options) { return options.part || options.tile; }

void check_part_options(const RenderOptions& options) {
    if (image_format_of(options.output) != ImageFormat::Exr) {
        throw UsageError(
            fmt::format("a part is an OpenEXR file: give -o NAME.exr (got '{}')", options.output));
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
    FrameRequest part = job.request;
    if (options.tile) {
        const auto [index, count] = part_tile(options);
        try {
            part.region = tile_region(part.width, part.height, index, count);
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    }
    // A part's own rows are what this process renders.
    check_render_cost(scene, StillJob{job.settings, part, job.aovs}, options, device.info);
    PrecisionRenderers renderers(device, cache, scene, still_switches(device, job.settings));
    Renderer& renderer = choose_still_renderer(renderers, scene, job.request, device, job.settings);

    const InterruptScope interrupt_scope;
    ProgressLine progress("launches");
    PartSettings settings;
    settings.tile_size = options.tile_size.value_or(kDefaultTileSize);
    settings.interrupted = interrupted;
    settings.embedded_view = options.embedded_view;
    const auto start = std::chrono::steady_clock::now();
    const PixelRegion rendered = rendered_region(part);
    const std::string rows =
        fmt::format("rows {}..{}", rendered.y, rendered.y + rendered.height - 1);
    settings.on_progress = [&](long done, long total) {
        progress.update(done, total, done, seconds_since(start), rows);
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
        return interrupted_exit_code();
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
