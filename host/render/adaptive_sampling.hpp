// SPDX-License-Identifier: Apache-2.0
#pragma once
// Adaptive sampling for the path tracer: samples go to the pixels whose estimate is still noisier
// than a threshold, in rounds, and the image stays an unbiased estimate of the exact one.
//
// A rule that stops a pixel once the samples it has look good enough, and then averages those
// very samples, is biased: a pixel whose first samples all missed a small bright light reads
// zero variance, stops, and stays dark. Here every decision about a round (which pixels take part,
// how many samples each takes, whether it is the pixel's last, and the weight its mean gets in the
// final average) is made before that round is rendered, from earlier rounds only; the weights of a
// pixel's rounds sum to exactly 1 at its last round. A round's mean is then an unbiased estimate
// whatever earlier rounds showed, so the weighted sum is one too. The price: a pixel that stops
// early has given its first rounds the small weight planned when it looked as if it would need
// every sample, and its last round carries the rest (measured in the user guide).

#include <string>

#include "render/renderer.hpp"

namespace fgr {

// The relative standard error fgr uses for a pixel: the root of the mean of its three channels'
// variance over the mean of their values, the latter at least kRelativeErrorFloor so that
// near-black pixels (whose relative error means nothing on screen) do not take every sample.
constexpr float kRelativeErrorFloor = 0.02f;
double relative_error(const float* rgb, const float* variance);

// The first round's samples when --min-spp is not given: a few of the cap's, at least 4.
int default_min_samples(int cap);

// Which stopping rule render_adaptive follows.
enum class AdaptiveRule {
    Unbiased,  // every decision from earlier rounds, weights fixed before each round (above)
    // A pixel stops when its own samples so far look converged and averages them all: biased.
    // Only the tests use it, to show the bias the default rule avoids.
    Naive,
};

// Renders `request` (path mode, request.path.noise_threshold > 0) on `renderer` in rounds;
// request.samples is the cap per pixel, request.path.min_samples (or default_min_samples) what
// every pixel takes in the first round. The frame holds the weighted estimate, each pixel's
// samples, the variance of its estimate and Frame::adaptive. Renderer::render calls this itself
// for such a request.
Frame render_adaptive(Renderer& renderer, const FrameRequest& request,
                      AdaptiveRule rule = AdaptiveRule::Unbiased);

// The report's one-line summary for the log.
std::string adaptive_summary(const AdaptiveReport& report);

}  // namespace fgr
