// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a still's file holds at each pixel, converted from a Frame one band of rows at a time, so
// the whole-image writers (write_still) and a tiled writer that streams bands share one
// conversion: the display colour with or without alpha, the linear colour at 16 bits, and the
// EXR channels of the layers.
//
// Alpha is coverage (Frame::alpha: the fraction of a pixel's samples whose camera ray met the
// surface). With alpha the background is removed from the colour (Frame::foreground holds the
// samples that hit, summed over all samples), so the object composites cleanly over another
// background:
//   PNG  straight (un-associated) alpha, as PNG specifies: RGB = foreground / alpha, the object's
//        own colour at the samples that hit; RGB 0 where alpha is 0.
//   EXR  associated (premultiplied) alpha, as OpenEXR specifies: R, G, B = foreground (the colour
//        times its coverage), A = alpha; where alpha is 0 all four are 0.

#include <cstdint>
#include <span>
#include <vector>

#include "image/display.hpp"
#include "image/hdr_io.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Auxiliary layers an EXR still carries beside its linear image.
struct Aovs {
    bool albedo = false;  // the first hit's albedo, averaged over the samples (0 where missed)
    bool normal = false;  // the first hit's shading normal, averaged likewise
    bool depth = false;   // distance along the pixel centre's camera ray; +Inf where it missed
    bool alpha = false;   // coverage, with the colour premultiplied by it (see above)
    // Path mode: each pixel's samples (adaptive sampling gives each its own) and the variance of
    // its estimate (Frame::samples_per_pixel, Frame::variance).
    bool samples = false;
    bool variance = false;
    bool any() const { return albedo || normal || depth || alpha || samples || variance; }
    // Whether the frame needs the planes KernelSwitches::aovs adds (depth is always there).
    bool need_aov_planes() const { return albedo || normal || alpha; }
};

// Rows first_row .. first_row + rows - 1 of a frame (all of them: whole_frame).
struct RowBand {
    int first_row = 0;
    int rows = 0;
};
RowBand whole_frame(const Frame& frame);

// The straight (un-premultiplied) linear colour of `pixel` under alpha: foreground / alpha, 0 where
// nothing was covered. The frame must have alpha (throws std::invalid_argument otherwise, as do
// the functions below for a layer the frame lacks).
void straight_colour(const Frame& frame, size_t pixel, float rgb[3]);

// 8-bit RGBA (4 bytes a pixel, rows of the band in order) for a PNG with alpha: the straight colour
// through the display transform, alpha rounded to 8 bits.
void rgba8_rows(const Frame& frame, const DisplayTransform& display, RowBand band,
                std::span<uint8_t> out);

// 16-bit linear RGBA (4 samples a pixel) for a 16-bit PNG with alpha: the straight colour times
// `exposure`, clamped to [0, 1], and alpha, each times 65535.
void rgba16_linear_rows(const Frame& frame, float exposure, RowBand band, std::span<uint16_t> out);

// The EXR layers of the band: R, G, B (the linear colour as rendered; the premultiplied
// foreground when aovs.alpha), then albedo.R/G/B, normal.X/Y/Z, depth.Z and A as `aovs` asks,
// and raw.R/G/B, the colour as rendered, when R, G, B are denoised (Frame::raw_linear).
std::vector<ExrLayer> exr_layers(const Frame& frame, const Aovs& aovs, RowBand band);

}  // namespace fgr
