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
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "image/embedded_view.hpp"
#include "output/parts/render_identity.hpp"
#include "output/tiled/streaming_image.hpp"
#include "render/sample_budget.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene.hpp"
#include "util/errors.hpp"
#include "util/files.hpp"
#include "util/json_fields.hpp"
#include "util/lower_case.hpp"
#include "util/strings.hpp"
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
        fmt::format("{} is not an fgr part ({}): parts are written by "
                    "fgr render --part or --tile",
                    quoted(path), why));
}

// The keys of a part header (part_header), every one required.
constexpr std::string_view kHeaderKeys[] = {"fgr_part", "seed",    "width",    "height",
                                            "region",   "samples", "exposure", "tone_map",
                                            "layers",   "identity"};
// More than image_identity gives, few enough that comparing parts stays cheap.
constexpr std::size_t kMaxIdentityFields = 64;

// A key or text as a message may quote it: in double quotes, escaped, bounded.
std::string header_text(std::string_view text) {
    return json_fields::shown(nlohmann::json(std::string(text.substr(0, 64))));
}

// `value` when it is a whole number in [low, high].
std::optional<long long> whole_in(const nlohmann::json& value, long long low, long long high) {
    if (value.is_number_unsigned()) {
        const auto number = value.get<std::uint64_t>();
        if (number > static_cast<std::uint64_t>(high)) return std::nullopt;
        const auto fits = static_cast<long long>(number);
        return fits >= low ? std::optional<long long>(fits) : std::nullopt;
    }
    if (!value.is_number_integer()) return std::nullopt;
    const auto number = value.get<long long>();
    return number >= low && number <= high ? std::optional<long long>(number) : std::nullopt;
}

// The exposure parameter's range, which every scene has (scene.cpp), so every part was rendered
// within it.
std::pair<float, float> exposure_range() {
    static const std::pair<float, float> range = [] {
        Scene scene;
        add_builtin_params(scene);
        const ParamInfo* exposure = scene.find_param("exposure");
        if (exposure == nullptr) throw std::logic_error("no built-in exposure parameter");
        return std::pair<float, float>{exposure->min_value, exposure->max_value};
    }();
    return range;
}

// The fields of a part's header, each checked as it is taken: a damaged or forged header is
// refused naming the file and the field, before anything is sized from it.
struct HeaderFields {
    const nlohmann::json& json;
    const fs::path& path;

    // `field`: one or more quoted keys.
    [[noreturn]] void bad(const std::string& field, const std::string& why) const {
        throw std::runtime_error(
            fmt::format("{} is a damaged fgr part: its header's {} {}", quoted(path), field, why));
    }
    const nlohmann::json& at(const char* key) const {
        const auto found = json.find(key);
        if (found == json.end()) bad(header_text(key), "is missing");
        return *found;
    }
    long long whole(const char* key, long long low, long long high) const {
        const nlohmann::json& value = at(key);
        const std::optional<long long> number = whole_in(value, low, high);
        if (!number) {
            bad(header_text(key), fmt::format("is {}, not a whole number in [{}, {}]",
                                              json_fields::shown(value), low, high));
        }
        return *number;
    }
    double number(const char* key, float low, float high) const {
        const nlohmann::json& value = at(key);
        if (!value.is_number() ||
            !(value.get<double>() >= double{low} && value.get<double>() <= double{high})) {
            bad(header_text(key), fmt::format("is {}, not a number in [{}, {}]",
                                              json_fields::shown(value), low, high));
        }
        return value.get<double>();
    }
};

// What an OpenEXR header may hold in a part: fgr writes a few KB (its view at most
// kMaxEmbeddedViewBytes).
constexpr std::uint64_t kMaxPartHeaderBytes = std::uint64_t{4} << 20;
constexpr std::size_t kMaxExrNameBytes = 255;  // an attribute's name or type (long names)

