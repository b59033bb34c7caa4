// SPDX-License-Identifier: Apache-2.0
// Reading the embedded view by walking each format's structure with bounded reads (image/
// embedded_view.hpp). The libraries' own readers are not used for this: libpng skips a text chunk
// past its allocation limit without saying so, OpenEXR 3.1 allocates what an untrusted header
// asks before reading it (hdr_io.cpp's check_exr_header), and libtiff reads every tag of the
// directory through global error handlers. A walk of a few chunks, attributes or tags is short,
// reads nothing it does not need and can refuse anything out of bounds with a reason.
#include "image/embedded_view.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "util/errors.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {
// A namespace of its own: the image library compiles as one unity batch with hdr_io.cpp and
// image_io.cpp, whose helpers have the same kind of names.
namespace view_walk {

namespace fs = std::filesystem;

// Chunks before a PNG's pixels, attributes of an EXR header, tags of a TIFF directory: real files
// have tens; a crafted one could make the walk read millions of tiny records.
constexpr std::size_t kMaxRecords = 4096;
// Room around the text in a PNG iTXt chunk: the keyword, flags, language tag and translated
// keyword (at most 79 bytes each by the PNG specification, more from careless writers), and the
// zlib stream's framing when the text is compressed.
constexpr std::size_t kMaxItxtOverhead = 64 * 1024;

[[noreturn]] void refuse(const fs::path& file, const std::string& reason) {
    throw std::runtime_error("cannot read " + quoted(file) + ": " + reason);
}

std::string over_limit(std::uint64_t bytes) {
    return "the embedded view is " + std::to_string(bytes) + " bytes (at most " +
           std::to_string(kMaxEmbeddedViewBytes) + ")";
}

// An open file descriptor, closed by its owner, also when the owner's constructor throws.
struct Descriptor {
    int number = -1;
    Descriptor() = default;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor() {
        if (number >= 0) ::close(number);
    }
};

// A regular file opened for reading at given offsets, every read within its size.
class BoundedFile {
public:
    explicit BoundedFile(const fs::path& file) : file_(file) {
        // Refused before opening: opening a FIFO for reading waits for a writer.
        std::error_code error;
        const fs::file_status status = fs::status(file, error);
        if (error && error != std::errc::no_such_file_or_directory) refuse(file, error.message());
        if (!fs::exists(status)) refuse(file, "no such file");
        if (fs::is_directory(status)) refuse(file, "is a directory");
        if (!fs::is_regular_file(status)) refuse(file, "not a regular file");
        // O_NONBLOCK: should something else be there by now, the open does not wait for it either.
        descriptor_.number = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
        if (descriptor_.number < 0) refuse(file, errno_message(errno));
        struct stat opened {};
        if (::fstat(descriptor_.number, &opened) != 0) refuse(file, errno_message(errno));
        if (!S_ISREG(opened.st_mode)) refuse(file, "not a regular file");
        size_ = static_cast<std::uint64_t>(opened.st_size);
        if (size_ == 0) refuse(file, "empty file");
    }
    std::uint64_t size() const { return size_; }
    const fs::path& path() const { return file_; }
    bool holds(std::uint64_t offset, std::uint64_t bytes) const {
        return offset <= size_ && bytes <= size_ - offset;
    }

