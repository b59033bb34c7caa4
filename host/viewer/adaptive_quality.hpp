// SPDX-License-Identifier: Apache-2.0
#pragma once
// Adaptive quality: while the view changes, render at a reduced resolution that holds a target
// frame time; once it is still, refine: the full-resolution centre sample, then one jittered
// sample after another (anti-aliasing, depth of field, soft effects) up to a sample cap.

#include <cstdint>

namespace fgr::viewer {

struct QualitySettings {
    double target_ms = 33.0;  // frame time to hold while the view changes
    int sample_cap = 16;      // samples per pixel accumulated when still
    float min_scale = 0.1f;   // smallest resolution scale (fraction of the width and height)
};

// What to render next.
struct RenderPass {
    enum class Kind { Preview, Refine, Idle } kind = Kind::Idle;
    float scale = 1.0f;  // Preview: resolution scale in [min_scale, 1]; otherwise 1
    int sample = 0;      // Refine: index of the sample to add (0 is the pixel centre)
};

class QualityController {
public:
    explicit QualityController(QualitySettings settings);

    // The next pass: a Preview while `interactive`; otherwise a Refine of sample
    // `samples_done` until the cap is reached (`sample_cap`, or the settings' when 0), then Idle.
    RenderPass next_pass(bool interactive, int samples_done, int64_t full_pixels,
                         int sample_cap = 0) const;

    // Resolution scale whose frame should take target_ms: sqrt(target / (cost * pixels)), clamped
    // to [min_scale, 1]; 1 before any measurement. Rounded down to a multiple of 1/64 so small
    // cost changes do not resize every frame.
    float preview_scale(int64_t full_pixels) const;

    // Feeds a finished frame of `pixels` pixels that took `ms`: updates the cost per pixel
    // (exponential moving average; the first measurement is taken as is). Ignores pixels <= 0 or
    // non-finite / non-positive ms.
    void record_frame(int64_t pixels, double ms);

    // Estimated milliseconds per pixel, 0 before any measurement.
    double ms_per_pixel() const { return ms_per_pixel_; }
    const QualitySettings& settings() const { return settings_; }
    void set_settings(const QualitySettings& settings) { settings_ = settings; }

private:
    QualitySettings settings_;
    double ms_per_pixel_ = 0.0;
};

// Pixels of a dimension scaled by `scale`: round(full * scale), at least 1, at most full.
int scaled_size(int full, float scale);

}  // namespace fgr::viewer
