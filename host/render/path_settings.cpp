// SPDX-License-Identifier: Apache-2.0
#include "render/path_settings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace fgr {

void check_path_settings(const PathSettings& settings) {
    if (settings.max_bounces < 0 || settings.max_bounces > kMaxBounces) {
        throw std::invalid_argument(fmt::format("bounces must be between 0 and {}", kMaxBounces));
    }
    if (settings.roulette_depth < 0 || settings.roulette_depth > kMaxBounces) {
        throw std::invalid_argument(
            fmt::format("Russian roulette depth must be between 0 (off) and {}", kMaxBounces));
    }
    if (!std::isfinite(settings.radiance_clamp) || settings.radiance_clamp < 0.0f) {
        throw std::invalid_argument("radiance clamp must be 0 (off) or a positive number");
    }
    if (!std::isfinite(settings.noise_threshold) || settings.noise_threshold < 0.0f ||
        settings.noise_threshold > 1.0f) {
        throw std::invalid_argument(
            "noise threshold must be 0 (off) or a relative error in (0, 1], e.g. 0.01");
    }
    if (settings.min_samples < 0) {
        throw std::invalid_argument("minimum samples per pixel must be 0 (automatic) or more");
    }
}

}  // namespace fgr
