// SPDX-License-Identifier: Apache-2.0
// Part files (output/parts/render_parts.hpp): rendering a region into one, reading one's header and
// rows.
#include "output/parts/part_file.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "image/embedded_view.hpp"
#include "output/parts/render_identity.hpp"
#include "output/tiled/streaming_image.hpp"
#include "util/json_fields.hpp"
#include "util/lower_case.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

constexpr int kPartVersion = 1;
constexpr const char* kPartAttribute = "fgr.part";
// Part files may be as large as a tiled still (OpenEXR refuses larger headers by default).
constexpr int kMaxPartSide = kMaxTiledImageSide;

// Packets cover up to 4x4 pixels (fgr::tile_layout).
constexpr int kPacketAlignment = 4;

using Rect = PixelRegion;

// `rect` grown to start and end on multiples of 4 pixels (or the image's edge). A launch groups
// its pixels into packets of up to 4x4 from its corner (tile_layout), and a pixel's result may
// depend on its packet's other rays: on this grid each pixel shares its packet with the
// neighbours it has in the untiled render, so it comes out bit for bit the same.
Rect aligned_to_packets(const Rect& rect, int width, int height) {
    constexpr int k = kPacketAlignment;
    const int x0 = rect.x / k * k, y0 = rect.y / k * k;
    const int x1 = std::min(width, (rect.x + rect.width + k - 1) / k * k);
    const int y1 = std::min(height, (rect.y + rect.height + k - 1) / k * k);
    return {x0, y0, x1 - x0, y1 - y0};
}

// The part's header: its render's identity, region, samples and seed, and the display transform
// the merge's 8-bit output needs as numbers.
std::string part_header(const Renderer& renderer, const FrameRequest& request,
                        const DisplayTransform& display, const PixelRegion& region) {
    FrameRequest whole = request;
    whole.region = {};
    nlohmann::ordered_json identity = nlohmann::ordered_json::object();
    for (const auto& [key, value] : image_identity(renderer, whole, display)) identity[key] = value;
    const nlohmann::ordered_json header = {
        {"fgr_part", kPartVersion},
        {"width", request.width},
        {"height", request.height},
        {"region", {region.x, region.y, region.width, region.height}},
        {"samples", request.samples},
        {"seed", request.path.seed},
        {"exposure", display.exposure},
        {"tone_map", static_cast<int>(display.tone_map)},
        {"layers", renderer.switches().aovs},
        {"identity", identity},
    };
    return header.dump();
}

void require_plane(const Frame& frame, const std::vector<float>& plane, size_t per_pixel,
                   const char* name) {
    if (plane.size() != frame.linear.size() / 3 * per_pixel) {
        throw std::runtime_error(
            fmt::format("the renderer gave no {} plane for a part with layers", name));
    }
}

// Interleaves the planes of `frame`'s pixel i as part_channels orders them.
float* put_pixel(const Frame& frame, size_t i, bool layers, float* out) {
    out = std::copy_n(&frame.linear[i * 3], 3, out);
    *out++ = frame.depth[i];
    if (!layers) return out;
    out = std::copy_n(&frame.albedo[i * 3], 3, out);
    out = std::copy_n(&frame.normal[i * 3], 3, out);
    *out++ = frame.alpha[i];
    return std::copy_n(&frame.foreground[i * 3], 3, out);
}

[[noreturn]] void not_a_part(const fs::path& path, const std::string& why) {
    throw std::runtime_error(
        fmt::format("'{}' is not an fgr part ({}): parts are written by "
                    "fgr render --part or --tile",
                    path.string(), why));
}

}  // namespace

std::vector<std::string> part_channels(bool layers) {
    std::vector<std::string> channels{"R", "G", "B", "depth.Z"};
    if (layers) {
        channels.insert(channels.end(),
                        {"albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y", "normal.Z",
                         "alpha.A", "foreground.R", "foreground.G", "foreground.B"});
    }
    return channels;
}

PixelRegion tile_region(int width, int height, int index, int count) {
    if (count < 1 || count > height || index < 1 || index > count) {
        throw std::invalid_argument(
            fmt::format("--tile {}/{} must be I/N with 1 <= I <= N <= the image height ({})", index,
                        count, height));
    }
    const int first = static_cast<int>(long(index - 1) * height / count);
    const int end = static_cast<int>(long(index) * height / count);
    return {0, first, width, end - first};
}

