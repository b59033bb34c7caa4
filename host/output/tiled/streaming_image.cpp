// SPDX-License-Identifier: Apache-2.0
// Row-streaming PNG, OpenEXR and TIFF writers (output/tiled/streaming_image.hpp). Each holds only
// the library's own buffers (a few rows at most); the caller's band of rows is written and dropped.
#include "output/tiled/streaming_image.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <png.h>
#include <tiffio.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "image/embedded_view.hpp"
#include "image/png_errors.hpp"
#include "util/atomic_file.hpp"
#include "util/errors.hpp"
#include "util/lower_case.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

bool has_channels(const RowLayout& layout, std::initializer_list<const char*> names) {
    if (layout.channels.size() != names.size()) return false;
    return std::equal(names.begin(), names.end(), layout.channels.begin());
}

// PNG and TIFF hold RGB or RGBA as 8-bit (sRGB) or 16-bit (linear) samples.
void check_rgb_layout(const fs::path& path, const RowLayout& layout, const char* format) {
    const bool rgb =
        has_channels(layout, {"R", "G", "B"}) || has_channels(layout, {"R", "G", "B", "A"});
    if (!rgb || layout.type == SampleType::F32) {
        throw std::invalid_argument("cannot write " + quoted(path) + ": " + format +
                                    " output holds R, G, B and optionally A at 8 or 16 bits");
    }
}

// --- PNG -----------------------------------------------------------------------------------

// libpng's handles and the file, released however the writer ends (also when its constructor
// throws, which runs no destructor of the writer itself).
struct PngHandles {
    std::FILE* file = nullptr;
    png_structp png = nullptr;
    png_infop info = nullptr;
    PngHandles() = default;
    PngHandles(const PngHandles&) = delete;
    PngHandles& operator=(const PngHandles&) = delete;
    ~PngHandles() {
        if (png != nullptr) png_destroy_write_struct(&png, &info);
        if (file != nullptr) std::fclose(file);
    }
};

class PngStream final : public StreamingImageWriter {
public:
    PngStream(const fs::path& path, int width, int height, const RowLayout& layout,
              const std::string& embedded_view)
        : pending_(path), width_(width), layout_(layout) {
        check_rgb_layout(path, layout, "PNG");
        h_.file = std::fopen(pending_.temporary().c_str(), "wb");
        if (h_.file == nullptr) fail_write(path, errno_message(errno));
        h_.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error_, record_png_error,
                                         ignore_png_warning);
        if (h_.png == nullptr || (h_.info = png_create_info_struct(h_.png)) == nullptr) {
            fail_write(path, "out of memory");
        }
        png_init_io(h_.png, h_.file);
        if (!write_header(height, embedded_view)) fail_write(path, error_.message);
    }

    void write_rows(const uint8_t* rows, int count) override {
        if (!write_png_rows(rows, count)) fail_write(pending_.target(), error_.message);
    }

    void finish() override {
        if (!write_end()) fail_write(pending_.target(), error_.message);
        png_destroy_write_struct(&h_.png, &h_.info);
        h_.png = nullptr;
        if (const std::string failure = close_durably(h_.file); !failure.empty()) {
            fail_write(pending_.target(), failure);
        }
        pending_.commit();
    }

private:
    // Each libpng call sits behind its own setjmp, in a function with no locals that change
    // between the setjmp and a longjmp.
    bool write_header(int height, const std::string& embedded_view) {
        if (setjmp(png_jmpbuf(h_.png))) return false;
        const bool alpha = layout_.channels.size() == 4;
        const bool linear = layout_.type == SampleType::U16;
        png_set_IHDR(h_.png, h_.info, static_cast<png_uint_32>(width_),
                     static_cast<png_uint_32>(height), linear ? 16 : 8,
                     alpha ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                     PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        use_png_compression(h_.png);
        if (linear) {
            png_set_gAMA(h_.png, h_.info, 1.0);
        } else {
            png_set_sRGB_gAMA_and_cHRM(h_.png, h_.info, PNG_sRGB_INTENT_PERCEPTUAL);
        }
        set_png_embedded_view(h_.png, h_.info, embedded_view);
        png_write_info(h_.png, h_.info);
        if (linear) png_set_swap(h_.png);  // our 16-bit samples are native (little-endian)
        return true;
    }

    bool write_png_rows(const uint8_t* rows, int count) {
        if (setjmp(png_jmpbuf(h_.png))) return false;
        for (int y = 0; y < count; ++y) {
            png_write_row(h_.png, rows + size_t(y) * size_t(width_) * layout_.pixel_bytes());
        }
        return true;
    }

    bool write_end() {
        if (setjmp(png_jmpbuf(h_.png))) return false;
        png_write_end(h_.png, h_.info);
        return true;
    }

    PendingFile pending_;
    int width_;
    RowLayout layout_;
    PngErrorSink error_;
    PngHandles h_;
};

