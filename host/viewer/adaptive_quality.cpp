// SPDX-License-Identifier: Apache-2.0
#include "viewer/adaptive_quality.hpp"

#include <algorithm>
#include <cmath>

namespace fgr::viewer {
namespace {

// Preview scales are multiples of this, so a cost that wobbles a little keeps the same size.
constexpr double kScaleStep = 1.0 / 64.0;

// Weight of a new measurement in the cost average: smooths out single slow frames (a compile, a
// scheduler hiccup) while still following a real change within a handful of frames.
constexpr double kCostSmoothing = 0.25;

// settings.min_scale made usable: a positive scale no larger than 1.
float lowest_scale(const QualitySettings& settings) {
    constexpr auto kSmallest = static_cast<float>(kScaleStep);
    if (!(settings.min_scale > kSmallest)) {
        return kSmallest;  // also catches NaN
    }
    return std::min(settings.min_scale, 1.0f);
}

}  // namespace

QualityController::QualityController(QualitySettings settings) : settings_(settings) {}

RenderPass QualityController::next_pass(bool interactive, int samples_done, int64_t full_pixels,
                                        int sample_cap) const {
    RenderPass pass;
    if (interactive) {
        pass.kind = RenderPass::Kind::Preview;
        pass.scale = preview_scale(full_pixels);
        return pass;
    }
    // A still view always gets its full-resolution centre sample, whatever the cap says.
    const int cap = std::max(sample_cap > 0 ? sample_cap : settings_.sample_cap, 1);
    const int next_sample = std::max(samples_done, 0);
    if (next_sample < cap) {
        pass.kind = RenderPass::Kind::Refine;
        pass.sample = next_sample;
    }
    return pass;
}

float QualityController::preview_scale(int64_t full_pixels) const {
    if (!(ms_per_pixel_ > 0.0) || full_pixels <= 0) {
        return 1.0f;
    }
    const float lowest = lowest_scale(settings_);
    if (!(settings_.target_ms > 0.0)) {
        return lowest;
    }
    // Frame time grows with the pixel count, i.e. with the square of the scale.
    const double full_frame_ms = ms_per_pixel_ * static_cast<double>(full_pixels);
    const double exact = std::sqrt(settings_.target_ms / full_frame_ms);
    const double rounded = std::floor(exact / kScaleStep) * kScaleStep;
    return static_cast<float>(std::clamp(rounded, static_cast<double>(lowest), 1.0));
}

void QualityController::record_frame(int64_t pixels, double ms) {
    if (pixels <= 0 || !std::isfinite(ms) || !(ms > 0.0)) {
        return;
    }
    const double cost = ms / static_cast<double>(pixels);
    if (ms_per_pixel_ > 0.0) {
        ms_per_pixel_ += kCostSmoothing * (cost - ms_per_pixel_);
    } else {
        ms_per_pixel_ = cost;
    }
}

int scaled_size(int full, float scale) {
    // A zero-sized window (minimised) still gets one pixel: renderers cannot make an empty image.
    const int largest = std::max(full, 1);
    if (!std::isfinite(scale)) {
        return largest;
    }
    const double exact = static_cast<double>(full) * static_cast<double>(scale);
    const double bounded = std::clamp(std::round(exact), 1.0, static_cast<double>(largest));
    return static_cast<int>(bounded);
}

}  // namespace fgr::viewer