// OpenEXR sizes each header attribute's buffer from the size the file states, before it reads
// the value: a damaged 1 KB file can make it allocate gigabytes. Walks the header first (magic,
// version, then name, type, size and value of each attribute), refusing a single-part file whose
// attributes do not fit in it or in kMaxPartHeaderBytes. Returns "" or the reason.
std::string exr_header_problem(const fs::path& path) {
    const FilePointer file(std::fopen(path.c_str(), "rb"));
    if (file == nullptr) return errno_message(errno);
    std::error_code error;
    const std::uintmax_t size = fs::file_size(path, error);
    if (error) return error.message();
    unsigned char start[8];
    if (std::fread(start, 1, sizeof start, file.get()) != sizeof start ||
        !(start[0] == 0x76 && start[1] == 0x2f && start[2] == 0x31 && start[3] == 0x01)) {
        return "not an OpenEXR file";
    }
    if (start[5] & 0x18) return "a multi-part or deep OpenEXR file, not a part";
    std::uint64_t at = sizeof start;
    const auto text = [&](std::string& out) {
        out.clear();
        for (int c; (c = std::fgetc(file.get())) != 0;) {
            if (c == EOF || out.size() == kMaxExrNameBytes) return false;
            out += static_cast<char>(c);
        }
        at += out.size() + 1;
        return true;
    };
    for (std::string name, type;;) {
        if (!text(name)) return "its header is cut short or damaged";
        if (name.empty()) return "";  // the end of the header
        unsigned char bytes[4];
        if (!text(type) || std::fread(bytes, 1, sizeof bytes, file.get()) != sizeof bytes) {
            return "its header is cut short or damaged";
        }
        at += sizeof bytes;
        const std::uint64_t value = std::uint64_t{bytes[0]} | std::uint64_t{bytes[1]} << 8 |
                                    std::uint64_t{bytes[2]} << 16 | std::uint64_t{bytes[3]} << 24;
        if (value > kMaxPartHeaderBytes || at + value > size || at + value > kMaxPartHeaderBytes) {
            return fmt::format("its header attribute {} claims {} bytes, more than {}",
                               header_text(name), value,
                               at + value > size ? "the file holds" : "a part's header may hold");
        }
        if (std::fseek(file.get(), static_cast<long>(value), SEEK_CUR) != 0) {
            return errno_message(errno);
        }
        at += value;
    }
}

// The part's windows and channels, as its header says: the display window the whole image, the
// data window its region, every channel of its planes there.
void check_part_layout(const Imf::Header& header, const PartInfo& info) {
    const Imath::Box2i data = header.dataWindow(), display = header.displayWindow();
    const PixelRegion& r = info.region;
    if (display.min != Imath::V2i(0, 0) ||
        display.max != Imath::V2i(info.width - 1, info.height - 1) ||
        data.min != Imath::V2i(r.x, r.y) ||
        data.max != Imath::V2i(r.x + r.width - 1, r.y + r.height - 1)) {
        not_a_part(info.path, "its windows do not match its fgr.part header");
    }
    for (const std::string& channel : part_channels(info.layers)) {
        const Imf::Channel* found = header.channels().findChannel(channel);
        if (found == nullptr) not_a_part(info.path, fmt::format("it has no {} channel", channel));
        if (found->xSampling != 1 || found->ySampling != 1) {
            not_a_part(info.path, fmt::format("its {} channel is subsampled", channel));
        }
    }
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
            fmt::format("a part is an OpenEXR file: {} must end in .exr", quoted(path)));
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
    launch.cancel_response = CancelResponse::Batch;
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

