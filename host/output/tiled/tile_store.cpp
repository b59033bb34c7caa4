// SPDX-License-Identifier: Apache-2.0
#include "output/tiled/tile_store.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <zlib.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "output/parts/render_identity.hpp"
#include "util/atomic_file.hpp"
#include "util/files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

constexpr int kStoreVersion = 1;
constexpr char kBandMagic[8] = {'F', 'G', 'R', 'B', 'A', 'N', 'D', '1'};

// The header of a band file; the band's rows follow, zlib-compressed.
struct BandHeader {
    char magic[8];
    uint32_t band;
    uint32_t reserved;
    uint64_t raw_bytes;
    uint64_t compressed_bytes;
    int64_t hits;
};

std::string format_name(ImageFormat format) {
    switch (format) {
        case ImageFormat::Png:
            return "png";
        case ImageFormat::Exr:
            return "exr";
        case ImageFormat::Tiff:
            return "tiff";
    }
    return "?";
}

}  // namespace

nlohmann::json render_identity(const Renderer& renderer, const FrameRequest& request,
                               const TiledOutput& output, const RowLayout& layout,
                               const TilePlan& plan) {
    nlohmann::json identity;
    for (const auto& [key, value] : image_identity(renderer, request, output.display)) {
        identity[key] = value;
    }
    std::string channels;
    for (const std::string& name : layout.channels)
        channels += (channels.empty() ? "" : ",") + name;
    identity["samples"] = request.samples;
    identity["seed"] = request.path.seed;
    identity["tiles"] = fmt::format("{} rows a band, {} columns a tile, {} padding", plan.band_rows,
                                    plan.tile_width, plan.padding);
    identity["output"] =
        fmt::format("{} {} {}-bit exposure {:.9g} tone map {}", format_name(output.format),
                    channels, 8 * sample_bytes(layout.type), output.display.exposure,
                    static_cast<int>(output.display.tone_map));
    return identity;
}

TileStore::TileStore(fs::path directory, nlohmann::json identity, bool resume,
                     const fs::path& output)
    : directory_(std::move(directory)) {
    const fs::path manifest = directory_ / "render.json";
    std::error_code error;
    if (fs::exists(directory_, error)) {
        if (!resume) {
            throw std::runtime_error(fmt::format(
                "'{}' holds {} finished bands of an interrupted render of '{}': add --resume to "
                "continue it, or delete the directory to start again",
                directory_.string(), bands_kept(), output.string()));
        }
        nlohmann::json kept;
        try {
            std::string text;
            read_file_bytes(manifest, text);  // unreadable: empty, which does not parse
            kept = nlohmann::json::parse(text);
        } catch (const std::exception&) {
            throw std::runtime_error(fmt::format(
                "cannot resume from '{}': its render.json is missing or damaged (delete the "
                "directory to start again)",
                directory_.string()));
        }
        if (kept.value("fgr_tile_store", 0) != kStoreVersion || !kept.contains("render")) {
            throw std::runtime_error(
                fmt::format("cannot resume from '{}': not a tile store of "
                            "this fgr version",
                            directory_.string()));
        }
        for (const auto& [key, value] : identity.items()) {
            if (!kept["render"].contains(key) || kept["render"][key] != value) {
                throw std::runtime_error(fmt::format(
                    "cannot resume from '{}': it was rendered with another {} ({} there, {} now); "
                    "render with the same settings, or delete the directory to start again",
                    directory_.string(), key,
                    kept["render"].contains(key) ? kept["render"][key].dump() : "none",
                    value.dump()));
            }
        }
        spdlog::info("resuming from '{}': {} bands already finished", directory_.string(),
                     bands_kept());
        return;
    }
    if (resume)
        spdlog::info("nothing to resume in '{}': starting from the first tile",
                     directory_.string());
    fs::create_directories(directory_, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot create '{}': {}", directory_.string(), error.message()));
    }
    const nlohmann::json contents = {{"fgr_tile_store", kStoreVersion}, {"render", identity}};
    write_text_file_atomically(manifest, contents.dump(2) + "\n");
}

fs::path TileStore::band_path(int band) const {
    return directory_ / fmt::format("band_{:06d}.z", band);
}

long TileStore::bands_kept() const {
    long count = 0;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(directory_, error)) {
        const std::string name = entry.path().filename().string();
        count += name.starts_with("band_") && name.ends_with(".z");
    }
    return count;
}

std::optional<long> TileStore::load_band(int band, std::vector<uint8_t>& rows) const {
    const fs::path path = band_path(band);
    std::error_code error;
    if (!fs::exists(path, error)) return std::nullopt;
    std::string bytes;
    read_file_bytes(path, bytes);  // unreadable: empty, so damaged below
    BandHeader header{};
    const auto damaged = [&](const char* why) -> std::optional<long> {
        spdlog::warn("'{}' is damaged ({}): rendering that band again", path.string(), why);
        return std::nullopt;
    };
    if (bytes.size() < sizeof header) return damaged("too short");
    std::memcpy(&header, bytes.data(), sizeof header);
    if (std::memcmp(header.magic, kBandMagic, sizeof kBandMagic) != 0 ||
        header.band != uint32_t(band)) {
        return damaged("not this band");
    }
    if (header.raw_bytes != rows.size() ||
        header.compressed_bytes != bytes.size() - sizeof header) {
        return damaged("wrong size");
    }
    uLongf size = static_cast<uLongf>(rows.size());
    const int status =
        uncompress(rows.data(), &size, reinterpret_cast<const Bytef*>(bytes.data() + sizeof header),
                   static_cast<uLong>(header.compressed_bytes));
    if (status != Z_OK || size != rows.size()) return damaged("does not decompress");
    return header.hits;
}

void TileStore::save_band(int band, const std::vector<uint8_t>& rows, long hits) {
    uLongf size = compressBound(static_cast<uLong>(rows.size()));
    std::string bytes(sizeof(BandHeader) + size, '\0');
    // Level 1: the store is scratch; the output file's own compression is what is kept.
    if (compress2(reinterpret_cast<Bytef*>(bytes.data() + sizeof(BandHeader)), &size, rows.data(),
                  static_cast<uLong>(rows.size()), 1) != Z_OK) {
        throw std::runtime_error("cannot compress a band for the tile store");
    }
    BandHeader header{};
    std::memcpy(header.magic, kBandMagic, sizeof kBandMagic);
    header.band = uint32_t(band);
    header.raw_bytes = rows.size();
    header.compressed_bytes = size;
    header.hits = hits;
    std::memcpy(bytes.data(), &header, sizeof header);
    bytes.resize(sizeof header + size);
    write_text_file_atomically(band_path(band), bytes);
}

void TileStore::remove() {
    std::error_code error;
    fs::remove_all(directory_, error);
    if (error)
        spdlog::warn("could not remove the tile store '{}': {}", directory_.string(),
                     error.message());
}

}  // namespace fgr
