// SPDX-License-Identifier: Apache-2.0
#include "output/denoised_frame.hpp"

#include <algorithm>
#include <stdexcept>

#include "output/parts/frame_merge.hpp"

namespace fgr {

Frame render_with_variance(const FrameRequest& request,
                           const std::function<Frame(const FrameRequest&)>& render) {
    if (request.samples < 2) {
        throw std::invalid_argument(
            "denoising needs at least 2 samples per pixel to estimate the noise (--spp 2 or more)");
    }
    // The path tracer estimates each pixel's variance itself (from its odd and even samples):
    // one render does.
    Frame whole = render(request);
    if (whole.cancelled) return whole;
    if (whole.variance.size() == whole.linear.size() && !whole.linear.empty()) {
        if (whole.samples < 2) {
            throw std::runtime_error(
                "denoising needs at least 2 samples per pixel to estimate the noise, and the "
                "time limit left fewer");
        }
        return whole;
    }
    // A renderer without its own estimate (none in fgr's modes that denoise; the fallback keeps
    // this usable with any): two halves of the samples, whose difference is noise, the whole
    // render above discarded.
    FrameRequest first = request;
    first.samples = request.samples / 2;
    Frame merged = render(first);
    if (merged.cancelled) return merged;
    FrameRequest second = request;
    second.first_sample = request.first_sample + first.samples;
    second.samples = request.samples - first.samples;
    Frame rest = render(second);
    if (rest.cancelled) return rest;
    if (rest.samples <= 0 || merged.samples <= 0) {
        throw std::runtime_error(
            "denoising needs the samples in two halves to estimate the noise, and the time "
            "limit left the second half none");
    }
    const double n1 = merged.samples, n2 = rest.samples, n = n1 + n2;
    std::vector<float> variance(merged.linear.size());
    if (merged.variance.size() == variance.size() && rest.variance.size() == variance.size()) {
        // The renderer's own estimates, of each half's mean: the merged mean's is theirs weighted
        // by the squares of the halves' shares.
        const float w1 = float(n1 * n1 / (n * n)), w2 = float(n2 * n2 / (n * n));
        for (size_t i = 0; i < variance.size(); ++i) {
            variance[i] = w1 * merged.variance[i] + w2 * rest.variance[i];
        }
    } else {
        // Halves of n1 and n2 samples differ by noise of variance sigma^2 (1/n1 + 1/n2), sigma^2
        // a sample's; their merged mean has variance sigma^2 / (n1 + n2).
        const float scale = float(n1 * n2 / (n * n));
        for (size_t i = 0; i < variance.size(); ++i) {
            const float d = merged.linear[i] - rest.linear[i];
            variance[i] = d * d * scale;
        }
    }
    const double render_ms = merged.render_ms + rest.render_ms;
    merged.variance.clear();
    rest.variance.clear();
    add_samples(merged, rest);
    merged.variance = std::move(variance);
    merged.render_ms = render_ms;
    return merged;
}

DenoiseInput denoise_input(const Frame& frame) {
    if (frame.variance.empty()) {
        throw std::invalid_argument("denoising needs the variance of the frame's estimate");
    }
    return DenoiseInput{frame.image.width, frame.image.height, frame.linear, frame.variance,
                        frame.albedo,      frame.normal,       frame.depth,  frame.alpha};
}

void denoise_frame(Frame& frame, const DisplayTransform& display, const DenoiseSettings& settings) {
    std::vector<float> denoised = denoise(denoise_input(frame), settings);
    frame.raw_linear = std::move(frame.linear);
    frame.linear = std::move(denoised);
    if (frame.foreground.size() == frame.linear.size() &&
        frame.alpha.size() * 3 == frame.linear.size()) {
        for (size_t i = 0; i < frame.linear.size(); ++i) {
            const float change = frame.linear[i] - frame.raw_linear[i];
            frame.foreground[i] = std::max(frame.foreground[i] + change * frame.alpha[i / 3], 0.0f);
        }
    }
    fill_display_image(frame.linear, display, frame.image);
}

}  // namespace fgr
