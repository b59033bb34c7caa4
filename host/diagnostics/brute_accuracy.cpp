// SPDX-License-Identifier: Apache-2.0
#include "diagnostics/brute_accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "camera/camera.hpp"
#include "scene/parameters.hpp"

namespace fgr {

DepthAgreement depth_agreement(const std::vector<float>& depth, const std::vector<float>& reference,
                               float pixel_angle, float tolerance_footprints) {
    if (depth.size() != reference.size()) {
        throw std::invalid_argument("depth agreement: the buffers differ in size");
    }
    DepthAgreement agreement;
    double footprints = 0.0;
    for (size_t i = 0; i < depth.size(); ++i) {
        const bool hit = depth[i] >= 0.0f, reference_hit = reference[i] >= 0.0f;
        agreement.either += hit || reference_hit;
        if (!(hit && reference_hit)) continue;
        ++agreement.both;
        const double footprint = std::max(double(reference[i]) * pixel_angle, 1e-30);
        const double error = std::abs(double(depth[i]) - double(reference[i])) / footprint;
        footprints += error;
        agreement.within += error <= tolerance_footprints;
    }
    agreement.mean_footprints = agreement.both ? footprints / double(agreement.both) : 0.0;
    return agreement;
}

namespace {

FrameRequest first_view(const Scene& scene, const BruteConvergenceSettings& settings, int samples) {
    FrameRequest request;
    request.width = settings.width;
    request.height = settings.height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    request.samples = samples;
    return request;
}

KernelSwitches switches_for(const Scene& scene, const ComputeDevice& device, RenderMode mode,
                            bool stats) {
    KernelSwitches switches;
    switches.packet_width = preferred_packet_width(device.info);
    switches.effects = scene.effects;
    switches.stats = stats;
    switches.mode = mode;
    return switches;
}

// Text for inside a single-quoted gnuplot string, where a quote is written twice.
std::string gnuplot_escaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        out += c;
        if (c == '\'') out += c;
    }
    return out;
}

}  // namespace

BruteConvergence run_brute_convergence(
    const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
    const BruteConvergenceSettings& settings,
    const std::function<void(int, int, const std::string&)>& progress) {
    if (scene.ifs) {
        throw std::invalid_argument(
            fmt::format("the IFS scene '{}' has no brute-force rendering to measure", scene.id));
    }
    std::vector<int> passes;
    for (int n = 1; n <= std::max(settings.max_passes, 1); n *= 2) passes.push_back(n);
    const int total = static_cast<int>(passes.size()) + 1;
    Renderer brute(device, cache, scene, switches_for(scene, device, RenderMode::Brute, true));
    BruteConvergence result;
    if (progress) progress(0, total, "reference");
    std::vector<float> reference;
    if (scene.has_distance_estimator()) {
        Renderer traced(device, cache, scene,
                        switches_for(scene, device, RenderMode::Shaded, false));
        result.reference = "the sphere-traced depth (shaded mode)";
        result.sphere_traced = true;
        for (int round = 0; round < settings.repeats; ++round) {
            const Frame frame = traced.render(first_view(scene, settings, 1));
            result.reference_ms =
                round == 0 ? frame.render_ms : std::min(result.reference_ms, frame.render_ms);
            reference = frame.depth;
        }
    } else {
        result.reference = fmt::format("{} brute-force passes", settings.reference_passes);
        const Frame frame = brute.render(first_view(scene, settings, settings.reference_passes));
        result.reference_ms = frame.render_ms;
        reference = frame.depth;
    }
    const float angle = pixel_angle(camera_basis(scene.cameras.front().view), settings.width);
    for (int round = 0; round < settings.repeats; ++round) {
        for (size_t i = 0; i < passes.size(); ++i) {
            if (round == 0 && progress) {
                progress(int(i) + 1, total, fmt::format("{} passes", passes[i]));
            }
            const Frame frame = brute.render(first_view(scene, settings, passes[i]));
            if (round == 0) {
                BrutePoint point;
                point.passes = passes[i];
                point.render_ms = frame.render_ms;
                point.inside_tests_per_pixel = frame.inside_tests_per_pixel.value_or(0.0);
                point.agreement =
                    depth_agreement(frame.depth, reference, angle, kBruteAgreementFootprints);
                result.points.push_back(point);
            } else {
                result.points[i].render_ms = std::min(result.points[i].render_ms, frame.render_ms);
            }
        }
    }
    if (progress) progress(total, total, "done");
    return result;
}

std::string brute_convergence_csv(const BruteConvergence& convergence) {
    std::string csv =
        "passes,render_ms,inside_tests_per_pixel,disagreeing_percent,iou,within_fraction,"
        "mean_error_footprints,reference_ms\n";
    for (const BrutePoint& point : convergence.points) {
        csv += fmt::format("{},{:.3f},{:.2f},{:.4f},{:.5f},{:.5f},{:.4f},{:.3f}\n", point.passes,
                           point.render_ms, point.inside_tests_per_pixel,
                           point.agreement.disagreeing_percent(), point.agreement.iou(),
                           point.agreement.within_fraction(), point.agreement.mean_footprints,
                           convergence.reference_ms);
    }
    return csv;
}

std::string brute_convergence_gnuplot(const BruteConvergence& convergence,
                                      const std::string& scene_id, const std::string& csv,
                                      const std::string& png) {
    // CSV columns: 1 passes, 2 render_ms, 4 disagreeing_percent, 7 mean_error_footprints.
    return fmt::format(
        "set terminal pngcairo size 960,400 font ',10'\n"
        "set output '{1}'\n"
        "set datafile separator ','\n"
        "set multiplot layout 1,2 title 'Brute force on {0}: depth against {2}'\n"
        "set grid\n"
        "set logscale xy\n"
        "set xlabel 'render time (ms)'\n"
        "set ylabel 'disagreeing pixels (%): > {3:g} footprints, or hit in one only'\n"
        "set arrow 1 from {4:g}, graph 0 to {4:g}, graph 1 nohead dashtype 2 lc rgb '#888888'\n"
        "set label 1 'reference: {4:.0f} ms' at {4:g}, graph 0.95 offset 0.5,0 "
        "textcolor rgb '#666666'\n"
        "plot '{5}' skip 1 using 2:4:1 with linespoints pt 7 title 'passes (labelled)', \\\n"
        "     '{5}' skip 1 using 2:4:(sprintf('%d', $1)) with labels offset 0,1 notitle\n"
        "unset arrow 1\n"
        "unset label 1\n"
        "set logscale x 2\n"
        "set xlabel 'passes'\n"
        "set ylabel 'mean depth error where both hit (footprints)'\n"
        "plot '{5}' skip 1 using 1:7 with linespoints pt 7 title 'mean |t - t_{{ref}}|'\n"
        "unset multiplot\n",
        gnuplot_escaped(scene_id), gnuplot_escaped(png), gnuplot_escaped(convergence.reference),
        kBruteAgreementFootprints, convergence.reference_ms, gnuplot_escaped(csv));
}

}  // namespace fgr