    // `bytes` bytes at `offset`; refuses the file as `truncated` when they are not all there.
    void read(std::uint64_t offset, std::size_t bytes, unsigned char* out,
              const std::string& truncated) const {
        if (!holds(offset, bytes)) refuse(file_, truncated);
        std::size_t done = 0;
        while (done < bytes) {
            const ssize_t got = ::pread(descriptor_.number, out + done, bytes - done,
                                        static_cast<off_t>(offset + done));
            if (got < 0 && errno == EINTR) continue;
            if (got < 0) refuse(file_, errno_message(errno));
            if (got == 0) refuse(file_, truncated);  // it shrank since fstat
            done += static_cast<std::size_t>(got);
        }
    }
    std::vector<unsigned char> read(std::uint64_t offset, std::size_t bytes,
                                    const std::string& truncated) const {
        if (!holds(offset, bytes)) refuse(file_, truncated);  // before allocating for it
        std::vector<unsigned char> out(bytes);
        read(offset, bytes, out.data(), truncated);
        return out;
    }
    // Up to `bytes` bytes at `offset`, fewer at the end of the file.
    std::vector<unsigned char> read_some(std::uint64_t offset, std::size_t bytes) const {
        if (offset >= size_) return {};
        return read(offset,
                    static_cast<std::size_t>(std::min<std::uint64_t>(bytes, size_ - offset)),
                    "truncated");
    }

private:
    fs::path file_;
    Descriptor descriptor_;
    std::uint64_t size_ = 0;
};

std::uint32_t big_endian_32(const unsigned char* bytes) {
    return std::uint32_t(bytes[0]) << 24 | std::uint32_t(bytes[1]) << 16 |
           std::uint32_t(bytes[2]) << 8 | std::uint32_t(bytes[3]);
}

// The text up to the first NUL of `bytes` from `at`, which moves past the NUL; nullopt when there
// is none.
std::optional<std::string> text_to_nul(const std::vector<unsigned char>& bytes, std::size_t& at) {
    const auto begin = bytes.begin() + static_cast<std::ptrdiff_t>(std::min(at, bytes.size()));
    const auto nul = std::find(begin, bytes.end(), static_cast<unsigned char>(0));
    if (nul == bytes.end()) return std::nullopt;
    std::string text(begin, nul);
    at = static_cast<std::size_t>(nul - bytes.begin()) + 1;
    return text;
}

// ---- PNG ----

constexpr std::string_view kPngSignature("\x89PNG\r\n\x1a\n", 8);

// A zlib stream inflated to at most kMaxEmbeddedViewBytes.
std::string inflate_view(const fs::path& file, const unsigned char* data, std::size_t size) {
    z_stream stream{};
    if (inflateInit(&stream) != Z_OK) refuse(file, "out of memory");
    std::string text;
    std::array<unsigned char, 16384> buffer{};
    stream.next_in = const_cast<unsigned char*>(data);
    stream.avail_in = static_cast<uInt>(size);
    int status = Z_OK;
    while (status == Z_OK) {
        stream.next_out = buffer.data();
        stream.avail_out = static_cast<uInt>(buffer.size());
        status = inflate(&stream, Z_NO_FLUSH);
        text.append(reinterpret_cast<const char*>(buffer.data()), buffer.size() - stream.avail_out);
        if (text.size() > kMaxEmbeddedViewBytes) {
            inflateEnd(&stream);
            refuse(file, "the embedded view is over " + std::to_string(kMaxEmbeddedViewBytes) +
                             " bytes once inflated");
        }
    }
    inflateEnd(&stream);
    if (status != Z_STREAM_END) {
        refuse(file, "corrupt (the fgr:view chunk's text does not inflate)");
    }
    return text;
}

// The document in an iTXt chunk's data: keyword, compression flag and method, language tag,
// translated keyword, text (PNG specification, 11.3.4.5).
std::string png_view_text(const fs::path& file, const std::vector<unsigned char>& data) {
    std::size_t at = 0;
    const auto corrupt = [&] { refuse(file, "corrupt (the fgr:view chunk is malformed)"); };
    if (!text_to_nul(data, at) || data.size() - at < 2) corrupt();
    const unsigned char compressed = data[at];
    const unsigned char method = data[at + 1];
    at += 2;
    if (compressed > 1 || method != 0 || !text_to_nul(data, at) || !text_to_nul(data, at)) {
        corrupt();
    }
    const unsigned char* text = data.data() + at;
    const std::size_t size = data.size() - at;
    if (compressed == 1) return inflate_view(file, text, size);
    if (size > kMaxEmbeddedViewBytes) refuse(file, over_limit(size));
    return std::string(reinterpret_cast<const char*>(text), size);
}

// fgr writes the view before the pixels, so the walk ends at the first IDAT.
std::optional<std::string> read_png_view(const BoundedFile& file) {
    std::uint64_t offset = kPngSignature.size();
    for (std::size_t chunk = 0; chunk < kMaxRecords; ++chunk) {
        unsigned char header[8];
        file.read(offset, sizeof header, header, "truncated (it ends before the image data)");
        const std::uint32_t length = big_endian_32(header);
        const std::string type(reinterpret_cast<const char*>(header + 4), 4);
        if (length > 0x7fffffffu) refuse(file.path(), "corrupt (a chunk length is out of range)");
        if (chunk == 0 && (type != "IHDR" || length != 13)) {
            refuse(file.path(), "corrupt (the first chunk is not a header)");
        }
        if (!file.holds(offset + 8, std::uint64_t(length) + 4)) {
            refuse(file.path(), "truncated (in a chunk before the image data)");
        }
        if (type == "IDAT" || type == "IEND") return std::nullopt;
        if (type == "iTXt") {
            // The keyword first: other programs' iTXt chunks (XMP) may be large and are not read.
            const std::vector<unsigned char> start =
                file.read_some(offset + 8, std::min(length, 80u));
            std::size_t at = 0;
            if (text_to_nul(start, at) == std::string(kPngViewKeyword)) {
                if (length > kMaxEmbeddedViewBytes + kMaxItxtOverhead) {
                    refuse(file.path(), over_limit(length));
                }
                const std::vector<unsigned char> chunk_bytes =
                    file.read(offset + 4, std::size_t(length) + 8, "truncated");
                const std::uint32_t stored = big_endian_32(chunk_bytes.data() + 4 + length);
                if (crc32(crc32(0, nullptr, 0), chunk_bytes.data(), uInt(length + 4)) != stored) {
                    refuse(file.path(), "corrupt (the fgr:view chunk fails its checksum)");
                }
                return png_view_text(file.path(),
                                     std::vector<unsigned char>(chunk_bytes.begin() + 4,
                                                                chunk_bytes.begin() + 4 + length));
            }
        }
        offset += std::uint64_t(length) + 12;
    }
    refuse(file.path(),
           "corrupt (over " + std::to_string(kMaxRecords) + " chunks before the image data)");
}

// ---- OpenEXR ----

constexpr std::string_view kExrMagicBytes("\x76\x2f\x31\x01", 4);

std::uint32_t little_endian_32(const unsigned char* bytes) {
    return std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 | std::uint32_t(bytes[2]) << 16 |
           std::uint32_t(bytes[3]) << 24;
}

// The first (for fgr's single-part files, the only) header's attributes: name, type, size,
// value (OpenEXR file layout, "Header"). The walk reaches the header's end, so a header cut short
// is refused even after the view.
std::optional<std::string> read_exr_view(const BoundedFile& file) {
    constexpr std::uint32_t kLongNames = 0x400;
    unsigned char start[8];
    file.read(0, sizeof start, start, "truncated header");
    const std::uint32_t version = little_endian_32(start + 4);
    if ((version & 0xff) != 2) {
        refuse(file.path(), "unsupported OpenEXR version " + std::to_string(version & 0xff));
    }
    const std::size_t max_name = (version & kLongNames) != 0 ? 256 : 32;  // with the NUL
    std::optional<std::string> view;
    bool has_channels = false;
    std::uint64_t offset = 8;
    for (std::size_t attribute = 0; attribute < kMaxRecords; ++attribute) {
        // Name and type: each up to max_name bytes with its NUL.
        const std::vector<unsigned char> names = file.read_some(offset, 2 * max_name + 4);
        std::size_t at = 0;
        const auto bad_name = [&] { refuse(file.path(), "truncated or corrupt header"); };
        const std::optional<std::string> name = text_to_nul(names, at);
        if (!name || name->size() >= max_name) bad_name();
        if (name->empty()) {
            if (!has_channels) refuse(file.path(), "corrupt header (no channels)");
            return view;
        }
        const std::size_t type_at = at;
        const std::optional<std::string> type = text_to_nul(names, at);
        if (!type || type->empty() || at - type_at > max_name || names.size() - at < 4) bad_name();
        const std::uint32_t size = little_endian_32(names.data() + at);
        offset += at + 4;
        if (!file.holds(offset, size)) refuse(file.path(), "truncated or corrupt header");
        if (*name == "channels") has_channels = true;
        if (*name == kExrViewAttribute && !view) {
            if (*type != "string") {
                refuse(file.path(),
                       "corrupt header (fgrView is of type '" + *type + "', not a string)");
            }
            if (size > kMaxEmbeddedViewBytes) refuse(file.path(), over_limit(size));
            const std::vector<unsigned char> value = file.read(offset, size, "truncated header");
            view.emplace(value.begin(), value.end());
        }
        offset += size;
    }
    refuse(file.path(), "corrupt header (over " + std::to_string(kMaxRecords) + " attributes)");
}

// ---- TIFF ----

// Classic TIFF and BigTIFF, either byte order (TIFF 6.0 section 2; BigTIFF's 8-byte offsets).
class TiffWalk {
public:
    explicit TiffWalk(const BoundedFile& file) : file_(file) {
        unsigned char header[16] = {};
        file.read(0, 8, header, "truncated header");
        big_endian_ = header[0] == 'M';
        big_tiff_ = number(header + 2, 2) == 43;
        if (big_tiff_) {
            file.read(8, 8, header + 8, "truncated header");
            if (number(header + 4, 2) != 8) refuse(file.path(), "corrupt BigTIFF header");
        }
        first_directory_ = big_tiff_ ? number(header + 8, 8) : number(header + 4, 4);
    }

