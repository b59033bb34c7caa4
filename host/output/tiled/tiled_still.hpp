// SPDX-License-Identifier: Apache-2.0
#pragma once
// Stills of any size (up to kMaxTiledImageSide a side), rendered a tile at a time and streamed
// to a PNG, EXR or TIFF file a band of rows at a time, so memory is bounded by the band, not the
// image.
//
// The image is cut into bands of whole rows, each band into tiles. A tile is a region of the
// whole image (FrameRequest::region), so each pixel gets exactly the ray, samples and random
// numbers of an untiled render; a mode whose shading reads neighbouring pixels (the brute-force
// mode's screen-space normals, occlusion and glow) renders each tile with the padding it reads
// (region_padding) and keeps the inside. A finished band is encoded into the output's samples,
// kept compressed in a tile store beside the output (what --resume continues from) and written
// to the file; the store goes once the file is complete. Interrupted renders keep the store and
// leave no file at the output path.

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "output/still_image.hpp"
#include "output/still_layers.hpp"
#include "output/tiled/streaming_image.hpp"
#include "render/renderer.hpp"

namespace fgr {

// What the output file holds.
struct TiledOutput {
    std::filesystem::path path;
    ImageFormat format = ImageFormat::Png;
    int bit_depth = 8;           // PNG and TIFF: 8 (tone-mapped sRGB) or 16 (linear, exposure only)
    bool alpha = false;          // PNG and TIFF: straight alpha of coverage (EXR: aovs.alpha)
    Aovs aovs{};                 // EXR: layers beside R, G, B
    DisplayTransform display{};  // exposure and tone map (8-bit); exposure (16-bit linear)
    // The document the file carries (image/embedded_view.hpp: the view that made it); "": none.
    // Not part of the tile store's identity: a resumed render may carry another.
    std::string embedded_view{};
};

// The channels a row of `output` holds, in order.
RowLayout output_row_layout(const TiledOutput& output);

// How a tiled render cuts its image.
struct TilePlan {
    int width = 0;
    int height = 0;
    int band_rows = 0;   // rows per band (the last may have fewer)
    int tile_width = 0;  // columns per tile (the last of a band may have fewer)
    int padding = 0;     // pixels rendered around each tile for neighbour-reading shading
    int bands() const { return (height + band_rows - 1) / band_rows; }
    int tiles_per_band() const { return (width + tile_width - 1) / tile_width; }
    long tiles() const { return long(bands()) * tiles_per_band(); }
    // Tile `index` (band by band, left to right) in image pixels.
    PixelRegion tile(long index) const {
        const int band = static_cast<int>(index / tiles_per_band());
        const int x = static_cast<int>(index % tiles_per_band()) * tile_width;
        const int y = band * band_rows;
        return {x, y, std::min(tile_width, width - x), std::min(band_rows, height - y)};
    }
};

// Default tile side, and the most memory a band of encoded rows may take.
constexpr int kDefaultTileSize = 512;
constexpr size_t kBandBudgetBytes = size_t{16} << 20;

// Images over this many pixels render in tiles unless told otherwise.
constexpr long kTiledFromPixels = 4096L * 4096L;

// Whether a width x height still written as `format` must render in tiles: a TIFF file (only
// the tiled writer streams it), a side over kMaxImageSide, or over kTiledFromPixels pixels.
bool renders_in_tiles(int width, int height, ImageFormat format);

// The tile side when `ranks` processes share a width x height still: about eight tiles a rank, so
// that a slow tile does not leave the others idle at the end, a multiple of 4 in
// [64, kDefaultTileSize]; one process takes kDefaultTileSize.
int tile_size_for_ranks(int width, int height, int ranks);

// Bands of `tile_size` rows unless a band of encoded rows (pixel_bytes each) would pass
// kBandBudgetBytes, then fewer (a multiple of 4, at least 4); tiles of about tile_size^2 pixels.
// Throws std::invalid_argument for a tile size that is not a multiple of 4 in [16, 8192].
TilePlan plan_tiles(int width, int height, int tile_size, size_t pixel_bytes, int padding);

// Pixels a tile of `mode` must be rendered with around it so that its own pixels come out as in
// an untiled render: what the mode's shading reads of neighbouring pixels (0: nothing).
int region_padding(RenderMode mode);

// `tile` and `padding` pixels around it, within a width x height image: the region such a tile is
// rendered over.
PixelRegion padded_region(const PixelRegion& tile, int padding, int width, int height);

struct TiledProgress {
    long tiles_done = 0;  // including those taken from an earlier run
    long tiles_total = 0;
    long tiles_resumed = 0;        // taken from the tile store, not rendered now
    double seconds = 0.0;          // since this run started
    double rays_per_second = 0.0;  // camera rays (pixels x samples) rendered by this run
};

struct TiledSettings {
    int tile_size = kDefaultTileSize;
    bool resume = false;  // continue from the tile store of an earlier, interrupted run
    // Polled between tiles (and within them): true stops the render, keeping the tile store.
    std::function<bool()> interrupted{};
    std::function<void(const TiledProgress&)> on_progress{};
};

struct TiledResult {
    bool interrupted = false;  // stopped by TiledSettings::interrupted: no file was written
    long tiles = 0;
    long tiles_resumed = 0;
    long hits = 0;           // pixels whose camera ray met the surface (rendered now)
    int samples = 0;         // per pixel
    double render_ms = 0.0;  // rendering, encoding and writing, this run
    TilePlan plan;
    std::filesystem::path store;  // the tile store (kept when interrupted)
};

// The tile store of `output`: a directory beside it.
std::filesystem::path tile_store_path(const std::filesystem::path& output);

// A tile's own pixels encoded as the output's samples: its rows (tile width x pixel bytes each),
// top to bottom, and how many of them hit the surface.
struct EncodedTile {
    std::vector<uint8_t> rows;
    long hits = 0;
};

// The rendering half of a tiled still: the plan, and any tile of it rendered and encoded. Tiles
// are numbered band by band, left to right (0 .. plan().tiles() - 1), so a caller may hand them
// to other processes (fgr render under MPI) and place the results with a TiledFile.
class TiledRender {
public:
    // Throws std::invalid_argument for a request that is not of the whole image or a tile size
    // plan_tiles refuses.
    TiledRender(Renderer& renderer, const FrameRequest& request, const TiledOutput& output,
                int tile_size);
    const TilePlan& plan() const { return plan_; }
    const RowLayout& layout() const { return layout_; }
    const FrameRequest& request() const { return request_; }
    Renderer& renderer() const { return renderer_; }
    // Tile `index` rendered and encoded; nullopt when request.cancel stopped it. Throws
    // std::runtime_error for non-finite pixels.
    std::optional<EncodedTile> render(long index) const;

private:
    Renderer& renderer_;
    FrameRequest request_;
    const TiledOutput& output_;
    RowLayout layout_;
    TilePlan plan_;
};

class TileStore;

// The writing half: the output file and the tile store beside it. Tiles arrive in any order;
// each band is written (and kept in the store) as soon as it and every band above it are
// complete, so memory holds only the bands still open.
class TiledFile {
public:
    // Opens the output (std::runtime_error when it cannot be written) and the tile store
    // (resumed with `resume`; refused as TileStore says). Resuming removes the temporary output a
    // killed run left (remove_stale_temporaries) and takes the bands the store holds valid.
    TiledFile(const TiledRender& render, const TiledOutput& output, bool resume);
    ~TiledFile();
    TiledFile(const TiledFile&) = delete;
    TiledFile& operator=(const TiledFile&) = delete;
    // The tiles still to render, in order: those of the bands the store does not hold.
    const std::vector<long>& tiles_to_render() const { return to_render_; }
    long tiles_resumed() const { return plan_.tiles() - long(to_render_.size()); }
    long hits() const { return hits_; }  // of the bands written so far
    // Places tile `index`, then writes every band completed in order.
    void add(long index, const EncodedTile& tile);
    // After the last tile: completes the file and removes the store (std::runtime_error when a
    // band is still missing).
    void finish();
    const std::filesystem::path& store_path() const { return store_path_; }
    // After a failure: removes the tile store when it holds no band (nothing to resume from);
    // returns whether it is kept.
    bool keep_store_if_useful();

private:
    struct OpenBand {
        std::vector<uint8_t> rows;
        int tiles_left = 0;
        long hits = 0;
    };
    int band_rows(int band) const;
    long band_pixels(int band) const;
    void write_ready_bands();

    TilePlan plan_;
    size_t pixel_bytes_;
    std::filesystem::path store_path_;
    std::unique_ptr<StreamingImageWriter> writer_;
    std::unique_ptr<TileStore> store_;
    std::vector<bool> band_in_store_;
    std::vector<long> to_render_;
    std::map<int, OpenBand> open_;
    int next_band_ = 0;  // the first band not yet written
    long hits_ = 0;
};

// Renders `request` (the whole image: request.region must be whole) with `renderer` in tiles and
// streams it to `output`. Throws std::invalid_argument for a plan or output that cannot be,
// std::runtime_error for a file that cannot be written, non-finite pixels, or a tile store that
// exists but is not resumable (another render's, or without --resume: named, with what to do).
TiledResult render_tiled_still(Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const TiledSettings& settings);

}  // namespace fgr
