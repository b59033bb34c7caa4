// SPDX-License-Identifier: Apache-2.0
#include "image/hdr_io.hpp"

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "image/embedded_view.hpp"
#include "util/atomic_file.hpp"
#include "util/errors.hpp"
#include "util/files.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// stb_image takes the encoded size as an int.
constexpr std::uintmax_t kMaxFileBytes = std::numeric_limits<int>::max();
// OpenEXR allocates a tile's worth of pixels per tile read; real files use 32 to 256.
constexpr int kMaxExrTileSide = 1024;
// Longest channel name OpenEXR writes (its "long names" limit).
constexpr std::size_t kMaxExrNameBytes = 255;

// What read_hdr_image throws for a bad file: a std::runtime_error of its own type, so the
// handlers that turn library exceptions into messages pass it through unchanged.
struct ReadFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

[[noreturn]] void fail_read(const fs::path& path, const std::string& reason) {
    throw ReadFailure("cannot read " + quoted(path) + ": " + reason);
}

[[noreturn]] void fail_argument(const fs::path& path, const std::string& reason) {
    throw std::invalid_argument("cannot write " + quoted(path) + ": " + reason);
}

// Library messages and names from callers may span lines; ours are one line each.
std::string printable(std::string text) {
    for (char& c : text) {
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    }
    return text;
}

std::string one_line(const std::string& message) {
    std::string line = printable(message);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line.empty() ? "unknown error" : line;
}

// The whole file, after checking it is a regular file within the size limit.
std::vector<unsigned char> read_image_file(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error);
    if (error || !fs::exists(status)) {
        fail_read(path, error && error != std::errc::no_such_file_or_directory ? error.message()
                                                                               : "no such file");
    }
    if (fs::is_directory(status)) fail_read(path, "is a directory");
    if (!fs::is_regular_file(status)) fail_read(path, "not a regular file");
    std::vector<unsigned char> bytes;
    const std::string failure = read_file_bytes(path, bytes, kMaxFileBytes);
    if (!failure.empty()) fail_read(path, failure);
    if (bytes.empty()) fail_read(path, "empty file");
    return bytes;
}

bool starts_with(const std::vector<unsigned char>& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() &&
           std::memcmp(bytes.data(), prefix.data(), prefix.size()) == 0;
}

const std::string_view kExrMagic("\x76\x2f\x31\x01", 4);

bool is_radiance(const std::vector<unsigned char>& bytes) {
    return starts_with(bytes, "#?RADIANCE\n") || starts_with(bytes, "#?RGBE\n");
}

// What a file that is neither format is, for the message.
std::string describe_other(const std::vector<unsigned char>& bytes) {
    if (starts_with(bytes, "\x89PNG\r\n\x1a\n")) return "a PNG image, not an HDR image";
    if (starts_with(bytes, "\xff\xd8\xff")) return "a JPEG image, not an HDR image";
    if (starts_with(bytes, "#?")) return "a Radiance file of an unsupported kind";
    return "not a Radiance .hdr or OpenEXR file";
}

// Throws unless width x height is within the side and byte limits.
void check_dimensions(const fs::path& path, std::int64_t width, std::int64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width <= 0 || height <= 0) fail_read(path, "image is " + size);
    if (width > kMaxHdrImageSide || height > kMaxHdrImageSide) {
        fail_read(path, "image too large (" + size + "; at most " +
                            std::to_string(kMaxHdrImageSide) + " a side)");
    }
    if (std::uint64_t(width) * std::uint64_t(height) * 3 * sizeof(float) > kMaxHdrImageBytes) {
        fail_read(path, "image too large (" + size + "; at most " +
                            std::to_string(kMaxHdrImageBytes >> 20) + " MiB decoded)");
    }
}

// ---- Radiance .hdr ----

// Where the scanlines start and the image's size, from the text header as stb_image reads it:
// the magic line, variable lines up to an empty one (stb_image takes a line starting with a NUL
// as empty too), then the resolution line.
struct RadianceHeader {
    std::size_t data_offset = 0;
    int width = 0;
    int height = 0;
};

