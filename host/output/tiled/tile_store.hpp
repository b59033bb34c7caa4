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
#include <vector>

#include "output/tiled/streaming_image.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/renderer.hpp"

namespace fgr {

// What a render is, field by field (a changed field is named when a resume is refused).
nlohmann::json render_identity(const Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const RowLayout& layout,
                               const TilePlan& plan);

class TileStore {
public:
    // Opens the store at `directory` for a render of `identity`. An existing store is resumed
    // when `resume` and its identity matches; otherwise std::runtime_error says why and what to
    // do. Without one, a new store is made (with `resume`, after a note that there was none).
    TileStore(std::filesystem::path directory, nlohmann::json identity, bool resume,
              const std::filesystem::path& output);

    // Band `band` into `rows` (sized to the band's bytes) and its hits, when the store has it
    // whole; a damaged band file is reported and rendered again.
    std::optional<long> load_band(int band, std::vector<uint8_t>& rows) const;

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
