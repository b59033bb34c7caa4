// SPDX-License-Identifier: Apache-2.0
#pragma once
// RGB and RGBA images and their PNG files: 8-bit sRGB for display, 16-bit linear for further
// processing. Alpha is straight (un-associated), as PNG specifies: a pixel's colour is the
// object's own, not yet multiplied by its coverage.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fgr {

struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;      // tightly packed rows, top row first, 3 bytes a pixel
    std::vector<uint8_t> alpha{};  // empty: opaque (an RGB file); else a byte a pixel (RGBA)
};

// Linear-light RGB at 16 bits a sample (0 = black, 65535 = 1.0).
struct Image16 {
    int width = 0;
    int height = 0;
    std::vector<uint16_t> rgb;      // tightly packed rows, top row first, 3 samples a pixel
    std::vector<uint16_t> alpha{};  // empty: opaque (an RGB file); else a sample a pixel (RGBA)
};

// A PNG's samples as stored, for checking what a file holds: RGB or RGBA, 8 or 16 bits.
struct PngSamples {
    int width = 0;
    int height = 0;
    int channels = 0;               // 3 (RGB) or 4 (RGBA)
    int bit_depth = 0;              // 8 or 16
    std::vector<uint16_t> samples;  // rows top first, `channels` a pixel
};

// Writes `image` as an 8-bit RGB PNG tagged sRGB (RGBA when it has alpha), carrying
// `embedded_view` (image/embedded_view.hpp; empty: none). The file is written beside `path` under
// a temporary name and renamed over it only when complete, so `path` holds either its old content
// or the whole new image, never a partial file. Throws std::invalid_argument for non-positive
// dimensions, a pixel buffer of the wrong size or a document check_embedded_view refuses,
// std::runtime_error ("cannot write '<path>': <reason>") otherwise.
void write_png(const std::filesystem::path& path, const Image8& image,
               const std::string& embedded_view = {});

// Writes `image` as a 16-bit RGB PNG tagged linear (gAMA 1.0), RGBA when it has alpha, carrying
// `embedded_view`, atomically like write_png.
void write_png16_linear(const std::filesystem::path& path, const Image16& image,
                        const std::string& embedded_view = {});

// Reads a PNG as 8-bit RGB: palette and grey are expanded to RGB, alpha is dropped (not
// composited), 16-bit samples are reduced to 8 bits. Throws std::runtime_error
// ("cannot read '<path>': <reason>").
Image8 read_png(const std::filesystem::path& path);

// Reads an RGB or RGBA PNG of 8 or 16 bits without converting its samples. Throws
// std::runtime_error ("cannot read '<path>': <reason>"), also for other colour types.
PngSamples read_png_samples(const std::filesystem::path& path);

}  // namespace fgr
