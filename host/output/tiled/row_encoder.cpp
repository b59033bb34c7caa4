// SPDX-License-Identifier: Apache-2.0
// Row encoding (tiled/row_encoder.hpp).
#include "output/tiled/row_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "output/still_layers.hpp"

namespace fgr {
namespace {

uint16_t to_u16(float value) {
    const float clamped = value > 0.0f ? std::min(value, 1.0f) : 0.0f;  // NaN to 0
    return static_cast<uint16_t>(std::lround(clamped * 65535.0f));
}

}  // namespace

void RowEncoder::encode(int y, int first_x, int count, uint8_t* out) {
    const size_t width = size_t(frame_.image.width);
    const size_t pixel_bytes = layout_.pixel_bytes();
    const size_t row_pixel = size_t(y) * width;
    const RowBand row{y, 1};
    if (layout_.type == SampleType::F32) {
        const std::vector<ExrLayer> layers = exr_layers(frame_, output_.aovs, row);
        for (int x = 0; x < count; ++x) {
            float* pixel = reinterpret_cast<float*>(out + size_t(x) * pixel_bytes);
            for (const ExrLayer& layer : layers) {
                const size_t n = layer.channels.size();
                for (size_t c = 0; c < n; ++c) *pixel++ = layer.values[size_t(first_x + x) * n + c];
            }
        }
        return;
    }
    const bool alpha = layout_.channels.size() == 4;
    if (layout_.type == SampleType::U8 && !alpha) {
        std::memcpy(out, &frame_.image.rgb[(row_pixel + size_t(first_x)) * 3], size_t(count) * 3);
    } else if (layout_.type == SampleType::U8) {
        scratch8_.resize(width * 4);
        rgba8_rows(frame_, output_.display, row, scratch8_);
        std::memcpy(out, &scratch8_[size_t(first_x) * 4], size_t(count) * 4);
    } else if (alpha) {
        scratch16_.resize(width * 4);
        rgba16_linear_rows(frame_, output_.display.exposure, row, scratch16_);
        std::memcpy(out, &scratch16_[size_t(first_x) * 4], size_t(count) * 8);
    } else {
        uint16_t* samples = reinterpret_cast<uint16_t*>(out);
        const float* linear = &frame_.linear[(row_pixel + size_t(first_x)) * 3];
        for (size_t i = 0; i < size_t(count) * 3; ++i) {
            samples[i] = to_u16(linear[i] * output_.display.exposure);  // as linear_image16
        }
    }
}

}  // namespace fgr
