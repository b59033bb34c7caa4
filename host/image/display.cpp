// SPDX-License-Identifier: Apache-2.0
#include "image/display.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "util/parallel_bands.hpp"

namespace fgr {
namespace {

// 4096 steps over [0, 1] keep every 8-bit output code reachable.
const std::array<uint8_t, 4097>& srgb_table() {
    static const auto table = [] {
        std::array<uint8_t, 4097> values{};
        for (size_t i = 0; i < values.size(); ++i) {
            const double linear = static_cast<double>(i) / 4096.0;
            const double encoded =
                linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
            values[i] = static_cast<uint8_t>(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
        }
        return values;
    }();
    return table;
}

uint8_t encode_srgb_with(const std::array<uint8_t, 4097>& table, float linear) {
    if (!(linear > 0.0f)) return 0;  // also NaN
    if (linear >= 1.0f) return 255;
    return table[static_cast<size_t>(linear * 4096.0f + 0.5f)];
}

// The tone curves of tone_map (NaN and values below 0 give 0).
float clamp_curve(float linear) { return linear > 0.0f ? std::min(linear, 1.0f) : 0.0f; }
float reinhard_curve(float linear) { return linear > 0.0f ? linear / (1.0f + linear) : 0.0f; }
float aces_curve(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    return std::clamp(
        linear * (2.51f * linear + 0.03f) / (linear * (2.43f * linear + 0.59f) + 0.14f), 0.0f,
        1.0f);
}

// Values a band of an image holds at least: under it a thread costs more than it saves.
constexpr size_t kMinDisplayBand = 1 << 16;

// fill_display_image's bytes with the curve chosen once for the image (a call and a switch per
// value cost more than the curve itself), in bands over the CPU's threads.
template <typename Curve>
void encode_display(const std::vector<float>& linear, float exposure, Curve curve,
                    std::vector<uint8_t>& bytes) {
    const std::array<uint8_t, 4097>& table = srgb_table();
    in_parallel_bands(linear.size(), kMinDisplayBand, [&](size_t first, size_t last) {
        for (size_t i = first; i < last; ++i) {
            bytes[i] = encode_srgb_with(table, curve(linear[i] * exposure));
        }
    });
}

}  // namespace

uint8_t encode_srgb(float linear) { return encode_srgb_with(srgb_table(), linear); }

float tone_map(float linear, ToneMap op) {
    switch (op) {
        case ToneMap::Clamp:
            return clamp_curve(linear);
        case ToneMap::Reinhard:
            return reinhard_curve(linear);
        case ToneMap::Aces:
            return aces_curve(linear);
    }
    return 0.0f;
}

void fill_display_image(const std::vector<float>& linear, const DisplayTransform& display,
                        Image8& image) {
    if (image.rgb.size() != linear.size()) {
        throw std::logic_error("fill_display_image: the image is not the size of the colour");
    }
    switch (display.tone_map) {
        case ToneMap::Clamp:
            encode_display(linear, display.exposure, clamp_curve, image.rgb);
            break;
        case ToneMap::Reinhard:
            encode_display(linear, display.exposure, reinhard_curve, image.rgb);
            break;
        case ToneMap::Aces:
            encode_display(linear, display.exposure, aces_curve, image.rgb);
            break;
    }
}

Image8 display_image(const std::vector<float>& linear, const DisplayTransform& display, int width,
                     int height) {
    Image8 image{width, height, std::vector<uint8_t>(linear.size())};
    fill_display_image(linear, display, image);
    return image;
}

}  // namespace fgr
