// SPDX-License-Identifier: Apache-2.0
#pragma once
// High-dynamic-range image files: Radiance .hdr (RGBE) and OpenEXR .exr, read as environment maps
// and written as the path tracer's output (with optional extra layers: albedo, normal, depth).

#include <filesystem>
#include <string>
#include <vector>

#include "image/hdr_image.hpp"

namespace fgr {

// Largest width or height read_hdr_image accepts, and its budget for the decoded image
// (3 floats a pixel): 2 GiB, e.g. a 16384x8192 latitude-longitude map (1.5 GiB).
inline constexpr int kMaxHdrImageSide = 16384;
inline constexpr std::size_t kMaxHdrImageBytes = std::size_t{1} << 31;

// Reads a Radiance .hdr (RGBE; flat or run-length-encoded scanlines, "-Y height +X width" only)
// or an OpenEXR .exr (the R, G and B channels of the first part's default layer, half, float or
// uint, any compression OpenEXR reads, scanlines or tiles up to 1024 a side; other channels and
// layers are ignored), chosen by the file's first bytes, not its name. The top row of the file
// is row 0. The file is untrusted: anything wrong (missing, a directory, not an HDR image,
// truncated, corrupt, over 2^31 - 1 bytes or the limits above, no R, G, B channels) throws a
// one-line std::runtime_error ("cannot read '<file>': <reason>"). Texels: NaN and infinities are
// refused (the error names the first such pixel); negative values, which filtered (resampled)
// images carry as ringing, become 0, since light is never negative. RGBE cannot hold either.
// Peak memory: the file, plus the image twice for .hdr (stb_image's copy, then ours).
HdrImage read_hdr_image(const std::filesystem::path& file);

// Writes `image` as a run-length-encoded Radiance .hdr ("-Y height +X width": top row first),
// written beside `file` and renamed over it when complete, so `file` holds its old content or
// the whole new image. RGBE keeps 8 bits of mantissa a component under a shared exponent: every
// component comes back within 2^(e-8) of its value, where 2^(e-1) <= the pixel's largest
// component < 2^e. Negative values are written as 0. Throws std::invalid_argument for a bad
// size or a NaN or infinite value (naming the pixel), std::runtime_error
// ("cannot write '<file>': <reason>") when the file cannot be written.
void write_radiance_hdr(const std::filesystem::path& file, const HdrImage& image);

// One layer of an OpenEXR file: the channels named `name`.`channel` ("R", not ".R", when `name`
// is empty, as the beauty and alpha are), `values` interleaved per pixel (width * height *
// channels.size() floats, rows from the top). E.g. {"", {"R", "G", "B"}} for the beauty,
// {"albedo", {"R", "G", "B"}}, {"normal", {"X", "Y", "Z"}}, {"depth", {"Z"}}, {"", {"A"}}.
struct ExrLayer {
    std::string name;
    std::vector<std::string> channels;
    std::vector<float> values;
};

// Writes one single-part scanline OpenEXR file holding every layer's channels as 32-bit floats,
// ZIP-compressed, rows top to bottom, display and data windows (0,0)-(width-1,height-1), and
// `embedded_view` (image/embedded_view.hpp; empty: none) in its header; values are stored as they
// are (NaN, infinities and negatives included). Compositors and denoisers (Nuke, Blender, OIDN's
// tools) read "albedo.R" etc. as layers. Written beside `file` and renamed over it, like
// write_radiance_hdr. Throws std::invalid_argument for a bad size, an empty,
// duplicate or ill-formed name (a name or channel may not be empty or contain '.', a layer needs
// at least one channel), a value count that does not match or a document check_embedded_view
// refuses, std::runtime_error ("cannot write '<file>': <reason>") when the file cannot be written.
void write_exr(const std::filesystem::path& file, int width, int height,
               const std::vector<ExrLayer>& layers, const std::string& embedded_view = {});

}  // namespace fgr