// --- OpenEXR -------------------------------------------------------------------------------

class ExrStream final : public StreamingImageWriter {
public:
    ExrStream(const fs::path& path, int width, int height, const RowLayout& layout,
              const ExrPlacement& placement, const std::string& embedded_view)
        : pending_(path), width_(width), x_(placement.x), layout_(layout) {
        if (layout.type != SampleType::F32) {
            throw std::invalid_argument("cannot write " + quoted(path) +
                                        ": EXR output holds 32-bit float channels");
        }
        // OpenEXR refuses headers past its global size limit, which fgr lowers while it reads
        // untrusted files; a tiled still may be larger, so the limit is the tiled one here (and
        // every read sets its own again first).
        Imf::Header::setMaxImageSize(1 << 20, 1 << 20);
        const Imath::Box2i data(Imath::V2i(placement.x, placement.y),
                                Imath::V2i(placement.x + width - 1, placement.y + height - 1));
        const Imath::V2i last(placement.image_width - 1, placement.image_height - 1);
        const Imath::Box2i display =
            placement.placed() ? Imath::Box2i(Imath::V2i(0, 0), last) : data;
        Imf::Header header(display, data);
        header.compression() = Imf::ZIP_COMPRESSION;
        for (const auto& [name, value] : placement.attributes) {
            header.insert(name, Imf::StringAttribute(value));
        }
        if (!embedded_view.empty()) {
            header.insert(kExrViewAttribute, Imf::StringAttribute(embedded_view));
        }
        for (const std::string& name : layout.channels) {
            header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        }
        try {
            file_ = std::make_unique<Imf::OutputFile>(pending_.temporary().c_str(), header);
        } catch (const std::exception& error) {
            fail_write(path, error.what());
        }
    }

    void write_rows(const uint8_t* rows, int count) override {
        const size_t pixel = layout_.pixel_bytes();
        const size_t row = pixel * size_t(width_);
        const int first = file_->currentScanLine();
        const Imath::Box2i band(Imath::V2i(x_, first),
                                Imath::V2i(x_ + width_ - 1, first + count - 1));
        Imf::FrameBuffer frame;
        for (size_t c = 0; c < layout_.channels.size(); ++c) {
            frame.insert(layout_.channels[c],
                         Imf::Slice::Make(Imf::FLOAT, rows + c * sizeof(float), band, pixel, row));
        }
        try {
            file_->setFrameBuffer(frame);
            file_->writePixels(count);
        } catch (const std::exception& error) {
            fail_write(pending_.target(), error.what());
        }
    }

    void finish() override {
        try {
            file_.reset();  // writes the line offsets and closes the file
        } catch (const std::exception& error) {
            fail_write(pending_.target(), error.what());
        }
        pending_.commit();
    }

private:
    PendingFile pending_;
    int width_;
    int x_;  // the data window's first column
    RowLayout layout_;
    std::unique_ptr<Imf::OutputFile> file_;
};

// --- TIFF ----------------------------------------------------------------------------------

// libtiff reports through global handlers; ours keeps the last error for the exception instead
// of printing it.
thread_local std::string tiff_error;

void record_tiff_error(const char* module, const char* format, va_list arguments) {
    char message[256];
    std::vsnprintf(message, sizeof message, format, arguments);
    tiff_error = (module != nullptr ? std::string(module) + ": " : std::string()) + message;
}

void ignore_tiff_warning(const char*, const char*, va_list) {}

// Rows per strip: each strip is compressed on its own, so a reader can fetch part of the image.
constexpr uint32_t kTiffRowsPerStrip = 16;

