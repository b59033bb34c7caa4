// SPDX-License-Identifier: Apache-2.0
#pragma once
// The text document an image file carries beside its pixels: the view that made the image (a JSON
// document), written into every PNG, TIFF and OpenEXR file fgr writes and read back without
// decoding the pixels. Where each format keeps it:
//   PNG      an iTXt chunk with the keyword "fgr:view", before the first IDAT (the pixels): plain
//            UTF-8 up to kPlainPngViewBytes, so any PNG tool shows it, zlib-compressed above
//   OpenEXR  a string attribute "fgrView" in the header
//   TIFF     ImageDescription (tag 270) of the first image, beside Software (tag 305) "fgr", which
//            tells fgr's description from another program's
// The writers take the document as a string, empty for none (image_io.hpp, hdr_io.hpp, and the
// streamed writers of output/tiled/streaming_image.hpp).

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fgr {

// The largest document written or read: 1 MiB.
inline constexpr std::size_t kMaxEmbeddedViewBytes = std::size_t{1} << 20;
// Documents up to this size go into a PNG uncompressed; larger ones deflated.
inline constexpr std::size_t kPlainPngViewBytes = 4096;

inline constexpr const char* kPngViewKeyword = "fgr:view";
inline constexpr const char* kExrViewAttribute = "fgrView";
inline constexpr const char* kTiffViewSoftware = "fgr";

// Throws std::invalid_argument ("cannot write '<file>': <reason>") unless `document` can be
// embedded in `file`: at most kMaxEmbeddedViewBytes of UTF-8 without a NUL byte (PNG's iTXt and
// TIFF's ASCII tags end at a NUL). The empty document (none) always can.
void check_embedded_view(const std::filesystem::path& file, std::string_view document);

// The document embedded in the PNG, TIFF or OpenEXR image `file` (the format is decided by its
// first bytes, not its name), or nullopt when it has none. Reads only the file's structure up to
// the document (PNG: the chunks before the pixels; OpenEXR: the header; TIFF: the first image's
// directory), never the pixels, each read bounded by the file's size. The file is untrusted: one
// that is not a regular file (refused before it is opened: a directory, a FIFO, a device), empty,
// of another format, truncated or corrupt where it was read, or whose document is over
// kMaxEmbeddedViewBytes throws a one-line std::runtime_error ("cannot read '<file>': <reason>").
// A file whose pixels are damaged past the document still gives the document.
std::optional<std::string> read_embedded_view(const std::filesystem::path& file);

}  // namespace fgr
