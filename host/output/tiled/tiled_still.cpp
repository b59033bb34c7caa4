// SPDX-License-Identifier: Apache-2.0
// Tiled stills (output/tiled/tiled_still.hpp): the plan, the loop over bands and tiles, and the
// encoding of a tile's pixels into the output's samples. The tile store is in tile_store.cpp.
#include "output/tiled/tiled_still.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "device/kernel_assembly.hpp"
#include "device/kernel_layout.hpp"
#include "output/still_layers.hpp"
#include "output/tiled/row_encoder.hpp"
#include "output/tiled/tile_store.hpp"
#include "util/atomic_file.hpp"
#include "util/interruption.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

int round_down_to_4(long value) { return static_cast<int>(value / 4 * 4); }

using Rect = PixelRegion;

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
    if (output.aovs.albedo)
        layout.channels.insert(layout.channels.end(), {"albedo.R", "albedo.G", "albedo.B"});
    if (output.aovs.normal)
        layout.channels.insert(layout.channels.end(), {"normal.X", "normal.Y", "normal.Z"});
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
    plan.band_rows =
        std::max(4, round_down_to_4(std::min<long>({tile_size, budget_rows, max_side})));
    const long area = long(tile_size) * tile_size;
    plan.tile_width =
        std::max(4, round_down_to_4(std::min<long>(area / plan.band_rows + 3, max_side)));
    return plan;
}

PixelRegion padded_region(const PixelRegion& tile, int padding, int width, int height) {
    const int x0 = std::max(0, tile.x - padding), y0 = std::max(0, tile.y - padding);
    const int x1 = std::min(width, tile.x + tile.width + padding);
    const int y1 = std::min(height, tile.y + tile.height + padding);
    return {x0, y0, x1 - x0, y1 - y0};
}

// The brute-force mode's screen-space shading reads up to FGR_BRUTE_MAX_REACH pixels away
// (kernels/modes/fgr_mode_brute.cl), so its tiles are rendered with that much padding.
int region_padding(RenderMode mode) { return mode == RenderMode::Brute ? FGR_BRUTE_MAX_REACH : 0; }

std::filesystem::path tile_store_path(const std::filesystem::path& output) {
    return output.parent_path() / (output.filename().string() + ".fgr-tiles");
}

TiledRender::TiledRender(Renderer& renderer, const FrameRequest& request, const TiledOutput& output,
                         int tile_size)
    : renderer_(renderer), request_(request), output_(output), layout_(output_row_layout(output)) {
    if (!request.region.whole())
        throw std::invalid_argument("a tiled still renders the whole image");
    plan_ = plan_tiles(request.width, request.height, tile_size, layout_.pixel_bytes(),
                       region_padding(renderer.switches().mode));
}

std::optional<EncodedTile> TiledRender::render(long index) const {
    const Rect tile = plan_.tile(index);
    const Rect region = padded_region(tile, plan_.padding, plan_.width, plan_.height);
    FrameRequest part = request_;
    part.region = {region.x, region.y, region.width, region.height};
    const Frame frame = renderer_.render(part);
    if (frame.cancelled) return std::nullopt;
    if (const long broken = non_finite_pixels(frame); broken > 0) {
        throw std::runtime_error(fmt::format(
            "rendering '{}' gave non-finite colour or depth at {} pixels of the tile at ({}, {})",
            renderer_.scene().id, broken, tile.x, tile.y));
    }
    RowEncoder encoder(frame, output_, layout_);
    const size_t row_bytes = layout_.pixel_bytes() * size_t(tile.width);
    EncodedTile encoded;
    encoded.rows.resize(row_bytes * size_t(tile.height));
    for (int y = 0; y < tile.height; ++y) {
        const int fy = tile.y - region.y + y;
        encoder.encode(fy, tile.x - region.x, tile.width,
                       encoded.rows.data() + size_t(y) * row_bytes);
        for (int x = 0; x < tile.width; ++x) {
            encoded.hits +=
                frame.depth[size_t(fy) * size_t(region.width) + size_t(tile.x - region.x + x)] >=
                0.0f;
        }
    }
    return encoded;
}

TiledFile::TiledFile(const TiledRender& render, const TiledOutput& output, bool resume)
    : plan_(render.plan()),
      pixel_bytes_(render.layout().pixel_bytes()),
      store_path_(tile_store_path(output.path)) {
    // A run killed outright (SIGKILL, a crash) leaves its temporary output: the run that replaces
    // it removes it.
    if (resume) remove_stale_temporaries(output.path);
    // The file first: if it cannot be written, no tile store is made either.
    writer_ = open_streaming_image(output.path, output.format, plan_.width, plan_.height,
                                   render.layout(), {}, output.embedded_view);
    store_ = std::make_unique<TileStore>(
        store_path_,
        render_identity(render.renderer(), render.request(), output, render.layout(), plan_),
        resume, output.path);
    band_in_store_.assign(size_t(plan_.bands()), false);
    std::vector<uint8_t> scratch;
    for (int b = 0; b < plan_.bands(); ++b) {
        if (resume) {
            scratch.resize(pixel_bytes_ * size_t(plan_.width) * size_t(band_rows(b)));
            band_in_store_[size_t(b)] = store_->load_band(b, band_pixels(b), scratch).has_value();
        }
        if (band_in_store_[size_t(b)]) continue;
        for (int t = 0; t < plan_.tiles_per_band(); ++t) {
            to_render_.push_back(long(b) * plan_.tiles_per_band() + t);
        }
    }
    write_ready_bands();  // bands at the top that the store already holds
}