class TiffStream final : public StreamingImageWriter {
public:
    TiffStream(const fs::path& path, int width, int height, const RowLayout& layout,
               const std::string& embedded_view)
        : pending_(path), width_(width), layout_(layout) {
        check_rgb_layout(path, layout, "TIFF");
        TIFFSetErrorHandler(record_tiff_error);
        TIFFSetWarningHandler(ignore_tiff_warning);
        // Classic TIFF addresses 4 GiB; past what the raw pixels could need, BigTIFF ("8").
        const double raw = double(width) * double(height) * double(layout.pixel_bytes());
        const bool big = raw > double(1u << 31);
        tiff_ = TIFFOpen(pending_.temporary().c_str(), big ? "w8" : "w");
        if (tiff_ == nullptr) fail_write(path, tiff_error);
        const uint16_t samples = static_cast<uint16_t>(layout.channels.size());
        TIFFSetField(tiff_, TIFFTAG_IMAGEWIDTH, uint32_t(width));
        TIFFSetField(tiff_, TIFFTAG_IMAGELENGTH, uint32_t(height));
        TIFFSetField(tiff_, TIFFTAG_SAMPLESPERPIXEL, samples);
        TIFFSetField(tiff_, TIFFTAG_BITSPERSAMPLE, uint16_t(8 * sample_bytes(layout.type)));
        TIFFSetField(tiff_, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
        TIFFSetField(tiff_, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
        TIFFSetField(tiff_, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
        TIFFSetField(tiff_, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
        TIFFSetField(tiff_, TIFFTAG_COMPRESSION, COMPRESSION_ADOBE_DEFLATE);
        TIFFSetField(tiff_, TIFFTAG_PREDICTOR, PREDICTOR_HORIZONTAL);
        TIFFSetField(tiff_, TIFFTAG_ROWSPERSTRIP, kTiffRowsPerStrip);
        if (samples == 4) {
            const uint16_t unassociated = EXTRASAMPLE_UNASSALPHA;  // as PNG's alpha
            TIFFSetField(tiff_, TIFFTAG_EXTRASAMPLES, uint16_t(1), &unassociated);
        }
        // Software "fgr" tells fgr's description from another program's (image/embedded_view.hpp).
        TIFFSetField(tiff_, TIFFTAG_SOFTWARE, kTiffViewSoftware);
        // TIFF 6.0 asks for 7-bit ASCII here; readers take UTF-8 as the bytes it is.
        if (!embedded_view.empty()) {
            TIFFSetField(tiff_, TIFFTAG_IMAGEDESCRIPTION, embedded_view.c_str());
        }
    }

    ~TiffStream() override {
        if (tiff_ != nullptr) TIFFClose(tiff_);
    }

    void write_rows(const uint8_t* rows, int count) override {
        const size_t row = layout_.pixel_bytes() * size_t(width_);
        // libtiff's predictor works in place, so each row goes through a copy.
        scratch_.resize(row);
        for (int y = 0; y < count; ++y, ++next_row_) {
            std::copy_n(rows + size_t(y) * row, row, scratch_.data());
            if (TIFFWriteScanline(tiff_, scratch_.data(), next_row_, 0) < 0) {
                fail_write(pending_.target(), tiff_error);
            }
        }
    }

    void finish() override {
        const bool written = TIFFFlush(tiff_) == 1;
        TIFFClose(tiff_);
        tiff_ = nullptr;
        if (!written) fail_write(pending_.target(), tiff_error);
        pending_.commit();
    }

private:
    PendingFile pending_;
    int width_;
    RowLayout layout_;
    TIFF* tiff_ = nullptr;
    uint32_t next_row_ = 0;
    std::vector<uint8_t> scratch_;
};

}  // namespace

size_t sample_bytes(SampleType type) {
    switch (type) {
        case SampleType::U8:
            return 1;
        case SampleType::U16:
            return 2;
        case SampleType::F32:
            return 4;
    }
    return 1;
}

ImageFormat image_format_of(const fs::path& path) {
    const std::string extension = lower_extension(path);
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".exr") return ImageFormat::Exr;
    if (extension == ".tif" || extension == ".tiff") return ImageFormat::Tiff;
    throw std::invalid_argument("output " + quoted(path) + " must be a .png, .exr or .tif file");
}

std::unique_ptr<StreamingImageWriter> open_streaming_image(const fs::path& path, ImageFormat format,
                                                           int width, int height,
                                                           const RowLayout& layout,
                                                           const ExrPlacement& placement,
                                                           const std::string& embedded_view) {
    if (width < 1 || height < 1) {
        throw std::invalid_argument("cannot write " + quoted(path) + ": image is " +
                                    std::to_string(width) + "x" + std::to_string(height));
    }
    if ((placement.placed() || !placement.attributes.empty()) && format != ImageFormat::Exr) {
        throw std::invalid_argument("cannot write " + quoted(path) +
                                    ": only an EXR file holds a part of an image");
    }
    if (placement.placed() &&
        (placement.x < 0 || placement.y < 0 || placement.x + width > placement.image_width ||
         placement.y + height > placement.image_height)) {
        throw std::invalid_argument("cannot write " + quoted(path) +
                                    ": its rectangle lies "
                                    "outside the image");
    }
    check_embedded_view(path, embedded_view);
    switch (format) {
        case ImageFormat::Png:
            return std::make_unique<PngStream>(path, width, height, layout, embedded_view);
        case ImageFormat::Exr:
            return std::make_unique<ExrStream>(path, width, height, layout, placement,
                                               embedded_view);
        case ImageFormat::Tiff:
            return std::make_unique<TiffStream>(path, width, height, layout, embedded_view);
    }
    throw std::invalid_argument("unknown image format");
}

}  // namespace fgr
