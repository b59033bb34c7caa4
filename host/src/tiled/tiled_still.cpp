// Tiled stills (fgr/tiled_still.hpp): the plan, the loop over bands and tiles, and the encoding
// of a tile's pixels into the output's samples. The tile store is in tile_store.cpp.
#include "fgr/tiled_still.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "fgr/kernel_assembly.hpp"
#include "fgr/still_layers.hpp"
#include "tiled/row_encoder.hpp"
#include "tiled/tile_store.hpp"

namespace fgr {
namespace {

// The brute-force mode's screen-space shading reads up to FGR_BRUTE_MAX_REACH pixels away
// (kernels/fgr_mode_brute.cl).
constexpr int kBruteMaxReach = 256;

int round_down_to_4(long value) { return static_cast<int>(value / 4 * 4); }

struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
};

// The region a tile is rendered over: the tile and `padding` pixels around it, within the image.
Rect padded(const Rect& tile, int padding, int width, int height) {
    const int x0 = std::max(0, tile.x - padding), y0 = std::max(0, tile.y - padding);
    const int x1 = std::min(width, tile.x + tile.width + padding);
    const int y1 = std::min(height, tile.y + tile.height + padding);
    return {x0, y0, x1 - x0, y1 - y0};
}

// Renders one tile and encodes its own pixels into the band's rows (row stride `band_stride`,
// the tile's first column at tile.x). Returns the hits among its own pixels.
long render_tile(Renderer& renderer, const FrameRequest& request, const TilePlan& plan,
                 const Rect& tile, int band_y, const TiledOutput& output, const RowLayout& layout,
                 std::vector<uint8_t>& band) {
    const Rect region = padded(tile, plan.padding, plan.width, plan.height);
    FrameRequest part = request;
    part.region = {region.x, region.y, region.width, region.height};
    const Frame frame = renderer.render(part);
    if (frame.cancelled) return -1;
    if (const long broken = non_finite_pixels(frame); broken > 0) {
        throw std::runtime_error(fmt::format(
            "rendering '{}' gave non-finite colour or depth at {} pixels of the tile at ({}, {})",
            renderer.scene().id, broken, tile.x, tile.y));
    }
    RowEncoder encoder(frame, output, layout);
    const size_t pixel_bytes = layout.pixel_bytes();
    const size_t band_stride = pixel_bytes * size_t(plan.width);
    long hits = 0;
    for (int y = 0; y < tile.height; ++y) {
        const int fy = tile.y - region.y + y;
        uint8_t* row = band.data() + size_t(tile.y - band_y + y) * band_stride +
                       size_t(tile.x) * pixel_bytes;
        encoder.encode(fy, tile.x - region.x, tile.width, row);
        for (int x = 0; x < tile.width; ++x) {
            hits += frame.depth[size_t(fy) * size_t(region.width) + size_t(tile.x - region.x + x)] >= 0.0f;
        }
    }
    return hits;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RowLayout output_row_layout(const TiledOutput& output) {
    RowLayout layout;
    if (output.format != ImageFormat::Exr) {
        layout.channels = {"R", "G", "B"};
        if (output.alpha) layout.channels.push_back("A");
        layout.type = output.bit_depth == 16 ? SampleType::U16 : SampleType::U8;
        return layout;
    }
    layout.type = SampleType::F32;
    // In the order exr_layers gives them.
    layout.channels = {"R", "G", "B"};
    if (output.aovs.albedo) layout.channels.insert(layout.channels.end(), {"albedo.R", "albedo.G", "albedo.B"});
    if (output.aovs.normal) layout.channels.insert(layout.channels.end(), {"normal.X", "normal.Y", "normal.Z"});
    if (output.aovs.depth) layout.channels.push_back("depth.Z");
    if (output.aovs.alpha) layout.channels.push_back("A");
    return layout;
}

TilePlan plan_tiles(int width, int height, int tile_size, size_t pixel_bytes, int padding) {
    if (tile_size < 16 || tile_size > 8192 || tile_size % 4 != 0) {
        throw std::invalid_argument(
            fmt::format("tile size {} must be a multiple of 4 between 16 and 8192", tile_size));
    }
    if (width < 1 || height < 1 || width > kMaxTiledImageSide || height > kMaxTiledImageSide) {
        throw std::invalid_argument(fmt::format("image size {}x{} must be between 1x1 and {}x{}",
                                                width, height, kMaxTiledImageSide,
                                                kMaxTiledImageSide));
    }
    TilePlan plan;
    plan.width = width;
    plan.height = height;
    plan.padding = padding;
    // What one launch may render: a side of kMaxImageSide with the padding on both sides.
    const int max_side = round_down_to_4(kMaxImageSide - 2 * padding);
    const long budget_rows = long(kBandBudgetBytes / (size_t(width) * pixel_bytes));
    plan.band_rows = std::max(4, round_down_to_4(std::min<long>({tile_size, budget_rows, max_side})));
    const long area = long(tile_size) * tile_size;
    plan.tile_width = std::max(4, round_down_to_4(std::min<long>(area / plan.band_rows + 3, max_side)));
    return plan;
}

int region_padding(RenderMode mode) { return mode == RenderMode::Brute ? kBruteMaxReach : 0; }

std::filesystem::path tile_store_path(const std::filesystem::path& output) {
    return output.parent_path() / (output.filename().string() + ".fgr-tiles");
}

TiledResult render_tiled_still(Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const TiledSettings& settings) {
    if (!request.region.whole()) throw std::invalid_argument("a tiled still renders the whole image");
    const RowLayout layout = output_row_layout(output);
    TiledResult result;
    result.plan = plan_tiles(request.width, request.height, settings.tile_size,
                             layout.pixel_bytes(), region_padding(renderer.switches().mode));
    const TilePlan& plan = result.plan;
    result.tiles = plan.tiles();
    result.samples = request.samples;
    result.store = tile_store_path(output.path);

    // The file first: if it cannot be written, no tile store is made either.
    auto writer = open_streaming_image(output.path, output.format, plan.width, plan.height, layout);
    TileStore store(result.store, render_identity(renderer, request, output, layout, plan),
                    settings.resume, output.path);

    const auto start = std::chrono::steady_clock::now();
    const size_t band_stride = layout.pixel_bytes() * size_t(plan.width);
    std::vector<uint8_t> band;
    TiledProgress progress;
    progress.tiles_total = plan.tiles();
    long rays = 0;
    FrameRequest tile_request = request;
    tile_request.cancel = settings.interrupted;
    const auto report = [&] {
        progress.seconds = seconds_since(start);
        progress.rays_per_second = progress.seconds > 0.0 ? double(rays) / progress.seconds : 0.0;
        if (settings.on_progress) settings.on_progress(progress);
    };
    for (int b = 0; b < plan.bands(); ++b) {
        const int band_y = b * plan.band_rows;
        const int rows = std::min(plan.band_rows, plan.height - band_y);
        band.resize(band_stride * size_t(rows));
        if (std::optional<long> kept_hits = store.load_band(b, band)) {
            result.hits += *kept_hits;
            result.tiles_resumed += plan.tiles_per_band();
            progress.tiles_resumed = result.tiles_resumed;
            progress.tiles_done += plan.tiles_per_band();
            report();
        } else {
            long band_hits = 0;
            for (int t = 0; t < plan.tiles_per_band(); ++t) {
                if (settings.interrupted && settings.interrupted()) {
                    result.interrupted = true;
                    return result;
                }
                const int x = t * plan.tile_width;
                const Rect tile{x, band_y, std::min(plan.tile_width, plan.width - x), rows};
                const long hits =
                    render_tile(renderer, tile_request, plan, tile, band_y, output, layout, band);
                if (hits < 0) {
                    result.interrupted = true;
                    return result;
                }
                band_hits += hits;
                rays += long(tile.width) * tile.height * request.samples;
                ++progress.tiles_done;
                report();
            }
            store.save_band(b, band, band_hits);
            result.hits += band_hits;
        }
        writer->write_rows(band.data(), rows);
    }
    writer->finish();
    store.remove();
    result.render_ms = seconds_since(start) * 1000.0;
    return result;
}

}  // namespace fgr