    std::optional<std::string> view() const {
        const std::size_t count_bytes = big_tiff_ ? 8 : 2;
        const std::size_t entry_bytes = big_tiff_ ? 20 : 12;
        if (first_directory_ < 8) refuse(file_.path(), "corrupt (no image directory)");
        const std::vector<unsigned char> count_field =
            file_.read(first_directory_, count_bytes, "truncated (the image directory is missing)");
        const std::uint64_t count = number(count_field.data(), count_bytes);
        if (count == 0 || count > kMaxRecords) {
            refuse(file_.path(),
                   "corrupt (an image directory of " + std::to_string(count) + " tags)");
        }
        const std::vector<unsigned char> entries =
            file_.read(first_directory_ + count_bytes, std::size_t(count) * entry_bytes,
                       "truncated (in the image directory)");
        const unsigned char* description = nullptr;
        const unsigned char* software = nullptr;
        bool has_width = false;
        bool has_length = false;
        for (std::size_t i = 0; i < count; ++i) {
            const unsigned char* entry = entries.data() + i * entry_bytes;
            switch (number(entry, 2)) {
                case 256:
                    has_width = true;
                    break;
                case 257:
                    has_length = true;
                    break;
                case 270:
                    description = entry;
                    break;
                case 305:
                    software = entry;
                    break;
                default:
                    break;
            }
        }
        if (!has_width || !has_length) {
            refuse(file_.path(), "corrupt (the image directory has no width or length)");
        }
        if (software == nullptr || description == nullptr) return std::nullopt;
        const std::optional<std::string> writer = ascii(software, 256);
        if (!writer || *writer != kTiffViewSoftware) return std::nullopt;
        std::optional<std::string> text = ascii(description, kMaxEmbeddedViewBytes + 1);
        if (!text) refuse(file_.path(), "corrupt (the image description is not text)");
        return text;
    }

private:
    std::uint64_t number(const unsigned char* bytes, std::size_t size) const {
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < size; ++i) {
            const unsigned char byte = big_endian_ ? bytes[i] : bytes[size - 1 - i];
            value = value << 8 | byte;
        }
        return value;
    }

