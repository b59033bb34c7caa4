// SPDX-License-Identifier: Apache-2.0
#include "output/tiled/tile_store.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

#include "output/parts/render_identity.hpp"
#include "util/atomic_file.hpp"
#include "util/files.hpp"
#include "util/json_fields.hpp"

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

namespace {

// A render.json is a few hundred bytes; a file far larger is not one.
constexpr std::uintmax_t kMaxManifestBytes = 1 << 20;

// At most `limit` characters of `text`, for quoting a value in a one-line message.
std::string excerpt(const std::string& text, std::size_t limit = 80) {
    std::string line = text.substr(0, std::min(text.size(), limit));
    for (char& c : line) {
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    }
    return text.size() > limit ? line + "..." : line;
}

// The render.json of a store: its identity, or std::runtime_error naming the file and why it is
// not one (and what to do).
nlohmann::json read_manifest(const fs::path& manifest) {
    const auto damaged = [&](const std::string& why) {
        return std::runtime_error(
            fmt::format("cannot resume from '{}': {} (delete the directory to start again)",
                        manifest.string(), why));
    };
    std::error_code error;
    const fs::file_status status = fs::status(manifest, error);
    if (!fs::exists(status)) throw damaged("it is missing");
    if (!fs::is_regular_file(status)) throw damaged("not a regular file");
    std::string text;
    if (const std::string why = read_file_bytes(manifest, text, kMaxManifestBytes); !why.empty()) {
        throw damaged(why);
    }
    nlohmann::json kept;
    try {
        // The one checked parse: nesting at most 64 deep (the identity's values are dumped into
        // messages below), no key twice, no NUL byte, nothing after the document.
        kept = json_fields::parse_document(text, "not valid JSON");
    } catch (const std::runtime_error& parse_error) {
        throw damaged(parse_error.what());
    }
    const auto version = kept.is_object() ? kept.find("fgr_tile_store") : kept.end();
    const auto render = kept.is_object() ? kept.find("render") : kept.end();
    if (version == kept.end() || !version->is_number_integer() || render == kept.end() ||
        !render->is_object()) {
        throw damaged("not the render.json of a tile store");
    }
    if (*version != kStoreVersion) {
        throw damaged(
            fmt::format("a tile store of another fgr version ({})", excerpt(version->dump())));
    }
    return *render;
}

}  // namespace

TileStore::TileStore(fs::path directory, nlohmann::json identity, bool resume,
                     const fs::path& output)
    : directory_(std::move(directory)) {
    const fs::path manifest = directory_ / "render.json";
    std::error_code error;
    const fs::file_status status = fs::symlink_status(directory_, error);
    if (fs::exists(status) && !fs::is_directory(status)) {
        throw std::runtime_error(
            fmt::format("'{}' is in the way of the tile store of '{}' (not a directory): delete "
                        "or rename it",
                        directory_.string(), output.string()));
    }
    if (fs::exists(status)) {
        if (!resume) {
            throw std::runtime_error(fmt::format(
                "'{}' holds {} finished bands of an interrupted render of '{}': add --resume to "
                "continue it, or delete the directory to start again",
                directory_.string(), bands_kept(), output.string()));
        }
        const nlohmann::json kept = read_manifest(manifest);
        for (const auto& [key, value] : identity.items()) {
            const auto there = kept.find(key);
            if (there == kept.end() || *there != value) {
                throw std::runtime_error(fmt::format(
                    "cannot resume from '{}': it was rendered with another {} ({} there, {} now); "
                    "render with the same settings, or delete the directory to start again",
                    directory_.string(), key, there == kept.end() ? "none" : excerpt(there->dump()),
                    excerpt(value.dump())));
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

std::string encode_band(int band, const std::vector<uint8_t>& rows, long hits) {
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
    return bytes;
}

std::uintmax_t max_band_file_bytes(std::size_t raw_bytes) {
    return sizeof(BandHeader) + compressBound(static_cast<uLong>(raw_bytes));
}

std::string decode_band(std::string_view bytes, int band, long pixels, std::vector<uint8_t>& rows,
                        long& hits) {
    BandHeader header{};
    if (bytes.size() < sizeof header) return "too short";
    std::memcpy(&header, bytes.data(), sizeof header);
    if (std::memcmp(header.magic, kBandMagic, sizeof kBandMagic) != 0) return "not a band file";
    if (header.band != uint32_t(band)) return fmt::format("it holds band {}", header.band);
    if (header.reserved != 0) return "unknown header fields";
    if (header.raw_bytes != rows.size()) {
        return fmt::format("{} bytes of rows where this band has {}", header.raw_bytes,
                           rows.size());
    }
    if (header.compressed_bytes != bytes.size() - sizeof header) return "wrong size";
    if (header.hits < 0 || header.hits > pixels) {
        return fmt::format("{} hits in a band of {} pixels", header.hits, pixels);
    }
    uLongf size = static_cast<uLongf>(rows.size());
    const int status =
        uncompress(rows.data(), &size, reinterpret_cast<const Bytef*>(bytes.data() + sizeof header),
                   static_cast<uLong>(header.compressed_bytes));
    if (status != Z_OK || size != rows.size()) return "does not decompress";
    hits = static_cast<long>(header.hits);
    return "";
}

std::optional<long> TileStore::load_band(int band, long pixels, std::vector<uint8_t>& rows) const {
    const fs::path path = band_path(band);
    std::error_code error;
    const fs::file_status status = fs::symlink_status(path, error);
    if (!fs::exists(status)) return std::nullopt;
    std::string why;
    long hits = 0;
    if (!fs::is_regular_file(status)) {
        // Checked before opening it: a FIFO would block the open, a directory fail the read.
        why = "not a regular file";
    } else {
        std::string bytes;
        why = read_file_bytes(path, bytes, max_band_file_bytes(rows.size()));
        if (why.empty()) why = decode_band(bytes, band, pixels, rows, hits);
    }
    if (why.empty()) return hits;
    spdlog::warn("'{}' is damaged ({}): rendering that band again", path.string(), why);
    // Out of the way of the band's new file (a rename cannot replace a directory).
    fs::remove_all(path, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot remove the damaged band '{}': {}", path.string(), error.message()));
    }
    return std::nullopt;
}

void TileStore::save_band(int band, const std::vector<uint8_t>& rows, long hits) {
    write_text_file_atomically(band_path(band), encode_band(band, rows, hits));
}

void TileStore::remove() {
    std::error_code error;
    fs::remove_all(directory_, error);
    if (error)
        spdlog::warn("could not remove the tile store '{}': {}", directory_.string(),
                     error.message());
}

}  // namespace fgr