PartResult render_part(Renderer& renderer, const FrameRequest& request,
                       const DisplayTransform& display, const fs::path& path,
                       const PartSettings& settings) {
    if (lower_extension(path) != ".exr") {
        throw std::invalid_argument(
            fmt::format("a part is an OpenEXR file: '{}' must end in .exr", path.string()));
    }
    PartResult result;
    result.region = rendered_region(request);
    const PixelRegion& region = result.region;
    if (region.x < 0 || region.y < 0 || region.width < 1 || region.height < 1 ||
        region.x + region.width > request.width || region.y + region.height > request.height) {
        throw std::invalid_argument("a part's region must lie inside its image");
    }
    const bool layers = renderer.switches().aovs;
    const RowLayout layout{part_channels(layers), SampleType::F32};
    const size_t floats = layout.channels.size();
    const int padding = region_padding(renderer.switches().mode);
    // Launches at most kMaxImageSide a side: the tile, its padding and up to 3 pixels each side
    // to reach the packet grid.
    const TilePlan plan = plan_tiles(region.width, region.height, settings.tile_size,
                                     layout.pixel_bytes(), padding + kPacketAlignment);
    ExrPlacement placement{request.width,
                           request.height,
                           region.x,
                           region.y,
                           {{kPartAttribute, part_header(renderer, request, display, region)}}};
    auto writer = open_streaming_image(path, ImageFormat::Exr, region.width, region.height, layout,
                                       placement, settings.embedded_view);

    const auto start = std::chrono::steady_clock::now();
    result.samples = request.samples;
    std::vector<float> band;
    FrameRequest launch = request;
    launch.cancel = settings.interrupted;
    for (int b = 0; b < plan.bands(); ++b) {
        const int band_y = region.y + b * plan.band_rows;
        const int rows = std::min(plan.band_rows, region.y + region.height - band_y);
        band.resize(size_t(rows) * size_t(region.width) * floats);
        for (int t = 0; t < plan.tiles_per_band(); ++t) {
            if (settings.interrupted && settings.interrupted()) {
                result.interrupted = true;
                return result;  // the writer, destroyed unfinished, removes its temporary
            }
            const int x = region.x + t * plan.tile_width;
            const Rect tile{x, band_y, std::min(plan.tile_width, region.x + region.width - x),
                            rows};
            const Rect rendered =
                aligned_to_packets(padded_region(tile, padding, request.width, request.height),
                                   request.width, request.height);
            launch.region = {rendered.x, rendered.y, rendered.width, rendered.height};
            const Frame frame = renderer.render(launch);
            if (frame.cancelled) {
                result.interrupted = true;
                return result;
            }
            if (const long broken = non_finite_pixels(frame); broken > 0) {
                throw std::runtime_error(fmt::format(
                    "rendering '{}' gave non-finite colour or depth at {} pixels of the launch "
                    "at ({}, {})",
                    renderer.scene().id, broken, tile.x, tile.y));
            }
            if (layers) {
                require_plane(frame, frame.albedo, 3, "albedo");
                require_plane(frame, frame.normal, 3, "normal");
                require_plane(frame, frame.alpha, 1, "alpha");
                require_plane(frame, frame.foreground, 3, "foreground");
            }
            for (int y = 0; y < tile.height; ++y) {
                const size_t source_row = size_t(tile.y - rendered.y + y) * size_t(rendered.width);
                float* out = &band[(size_t(tile.y - band_y + y) * size_t(region.width) +
                                    size_t(tile.x - region.x)) *
                                   floats];
                for (int column = 0; column < tile.width; ++column) {
                    const size_t i = source_row + size_t(tile.x - rendered.x + column);
                    out = put_pixel(frame, i, layers, out);
                    result.hits += frame.depth[i] >= 0.0f;
                }
            }
            ++result.launches;
            if (settings.on_progress) settings.on_progress(result.launches, plan.tiles());
        }
        writer->write_rows(reinterpret_cast<const uint8_t*>(band.data()), rows);
    }
    writer->finish();
    result.render_ms = seconds_since(start) * 1000.0;
    return result;
}

