// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the path tracer (render mode "path") is asked to do beyond the view: how long paths run,
// which sampling strategies it combines, and the environment that lights the scene (chosen and
// prepared in render/environment.hpp).

#include <cstdint>
#include <memory>

#include "render/environment.hpp"

namespace fgr {

struct PathSettings {
    int max_bounces = 8;          // scattering events after the camera ray, at most
    int roulette_depth = 3;       // Russian roulette from this bounce on (unbiased)
    float radiance_clamp = 0.0f;  // > 0 clamps each sample's radiance (removes fireflies, biased)
    bool light_sampling = true;   // next-event estimation towards the environment and lights
    bool mis = true;              // power-heuristic weights between light and BSDF sampling
    bool environment_importance = true;  // sample the environment by its luminance
    bool scene_lights = true;            // the scene's own lights shine besides the environment
    // Stratified samples (scrambled Sobol per pixel); false draws independent random ones, to
    // measure what stratification buys (the error then falls exactly as 1 / sqrt(samples)).
    bool stratified = true;
    uint32_t seed = 0;  // another seed, another noise pattern
    // Adaptive sampling (render/adaptive_sampling.hpp): > 0 stops each pixel once the relative
    // standard error of its estimate is estimated at most this, FrameRequest::samples being the
    // cap; 0 gives every pixel the same samples.
    float noise_threshold = 0.0f;
    int min_samples = 0;  // what every pixel takes first under adaptive sampling; 0: automatic
    // Regrouped packets: a launch traces several samples of each pixel and a lane whose path
    // ends starts the next one at once, so the lanes stay busy after the first bounce; false
    // runs the packet kernel, a sample a launch, whose lanes idle as their paths end (to
    // measure what regrouping buys). The image is the same either way, up to the order in which
    // a pixel's samples are summed.
    bool regroup = true;
    // What lights the scene; null renders with the default sky.
    std::shared_ptr<const PreparedEnvironment> environment;
    // The environment compares by identity: a prepared environment is never changed in place.
    bool operator==(const PathSettings&) const = default;
};

// Limits fgr accepts, checked by check_path_settings (std::invalid_argument, one line).
constexpr int kMaxBounces = 1024;
// Samples of each pixel a regrouped launch traces at most (PathSettings::regroup): the more, the
// shorter the tail in which a packet's last paths end with its other lanes idle (lane utilisation
// 0.73 at 8, 0.77 at 16 on the canonical Mandelbulb), but the coarser the steps at which a render
// reports each finished sample and can stop (FrameRequest::enough): a render with a time budget
// takes the smaller launches.
constexpr int kRegroupLaunchSamples = 16;
constexpr int kRegroupTimedLaunchSamples = 4;
// Samples a regrouped launch traces at most under per-pixel limits (an adaptive round,
// FrameRequest::sample_limits): a late round's few noisy pixels then fill a tile's queue, where
// launches of 16 samples left them a short queue each and repeated the launch overhead.
constexpr int kRegroupLimitedLaunchSamples = 256;
void check_path_settings(const PathSettings& settings);

}  // namespace fgr
