// SPDX-License-Identifier: Apache-2.0
#include "render/render_cost.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "camera/camera.hpp"
#include "scene/ifs/ifs_cost.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

// Steps a second one compute unit keeps: measured on a 2-core EPYC with PoCL (an IFS whose rays
// open 65536 nodes of 64 maps: 16x12 pixels in 15 s), and for a GPU's compute unit, which runs
// many more lanes at once, ten times that. Rough: the estimate only needs to tell minutes from
// hours.
constexpr double kCpuStepsPerComputeUnit = 4e7;
constexpr double kGpuStepsPerComputeUnit = 4e8;

// Nodes an IFS ray may visit per march step of max_steps (kernels/geometry/fgr_ifs.cl's
// FGR_IFS_NODES_PER_STEP).
constexpr double kIfsNodesPerStep = 256.0;

// Rays a path-traced sample follows: the camera ray and its bounces (Russian roulette ends most
// paths within a few), each with a light sample.
double path_rays(const PathSettings& path) { return 2.0 * (1.0 + std::min(path.max_bounces, 6)); }

// "45 s", "3 min", "2.5 h", "41 days".
std::string duration_text(double seconds) {
    if (seconds < 90.0) return fmt::format("{:.0f} s", seconds);
    if (seconds < 5400.0) return fmt::format("{:.0f} min", seconds / 60.0);
    if (seconds < 2.0 * 86400.0) return fmt::format("{:.1f} h", seconds / 3600.0);
    if (seconds < 3650.0 * 86400.0) return fmt::format("{:.0f} days", seconds / 86400.0);
    return fmt::format("{:.1e} years", seconds / (365.0 * 86400.0));
}

// The value of a built-in parameter, or its default when the request leaves the values out.
double param_or_default(const Scene& scene, const std::vector<float>& params, const char* id) {
    if (!params.empty()) return param_value(scene, params, id);
    const ParamInfo* param = scene.find_param(id);
    return param != nullptr ? param->default_value[0] : 0.0;
}

// An IFS ray's steps (ball tests), its node count against the kernel's cap, and what to change.
void ifs_cost(const Scene& scene, const FrameRequest& request, RenderCost& cost) {
    const IfsScene& ifs = *scene.ifs;
    const std::vector<float>& params = request.params;
    const int depth = static_cast<int>(param_or_default(scene, params, "ifs_depth"));
    const double max_nodes = param_or_default(scene, params, "max_steps") * kIfsNodesPerStep;
    const double footprint = param_or_default(scene, params, "hit_threshold") *
                             pixel_angle(camera_basis(request.view), request.width);
    const double distance =
        glm::length(request.view.position - ifs.bounds.centre) - ifs.bounds.radius;
    const IfsCost ray = estimate_ifs_cost(ifs, depth, footprint, distance);
    const double maps = static_cast<double>(ifs.maps.size());
    cost.rays_unfinished = ray.nodes_per_ray > max_nodes;
    cost.steps_per_sample = std::min(ray.tests_per_ray, max_nodes * maps);
    cost.costly = fmt::format(
        "IFS scene '{}': about {:.2g} nodes a ray ({} maps whose balls fill {:.3g}x their "
        "parent's a level, similarity dimension {:.3g}; depth {}, reached {})",
        scene.id, ray.nodes_per_ray, ifs.maps.size(), ray.overlap, ray.dimension, depth,
        ray.levels);
    // The depth that keeps rays within a thousandth of the cap.
    const int affordable = deepest_affordable_ifs_depth(ifs, depth, footprint, distance,
                                                        std::max(1.0, max_nodes / 64.0));
    if (affordable < depth) {
        cost.remedy =
            fmt::format("lower ifs_depth to {} (--set ifs_depth={})", affordable, affordable);
    } else {
        cost.remedy = "render fewer pixels or samples";
    }
}

}  // namespace

RenderCost estimate_render_cost(const Scene& scene, const FrameRequest& request, RenderMode mode) {
    RenderCost cost;
    const std::vector<float>& params = request.params;
    const double iterations = std::max(1.0, param_or_default(scene, params, "iterations"));
    const double march =
        std::min(kTypicalMarchSteps, param_or_default(scene, params, "max_steps")) * iterations *
        kMarchIterationSteps;
    if (scene.ifs) {
        ifs_cost(scene, request, cost);
        if (mode == RenderMode::Path) cost.steps_per_sample *= path_rays(request.path);
    } else if (mode == RenderMode::Brute) {
        const double tests = param_or_default(scene, params, "brute_samples") +
                             param_or_default(scene, params, "brute_bisection");
        cost.steps_per_sample = std::max(1.0, tests) * iterations * kInsideIterationSteps;
        cost.costly = fmt::format("brute force: {:g} inside tests of {:g} iterations a pass", tests,
                                  iterations);
        cost.remedy = "lower --spp (passes), brute_samples or iterations, or the size";
    } else if (mode == RenderMode::Path) {
        cost.steps_per_sample = path_rays(request.path) * march;
        cost.costly =
            fmt::format("path tracing: up to {} bounces a sample", request.path.max_bounces);
        cost.remedy = "lower --spp, the bounces or the size";
    } else {
        cost.steps_per_sample = 2.0 * march;
        cost.costly = "marching";
        cost.remedy = "lower --spp or the size";
    }
    const PixelRegion& region = request.region;
    const double pixels = region.width > 0 ? double(region.width) * region.height
                                           : double(request.width) * request.height;
    cost.steps = cost.steps_per_sample * pixels * std::max(1, request.samples);
    return cost;
}

double estimated_pace(const DeviceInfo& device) {
    const double units = std::max(1u, device.compute_units);
    return units * (device.is_gpu ? kGpuStepsPerComputeUnit : kCpuStepsPerComputeUnit);
}

std::string cost_refusal(const RenderCost& cost, double frames, double pace, double limit_seconds,
                         const std::string& override_hint) {
    const double seconds = cost.steps * std::max(frames, 1.0) / pace;
    const std::string what =
        frames > 1.0 ? fmt::format("these {:.0f} frames", frames) : std::string("this render");
    if (cost.rays_unfinished) {
        return fmt::format(
            "{}: more than a ray may visit (max_steps x 256), so rays would stop unfinished and "
            "{} would be wrong, and take about {}; {}, or {}",
            cost.costly, what, duration_text(seconds), cost.remedy, override_hint);
    }
    if (!(seconds > limit_seconds)) return "";
    return fmt::format("{} would take about {} ({}), over the limit of {}; {}, or {}", what,
                       duration_text(seconds), cost.costly, duration_text(limit_seconds),
                       cost.remedy, override_hint);
}

}  // namespace fgr