RadianceHeader parse_radiance_header(const fs::path& path,
                                     const std::vector<unsigned char>& bytes) {
    std::size_t position = 0;
    // The next line without its '\n', or nothing at the end of the file.
    auto next_line = [&]() -> std::optional<std::string_view> {
        const auto* begin = bytes.data() + position;
        const auto* end = bytes.data() + bytes.size();
        const auto* newline = std::find(begin, end, static_cast<unsigned char>('\n'));
        if (newline == end) return std::nullopt;
        position = static_cast<std::size_t>(newline - bytes.data()) + 1;
        return std::string_view(reinterpret_cast<const char*>(begin),
                                static_cast<std::size_t>(newline - begin));
    };
    next_line();  // the magic, checked by the caller
    bool rgbe = false;
    std::string format;
    for (;;) {
        const std::optional<std::string_view> line = next_line();
        if (!line) fail_read(path, "truncated header");
        if (line->empty() || line->front() == '\0') break;
        if (line->substr(0, 7) == "FORMAT=") format = std::string(line->substr(7, 40));
        if (*line == "FORMAT=32-bit_rle_rgbe") rgbe = true;
    }
    if (!rgbe) {
        fail_read(path, format.empty() ? "no FORMAT=32-bit_rle_rgbe line in the header"
                                       : "unsupported pixel format '" + one_line(format) +
                                             "' (only 32-bit_rle_rgbe)");
    }
    const std::optional<std::string_view> resolution = next_line();
    if (!resolution) fail_read(path, "truncated header (no resolution line)");
    // stb_image's own reading of the header decides the size it decodes; ours must agree.
    int width = 0;
    int height = 0;
    int components = 0;
    const int recognised = stbi_info_from_memory(bytes.data(), static_cast<int>(bytes.size()),
                                                 &width, &height, &components);
    if (!recognised || resolution->substr(0, 3) != "-Y ") {
        fail_read(path, "unsupported resolution line '" +
                            one_line(std::string(resolution->substr(0, 40))) +
                            "' (only \"-Y height +X width\": top row first)");
    }
    check_dimensions(path, width, height);
    return {position, width, height};
}

// Walks the scanlines exactly as stb_image 2.27 decodes them and throws unless they are whole
// and well-formed. stb_image itself reads zeros past the end of its input, so a truncated flat
// file decodes silently as black and a truncated run-length-encoded scanline as an endless
// series of zero-length runs: it hangs (CVE-2021-42715, unfixed in Debian 12's copy). It also
// restarts from the top on an unencoded scanline after encoded ones. Once this check has passed,
// none of that can happen. Zero-length literal runs, which no writer emits, are refused too.
void check_radiance_scanlines(const fs::path& path, const std::vector<unsigned char>& bytes,
                              const RadianceHeader& header) {
    std::size_t position = header.data_offset;
    const std::size_t size = bytes.size();
    const std::size_t width = std::size_t(header.width);
    const std::size_t flat_bytes = 4 * width * std::size_t(header.height);
    auto truncated = [&](std::size_t row) {
        fail_read(path, "truncated (scanline " + std::to_string(row) + " of " +
                            std::to_string(header.height) + " is incomplete)");
    };
    const bool may_encode = width >= 8 && width < 32768;
    const bool encoded = may_encode && size - position >= 3 && bytes[position] == 2 &&
                         bytes[position + 1] == 2 && (bytes[position + 2] & 0x80) == 0;
    if (!encoded) {
        if (size - position < flat_bytes) truncated((size - position) / (4 * width));
        return;
    }
    for (std::size_t row = 0; row < std::size_t(header.height); ++row) {
        if (size - position < 4) truncated(row);
        const unsigned char* start = bytes.data() + position;
        if (start[0] != 2 || start[1] != 2 || (start[2] & 0x80) != 0) {
            fail_read(path, "corrupt: scanline " + std::to_string(row) +
                                " is not run-length encoded but the first one is");
        }
        if ((std::size_t(start[2]) << 8 | start[3]) != width) {
            fail_read(path, "corrupt: scanline " + std::to_string(row) + " has the wrong length");
        }
        position += 4;
        for (int component = 0; component < 4; ++component) {
            std::size_t filled = 0;
            while (filled < width) {
                if (position >= size) truncated(row);
                const unsigned count = bytes[position++];
                const std::size_t run = count > 128 ? count - 128 : count;
                if (run == 0 || run > width - filled) {
                    fail_read(path, "corrupt: bad run length in scanline " + std::to_string(row));
                }
                const std::size_t stored = count > 128 ? 1 : run;
                if (size - position < stored) truncated(row);
                position += stored;
                filled += run;
            }
        }
    }
}

