// SPDX-License-Identifier: Apache-2.0
#pragma once
// A frame's pixels encoded into an output file's interleaved samples a row at a time, through the
// conversions whole-image stills use (output/still_layers.hpp), so a file streamed in pieces (a
// tiled still, merged parts) holds what an untiled one would.

#include <cstdint>
#include <vector>

#include "output/tiled/streaming_image.hpp"
#include "output/tiled/tiled_still.hpp"
#include "render/renderer.hpp"

namespace fgr {

class RowEncoder {
public:
    // Keeps references to all three. The frame holds the planes the output needs (its image for
    // 8-bit output without alpha, alpha and foreground with alpha, the layers an EXR asks for).
    RowEncoder(const Frame& frame, const TiledOutput& output, const RowLayout& layout)
        : frame_(frame), output_(output), layout_(layout) {}

    // Pixels first_x .. first_x + count - 1 of the frame's row y into `out`.
    void encode(int y, int first_x, int count, uint8_t* out);

private:
    const Frame& frame_;
    const TiledOutput& output_;
    const RowLayout& layout_;
    std::vector<uint8_t> scratch8_;
    std::vector<uint16_t> scratch16_;
};

}  // namespace fgr
