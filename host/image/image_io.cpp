// SPDX-License-Identifier: Apache-2.0
#include "image/image_io.hpp"

#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "image/embedded_view.hpp"
#include "image/png_errors.hpp"
#include "util/atomic_file.hpp"
#include "util/errors.hpp"
#include "util/files.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// Refuse to allocate for absurd headers in files we read (2^28 pixels is 16k x 16k).
constexpr std::size_t kMaxReadPixels = std::size_t{1} << 28;
constexpr std::size_t kPngSignatureBytes = 8;

[[noreturn]] void fail_png_read(const fs::path& path, const std::string& reason) {
    throw std::runtime_error("cannot read " + quoted(path) + ": " + reason);
}

// The handles of one encode or decode. They live in the caller of the function that calls setjmp,
// so a longjmp never skips their destructors and never leaves them indeterminate.
struct PngWriter {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngErrorSink error;

    PngWriter() = default;
    PngWriter(const PngWriter&) = delete;
    PngWriter& operator=(const PngWriter&) = delete;
    ~PngWriter() {
        if (png != nullptr) png_destroy_write_struct(&png, &info);
        if (file != nullptr) std::fclose(file);
    }
};

struct PngReader {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngErrorSink error;

    PngReader() = default;
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;
    ~PngReader() {
        if (png != nullptr) png_destroy_read_struct(&png, &info, nullptr);
        if (file != nullptr) std::fclose(file);
    }
};

// What the encoder needs of either image type: rows of big-endian samples and the colour space.
struct PngPixels {
    int width = 0;
    int height = 0;
    int bit_depth = 8;
    int channels = 3;              // 4: RGBA
    bool linear = false;           // gAMA 1.0 instead of sRGB
    std::vector<uint8_t> storage;  // interleaved RGBA, or 16-bit samples big-endian as PNG has
    const uint8_t* bytes = nullptr;
    const std::string* embedded_view = nullptr;  // the caller's; empty: none
    std::size_t row_bytes() const {
        return std::size_t(width) * std::size_t(channels) * std::size_t(bit_depth / 8);
    }
};

template <typename Image>
void validate_image(const fs::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0) {
        throw std::invalid_argument("cannot write " + quoted(path) + ": image is " +
                                    std::to_string(image.width) + "x" +
                                    std::to_string(image.height));
    }
    const std::size_t expected =
        std::size_t{3} * std::size_t(image.width) * std::size_t(image.height);
    if (image.rgb.size() != expected) {
        throw std::invalid_argument(
            "cannot write " + quoted(path) + ": " + std::to_string(image.width) + "x" +
            std::to_string(image.height) + " image needs " + std::to_string(expected) +
            " samples, has " + std::to_string(image.rgb.size()));
    }
    if (!image.alpha.empty() && image.alpha.size() != expected / 3) {
        throw std::invalid_argument("cannot write " + quoted(path) + ": alpha needs " +
                                    std::to_string(expected / 3) + " samples, has " +
                                    std::to_string(image.alpha.size()));
    }
}

// The image's samples in file order: RGB or RGBA interleaved, 16-bit ones as big-endian bytes.
template <typename Image>
std::vector<uint8_t> file_samples(const Image& image) {
    constexpr bool wide = sizeof(image.rgb[0]) == 2;
    const bool with_alpha = !image.alpha.empty();
    const std::size_t pixels = image.rgb.size() / 3;
    std::vector<uint8_t> bytes;
    bytes.reserve(pixels * (with_alpha ? 4 : 3) * (wide ? 2 : 1));
    const auto put = [&](auto sample) {
        if constexpr (wide) bytes.push_back(static_cast<uint8_t>(sample >> 8));
        bytes.push_back(static_cast<uint8_t>(sample & 0xff));
    };
    for (std::size_t i = 0; i < pixels; ++i) {
        for (std::size_t c = 0; c < 3; ++c) put(image.rgb[i * 3 + c]);
        if (with_alpha) put(image.alpha[i]);
    }
    return bytes;
}