HdrImage read_radiance(const fs::path& path, const std::vector<unsigned char>& bytes) {
    const RadianceHeader header = parse_radiance_header(path, bytes);
    check_radiance_scanlines(path, bytes, header);
    int width = 0;
    int height = 0;
    int components = 0;
    std::unique_ptr<float, decltype(&stbi_image_free)> pixels(
        stbi_loadf_from_memory(bytes.data(), static_cast<int>(bytes.size()), &width, &height,
                               &components, 3),
        &stbi_image_free);
    if (pixels == nullptr) fail_read(path, one_line(stbi_failure_reason()));
    if (width != header.width || height != header.height) fail_read(path, "corrupt header");
    HdrImage image;
    image.width = width;
    image.height = height;
    // RGBE holds no negative or non-finite values: nothing to clamp or refuse.
    image.rgb.assign(pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 3);
    return image;
}

// ---- OpenEXR ----

// OpenEXR reads through this view of the bytes already in memory.
class MemoryIStream final : public Imf::IStream {
public:
    MemoryIStream(const std::vector<unsigned char>& bytes, const std::string& name)
        : Imf::IStream(name.c_str()), bytes_(bytes) {}

    bool isMemoryMapped() const override { return true; }
    char* readMemoryMapped(int n) override {
        char* start = const_cast<char*>(reinterpret_cast<const char*>(bytes_.data())) + position_;
        advance(n);
        return start;
    }
    bool read(char c[], int n) override {
        const std::size_t start = position_;
        advance(n);
        std::memcpy(c, bytes_.data() + start, std::size_t(n));
        return position_ < bytes_.size();
    }
    uint64_t tellg() override { return position_; }
    void seekg(uint64_t position) override {
        if (position > bytes_.size()) throw std::runtime_error("seek past the end of the file");
        position_ = static_cast<std::size_t>(position);
    }

private:
    void advance(int n) {
        if (n < 0 || std::size_t(n) > bytes_.size() - position_) {
            throw std::runtime_error("unexpected end of file");
        }
        position_ += std::size_t(n);
    }

    const std::vector<unsigned char>& bytes_;
    std::size_t position_ = 0;
};

// Bytes of each fixed-size attribute type OpenEXR 3.1 knows. It reads these many whatever the
// attribute's size field says.
std::optional<std::size_t> fixed_attribute_bytes(std::string_view type) {
    static const std::pair<std::string_view, std::size_t> kSizes[] = {
        {"box2i", 16},      {"box2f", 16},    {"v2i", 8},      {"v2f", 8},
        {"v2d", 16},        {"v3i", 12},      {"v3f", 12},     {"v3d", 24},
        {"m33f", 36},       {"m33d", 72},     {"m44f", 64},    {"m44d", 128},
        {"int", 4},         {"float", 4},     {"double", 8},   {"rational", 8},
        {"compression", 1}, {"lineOrder", 1}, {"envmap", 1},   {"deepImageState", 1},
        {"tiledesc", 9},    {"keycode", 28},  {"timecode", 8}, {"chromaticities", 32},
    };
    for (const auto& [name, bytes] : kSizes) {
        if (name == type) return bytes;
    }
    return std::nullopt;
}

// Little-endian 32-bit value at `at`; the caller has checked the bytes are there.
std::uint32_t read_u32(const std::vector<unsigned char>& bytes, std::size_t at) {
    return std::uint32_t(bytes[at]) | std::uint32_t(bytes[at + 1]) << 8 |
           std::uint32_t(bytes[at + 2]) << 16 | std::uint32_t(bytes[at + 3]) << 24;
}

