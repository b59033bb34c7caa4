// SPDX-License-Identifier: Apache-2.0
#include "output/still_layers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fgr {
namespace {

size_t frame_pixels(const Frame& frame) {
    return static_cast<size_t>(frame.image.width) * static_cast<size_t>(frame.image.height);
}

// Throws when the frame lacks `layer` (`values` not `per_pixel` floats a pixel).
void require_layer(const Frame& frame, const std::vector<float>& values, size_t per_pixel,
                   const char* layer) {
    if (values.size() != frame_pixels(frame) * per_pixel) {
        throw std::invalid_argument(
            fmt::format("the frame has no {} layer: render it with KernelSwitches::aovs", layer));
    }
}

void require_band(const Frame& frame, RowBand band, size_t out_size, size_t per_pixel) {
    if (band.first_row < 0 || band.rows < 0 || band.first_row + band.rows > frame.image.height) {
        throw std::invalid_argument(fmt::format("rows {}..{} are outside a frame of {} rows",
                                                band.first_row, band.first_row + band.rows,
                                                frame.image.height));
    }
    const size_t needed =
        static_cast<size_t>(band.rows) * static_cast<size_t>(frame.image.width) * per_pixel;
    if (out_size != needed) {
        throw std::invalid_argument(
            fmt::format("{} rows need {} output samples, not {}", band.rows, needed, out_size));
    }
}

size_t first_pixel(const Frame& frame, RowBand band) {
    return static_cast<size_t>(band.first_row) * static_cast<size_t>(frame.image.width);
}

// The band's part of a layer with `per_pixel` floats a pixel.
std::vector<float> band_values(const Frame& frame, const std::vector<float>& values,
                               size_t per_pixel, RowBand band) {
    const size_t first = first_pixel(frame, band) * per_pixel;
    const size_t count =
        static_cast<size_t>(band.rows) * static_cast<size_t>(frame.image.width) * per_pixel;
    return {values.begin() + static_cast<std::ptrdiff_t>(first),
            values.begin() + static_cast<std::ptrdiff_t>(first + count)};
}

uint16_t to_unorm16(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;  // NaN to 0
    return static_cast<uint16_t>(std::lround(clamped * 65535.0f));
}

uint8_t to_unorm8(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;
    return static_cast<uint8_t>(std::lround(clamped * 255.0f));
}

}  // namespace

RowBand whole_frame(const Frame& frame) { return {0, frame.image.height}; }

void straight_colour(const Frame& frame, size_t pixel, float rgb[3]) {
    const float alpha = frame.alpha[pixel];
    // Below a millionth of a sample the division only magnifies rounding.
    const float unpremultiply = alpha > 1e-6f ? 1.0f / alpha : 0.0f;
    for (size_t c = 0; c < 3; ++c) rgb[c] = frame.foreground[pixel * 3 + c] * unpremultiply;
}

namespace {

// RGBA of the band with straight alpha: each straight colour channel through `encode_colour`,
// coverage through `encode_alpha`. Throws for a frame without alpha or an `out` of another size.
template <typename Sample, typename EncodeColour, typename EncodeAlpha>
void straight_rgba_rows(const Frame& frame, RowBand band, std::span<Sample> out,
                        EncodeColour encode_colour, EncodeAlpha encode_alpha) {
    require_layer(frame, frame.alpha, 1, "alpha");
    require_layer(frame, frame.foreground, 3, "foreground");
    require_band(frame, band, out.size(), 4);
    const size_t first = first_pixel(frame, band);
    for (size_t i = 0; i < out.size() / 4; ++i) {
        float rgb[3];
        straight_colour(frame, first + i, rgb);
        for (size_t c = 0; c < 3; ++c) out[i * 4 + c] = encode_colour(rgb[c]);
        out[i * 4 + 3] = encode_alpha(frame.alpha[first + i]);
    }
}

}  // namespace

void rgba8_rows(const Frame& frame, const DisplayTransform& display, RowBand band,
                std::span<uint8_t> out) {
    straight_rgba_rows(
        frame, band, out,
        [&](float linear) {
            return encode_srgb(tone_map(linear * display.exposure, display.tone_map));
        },
        to_unorm8);
}

void rgba16_linear_rows(const Frame& frame, float exposure, RowBand band, std::span<uint16_t> out) {
    straight_rgba_rows(
        frame, band, out, [&](float linear) { return to_unorm16(linear * exposure); }, to_unorm16);
}

std::vector<ExrLayer> exr_layers(const Frame& frame, const Aovs& aovs, RowBand band) {
    const size_t pixels = static_cast<size_t>(band.rows) * static_cast<size_t>(frame.image.width);
    require_band(frame, band, pixels, 1);
    if (aovs.alpha) {
        require_layer(frame, frame.alpha, 1, "alpha");
        require_layer(frame, frame.foreground, 3, "foreground");
    }
    if (aovs.albedo) require_layer(frame, frame.albedo, 3, "albedo");
    if (aovs.normal) require_layer(frame, frame.normal, 3, "normal");
    // Premultiplied, as EXR has it: the foreground is the colour times its coverage already.
    std::vector<ExrLayer> layers{
        {"",
         {"R", "G", "B"},
         band_values(frame, aovs.alpha ? frame.foreground : frame.linear, 3, band)}};
    if (aovs.albedo)
        layers.push_back({"albedo", {"R", "G", "B"}, band_values(frame, frame.albedo, 3, band)});
    if (aovs.normal)
        layers.push_back({"normal", {"X", "Y", "Z"}, band_values(frame, frame.normal, 3, band)});
    if (aovs.depth) {
        ExrLayer depth{"depth", {"Z"}, band_values(frame, frame.depth, 1, band)};
        for (float& z : depth.values) {
            if (z < 0.0f) z = std::numeric_limits<float>::infinity();  // missed
        }
        layers.push_back(std::move(depth));
    }
    if (aovs.samples) {
        require_layer(frame, frame.samples_per_pixel, 1, "samples (path mode)");
        layers.push_back({"samples", {"Y"}, band_values(frame, frame.samples_per_pixel, 1, band)});
    }
    if (aovs.variance) {
        require_layer(frame, frame.variance, 3, "variance (path mode)");
        layers.push_back(
            {"variance", {"R", "G", "B"}, band_values(frame, frame.variance, 3, band)});
    }
    if (aovs.alpha) layers.push_back({"", {"A"}, band_values(frame, frame.alpha, 1, band)});
    if (!frame.raw_linear.empty()) {
        require_layer(frame, frame.raw_linear, 3, "raw");
        layers.push_back({"raw", {"R", "G", "B"}, band_values(frame, frame.raw_linear, 3, band)});
    }
    return layers;
}

}  // namespace fgr