void write_rows(png_structp png, png_infop info, const PngPixels& image) {
    png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
                 static_cast<png_uint_32>(image.height), image.bit_depth,
                 image.channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    use_png_compression(png);
    if (image.linear) {
        png_set_gAMA(png, info, 1.0);
    } else {
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    }
    set_png_embedded_view(png, info, *image.embedded_view);
    png_write_info(png, info);
    const std::size_t stride = image.row_bytes();
    for (std::size_t y = 0; y < std::size_t(image.height); ++y) {
        png_write_row(png, image.bytes + y * stride);
    }
    png_write_end(png, info);
}

// False (message in writer.error) when libpng failed. Keeps no locals of its own: anything
// modified between setjmp and the longjmp would be indeterminate afterwards.
bool encode(PngWriter& writer, const PngPixels& image) {
    if (setjmp(png_jmpbuf(writer.png))) {
        return false;
    }
    write_rows(writer.png, writer.info, image);
    return true;
}

// Empty on success, else why the file could not be written.
std::string encode_to_file(const fs::path& file_path, const PngPixels& image) {
    PngWriter writer;
    writer.file = std::fopen(file_path.c_str(), "wb");
    if (writer.file == nullptr) {
        return errno_message(errno);
    }
    writer.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &writer.error, record_png_error,
                                         ignore_png_warning);
    if (writer.png == nullptr || (writer.info = png_create_info_struct(writer.png)) == nullptr) {
        return "out of memory";
    }
    png_init_io(writer.png, writer.file);
    if (!encode(writer, image)) {
        return writer.error.message;
    }
    return close_durably(writer.file);
}

// Expands every PNG flavour to 8-bit RGB rows.
void request_rgb8(png_structp png) {
    png_set_expand(png);  // palette to RGB, low-bit grey to 8 bits, tRNS to alpha
    png_set_strip_16(png);
    png_set_strip_alpha(png);
    png_set_gray_to_rgb(png);
    png_set_interlace_handling(png);
}

void read_rows(png_structp png, png_infop info, Image8& image, std::vector<png_bytep>& rows) {
    png_read_info(png, info);
    request_rgb8(png);
    png_read_update_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info);
    const png_uint_32 height = png_get_image_height(png, info);
    if (std::size_t(width) * height > kMaxReadPixels) {
        png_error(png, "image too large");
    }
    const std::size_t stride = std::size_t{3} * width;
    if (png_get_rowbytes(png, info) != stride) {
        png_error(png, "unexpected row size after conversion to RGB");
    }
    image.width = static_cast<int>(width);
    image.height = static_cast<int>(height);
    image.rgb.resize(stride * height);
    rows.resize(height);
    for (std::size_t y = 0; y < height; ++y) {
        rows[y] = image.rgb.data() + y * stride;
    }
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
}

// False (message in reader.error) when libpng failed; see encode() for why it has no locals.
bool decode(PngReader& reader, Image8& image, std::vector<png_bytep>& rows) {
    if (setjmp(png_jmpbuf(reader.png))) {
        return false;
    }
    read_rows(reader.png, reader.info, image, rows);
    return true;
}

void read_samples(png_structp png, png_infop info, PngSamples& image, std::vector<uint8_t>& bytes,
                  std::vector<png_bytep>& rows) {
    png_read_info(png, info);
    const int type = png_get_color_type(png, info);
    if (type != PNG_COLOR_TYPE_RGB && type != PNG_COLOR_TYPE_RGB_ALPHA) {
        png_error(png, "not an RGB or RGBA PNG");
    }
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    image.width = static_cast<int>(png_get_image_width(png, info));
    image.height = static_cast<int>(png_get_image_height(png, info));
    image.channels = type == PNG_COLOR_TYPE_RGB_ALPHA ? 4 : 3;
    image.bit_depth = png_get_bit_depth(png, info);
    if (std::size_t(image.width) * std::size_t(image.height) > kMaxReadPixels) {
        png_error(png, "image too large");
    }
    const std::size_t stride = png_get_rowbytes(png, info);
    bytes.resize(stride * std::size_t(image.height));
    rows.resize(std::size_t(image.height));
    for (std::size_t y = 0; y < rows.size(); ++y) rows[y] = bytes.data() + y * stride;
    png_read_image(png, rows.data());
    png_read_end(png, nullptr);
}

