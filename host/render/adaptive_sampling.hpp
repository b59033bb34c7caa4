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
#include <vector>

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

struct AdaptivePixel;

// The rounds one at a time, for a caller that renders and shows them itself (the viewer):
// next_round's request goes to Renderer::render, its frame to add_round, until next_round says
// there is none.
class AdaptiveSampler {
public:
    // `request` as render_adaptive takes it.
    explicit AdaptiveSampler(const FrameRequest& request,
                             AdaptiveRule rule = AdaptiveRule::Unbiased);
    ~AdaptiveSampler();
    AdaptiveSampler(AdaptiveSampler&&) noexcept;
    AdaptiveSampler& operator=(AdaptiveSampler&&) noexcept;

    // The next round's request, planned from the earlier rounds alone; null once every pixel is
    // done. Valid until the next call.
    const FrameRequest* next_round();
    // That round's frame (Renderer::render's, not cancelled).
    void add_round(const Frame& frame);
    // Makes the next round every pixel's last (a time limit): the image stays unbiased.
    void finish_next_round() { finishing_ = true; }
    bool finished() const { return finished_; }
    // Samples the pixels still going have taken.
    long samples_started() const { return started_; }
    // The estimate so far, with each pixel's samples, variance and the report. Before the last
    // round (a preview of the rounds so far) each pixel's rounds are scaled to a whole weight.
    Frame frame(const Scene& scene) const;

private:
    FrameRequest request_;
    AdaptiveRule rule_;
    int width_ = 0, height_ = 0;
    size_t count_ = 0;
    long cap_ = 0;
    long min_samples_ = 0;
    double threshold_ = 0.0;
    std::vector<AdaptivePixel> pixels_;
    FrameRequest round_;
    Frame result_;
    std::vector<double> albedo_, normal_, alpha_, foreground_;
    long started_ = 0;  // samples the continuing pixels have taken
    long batch_ = 0;    // the planned round's samples
    int rounds_ = 0;
    bool finishing_ = false;
    bool finished_ = false;
    double render_ms_ = 0.0;
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