// Walks the attributes of the file's headers (name, type, byte size, value) as OpenEXR 3.1
// reads them, and throws unless each value fits in the file and, where OpenEXR decides how much
// to read or allocate from the value itself, agrees with its size field. OpenEXR 3.1 allocates
// what a header says before reading it (an unknown type's value, a string, a preview image, a
// string list's entries), so a 100-byte file could otherwise make it allocate gigabytes; and it
// reads a fixed-size type's natural size whatever the size field says, which this walk must
// follow to stay in step with it.
void check_exr_header(const fs::path& path, const std::vector<unsigned char>& bytes) {
    constexpr std::uint32_t kLongNamesFlag = 0x400;
    constexpr std::uint32_t kMultipartFlag = 0x1000;
    const std::size_t size = bytes.size();
    if (size < 8) fail_read(path, "truncated header");
    const std::uint32_t version = read_u32(bytes, 4);
    const std::size_t max_name = (version & kLongNamesFlag) != 0 ? 256 : 32;  // with the NUL
    auto corrupt = [&](const std::string& what) {
        fail_read(path, "corrupt header (" + what + ")");
    };
    // The NUL-terminated string at `at` (at most `limit` bytes with the NUL); `at` moves past it.
    auto read_name = [&](std::size_t& at, std::size_t limit) -> std::string_view {
        const auto* begin = bytes.data() + at;
        const auto* end = bytes.data() + std::min(size, at + limit);
        const auto* nul = std::find(begin, end, static_cast<unsigned char>(0));
        if (nul == end) corrupt("a name is unterminated or too long");
        at += std::size_t(nul - begin) + 1;
        return {reinterpret_cast<const char*>(begin), std::size_t(nul - begin)};
    };
    std::size_t position = 8;
    for (;;) {
        for (;;) {
            const std::string_view name = read_name(position, max_name);
            if (name.empty()) break;
            const std::string_view type = read_name(position, max_name);
            if (size - position < 4) fail_read(path, "truncated header");
            const std::size_t value_bytes = read_u32(bytes, position);
            position += 4;
            if (value_bytes > size - position) {
                fail_read(path, "corrupt or truncated header (an attribute of " +
                                    std::to_string(value_bytes) + " bytes)");
            }
            const std::size_t value = position;
            const std::size_t value_end = position + value_bytes;
            const std::string label = "attribute '" + printable(std::string(name)) + "'";
            if (const auto fixed = fixed_attribute_bytes(type)) {
                if (value_bytes != *fixed) corrupt(label + " has the wrong size");
            } else if (type == "chlist") {
                std::size_t at = value;
                while (at < value_end && bytes[at] != 0) {
                    read_name(at, 256);
                    at += 16;  // pixel type, linear flag, reserved, x and y sampling
                }
                if (at + 1 != value_end) corrupt(label + " has the wrong size");
            } else if (type == "preview") {
                const std::uint64_t pixels =
                    value_bytes < 8
                        ? 0
                        : std::uint64_t(read_u32(bytes, value)) * read_u32(bytes, value + 4);
                if (value_bytes < 8 || pixels * 4 + 8 != value_bytes) {
                    corrupt(label + " has the wrong size");
                }
            } else if (type == "stringvector") {
                std::size_t at = value;
                while (at < value_end) {
                    if (value_end - at < 4 || read_u32(bytes, at) > value_end - at - 4) {
                        corrupt(label + " has the wrong size");
                    }
                    at += 4 + read_u32(bytes, at);
                }
            } else if (type == "floatvector") {
                if (value_bytes % 4 != 0) corrupt(label + " has the wrong size");
            } else if (type == "idmanifest") {
                fail_read(path, "unsupported " + label + " of type idmanifest");
            }
            // Anything else (a string, or a type OpenEXR does not know) is read at its size.
            position = value_end;
        }
        // Multi-part files list headers up to an empty one; single-part files have one.
        if ((version & kMultipartFlag) == 0) return;
        if (position >= size) fail_read(path, "truncated header");
        if (bytes[position] == 0) return;
    }
}

// Set before every read: a tiled still's EXR writer raises the image size limit for itself.
void limit_openexr_allocations() {
    Imf::Header::setMaxImageSize(kMaxHdrImageSide, kMaxHdrImageSide);
    Imf::Header::setMaxTileSize(kMaxExrTileSide, kMaxExrTileSide);
}

