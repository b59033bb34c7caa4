#pragma once
// RGB images and their PNG files: 8-bit sRGB for display, 16-bit linear for further processing.

#include <cstdint>
#include <filesystem>
#include <vector>

namespace fgr {

struct Image8 {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;  // tightly packed rows, top row first, 3 bytes a pixel
};

// Linear-light RGB at 16 bits a sample (0 = black, 65535 = 1.0).
struct Image16 {
    int width = 0;
    int height = 0;
    std::vector<uint16_t> rgb;  // tightly packed rows, top row first, 3 samples a pixel
};

// Writes `image` as an 8-bit RGB PNG tagged sRGB. The file is written beside `path` under a temporary name and
// renamed over it only when complete, so `path` holds either its old content or the whole new
// image, never a partial file. Throws std::invalid_argument for non-positive dimensions or a pixel
// buffer of the wrong size, std::runtime_error ("cannot write '<path>': <reason>") otherwise.
void write_png(const std::filesystem::path& path, const Image8& image);

// Writes `image` as a 16-bit RGB PNG tagged linear (gAMA 1.0), atomically like write_png.
void write_png16_linear(const std::filesystem::path& path, const Image16& image);

// Reads a PNG as 8-bit RGB: palette and grey are expanded to RGB, alpha is dropped (not
// composited), 16-bit samples are reduced to 8 bits. Throws std::runtime_error
// ("cannot read '<path>': <reason>").
Image8 read_png(const std::filesystem::path& path);

}  // namespace fgr
