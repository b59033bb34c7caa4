// SPDX-License-Identifier: Apache-2.0
#pragma once
// A path-traced frame denoised (denoise/denoise.hpp) as `fgr render --denoise`, `fgr video
// --denoise` and the viewer's toggle have it: the frame's linear colour filtered with its
// variance, albedo, normal, depth and coverage as guides, the raw estimate kept beside it.

#include <functional>

#include "denoise/denoise.hpp"
#include "image/display.hpp"
#include "render/renderer.hpp"

namespace fgr {

// Renders `request` through `render` with the variance of its estimate in Frame::variance, which
// the denoiser needs: one render when `render` estimates it (the path tracer does, from each
// pixel's odd and even samples); otherwise two renders of half the samples each (samples first ..
// first + n/2 - 1, then the rest: together the same estimate as one render of all of them,
// FrameRequest::first_sample), merged, the variance from the difference of the halves (or their
// own when the second render has it). Throws std::invalid_argument when the request has a single
// sample (nothing to estimate a variance from) and std::runtime_error when a time limit left
// fewer than 2 samples (or the second half none).
Frame render_with_variance(const FrameRequest& request,
                           const std::function<Frame(const FrameRequest&)>& render);

// The inputs denoise() takes from `frame` (colour, variance and the features it has). `frame`
// must outlive them. Throws std::invalid_argument when the frame has no variance.
DenoiseInput denoise_input(const Frame& frame);

// Denoises `frame` in place: Frame::raw_linear takes the colour as rendered, Frame::linear the
// denoised colour, Frame::image the display of it through `display`; with alpha, the foreground
// (the covered samples' colour) takes the change times the coverage: all of it where every sample
// hit, so that the foreground is the denoised colour there, none of it where none did. Throws
// std::invalid_argument as denoise_input does.
void denoise_frame(Frame& frame, const DisplayTransform& display, const DenoiseSettings& settings);

}  // namespace fgr