    // An ASCII tag's text up to its first NUL; nullopt for another type. A count past `limit`
    // bytes (the terminating NUL included) is refused: only the view's tag is read at its size.
    std::optional<std::string> ascii(const unsigned char* entry, std::uint64_t limit) const {
        constexpr std::uint64_t kAscii = 2;
        if (number(entry + 2, 2) != kAscii) return std::nullopt;
        const std::size_t field = big_tiff_ ? 8 : 4;
        const std::uint64_t count = number(entry + 4, field);
        const unsigned char* value = entry + 4 + field;
        if (count > limit) {
            if (limit > kMaxEmbeddedViewBytes) refuse(file_.path(), over_limit(count - 1));
            return std::nullopt;
        }
        std::vector<unsigned char> bytes;
        if (count <= field) {
            bytes.assign(value, value + count);  // stored in the entry itself
        } else {
            bytes = file_.read(number(value, field), std::size_t(count),
                               "truncated (a tag's value is past the end of the file)");
        }
        const auto nul = std::find(bytes.begin(), bytes.end(), static_cast<unsigned char>(0));
        return std::string(bytes.begin(), nul);
    }

    const BoundedFile& file_;
    bool big_endian_ = false;
    bool big_tiff_ = false;
    std::uint64_t first_directory_ = 0;
};