PartInfo parse_part_header(std::string_view text, const fs::path& path) {
    nlohmann::json json;
    try {
        json = json_fields::parse_document(text, "its fgr.part header is damaged");
    } catch (const std::runtime_error& error) {
        not_a_part(path, error.what());
    }
    if (!json.is_object()) not_a_part(path, "its fgr.part header is not a JSON object");
    const HeaderFields fields{json, path};
    if (fields.whole("fgr_part", 0, std::numeric_limits<int>::max()) != kPartVersion) {
        not_a_part(path, "another version");
    }
    for (const auto& [key, value] : json.items()) {
        if (std::find(std::begin(kHeaderKeys), std::end(kHeaderKeys), key) ==
            std::end(kHeaderKeys)) {
            fields.bad(header_text(key), "is not a part header's key");
        }
    }
    PartInfo info;
    info.path = path;
    info.width = static_cast<int>(fields.whole("width", 1, kMaxPartSide));
    info.height = static_cast<int>(fields.whole("height", 1, kMaxPartSide));
    const nlohmann::json& region = fields.at("region");
    if (!region.is_array() || region.size() != 4) {
        fields.bad(header_text("region"),
                   fmt::format("is {}, not [x, y, width, height]", json_fields::shown(region)));
    }
    // Each number within the image, given those before it.
    const auto region_value = [&](std::size_t i, long long low, long long high) {
        const std::optional<long long> number = whole_in(region[i], low, high);
        if (!number) {
            fields.bad(header_text("region"),
                       fmt::format("has {} at {}, not a whole number in [{}, {}]",
                                   json_fields::shown(region[i]), i, low, high));
        }
        return static_cast<int>(*number);
    };
    info.region.x = region_value(0, 0, info.width - 1);
    info.region.y = region_value(1, 0, info.height - 1);
    info.region.width = region_value(2, 1, info.width - info.region.x);
    info.region.height = region_value(3, 1, info.height - info.region.y);
    info.samples = static_cast<int>(fields.whole("samples", 1, kMaxSamples));
    info.seed = static_cast<uint32_t>(fields.whole("seed", 0, UINT32_MAX));
    const auto [min_exposure, max_exposure] = exposure_range();
    info.display.exposure =
        static_cast<float>(fields.number("exposure", min_exposure, max_exposure));
    const long long tone = fields.whole("tone_map", 0, std::numeric_limits<int>::max());
    constexpr ToneMap kToneMaps[] = {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces};
    if (std::none_of(std::begin(kToneMaps), std::end(kToneMaps),
                     [&](ToneMap known) { return static_cast<long long>(known) == tone; })) {
        fields.bad(header_text("tone_map"),
                   fmt::format("is {}, not a tone map (0 clamp, 1 Reinhard, 2 ACES)", tone));
    }
    info.display.tone_map = static_cast<ToneMap>(tone);
    const nlohmann::json& layers = fields.at("layers");
    if (!layers.is_boolean()) {
        fields.bad(header_text("layers"),
                   fmt::format("is {}, not true or false", json_fields::shown(layers)));
    }
    info.layers = layers.get<bool>();

    const nlohmann::json& identity = fields.at("identity");
    if (!identity.is_object() || identity.empty() || identity.size() > kMaxIdentityFields) {
        fields.bad(header_text("identity"),
                   fmt::format("is {}, not an object of 1 to {} text fields",
                               json_fields::shown(identity), kMaxIdentityFields));
    }
    for (const auto& [key, value] : identity.items()) {
        if (!value.is_string()) {
            fields.bad(
                header_text("identity"),
                fmt::format("has {} as {}, not text", json_fields::shown(value), header_text(key)));
        }
    }
    // In the order written (image_identity's, the most telling first), which a mismatch follows.
    const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(text);
    for (const auto& [key, value] : ordered.at("identity").items()) {
        info.identity.emplace_back(key, value.get<std::string>());
    }

    // The numbers the merge uses must be the ones the identity, which parts are matched by, says.
    const auto agree = [&](const char* key, const std::string& expected,
                           const std::string& numbers) {
        const auto found = identity.find(key);
        const std::string said = found == identity.end() ? "none" : found->get<std::string>();
        if (said != expected) {
            fields.bad(numbers,
                       fmt::format("say {} but its identity's {} is {}", header_text(expected),
                                   header_text(key), header_text(said)));
        }
    };
    agree("size", size_identity(info.width, info.height),
          header_text("width") + " and " + header_text("height"));
    agree("display", display_identity(info.display),
          header_text("exposure") + " and " + header_text("tone_map"));
    agree("layers", layers_identity(info.layers), header_text("layers"));
    const auto mode = identity.find("mode");
    info.mode = mode == identity.end() ? "" : mode->get<std::string>();
    const auto modes = render_modes();
    if (std::none_of(modes.begin(), modes.end(),
                     [&](const RenderModeInfo& known) { return known.name == info.mode; })) {
        fields.bad(header_text("identity"),
                   fmt::format("has the mode {}, which is no render mode", header_text(info.mode)));
    }
    return info;
}

PartInfo read_part_info(const fs::path& path) {
    if (const std::string problem = regular_file_problem(path); !problem.empty()) {
        throw std::runtime_error(fmt::format("cannot read {}: {}", quoted(path), problem));
    }
    if (const std::string problem = exr_header_problem(path); !problem.empty()) {
        throw std::runtime_error(fmt::format("cannot read {}: {}", quoted(path), problem));
    }
    Imf::Header::setMaxImageSize(kMaxPartSide, kMaxPartSide);
    std::unique_ptr<Imf::InputFile> file;
    try {
        file = std::make_unique<Imf::InputFile>(path.c_str());
    } catch (const std::exception& error) {
        throw std::runtime_error(fmt::format("cannot read {}: {}", quoted(path), error.what()));
    }
    const Imf::Header& header = file->header();
    const auto* attribute = header.findTypedAttribute<Imf::StringAttribute>(kPartAttribute);
    if (attribute == nullptr) not_a_part(path, "its header has no fgr.part");
    PartInfo info = parse_part_header(attribute->value(), path);
    check_part_layout(header, info);
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
            fmt::format("cannot read {}: {}", quoted(info.path), error.what()));
    }
    // The file may have changed since its header was read: the rows read must still be there.
    check_part_layout(file_->header(), info);
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
            fmt::format("cannot read {}: {}", quoted(info_.path), error.what()));
    }
    return frame;
}

}  // namespace fgr
