// SPDX-License-Identifier: Apache-2.0
#pragma once
// `fgr bench accuracy SCENE --mode brute`: what the brute-force mode's depth costs in time. The
// scene's first view is rendered with 1, 2, 4, ... passes and each depth buffer is compared with a
// reference: for a DE scene the sphere tracer's (the shaded mode's depth, the answer a distance
// estimator gives), for an inside-only scene a brute-force render of many more passes. The
// question Syntopia's post leaves at "a magnitude slower": how much slower, for which agreement.

#include <functional>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace fgr {

// How a depth buffer agrees with a reference of the same size, in pixel footprints (a pixel's
// angle times the reference's depth there: what one pixel covers at the surface).
struct DepthAgreement {
    long either = 0;               // pixels hit in either
    long both = 0;                 // pixels hit in both
    long within = 0;               // of those, the ones within the tolerance
    double mean_footprints = 0.0;  // mean |t - t_ref| over `both`, in footprints
    double iou() const { return either ? double(both) / double(either) : 1.0; }
    double within_fraction() const { return both ? double(within) / double(both) : 1.0; }
    // Pixels that disagree (hit in one only, or both beyond the tolerance), percent of `either`.
    double disagreeing_percent() const {
        return either ? 100.0 * double(either - within) / double(either) : 0.0;
    }
};

DepthAgreement depth_agreement(const std::vector<float>& depth, const std::vector<float>& reference,
                               float pixel_angle, float tolerance_footprints);

// The tolerance the sweep measures agreement at: a DE surface is taken where the DE falls below
// one footprint, which a sphere tracer approaches to within about one more.
constexpr float kBruteAgreementFootprints = 4.0f;

struct BrutePoint {
    int passes = 0;
    double render_ms = 0.0;  // fastest of the repeats
    double inside_tests_per_pixel = 0.0;
    DepthAgreement agreement;
};

struct BruteConvergence {
    std::string reference;  // what the points are compared with, in words
    double reference_ms = 0.0;
    bool sphere_traced = false;      // the reference is the sphere tracer's (a DE scene's)
    std::vector<BrutePoint> points;  // passes ascending
};

struct BruteConvergenceSettings {
    int width = 320;
    int height = 240;
    int repeats = 3;              // timing rounds, alternating over the points
    int max_passes = 128;         // the points: 1, 2, 4, ... up to this
    int reference_passes = 1024;  // inside-only scenes' reference
};

BruteConvergence run_brute_convergence(
    const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
    const BruteConvergenceSettings& settings,
    const std::function<void(int, int, const std::string&)>& progress = {});

std::string brute_convergence_csv(const BruteConvergence& convergence);

// Two panels: disagreeing pixels against render time (the reference's time marked), and the mean
// depth error in footprints against passes.
std::string brute_convergence_gnuplot(const BruteConvergence& convergence,
                                      const std::string& scene_id, const std::string& csv,
                                      const std::string& png);

}  // namespace fgr
