// SPDX-License-Identifier: Apache-2.0
#include "image/display.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
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

// A curve's lanes: four, SSE2's width and NEON's, through the compiler's vector extension (GCC
// and Clang). Written as scalar code the clamps' comparisons kept the loop scalar, a branch a
// value, and the display pass cost a tenth of a 640x480 shaded frame.
using Floats = float __attribute__((vector_size(16)));
using Indices = int32_t __attribute__((vector_size(16)));
constexpr size_t kLanes = sizeof(Floats) / sizeof(float);

// max(x, 0) and min(x, 1) for a float or Floats; NaN gives 0 (a comparison with NaN is false).
template <typename T>
T at_least_zero(T x) {
    return x > 0.0f ? x : T{};
}
template <typename T>
T at_most_one(T x) {
    return x < 1.0f ? x : T{} + 1.0f;
}

// The sRGB table's entry for linear (clamped to [0, 1]).
int32_t table_index(float linear) {
    return static_cast<int32_t>(at_most_one(at_least_zero(linear)) * 4096.0f + 0.5f);
}
Indices table_index(Floats linear) {
    return __builtin_convertvector(at_most_one(at_least_zero(linear)) * 4096.0f + 0.5f, Indices);
}

uint8_t encode_srgb_with(const std::array<uint8_t, 4097>& table, float linear) {
    return table[table_index(linear)];
}

// The tone curves of tone_map (NaN and values below 0 give 0), for a float or Floats, as types
// so that each encode_display instance inlines its own.
struct ClampCurve {
    template <typename T>
    T operator()(T linear) const {
        return at_most_one(at_least_zero(linear));
    }
};
struct ReinhardCurve {
    template <typename T>
    T operator()(T linear) const {
        const T x = at_least_zero(linear);
        return x / (1.0f + x);
    }
};
struct AcesCurve {
    template <typename T>
    T operator()(T linear) const {
        const T x = at_least_zero(linear);  // the curve is 0 at 0 and never below
        return at_most_one(x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f));
    }
};

// Values a band of an image holds at least: under it a thread costs more than it saves.
constexpr size_t kMinDisplayBand = 1 << 16;

// fill_display_image's bytes with the curve chosen once for the image (a switch per value cost
// more than the curve itself), kLanes values at a time, in bands over the CPU's threads. The
// table lookups stay scalar; each lane's bytes are those encode_srgb(tone_map(...)) gives.
template <typename Curve>
void encode_display(const std::vector<float>& linear, float exposure, Curve curve,
                    std::vector<uint8_t>& bytes) {
    const std::array<uint8_t, 4097>& table = srgb_table();
    // Raw pointers: through the vectors, each byte stored (which may alias anything) made the
    // compiler load their data pointers again.
    const float* values = linear.data();
    uint8_t* encoded = bytes.data();
    in_parallel_bands(linear.size(), kMinDisplayBand, [&](size_t first, size_t last) {
        size_t i = first;
        for (; i + kLanes <= last; i += kLanes) {
            Floats lanes;
            std::memcpy(&lanes, values + i, sizeof lanes);
            const Indices index = table_index(curve(lanes * exposure));
            for (size_t lane = 0; lane < kLanes; ++lane) encoded[i + lane] = table[index[lane]];
        }
        for (; i < last; ++i) encoded[i] = encode_srgb_with(table, curve(values[i] * exposure));
    });
}

}  // namespace

uint8_t encode_srgb(float linear) { return encode_srgb_with(srgb_table(), linear); }

float tone_map(float linear, ToneMap op) {
    switch (op) {
        case ToneMap::Clamp:
            return ClampCurve{}(linear);
        case ToneMap::Reinhard:
            return ReinhardCurve{}(linear);
        case ToneMap::Aces:
            return AcesCurve{}(linear);
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
            encode_display(linear, display.exposure, ClampCurve{}, image.rgb);
            break;
        case ToneMap::Reinhard:
            encode_display(linear, display.exposure, ReinhardCurve{}, image.rgb);
            break;
        case ToneMap::Aces:
            encode_display(linear, display.exposure, AcesCurve{}, image.rgb);
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
