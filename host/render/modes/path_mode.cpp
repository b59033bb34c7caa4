// SPDX-License-Identifier: Apache-2.0
#include "render/modes/path_mode.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "device/kernel_layout.hpp"
#include "util/parallel_bands.hpp"

namespace fgr {
namespace {

// The sample limit of a pixel that takes every sample (FGR_PATH_SAMPLE_LIMIT_PLANE): past any
// sample index.
constexpr float kEverySample = 3.0e38f;

// One light in the kernel's layout. Lights keep the shaded mode's meaning: a light of intensity
// I lights a white diffuse surface facing it to radiance I, so its irradiance is pi I. Light
// sampling weighs each light at each shading point by what it would add there
// (light_pick_weight in fgr_mode_path.cl), so the list carries no pick probabilities.
struct PathLight {
    bool point = false;
    glm::vec3 vector{0.0f, 0.0f, 1.0f};
    glm::vec3 radiance{0.0f};  // a disc's radiance, or a delta light's irradiance (times 1/d^2)
    float cos_max = 1.0f;
};

PathLight scene_light(const Light& light) {
    constexpr float pi = 3.14159265358979f;
    PathLight path;
    const glm::vec3 irradiance = pi * light.intensity * light.colour;
    path.point = light.type == LightType::Point;
    path.vector = path.point ? light.vector : glm::normalize(light.vector);
    if (!path.point && light.angular_radius > 0.0f) {
        // A disc of radiance L and angular radius r gives irradiance pi L sin^2 r facing it.
        const float sin_r = std::sin(light.angular_radius);
        path.radiance = irradiance / (pi * sin_r * sin_r);
        path.cos_max = std::cos(light.angular_radius);
    } else {
        path.radiance = irradiance;
    }
    return path;
}

PathLight sun_light(const SunDisc& sun, float intensity) {
    PathLight path;
    path.vector = glm::normalize(sun.direction);
    path.radiance = sun.radiance * intensity;
    path.cos_max = std::cos(sun.angular_radius_radians);
    return path;
}

// The path tracer's lights, FGR_PATH_LIGHT_FLOATS floats each: the sky's sun, then the scene's.
std::vector<float> light_list(const Scene& scene, const PreparedEnvironment& environment,
                              bool scene_lights) {
    std::vector<PathLight> lights;
    if (environment.sun) lights.push_back(sun_light(*environment.sun, environment.intensity));
    if (scene_lights) {
        // Under the sky its sun stands in for the scene's key light (its first directional one).
        bool key_replaced = !environment.sun.has_value();
        for (const Light& light : scene.lights) {
            if (!key_replaced && light.type == LightType::Directional) {
                key_replaced = true;
                continue;
            }
            lights.push_back(scene_light(light));
        }
    }
    std::vector<float> values;
    for (const PathLight& light : lights) {
        std::array<float, FGR_PATH_LIGHT_FLOATS> light_values{};
        light_values[FGR_PATH_LIGHT_KIND] =
            static_cast<float>(light.point ? FGR_LIGHT_KIND_POINT : FGR_LIGHT_KIND_DIRECTIONAL);
        for (int c = 0; c < 3; ++c) {
            light_values[FGR_PATH_LIGHT_VECTOR + c] = light.vector[c];
            light_values[FGR_PATH_LIGHT_RADIANCE + c] = light.radiance[c];
        }
        light_values[FGR_PATH_LIGHT_COS_MAX] = light.cos_max;
        values.insert(values.end(), light_values.begin(), light_values.end());
    }
    return values;
}

}  // namespace

PathMode::PathMode(const ComputeDevice& device, const Scene& scene, const KernelSwitches& switches)
    : device_(device), scene_(scene), stats_(switches.stats), aovs_(switches.aovs) {}

int PathMode::extra_planes(const KernelSwitches& switches) const {
    return FGR_PATH_AUXILIARY_PLANES + (switches.stats ? FGR_PATH_STATS_PLANES : 0) +
           (switches.aovs ? FGR_PATH_FOREGROUND_PLANES : 0);
}

void PathMode::prepare(const PathSettings& settings) {
    std::shared_ptr<const PreparedEnvironment> environment = settings.environment;
    if (!environment) {
        if (!default_environment_) {
            default_environment_ = prepare_environment(EnvironmentChoice{}, scene_);
        }
        environment = default_environment_;
    }
    if (environment == bound_environment_ && settings.scene_lights == bound_scene_lights_) return;
    environment_data_ = upload_floats(device_, environment->tables.data);
    const std::vector<float> lights = light_list(scene_, *environment, settings.scene_lights);
    lights_ = upload_floats(device_, lights);
    light_count_ = static_cast<int>(lights.size() / FGR_PATH_LIGHT_FLOATS);
    environment_weight_ = environment->mean_luminance;
    bound_environment_ = environment;
    bound_scene_lights_ = settings.scene_lights;
}

void PathMode::bind(cl::Kernel& kernel, const FrameRequest& request, const TileLayout&) {
    const PathSettings& settings = request.path;
    check_path_settings(settings);
    prepare(settings);
    layout::path_settings argument{};
    argument.max_bounces = settings.max_bounces;
    argument.roulette_depth =
        settings.roulette_depth > 0 ? settings.roulette_depth : kMaxBounces + 1;
    argument.radiance_clamp = settings.radiance_clamp;
    argument.flags = (settings.light_sampling ? FGR_PATH_LIGHT_SAMPLING : 0) |
                     (settings.mis ? FGR_PATH_MIS : 0) |
                     (settings.environment_importance ? FGR_PATH_ENVIRONMENT_IS : 0) |
                     (settings.stratified ? 0 : FGR_PATH_INDEPENDENT) |
                     (regrouped(settings) ? FGR_PATH_REGROUP : 0);
    argument.launch_samples = 1;
    argument.seed = settings.seed;
    argument.light_count = light_count_;
    argument.environment_weight = environment_weight_;
    kernel.setArg(FGR_PATH_ARG_LIGHTS, lights_);
    kernel.setArg(FGR_PATH_ARG_SETTINGS, argument);
    bound_settings_ = argument;
    kernel.setArg(FGR_PATH_ARG_ENV_DATA, environment_data_);
    kernel.setArg(FGR_PATH_ARG_ENVIRONMENT,
                  environment_info(bound_environment_->tables, bound_environment_->rotation_degrees,
                                   bound_environment_->intensity));
}

void PathMode::write_inputs(const cl::CommandQueue& queue, const cl::Buffer& planes,
                            const TileLayout& layout, const FrameRequest& request) {
    const size_t plane = static_cast<size_t>(layout.plane_size());
    const size_t offset = sizeof(float) * plane * FGR_PATH_SAMPLE_LIMIT_PLANE;
    if (request.sample_limits.empty()) {
        queue.enqueueFillBuffer(planes, kEverySample, offset, sizeof(float) * plane);
        return;
    }
    // Padding lanes (past the region's edge) take none; they trace nothing anyway.
    std::vector<float> limits(plane, 0.0f);
    const PixelRegion region = rendered_region(request);
    for (int y = 0; y < region.height; ++y) {
        for (int x = 0; x < region.width; ++x) {
            limits[static_cast<size_t>(layout.index(x, y))] =
                request.sample_limits[static_cast<size_t>(y) * region.width + x];
        }
    }
    queue.enqueueWriteBuffer(planes, CL_TRUE, offset, sizeof(float) * plane, limits.data());
}

// IFS scenes trace their rays whole (kernels/geometry/fgr_ifs.cl), which the regrouped kernel's
// one DE evaluation a turn cannot interleave: they keep the packet kernel.
bool PathMode::regrouped(const PathSettings& settings) const {
    return settings.regroup && scene_.ifs == nullptr;
}

int PathMode::launch_samples(const FrameRequest& request) const {
    if (!regrouped(request.path)) return 1;
    if (request.enough) return kRegroupTimedLaunchSamples;
    return request.sample_limits.empty() ? kRegroupLaunchSamples : kRegroupLimitedLaunchSamples;
}

void PathMode::bind_launch(cl::Kernel& kernel, int count) {
    if (bound_settings_.launch_samples == count) return;
    bound_settings_.launch_samples = count;
    kernel.setArg(FGR_PATH_ARG_SETTINGS, bound_settings_);
}

void PathMode::read_back(std::span<const float> planes, const TileLayout& layout,
                         const FrameRequest& request, int samples, Frame& frame) const {
    const int width = frame.image.width, height = frame.image.height;  // the region's
    const size_t pixels = static_cast<size_t>(width) * static_cast<size_t>(height);
    const float average = 1.0f / static_cast<float>(std::max(samples, 1));
    frame.albedo = planes_in_rows(planes, layout, FGR_PATH_ALBEDO_PLANE, 3, width, height, average);
    frame.normal = planes_in_rows(planes, layout, FGR_PATH_NORMAL_PLANE, 3, width, height, average);
    frame.alpha = planes_in_rows(planes, layout, FGR_PATH_ALPHA_PLANE, 1, width, height, average);
    if (aovs_) {
        frame.foreground = planes_in_rows(planes, layout, FGR_PATH_FOREGROUND_PLANE(stats_),
                                          FGR_PATH_FOREGROUND_PLANES, width, height, average);
    }
    // Each pixel's samples: first_sample .. its limit, of those launched. The planes above were
    // averaged over all launched samples; a pixel that took fewer is rescaled to its own count.
    const std::vector<float> odd =
        planes_in_rows(planes, layout, FGR_PATH_ODD_RADIANCE_PLANE, 3, width, height);
    frame.samples_per_pixel.assign(pixels, static_cast<float>(samples));
    frame.variance.assign(pixels * 3, -1.0f);
    const long first = request.first_sample;
    // Pixels are independent: bands of them on the host's threads (on a GPU the host's work is
    // much of a path-traced frame).
    in_parallel_bands(pixels, kMinHostBand, [&](size_t first_pixel, size_t last_pixel) {
        for (size_t pixel = first_pixel; pixel < last_pixel; ++pixel) {
            long taken = samples;
            if (!request.sample_limits.empty()) {
                const double limit = std::floor(double(request.sample_limits[pixel]));
                taken = static_cast<long>(std::clamp(limit - double(first), 0.0, double(samples)));
                frame.samples_per_pixel[pixel] = static_cast<float>(taken);
                const float rescale = taken > 0 ? float(samples) / float(taken) : 0.0f;
                if (taken != samples) {
                    for (int c = 0; c < 3; ++c) {
                        frame.linear[pixel * 3 + c] *= rescale;
                        frame.albedo[pixel * 3 + c] *= rescale;
                        frame.normal[pixel * 3 + c] *= rescale;
                        if (aovs_) frame.foreground[pixel * 3 + c] *= rescale;
                    }
                    frame.alpha[pixel] *= rescale;
                }
            }
            // The odd and even samples among first .. first + taken - 1 (x / 2 odd numbers are
            // below x), whose means differ by about the noise: Var(odd mean - even mean) =
            // s^2 (1/o + 1/e) for a per-sample variance s^2, so (difference)^2 / (1/o + 1/e)
            // estimates s^2 without bias, and s^2 / taken the variance of the pixel's mean.
            const long odd_count = (first + taken) / 2 - first / 2;
            const long even_count = taken - odd_count;
            if (odd_count < 1 || even_count < 1) continue;
            for (int c = 0; c < 3; ++c) {
                const double sum = double(frame.linear[pixel * 3 + c]) * double(taken);
                const double odd_sum = odd[pixel * 3 + c];
                const double difference =
                    odd_sum / double(odd_count) - (sum - odd_sum) / double(even_count);
                const double per_sample =
                    difference * difference / (1.0 / double(odd_count) + 1.0 / double(even_count));
                frame.variance[pixel * 3 + c] = static_cast<float>(per_sample / double(taken));
            }
        }
    });
    const size_t plane = static_cast<size_t>(layout.plane_size());
    if (!stats_) return;
    // Sum the lanes' evaluations over every pixel; a packet's count is the same in all of its
    // lanes, so it is taken once per tile (from its first lane).
    LaneStats stats;
    stats.packet_width = layout.packet_width;
    const size_t lanes = plane * FGR_PATH_LANE_STEPS_PLANE;
    const size_t packets = plane * FGR_PATH_PACKET_STEPS_PLANE;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            stats.lane_evaluations += planes[lanes + static_cast<size_t>(layout.index(x, y))];
        }
    }
    for (size_t tile = 0; tile < plane; tile += static_cast<size_t>(layout.packet_width)) {
        stats.packet_evaluations += planes[packets + tile];
    }
    frame.lane_stats = stats;
}

}  // namespace fgr
