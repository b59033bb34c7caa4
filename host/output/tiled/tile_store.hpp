// SPDX-License-Identifier: Apache-2.0
#pragma once
// The tile store of a tiled still: a directory beside the output holding each finished band of
// encoded rows, zlib-compressed, and render.json, what the render was (the identity: scene,
// kernel, view, parameters, samples, size, plan, output layout). --resume takes the bands of a
// store whose identity is the current render's; any other store is refused by name, so tiles of
// two different renders never meet in one file.

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "output/tiled/streaming_image.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/renderer.hpp"

namespace fgr {

// What a render is, field by field (a changed field is named when a resume is refused).
nlohmann::json render_identity(const Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const RowLayout& layout,
                               const TilePlan& plan);

// A band file: a header (what band, how many bytes raw and compressed, how many hits), then the
// band's encoded rows, zlib-compressed.
std::string encode_band(int band, const std::vector<uint8_t>& rows, long hits);

// The most bytes a band file of `raw_bytes` encoded rows takes.
std::uintmax_t max_band_file_bytes(std::size_t raw_bytes);

// Checks `bytes` as band file `band` of a band of `pixels` pixels whose encoded rows take
// rows.size() bytes, and decodes the rows into `rows`: the right magic and band number, a raw size
// equal to rows.size(), a compressed size equal to what follows the header, a hit count in
// [0, pixels], data that decompresses to exactly rows.size() bytes. Returns "" and sets `hits`, or
// says why the file cannot be this band (rows then hold anything).
std::string decode_band(std::string_view bytes, int band, long pixels, std::vector<uint8_t>& rows,
                        long& hits);

class TileStore {
public:
    // Opens the store at `directory` for a render of `identity`. An existing store is resumed
    // when `resume` and its identity matches; otherwise std::runtime_error says why and what to
    // do. Without one, a new store is made (with `resume`, after a note that there was none).
    TileStore(std::filesystem::path directory, nlohmann::json identity, bool resume,
              const std::filesystem::path& output);

    // Band `band` (of `pixels` pixels) into `rows` (sized to the band's bytes) and its hits, when
    // the store has it whole and as decode_band checks it. Anything else named like the band (a
    // damaged or foreign file, a directory, a FIFO) is reported in one warning line and removed,
    // for the band to be rendered again.
    std::optional<long> load_band(int band, long pixels, std::vector<uint8_t>& rows) const;

    // Keeps band `band` (atomically: a band file is whole or absent).
    void save_band(int band, const std::vector<uint8_t>& rows, long hits);

    // Deletes the store (the output file is complete).
    void remove();

    long bands_kept() const;

private:
    std::filesystem::path band_path(int band) const;

    std::filesystem::path directory_;
};

}  // namespace fgr
