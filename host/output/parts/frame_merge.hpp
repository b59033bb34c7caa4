// SPDX-License-Identifier: Apache-2.0
#pragma once
// Renders of the same image with different seeds (MPI ranks, or `fgr render --part` runs on a
// farm) merged into one: each pixel's estimate is the mean of its samples, so the merged value is
// the mean of the parts weighted by their sample counts, and the result is the same estimator as
// one render that took all the samples.

#include "render/renderer.hpp"

namespace fgr {

// Adds `part` (Frame::samples samples a pixel) into `merged`, which then holds the samples of
// both: linear colour, albedo, normal, alpha and foreground become the sample-weighted means;
// depth and hits (sample 0's) stay `merged`'s; `merged.image` is not updated (display_image
// makes it from the merged linear colour). An empty `merged` (no samples) becomes `part`.
// Throws std::invalid_argument when the two differ in size or in the planes they hold.
void add_samples(Frame& merged, const Frame& part);

}  // namespace fgr
