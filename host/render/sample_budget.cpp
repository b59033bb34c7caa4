// SPDX-License-Identifier: Apache-2.0
#include "render/sample_budget.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace fgr {

SampleBudget sample_budget(RenderMode mode) {
    switch (mode) {
        case RenderMode::Shaded:
            // Sample 0 is the pixel's centre, so one sample is the sharp image; more anti-alias.
            return {"samples", 1, 0, false};
        case RenderMode::Path:
            // 64 samples make a still of most scenes clean enough to judge; a view standing in
            // the viewer keeps converging for minutes.
            return {"samples", 64, kMaxSamples, true};
        case RenderMode::Brute:
            // Each pass can only bring a pixel's hit closer: 16 find most of a set's detail, and
            // after a few hundred the depth has settled.
            return {"passes", 16, 256, false};
    }
    throw std::invalid_argument("unknown render mode");
}

bool seeded_samples(std::string_view mode) {
    for (const RenderModeInfo& info : render_modes()) {
        if (info.name == mode) return sample_budget(info.mode).seeded;
    }
    return false;
}

void check_samples(int samples) {
    if (samples < kMinSamples || samples > kMaxSamples) {
        throw std::invalid_argument(
            fmt::format("samples per pixel must be between {} and {}", kMinSamples, kMaxSamples));
    }
}

int still_samples(RenderMode mode, std::optional<int> asked) {
    if (!asked) return sample_budget(mode).still;
    check_samples(*asked);
    return *asked;
}

}  // namespace fgr
