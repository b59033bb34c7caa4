// SPDX-License-Identifier: Apache-2.0
// `fgr bench accuracy SCENE --mode path`: what the path tracer's noise costs in time. Every
// point renders the scene's first camera with one knob changed from the given settings and is
// compared with a long render (see run_path_accuracy_sweep in accuracy.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "diagnostics/accuracy.hpp"
#include "diagnostics/image_metrics.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

constexpr const char* kPathReference = "path";
constexpr int kReferenceBounces = 32;
constexpr int kMinReferenceSamples = 256;
constexpr int kKnobSamples = 16;  // the bounce, roulette and strategy points' samples per pixel

struct PathPoint {
    std::string knob;
    std::string value;
    PathSettings settings;
    int samples = kKnobSamples;
};

std::vector<PathPoint> path_points(const PathSettings& base) {
    std::vector<PathPoint> points = {{"default", "", base, kKnobSamples}};
    for (int samples : {1, 4, 64}) {
        points.push_back({"spp", std::to_string(samples), base, samples});
    }
    for (int bounces : {1, 2, 4}) {
        if (bounces >= base.max_bounces) continue;
        PathPoint point{"bounces", std::to_string(bounces), base};
        point.settings.max_bounces = bounces;
        points.push_back(point);
    }
    for (int depth : {1, 0}) {
        PathPoint point{"roulette_depth", depth == 0 ? "off" : std::to_string(depth), base};
        point.settings.roulette_depth = depth;
        points.push_back(point);
    }
    PathPoint no_mis{"strategy", "no MIS", base};
    no_mis.settings.mis = false;
    PathPoint no_light{"strategy", "no light sampling", base};
    no_light.settings.light_sampling = false;
    PathPoint uniform{"strategy", "uniform environment", base};
    uniform.settings.environment_importance = false;
    points.insert(points.end(), {no_mis, no_light, uniform});
    return points;
}

FrameRequest path_request(const Scene& scene, const AccuracySettings& settings,
                          const PathSettings& path, int samples) {
    FrameRequest request;
    request.width = settings.width;
    request.height = settings.height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    request.samples = samples;
    request.path = path;
    return request;
}

}  // namespace

AccuracyReport run_path_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                       ProgramCache& cache, const AccuracySettings& settings,
                                       const PathSettings& base, const AccuracyProgress& progress) {
    if (settings.width < kSsimWindow || settings.height < kSsimWindow) {
        throw std::invalid_argument(
            fmt::format("accuracy sweep: {}x{} is smaller than SSIM's {}x{} window", settings.width,
                        settings.height, kSsimWindow, kSsimWindow));
    }
    KernelSwitches switches;
    switches.packet_width = preferred_packet_width(device.info);
    switches.effects = scene.effects;
    switches.mode = RenderMode::Path;
    Renderer renderer(device, cache, scene, switches);
    const std::vector<PathPoint> points = path_points(base);
    const int total = static_cast<int>(points.size()) + 1;
    AccuracyReport report;
    // The reference: the same settings, many more samples, a bounce cap no point reaches, and
    // its own seed, so its noise is independent of every point's.
    PathSettings reference_settings = base;
    reference_settings.max_bounces = std::max(base.max_bounces, kReferenceBounces);
    reference_settings.seed = base.seed + 1;
    const int reference_samples = std::max(settings.reference_samples, kMinReferenceSamples);
    if (progress) progress(0, total, "path reference");
    const Frame truth =
        renderer.render(path_request(scene, settings, reference_settings, reference_samples));
    report.references.push_back(
        {kPathReference,
         fmt::format("spp={} bounces={} roulette_depth={} seed={}", reference_samples,
                     reference_settings.max_bounces, reference_settings.roulette_depth,
                     reference_settings.seed),
         truth.render_ms});
    for (int round = 0; round < settings.repeats; ++round) {
        for (size_t i = 0; i < points.size(); ++i) {
            const PathPoint& point = points[i];
            if (round == 0 && progress) {
                progress(int(i) + 1, total,
                         point.value.empty() ? point.knob : point.knob + "=" + point.value);
            }
            const Frame frame =
                renderer.render(path_request(scene, settings, point.settings, point.samples));
            if (round == 0) {
                report.points.push_back({point.knob, point.value, kPathReference, frame.render_ms,
                                         0.0, compare_frames(frame, truth)});
            } else {
                report.points[i].render_ms = std::min(report.points[i].render_ms, frame.render_ms);
            }
        }
    }
    if (progress) progress(total, total, "done");
    mark_pareto_front(report.points);
    return report;
}

}  // namespace fgr
