// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a screen shows of scene-referred linear RGB: an exposure, a tone curve, then the sRGB
// curve at 8 bits. The renderer, the viewer, stills, tiles and merged parts all encode through
// these, so one linear frame gives the same bytes wherever it is displayed.

#include <cstdint>
#include <vector>

#include "image/image_io.hpp"

namespace fgr {

// Linear [0, 1] to 8-bit sRGB (values outside are clamped, NaN becomes 0).
uint8_t encode_srgb(float linear);

enum class ToneMap { Clamp = 0, Reinhard = 1, Aces = 2 };

// Scene-referred linear value (after exposure) to display-referred [0, 1]: clamp, Reinhard's
// x / (1 + x), or Narkowicz's fit of the ACES filmic curve.
float tone_map(float linear, ToneMap op);

// What the 8-bit display image does to linear colour: `exposure` and `tone_map`, then the sRGB
// curve (fill_display_image).
struct DisplayTransform {
    float exposure = 1.0f;
    ToneMap tone_map = ToneMap::Clamp;
};

// Linear RGB rows through `display` into `image`, whose width, height and bytes are already sized
// (the renderer claims them while the device renders). Throws std::logic_error when the bytes are
// not as many as the values.
void fill_display_image(const std::vector<float>& linear, const DisplayTransform& display,
                        Image8& image);

// fill_display_image into a new width x height image.
Image8 display_image(const std::vector<float>& linear, const DisplayTransform& display, int width,
                     int height);

}  // namespace fgr