PartInfo read_part_info(const fs::path& path) {
    Imf::Header::setMaxImageSize(kMaxPartSide, kMaxPartSide);
    std::unique_ptr<Imf::InputFile> file;
    try {
        file = std::make_unique<Imf::InputFile>(path.c_str());
    } catch (const std::exception& error) {
        throw std::runtime_error(fmt::format("cannot read '{}': {}", path.string(), error.what()));
    }
    const Imf::Header& header = file->header();
    const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(kPartAttribute);
    if (attribute == nullptr) not_a_part(path, "its header has no fgr.part");
    PartInfo info;
    info.path = path;
    try {
        // The one checked parse (depth, duplicate keys, NUL bytes, trailing bytes) first; then
        // again keeping the keys' order, in which the identity's fields are compared and named.
        (void)json_fields::parse_document(attribute->value(), "damaged");
    } catch (const std::runtime_error& error) {
        not_a_part(path, fmt::format("its fgr.part header is {}", error.what()));
    }
    try {
        const nlohmann::ordered_json json = nlohmann::ordered_json::parse(attribute->value());
        if (json.at("fgr_part").get<int>() != kPartVersion) not_a_part(path, "another version");
        info.width = json.at("width").get<int>();
        info.height = json.at("height").get<int>();
        const auto& region = json.at("region");
        info.region = {region.at(0).get<int>(), region.at(1).get<int>(), region.at(2).get<int>(),
                       region.at(3).get<int>()};
        info.samples = json.at("samples").get<int>();
        info.seed = json.at("seed").get<uint32_t>();
        info.display = {json.at("exposure").get<float>(),
                        static_cast<ToneMap>(json.at("tone_map").get<int>())};
        info.layers = json.at("layers").get<bool>();
        for (const auto& [key, value] : json.at("identity").items()) {
            info.identity.emplace_back(key, value.get<std::string>());
        }
    } catch (const nlohmann::json::exception& error) {
        not_a_part(path, fmt::format("its fgr.part header is damaged: {}", error.what()));
    }
    for (const auto& [key, value] : info.identity) {
        if (key == "mode") info.mode = value;
    }
    const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
    const PixelRegion& r = info.region;
    if (display.min != Imath::V2i(0, 0) ||
        display.max != Imath::V2i(info.width - 1, info.height - 1) ||
        data.min != Imath::V2i(r.x, r.y) ||
        data.max != Imath::V2i(r.x + r.width - 1, r.y + r.height - 1) || r.width < 1 ||
        r.height < 1 || r.x < 0 || r.y < 0 || r.x + r.width > info.width ||
        r.y + r.height > info.height || info.samples < 1) {
        not_a_part(path, "its windows do not match its fgr.part header");
    }
    for (const std::string& channel : part_channels(info.layers)) {
        if (header.channels().findChannel(channel) == nullptr) {
            not_a_part(path, fmt::format("it has no {} channel", channel));
        }
    }
    if (const auto* view = header.findTypedAttribute<Imf::StringAttribute>(kExrViewAttribute)) {
        info.view = view->value();
        if (info.view.size() > kMaxEmbeddedViewBytes) not_a_part(path, "its view is too large");
    }
    return info;
}

PartReader::PartReader(const PartInfo& info) : info_(info) {
    Imf::Header::setMaxImageSize(kMaxPartSide, kMaxPartSide);
    try {
        file_ = std::make_unique<Imf::InputFile>(info.path.c_str());
    } catch (const std::exception& error) {
        throw std::runtime_error(
            fmt::format("cannot read '{}': {}", info.path.string(), error.what()));
    }
}

PartReader::~PartReader() = default;

Frame PartReader::read_rows(int first_row, int rows) {
    const int width = info_.region.width;
    const size_t pixels = size_t(width) * size_t(rows);
    Frame frame;
    frame.image.width = width;
    frame.image.height = rows;
    frame.samples = info_.samples;
    frame.linear.resize(pixels * 3);
    frame.depth.resize(pixels);
    if (info_.layers) {
        frame.albedo.resize(pixels * 3);
        frame.normal.resize(pixels * 3);
        frame.alpha.resize(pixels);
        frame.foreground.resize(pixels * 3);
    }
    const Imath::Box2i rows_box(Imath::V2i(info_.region.x, first_row),
                                Imath::V2i(info_.region.x + width - 1, first_row + rows - 1));
    Imf::FrameBuffer buffer;
    const auto insert = [&](std::vector<float>& plane, size_t per_pixel,
                            std::initializer_list<const char*> names) {
        size_t c = 0;
        for (const char* name : names) {
            buffer.insert(name, Imf::Slice::Make(Imf::FLOAT, plane.data() + c++, rows_box,
                                                 per_pixel * sizeof(float),
                                                 per_pixel * sizeof(float) * size_t(width)));
        }
    };
    insert(frame.linear, 3, {"R", "G", "B"});
    insert(frame.depth, 1, {"depth.Z"});
    if (info_.layers) {
        insert(frame.albedo, 3, {"albedo.R", "albedo.G", "albedo.B"});
        insert(frame.normal, 3, {"normal.X", "normal.Y", "normal.Z"});
        insert(frame.alpha, 1, {"alpha.A"});
        insert(frame.foreground, 3, {"foreground.R", "foreground.G", "foreground.B"});
    }
    try {
        file_->setFrameBuffer(buffer);
        file_->readPixels(first_row, first_row + rows - 1);
    } catch (const std::exception& error) {
        throw std::runtime_error(
            fmt::format("cannot read '{}': {}", info_.path.string(), error.what()));
    }
    return frame;
}

}  // namespace fgr