HdrImage read_openexr(const fs::path& path, const std::vector<unsigned char>& bytes) {
    check_exr_header(path, bytes);
    limit_openexr_allocations();
    HdrImage image;
    try {
        MemoryIStream stream(bytes, path.string());
        Imf::InputFile input(stream);
        const Imf::Header& header = input.header();
        const Imath::Box2i window = header.dataWindow();
        const std::int64_t width = std::int64_t(window.max.x) - window.min.x + 1;
        const std::int64_t height = std::int64_t(window.max.y) - window.min.y + 1;
        check_dimensions(path, width, height);
        const Imf::ChannelList& channels = header.channels();
        for (const char* name : {"R", "G", "B"}) {
            const Imf::Channel* channel = channels.findChannel(name);
            if (channel == nullptr) {
                std::string found;
                int listed = 0;
                for (auto it = channels.begin(); it != channels.end() && listed < 8; ++it) {
                    found += (listed++ == 0 ? "" : ", ") + std::string(it.name());
                }
                fail_read(path, "no R, G and B channels (it has: " +
                                    (found.empty() ? std::string("none") : one_line(found)) + ")");
            }
            if (channel->xSampling != 1 || channel->ySampling != 1) {
                fail_read(path, std::string("channel ") + name + " is subsampled");
            }
        }
        if (!input.isComplete()) fail_read(path, "truncated or corrupt (pixels are missing)");
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        image.rgb.assign(std::size_t(width) * std::size_t(height) * 3, 0.0f);
        Imf::FrameBuffer frame;
        const std::size_t pixel_stride = 3 * sizeof(float);
        const std::size_t row_stride = pixel_stride * std::size_t(width);
        for (int c = 0; c < 3; ++c) {
            frame.insert(c == 0   ? "R"
                         : c == 1 ? "G"
                                  : "B",
                         Imf::Slice::Make(Imf::FLOAT, image.rgb.data() + c, window, pixel_stride,
                                          row_stride));
        }
        input.setFrameBuffer(frame);
        input.readPixels(window.min.y, window.max.y);
    } catch (const ReadFailure&) {
        throw;
    } catch (const std::exception& error) {
        fail_read(path, one_line(error.what()));
    }
    for (std::size_t i = 0; i < image.rgb.size(); ++i) {
        float& value = image.rgb[i];
        if (!std::isfinite(value)) {
            const std::size_t pixel = i / 3;
            fail_read(path, std::string(std::isnan(value) ? "NaN" : "infinite") +
                                " value at pixel (" + std::to_string(pixel % image.width) + ", " +
                                std::to_string(pixel / image.width) + ")");
        }
        if (value <= 0.0f) value = 0.0f;
    }
    return image;
}

// ---- Writing ----

void validate_hdr_image(const fs::path& path, const HdrImage& image) {
    if (image.width <= 0 || image.height <= 0) {
        fail_argument(
            path, "image is " + std::to_string(image.width) + "x" + std::to_string(image.height));
    }
    const std::size_t expected =
        std::size_t{3} * std::size_t(image.width) * std::size_t(image.height);
    if (image.rgb.size() != expected) {
        fail_argument(path, std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " image needs " + std::to_string(expected) + " samples, has " +
                                std::to_string(image.rgb.size()));
    }
}

// stb_image_write hands the encoded bytes to this sink, which appends them to a file.
struct FileSink {
    std::FILE* file = nullptr;
    int error = 0;
};

void write_to_sink(void* context, void* data, int size) {
    auto* sink = static_cast<FileSink*>(context);
    if (sink->error != 0 || size <= 0) return;
    if (std::fwrite(data, 1, std::size_t(size), sink->file) != std::size_t(size)) {
        sink->error = errno != 0 ? errno : EIO;
    }
}

// OpenEXR writes through this stream onto a FILE*, so the file can be fsync'd before the rename.
class FileOStream final : public Imf::OStream {
public:
    FileOStream(std::FILE* file, const std::string& name)
        : Imf::OStream(name.c_str()), file_(file) {}

    void write(const char c[], int n) override {
        if (n < 0 || std::fwrite(c, 1, std::size_t(n), file_) != std::size_t(n)) {
            throw std::runtime_error(errno_message(errno != 0 ? errno : EIO));
        }
    }
    uint64_t tellp() override {
        const off_t position = ::ftello(file_);
        if (position < 0) throw std::runtime_error(errno_message(errno));
        return static_cast<uint64_t>(position);
    }
    void seekp(uint64_t position) override {
        if (::fseeko(file_, static_cast<off_t>(position), SEEK_SET) != 0) {
            throw std::runtime_error(errno_message(errno));
        }
    }

private:
    std::FILE* file_;
};

bool well_formed_name(std::string_view name, bool may_hold_dots) {
    if (name.empty() || name.front() == '.' || name.back() == '.') return false;
    if (name.find("..") != std::string_view::npos) return false;
    return std::all_of(name.begin(), name.end(), [&](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte >= 0x20 && byte != 0x7f && (may_hold_dots || c != '.');
    });
}

