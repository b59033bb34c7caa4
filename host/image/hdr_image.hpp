// SPDX-License-Identifier: Apache-2.0
#pragma once
// High-dynamic-range images in memory: linear RGB floats, as environment maps are loaded and
// generated and as the path tracer's estimate is written out.

#include <cstddef>
#include <vector>

namespace fgr {

// Row-major from the top row, three linear floats (R, G, B) per pixel; unbounded, non-negative
// where they hold light. An environment map is an equirectangular (latitude-longitude) image of
// this kind: see fgr_environment.cl for how directions map to pixels.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;

    size_t pixel_index(int x, int y) const {
        return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3;
    }
};

}  // namespace fgr