bool is_tiff(const std::vector<unsigned char>& start) {
    if (start.size() < 4) return false;
    const bool little =
        start[0] == 'I' && start[1] == 'I' && start[3] == 0 && (start[2] == 42 || start[2] == 43);
    const bool big =
        start[0] == 'M' && start[1] == 'M' && start[2] == 0 && (start[3] == 42 || start[3] == 43);
    return little || big;
}

bool begins_with(const std::vector<unsigned char>& bytes, std::string_view prefix) {
    return bytes.size() >= prefix.size() &&
           std::memcmp(bytes.data(), prefix.data(), prefix.size()) == 0;
}

// The length of the UTF-8 sequence starting at `text[at]`, 0 when it is not one (overlong forms,
// surrogates and code points past U+10FFFF included, as RFC 3629 excludes them).
std::size_t utf8_sequence(std::string_view text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[at + i]); };
    const unsigned char lead = byte(0);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xbf;  // the second byte's range
    if (lead >= 0xc2 && lead <= 0xdf) {
        length = 2;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        length = 3;
        if (lead == 0xe0) low = 0xa0;
        if (lead == 0xed) high = 0x9f;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        length = 4;
        if (lead == 0xf0) low = 0x90;
        if (lead == 0xf4) high = 0x8f;
    } else {
        return 0;
    }
    if (text.size() - at < length || byte(1) < low || byte(1) > high) return 0;
    for (std::size_t i = 2; i < length; ++i) {
        if (byte(i) < 0x80 || byte(i) > 0xbf) return 0;
    }
    return length;
}

}  // namespace view_walk
}  // namespace

void check_embedded_view(const std::filesystem::path& file, std::string_view document) {
    const auto refuse = [&](const std::string& reason) {
        throw std::invalid_argument("cannot write " + quoted(file) + ": " + reason);
    };
    if (document.size() > kMaxEmbeddedViewBytes) refuse(view_walk::over_limit(document.size()));
    for (std::size_t at = 0; at < document.size();) {
        if (document[at] == '\0') {
            refuse("the embedded view holds a NUL byte at " + std::to_string(at));
        }
        const std::size_t length = view_walk::utf8_sequence(document, at);
        if (length == 0) refuse("the embedded view is not UTF-8 at byte " + std::to_string(at));
        at += length;
    }
}

std::optional<std::string> read_embedded_view(const std::filesystem::path& file) {
    using namespace view_walk;
    const BoundedFile opened(file);
    const std::vector<unsigned char> start = opened.read_some(0, 8);
    if (begins_with(start, kPngSignature)) return read_png_view(opened);
    if (begins_with(start, kExrMagicBytes)) return read_exr_view(opened);
    if (is_tiff(start)) return TiffWalk(opened).view();
    refuse(file, "not a PNG, TIFF or OpenEXR image");
}

}  // namespace fgr
