// SPDX-License-Identifier: Apache-2.0
#pragma once
// Image files written a band of rows at a time, top to bottom, so an image far larger than memory
// (a gigapixel still) passes through a buffer of a few rows: PNG through libpng row by row,
// OpenEXR as scanlines, TIFF (BigTIFF once the pixels could pass 4 GiB) in strips through libtiff.
// The file is written under a temporary name and renamed into place by finish(): an error, an
// exception or Ctrl-C before that leaves no file at the path.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fgr {

enum class SampleType { U8, U16, F32 };

size_t sample_bytes(SampleType type);

enum class ImageFormat { Png, Exr, Tiff };

// The format a path's extension names (.png, .exr, .tif/.tiff, any case); throws
// std::invalid_argument otherwise.
ImageFormat image_format_of(const std::filesystem::path& path);

// What each pixel of a row holds: channels interleaved in this order, all of one sample type.
// PNG and TIFF take R, G, B and optionally A, as U8 (sRGB) or U16 (linear); EXR takes any
// channels (e.g. "R", "G", "B", "A", "depth.Z") as F32.
struct RowLayout {
    std::vector<std::string> channels;
    SampleType type = SampleType::U8;
    size_t pixel_bytes() const { return channels.size() * sample_bytes(type); }
};

class StreamingImageWriter {
public:
    virtual ~StreamingImageWriter() = default;
    // `count` rows of width * layout.pixel_bytes() bytes each, the next ones down the image.
    virtual void write_rows(const uint8_t* rows, int count) = 0;
    // After the last row: completes the file and renames it into place.
    virtual void finish() = 0;
};

// What an EXR file may say beyond its pixels: that its rows are a rectangle of a larger image
// (OpenEXR's display window is the whole image, its data window the rows written), and text
// attributes for its header (fgr's part files, output/parts/render_parts.hpp).
struct ExrPlacement {
    int image_width = 0;  // the whole image; 0: the rows written are the whole image
    int image_height = 0;
    int x = 0;  // the written rectangle's top-left corner in the whole image
    int y = 0;
    std::vector<std::pair<std::string, std::string>> attributes;  // name, value
    bool placed() const { return image_width > 0; }
};

// Opens a writer for a width x height image at `path` in `format` (an EXR with `placement`: a
// width x height rectangle of a larger image), carrying `embedded_view` (image/embedded_view.hpp;
// empty: none) where each format keeps it. Throws std::invalid_argument for a layout the format
// cannot hold, a placement that is not an EXR's or not inside its image, or a document
// check_embedded_view refuses, and std::runtime_error ("cannot write '<path>': <reason>") when the
// file cannot be created or written.
std::unique_ptr<StreamingImageWriter> open_streaming_image(const std::filesystem::path& path,
                                                           ImageFormat format, int width,
                                                           int height, const RowLayout& layout,
                                                           const ExrPlacement& placement = {},
                                                           const std::string& embedded_view = {});

}  // namespace fgr