// The full channel names, in layer order; throws for a bad layer.
std::vector<std::string> exr_channel_names(const fs::path& path, int width, int height,
                                           const std::vector<ExrLayer>& layers) {
    if (width <= 0 || height <= 0) {
        fail_argument(path, "image is " + std::to_string(width) + "x" + std::to_string(height));
    }
    if (layers.empty()) fail_argument(path, "no layers to write");
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<std::string> names;
    std::set<std::string> seen;
    for (const ExrLayer& layer : layers) {
        const std::string label = "layer '" + printable(layer.name) + "'";
        if (!layer.name.empty() && !well_formed_name(layer.name, true)) {
            fail_argument(path, "bad " + label + " name");
        }
        if (layer.channels.empty()) fail_argument(path, label + " has no channels");
        if (layer.values.size() != pixels * layer.channels.size()) {
            fail_argument(path, label + " needs " + std::to_string(pixels) + " x " +
                                    std::to_string(layer.channels.size()) + " values, has " +
                                    std::to_string(layer.values.size()));
        }
        for (const std::string& channel : layer.channels) {
            if (!well_formed_name(channel, false)) {
                fail_argument(path, label + " has a bad channel name '" + printable(channel) + "'");
            }
            std::string name = layer.name.empty() ? channel : layer.name + "." + channel;
            if (name.size() > kMaxExrNameBytes) fail_argument(path, "channel name too long");
            if (!seen.insert(name).second) {
                fail_argument(path, "channel '" + name + "' appears twice");
            }
            names.push_back(std::move(name));
        }
    }
    return names;
}

std::string encode_exr(const fs::path& temporary, int width, int height,
                       const std::vector<ExrLayer>& layers, const std::vector<std::string>& names,
                       const std::string& embedded_view) {
    FilePointer owned(std::fopen(temporary.c_str(), "wb"));
    if (owned == nullptr) return errno_message(errno);
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        header.lineOrder() = Imf::INCREASING_Y;
        if (!embedded_view.empty()) {
            header.insert(kExrViewAttribute, Imf::StringAttribute(embedded_view));
        }
        Imf::FrameBuffer frame;
        std::size_t next = 0;
        for (const ExrLayer& layer : layers) {
            const std::size_t pixel_stride = layer.channels.size() * sizeof(float);
            for (std::size_t c = 0; c < layer.channels.size(); ++c) {
                const std::string& name = names[next++];
                header.channels().insert(name, Imf::Channel(Imf::FLOAT));
                char* base = reinterpret_cast<char*>(const_cast<float*>(layer.values.data() + c));
                frame.insert(name, Imf::Slice(Imf::FLOAT, base, pixel_stride,
                                              pixel_stride * std::size_t(width)));
            }
        }
        FileOStream stream(owned.get(), temporary.string());
        // The line offset table is written when the file object is destroyed.
        {
            Imf::OutputFile output(stream, header);
            output.setFrameBuffer(frame);
            output.writePixels(height);
        }
    } catch (const std::exception& error) {
        return one_line(error.what());
    }
    if (std::ferror(owned.get())) return "write error";
    std::FILE* file = owned.release();
    return close_durably(file);
}

void replace_or_throw(const fs::path& file,
                      const std::function<std::string(const fs::path&)>& write_temporary) {
    const std::string failure = replace_file_atomically(file, write_temporary);
    if (!failure.empty()) fail_write(file, one_line(failure));
}

}  // namespace

HdrImage read_hdr_image(const fs::path& file) {
    const std::vector<unsigned char> bytes = read_image_file(file);
    if (is_radiance(bytes)) return read_radiance(file, bytes);
    if (starts_with(bytes, kExrMagic)) return read_openexr(file, bytes);
    fail_read(file, describe_other(bytes));
}

void write_radiance_hdr(const fs::path& file, const HdrImage& image) {
    validate_hdr_image(file, image);
    std::vector<float> values(image.rgb);
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            const std::size_t pixel = i / 3;
            fail_argument(file, std::string(std::isnan(values[i]) ? "NaN" : "infinite") +
                                    " value at pixel (" + std::to_string(pixel % image.width) +
                                    ", " + std::to_string(pixel / image.width) + ")");
        }
        if (values[i] <= 0.0f) values[i] = 0.0f;
    }
    replace_or_throw(file, [&](const fs::path& temporary) -> std::string {
        FileSink sink;
        FilePointer owned(std::fopen(temporary.c_str(), "wb"));
        if (owned == nullptr) return errno_message(errno);
        sink.file = owned.get();
        if (!stbi_write_hdr_to_func(write_to_sink, &sink, image.width, image.height, 3,
                                    values.data())) {
            return "stb_image_write failed";
        }
        if (sink.error != 0) return errno_message(sink.error);
        std::FILE* written = owned.release();
        return close_durably(written);
    });
}

void write_exr(const fs::path& file, int width, int height, const std::vector<ExrLayer>& layers,
               const std::string& embedded_view) {
    const std::vector<std::string> names = exr_channel_names(file, width, height, layers);
    check_embedded_view(file, embedded_view);
    replace_or_throw(file, [&](const fs::path& temporary) {
        return encode_exr(temporary, width, height, layers, names, embedded_view);
    });
}

}  // namespace fgr