TiledFile::~TiledFile() = default;

int TiledFile::band_rows(int band) const {
    return std::min(plan_.band_rows, plan_.height - band * plan_.band_rows);
}

long TiledFile::band_pixels(int band) const { return long(plan_.width) * band_rows(band); }

void TiledFile::add(long index, const EncodedTile& tile) {
    const int band = static_cast<int>(index / plan_.tiles_per_band());
    const Rect rect = plan_.tile(index);
    const size_t row_bytes = pixel_bytes_ * size_t(rect.width);
    if (band < next_band_ || band_in_store_[size_t(band)] ||
        tile.rows.size() != row_bytes * size_t(rect.height)) {
        throw std::logic_error(fmt::format("tile {} does not belong in the open bands", index));
    }
    auto [it, opened] = open_.try_emplace(band);
    OpenBand& open = it->second;
    if (opened) {
        open.rows.resize(pixel_bytes_ * size_t(plan_.width) * size_t(rect.height));
        open.tiles_left = plan_.tiles_per_band();
    }
    const size_t band_stride = pixel_bytes_ * size_t(plan_.width);
    for (int y = 0; y < rect.height; ++y) {
        std::memcpy(open.rows.data() + size_t(y) * band_stride + size_t(rect.x) * pixel_bytes_,
                    tile.rows.data() + size_t(y) * row_bytes, row_bytes);
    }
    open.hits += tile.hits;
    --open.tiles_left;
    write_ready_bands();
}

void TiledFile::write_ready_bands() {
    std::vector<uint8_t> kept;
    while (next_band_ < plan_.bands()) {
        const int b = next_band_;
        if (band_in_store_[size_t(b)]) {
            kept.resize(pixel_bytes_ * size_t(plan_.width) * size_t(band_rows(b)));
            const std::optional<long> hits = store_->load_band(b, band_pixels(b), kept);
            if (!hits)
                throw std::runtime_error(fmt::format("band {} of the tile store vanished", b));
            hits_ += *hits;
            writer_->write_rows(kept.data(), band_rows(b));
        } else {
            const auto it = open_.find(b);
            if (it == open_.end() || it->second.tiles_left > 0) return;
            store_->save_band(b, it->second.rows, it->second.hits);
            hits_ += it->second.hits;
            writer_->write_rows(it->second.rows.data(), band_rows(b));
            open_.erase(it);
            hold_for_test("band");
        }
        ++next_band_;
    }
}

void TiledFile::finish() {
    if (next_band_ < plan_.bands()) {
        throw std::logic_error(
            fmt::format("band {} of {} was never completed", next_band_, plan_.bands()));
    }
    writer_->finish();
    store_->remove();
}

bool TiledFile::keep_store_if_useful() {
    if (store_->bands_kept() > 0) return true;
    store_->remove();
    return false;
}

TiledResult render_tiled_still(Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const TiledSettings& settings) {
    FrameRequest tile_request = request;
    tile_request.cancel = settings.interrupted;
    tile_request.cancel_response = CancelResponse::Batch;
    const TiledRender render(renderer, tile_request, output, settings.tile_size);
    TiledFile file(render, output, settings.resume);
    TiledResult result;
    result.plan = render.plan();
    result.tiles = render.plan().tiles();
    result.tiles_resumed = file.tiles_resumed();
    result.samples = request.samples;
    result.store = file.store_path();

    const auto start = std::chrono::steady_clock::now();
    TiledProgress progress;
    progress.tiles_total = result.tiles;
    progress.tiles_resumed = result.tiles_resumed;
    progress.tiles_done = result.tiles_resumed;
    long rays = 0;
    const auto report = [&] {
        progress.seconds = seconds_since(start);
        progress.rays_per_second = progress.seconds > 0.0 ? double(rays) / progress.seconds : 0.0;
        if (settings.on_progress) settings.on_progress(progress);
    };
    if (result.tiles_resumed > 0) report();
    for (long index : file.tiles_to_render()) {
        if (settings.interrupted && settings.interrupted()) {
            result.interrupted = true;
            return result;
        }
        const std::optional<EncodedTile> tile = render.render(index);
        if (!tile) {
            result.interrupted = true;
            return result;
        }
        file.add(index, *tile);
        const Rect rect = render.plan().tile(index);
        rays += long(rect.width) * rect.height * request.samples;
        ++progress.tiles_done;
        report();
    }
    file.finish();
    result.hits = file.hits();
    result.render_ms = seconds_since(start) * 1000.0;
    return result;
}

bool renders_in_tiles(int width, int height, ImageFormat format) {
    return format == ImageFormat::Tiff || width > kMaxImageSide || height > kMaxImageSide ||
           long(width) * long(height) > kTiledFromPixels;
}

int tile_size_for_ranks(int width, int height, int ranks) {
    if (ranks <= 1) return kDefaultTileSize;
    const double side = std::sqrt(double(width) * double(height) / (8.0 * ranks));
    return std::clamp(static_cast<int>(side) / 4 * 4, 64, kDefaultTileSize);
}

}  // namespace fgr