// False (message in reader.error) when libpng failed; see encode() for why it has no locals.
bool decode_samples(PngReader& reader, PngSamples& image, std::vector<uint8_t>& bytes,
                    std::vector<png_bytep>& rows) {
    if (setjmp(png_jmpbuf(reader.png))) {
        return false;
    }
    read_samples(reader.png, reader.info, image, bytes, rows);
    return true;
}

bool has_png_signature(std::FILE* file) {
    png_byte signature[kPngSignatureBytes];
    return std::fread(signature, 1, sizeof signature, file) == sizeof signature &&
           png_sig_cmp(signature, 0, sizeof signature) == 0;
}

// Encodes to a temporary beside `path`, then renames it over `path`.
void write_pixels_atomically(const fs::path& path, const PngPixels& image) {
    const std::string failure = replace_file_atomically(
        path, [&](const fs::path& temporary) { return encode_to_file(temporary, image); });
    if (!failure.empty()) {
        fail_write(path, failure);
    }
}

// Opens PATH for decoding into READER: the file, its signature, libpng's structs.
void open_png_reader(PngReader& reader, const fs::path& path) {
    // Only a regular file: a FIFO named like a frame would block the read forever.
    std::string reason;
    reader.file = open_regular_file(path, reason).release();
    if (reader.file == nullptr) {
        fail_png_read(path, reason);
    }
    if (!has_png_signature(reader.file)) {
        fail_png_read(path, "not a PNG file");
    }
    reader.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &reader.error, record_png_error,
                                        ignore_png_warning);
    if (reader.png == nullptr || (reader.info = png_create_info_struct(reader.png)) == nullptr) {
        fail_png_read(path, "out of memory");
    }
    png_init_io(reader.png, reader.file);
    png_set_sig_bytes(reader.png, static_cast<int>(kPngSignatureBytes));
}

}  // namespace

void write_png(const fs::path& path, const Image8& image, const std::string& embedded_view) {
    validate_image(path, image);
    check_embedded_view(path, embedded_view);
    PngPixels pixels;
    pixels.embedded_view = &embedded_view;
    pixels.width = image.width;
    pixels.height = image.height;
    if (image.alpha.empty()) {
        pixels.bytes = image.rgb.data();
    } else {
        pixels.channels = 4;
        pixels.storage = file_samples(image);
        pixels.bytes = pixels.storage.data();
    }
    write_pixels_atomically(path, pixels);
}

void write_png16_linear(const fs::path& path, const Image16& image,
                        const std::string& embedded_view) {
    validate_image(path, image);
    check_embedded_view(path, embedded_view);
    PngPixels pixels;
    pixels.embedded_view = &embedded_view;
    pixels.width = image.width;
    pixels.height = image.height;
    pixels.bit_depth = 16;
    pixels.linear = true;
    pixels.channels = image.alpha.empty() ? 3 : 4;
    pixels.storage = file_samples(image);
    pixels.bytes = pixels.storage.data();
    write_pixels_atomically(path, pixels);
}

Image8 read_png(const fs::path& path) {
    PngReader reader;
    open_png_reader(reader, path);

    Image8 image;
    std::vector<png_bytep> rows;
    if (!decode(reader, image, rows)) {
        fail_png_read(path, reader.error.message);
    }
    return image;
}

PngSamples read_png_samples(const fs::path& path) {
    PngReader reader;
    open_png_reader(reader, path);
    PngSamples image;
    std::vector<uint8_t> bytes;
    std::vector<png_bytep> rows;
    if (!decode_samples(reader, image, bytes, rows)) {
        fail_png_read(path, reader.error.message);
    }
    const bool wide = image.bit_depth == 16;
    image.samples.resize(bytes.size() / (wide ? 2 : 1));
    for (std::size_t i = 0; i < image.samples.size(); ++i) {
        image.samples[i] =
            wide ? static_cast<uint16_t>(bytes[2 * i] << 8 | bytes[2 * i + 1]) : bytes[i];
    }
    return image;
}

}  // namespace fgr
