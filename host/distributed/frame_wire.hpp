// SPDX-License-Identifier: Apache-2.0
#pragma once
// Frames and encoded tiles as bytes, to send between ranks of one job (same machine type, same
// build: native byte order, no versioning).

#include <cstdint>
#include <span>
#include <vector>

#include "output/tiled/tiled_still.hpp"
#include "render/renderer.hpp"

namespace fgr {

// The frame's image and planes (linear, depth, albedo, normal, alpha, foreground), its size,
// samples and hits; not its statistics.
std::vector<uint8_t> frame_to_bytes(const Frame& frame);
// Throws std::runtime_error for bytes that are not a whole frame.
Frame frame_from_bytes(std::span<const uint8_t> bytes);

std::vector<uint8_t> tile_to_bytes(const EncodedTile& tile);
EncodedTile tile_from_bytes(std::span<const uint8_t> bytes);

}  // namespace fgr
