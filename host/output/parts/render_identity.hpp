// SPDX-License-Identifier: Apache-2.0
#pragma once
// What an image is, as text fields: the settings that decide every pixel of a render (scene and
// kernel, size, view, parameters, mode, effects, precision, projection, path tracing but its
// seed, display transform). Two renders with equal fields give pieces of one image: the tile
// store checks them before --resume takes its bands, and `fgr merge` before it joins parts.

#include <string>
#include <utility>
#include <vector>

#include "image/display.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Field name and value, in the order a mismatch is reported (the most telling first).
using IdentityFields = std::vector<std::pair<std::string, std::string>>;

// The identity of `request` (the whole image) rendered by `renderer`, shown with `display`.
// Leaves out what may differ between pieces of one image: the region, the samples, the seed, and
// the packet width (a device's preference, which does not change the pixels).
IdentityFields image_identity(const Renderer& renderer, const FrameRequest& request,
                              const DisplayTransform& display);

// The identity's "size", "display" and "layers" fields, which a part's header also gives as
// numbers: its reader checks the two agree.
std::string size_identity(int width, int height);
std::string display_identity(const DisplayTransform& display);
std::string layers_identity(bool layers);

}  // namespace fgr
