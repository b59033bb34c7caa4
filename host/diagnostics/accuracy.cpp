// SPDX-License-Identifier: Apache-2.0
#include "diagnostics/accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "diagnostics/image_metrics.hpp"
#include "render/precision.hpp"
#include "scene/parameters.hpp"

namespace fgr {
namespace {

struct Setting {
    std::string knob;
    std::string value;
    std::vector<std::string> assignments;
    int samples = 1;
    bool double_precision = false;
    std::string reference = "geometry";
};

constexpr const char* kGeometryReference = "geometry";
constexpr const char* kSamplesReference = "samples";

std::string number(double value) { return fmt::format("{:.4g}", value); }

// A scene's parameter defaults, and values clamped into each parameter's range: what the sweep
// and the reference are built from.
struct DefaultParams {
    explicit DefaultParams(const Scene& s) : scene(s), values(default_param_values(s)) {}
    double value_of(const char* id) const { return double(param_value(scene, values, id)); }
    double clamp_to(const char* id, double value) const {
        const ParamInfo* param = scene.find_param(id);
        return std::clamp(value, double(param->min_value), double(param->max_value));
    }
    const Scene& scene;
    std::vector<float> values;
};

// One knob at a time around the scene's defaults, clamped into each parameter's range.
std::vector<Setting> sweep_settings(const Scene& scene) {
    const DefaultParams defaults(scene);
    const auto value_of = [&](const char* id) { return defaults.value_of(id); };
    const auto clamp_to = [&](const char* id, double value) {
        return defaults.clamp_to(id, value);
    };
    std::vector<Setting> settings = {{"default", "", {}, 1}};
    const auto sweep = [&](const char* id, const std::vector<double>& values, bool integral) {
        std::vector<double> seen;
        for (double value : values) {
            value = clamp_to(id, integral ? std::round(value) : value);
            if (std::find(seen.begin(), seen.end(), value) != seen.end()) continue;
            // The default point (compared as the float the parameter holds).
            if (float(value) == float(value_of(id))) continue;
            seen.push_back(value);
            settings.push_back({id, number(value), {fmt::format("{}={}", id, number(value))}, 1});
        }
    };
    const double steps = value_of("max_steps"), iterations = value_of("iterations");
    const double step_factor = value_of("step_factor");
    sweep("hit_threshold", {0.25, 0.5, 2.0, 4.0, 8.0}, false);
    sweep("max_steps", {steps / 8, steps / 4, steps / 2, steps * 2}, true);
    sweep("iterations", {iterations / 2, iterations * 0.75, iterations * 1.5}, true);
    sweep("step_factor", {step_factor * 0.6, step_factor * 0.8, 1.0}, false);
    sweep("over_relaxation", {1.0, 1.2, 1.4, 1.6, 1.8}, false);
    sweep("normal_epsilon", {0.1, 0.25, 1.0, 2.0}, false);
    settings.push_back({"precision", "double", {}, 1, true});
    // Samples per pixel from the default's 1, each against the default geometry at many samples.
    for (int samples : {1, 2, 4, 8, 16}) {
        settings.push_back({"spp", number(samples), {}, samples, false, kSamplesReference});
    }
    return settings;
}

// The geometry reference: a tenth of the default hit threshold, cautious plain steps, four times
// the steps, twice the iterations, a fine normal stencil (rendered at one sample per pixel, in
// double precision where the device has it).
std::vector<std::string> reference_assignments(const Scene& scene) {
    const DefaultParams defaults(scene);
    const auto value_of = [&](const char* id) { return defaults.value_of(id); };
    const auto clamp_to = [&](const char* id, double value) {
        return defaults.clamp_to(id, value);
    };
    return {"hit_threshold=" + number(clamp_to("hit_threshold", value_of("hit_threshold") / 10)),
            "step_factor=" + number(clamp_to("step_factor", value_of("step_factor") * 0.5)),
            "over_relaxation=1",
            "max_steps=" + number(clamp_to("max_steps", std::round(value_of("max_steps") * 4))),
            "iterations=" + number(clamp_to("iterations", std::round(value_of("iterations") * 2))),
            "normal_epsilon=0.1"};
}

FrameRequest request_for(const Scene& scene, const AccuracySettings& settings,
                         const std::vector<std::string>& assignments, int samples) {
    FrameRequest request;
    request.width = settings.width;
    request.height = settings.height;
    request.view = scene.cameras.front().view;
    request.params = default_param_values(scene);
    for (const std::string& assignment : assignments) {
        set_param_from_text(scene, request.params, assignment);
    }
    request.samples = samples;
    return request;
}

}  // namespace

ImageError compare_frames(const Frame& frame, const Frame& reference) {
    ImageError error;
    error.one_minus_ssim = 1.0 - ssim(linear_rgb(frame.image), linear_rgb(reference.image));
    const std::vector<uint8_t>& a = frame.image.rgb;
    const std::vector<uint8_t>& b = reference.image.rgb;
    double squares = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double d = double(a[i]) - double(b[i]);
        squares += d * d;
    }
    error.rmse = a.empty() ? 0.0 : std::sqrt(squares / double(a.size()));
    error.psnr = error.rmse > 0.0 ? 20.0 * std::log10(255.0 / error.rmse) : 99.0;
    long mismatched = 0, both = 0;
    double depth_sum = 0.0, relative_sum = 0.0;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
        const bool hit = frame.depth[i] >= 0.0f, reference_hit = reference.depth[i] >= 0.0f;
        mismatched += hit != reference_hit;
        if (hit && reference_hit) {
            const double d = std::abs(double(frame.depth[i]) - double(reference.depth[i]));
            depth_sum += d;
            relative_sum += d / std::max(double(reference.depth[i]), 1e-30);
            ++both;
        }
    }
    error.hit_mismatch_percent =
        frame.depth.empty() ? 0.0 : 100.0 * double(mismatched) / double(frame.depth.size());
    error.mean_depth_error = both ? depth_sum / double(both) : 0.0;
    error.mean_depth_error_relative = both ? relative_sum / double(both) : 0.0;
    return error;
}

void mark_pareto_front(std::vector<AccuracyPoint>& points) {
    const auto unbeaten = [&](const AccuracyPoint& point, double ImageError::*error) {
        return std::none_of(points.begin(), points.end(), [&](const AccuracyPoint& other) {
            return other.reference == point.reference && other.render_ms <= point.render_ms &&
                   other.error.*error <= point.error.*error &&
                   (other.render_ms < point.render_ms || other.error.*error < point.error.*error);
        });
    };
    for (AccuracyPoint& point : points) {
        point.pareto = unbeaten(point, &ImageError::rmse);
        point.pareto_ssim = unbeaten(point, &ImageError::one_minus_ssim);
    }
}

AccuracyReport run_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                  ProgramCache& cache, const AccuracySettings& settings,
                                  const AccuracyProgress& progress) {
    if (settings.width < kSsimWindow || settings.height < kSsimWindow) {
        throw std::invalid_argument(
            fmt::format("accuracy sweep: {}x{} is smaller than SSIM's "
                        "{}x{} window",
                        settings.width, settings.height, kSsimWindow, kSsimWindow));
    }
    // Both renderers count march steps, the sweep's measure of work that timing noise cannot
    // blur. Devices without cl_khr_fp64 skip the double point and render the reference in float.
    PrecisionRenderers renderers(device, cache, scene,
                                 {preferred_packet_width(device.info), scene.effects, true});
    const bool has_double = device.info.has_fp64;
    std::vector<Setting> sweep = sweep_settings(scene);
    if (!has_double) {
        std::erase_if(sweep, [](const Setting& setting) { return setting.double_precision; });
    }
    // Sample counts below the samples reference's (1, the default, always).
    std::erase_if(sweep, [&](const Setting& setting) {
        return setting.reference == kSamplesReference && setting.samples > 1 &&
               setting.samples >= settings.reference_samples;
    });
    const int total = static_cast<int>(sweep.size()) + 2;
    AccuracyReport report;
    // The geometry reference: fine geometry at the points' one sample per pixel.
    const std::vector<std::string> fine = reference_assignments(scene);
    std::string fine_settings;
    for (const std::string& assignment : fine) {
        fine_settings += (fine_settings.empty() ? "" : " ") + assignment;
    }
    fine_settings += fmt::format(" spp=1 precision={}", has_double ? "double" : "float");
    if (progress) progress(0, total, "geometry reference");
    const Frame geometry_truth =
        renderers.get(has_double).render(request_for(scene, settings, fine, 1));
    report.references.push_back({kGeometryReference, fine_settings, geometry_truth.render_ms});
    // The samples reference: the default geometry and precision at many samples per pixel. Its
    // first samples are the points' own (sample 0 is the pixel centre, then the same jitter), so
    // a point at n samples of independent per-sample error sigma is off by sigma^2 (1/n - 1/N)
    // in mean square: what is left to gain on the way to N.
    if (progress) progress(1, total, "samples reference");
    const Frame samples_truth =
        renderers.get(false).render(request_for(scene, settings, {}, settings.reference_samples));
    report.references.push_back(
        {kSamplesReference,
         fmt::format("scene defaults spp={} precision=float", settings.reference_samples),
         samples_truth.render_ms});
    // Timing rounds go over every setting in turn, so a slow spell on a shared machine slows
    // all settings alike instead of one; each setting keeps its fastest render. The error comes
    // from the first round (the images do not change between rounds).
    for (int round = 0; round < settings.repeats; ++round) {
        if (round > 0 && progress) {
            progress(total - 1, total,
                     fmt::format("timing round {}/{}", round + 1, settings.repeats));
        }
        for (size_t i = 0; i < sweep.size(); ++i) {
            const Setting& setting = sweep[i];
            if (round == 0 && progress) {
                progress(int(i) + 2, total,
                         setting.value.empty() ? setting.knob : setting.knob + "=" + setting.value);
            }
            const Frame frame =
                renderers.get(setting.double_precision)
                    .render(request_for(scene, settings, setting.assignments, setting.samples));
            if (round == 0) {
                const Frame& truth =
                    setting.reference == kSamplesReference ? samples_truth : geometry_truth;
                report.points.push_back(
                    {setting.knob, setting.value, setting.reference, frame.render_ms,
                     frame.stats ? frame.stats->mean_steps : 0.0, compare_frames(frame, truth)});
            } else {
                report.points[i].render_ms = std::min(report.points[i].render_ms, frame.render_ms);
            }
        }
    }
    if (progress) progress(total, total, "done");
    mark_pareto_front(report.points);
    return report;
}

std::string accuracy_csv(const AccuracyReport& report) {
    std::string csv =
        "knob,value,reference,render_ms,rmse,psnr_db,one_minus_ssim,hit_mismatch_percent,"
        "mean_depth_error,mean_depth_error_relative,pareto,pareto_ssim,steps_per_pixel\n";
    for (const AccuracyPoint& point : report.points) {
        csv += fmt::format(
            "{},{},{},{:.3f},{:.4f},{:.2f},{:.6g},{:.4f},{:.6g},{:.6g},{},{},{:.3f}\n", point.knob,
            point.value, point.reference, point.render_ms, point.error.rmse, point.error.psnr,
            point.error.one_minus_ssim, point.error.hit_mismatch_percent,
            point.error.mean_depth_error, point.error.mean_depth_error_relative,
            point.pareto ? 1 : 0, point.pareto_ssim ? 1 : 0, point.steps_per_pixel);
    }
    return csv;
}

std::string accuracy_gnuplot(const AccuracyReport& report, const std::string& scene_id,
                             const std::string& csv, const std::string& png) {
    // (knob, reference) in order of first appearance.
    std::vector<std::pair<std::string, std::string>> series;
    for (const AccuracyPoint& point : report.points) {
        if (point.knob != "default" &&
            std::find_if(series.begin(), series.end(),
                         [&](const auto& s) { return s.first == point.knob; }) == series.end()) {
            series.emplace_back(point.knob, point.reference);
        }
    }
    // The Pareto fronts of the points against the first reference (the geometry knobs', or the
    // path tracer's) as inline data, in order of time (drawn from the CSV, a
    // line would break at every row that is not on the front).
    const auto front = [&](const std::string& name, bool AccuracyPoint::*on_front,
                           double ImageError::*error) {
        std::vector<std::pair<double, double>> line;
        for (const AccuracyPoint& point : report.points) {
            if (point.reference == report.references.front().name && point.*on_front) {
                line.emplace_back(point.render_ms, point.error.*error);
            }
        }
        std::sort(line.begin(), line.end());
        std::string block = "$" + name + " << EOD\n";
        for (const auto& [ms, value] : line) block += fmt::format("{:.6g},{:.6g}\n", ms, value);
        return block + "EOD\n";
    };
    // CSV columns: 1 knob, 2 value, 4 render_ms, 5 rmse, 7 one_minus_ssim.
    const auto panel = [&](int error_column, const std::string& front_name,
                           const std::string& ylabel) {
        std::string plot = fmt::format(
            "set ylabel '{}'\n"
            "plot ${} using 1:2 with lines lw 2 lc rgb '#888888' title 'Pareto front ({} "
            "reference)'",
            ylabel, front_name, report.references.front().name);
        int style = 1;
        for (const auto& [knob, reference] : series) {
            const bool own = reference != report.references.front().name;
            plot += fmt::format(
                ", \\\n     '{0}' skip 1 using (strcol(1) eq '{1}' ? $4 : NaN):{2} with "
                "linespoints pt {3} ps 1.3{4} title '{1}{5}', \\\n     '{0}' skip 1 using "
                "(strcol(1) eq '{1}' ? $4 : NaN):{2}:2 with labels offset 0.8,0.6 font 'sans,8' "
                "notitle",
                csv, knob, error_column, style++ + 4, own ? " dt 2 lw 2" : "",
                own ? fmt::format(" (vs {} reference)", reference) : "");
        }
        plot += fmt::format(
            ", \\\n     '{}' skip 1 using (strcol(1) eq 'default' ? $4 : NaN):{} with points "
            "pt 7 ps 2.2 lc rgb 'black' title 'defaults'\n",
            csv, error_column);
        return plot;
    };
    std::string labels;
    double y = 0.055;
    for (const AccuracyReference& reference : report.references) {
        labels += fmt::format(
            "set label '{} reference: {}' at screen 0.01,{:.3f} font 'sans,9' "
            "noenhanced\n",
            reference.name, reference.settings, y);
        y -= 0.03;
    }
    return fmt::format(
        "# generated by fgr bench accuracy\n"
        "{}"
        "set terminal pngcairo size 1400,680 font 'sans,11'\n"
        "set output '{}'\n"
        "set datafile separator ','\n"
        "set multiplot title 'what accuracy costs in time: {} (each knob against the reference "
        "that isolates it)' noenhanced\n"
        "{}"
        "set xlabel 'render time (ms)'\n"
        "set logscale xy\n"
        "set grid\n"
        "set bmargin 8\n"
        "set tmargin 3\n"
        "set origin 0,0\n"
        "set size 0.42,1\n"
        "unset key\n"
        "{}"
        "unset label\n"
        "set origin 0.42,0\n"
        "set size 0.58,1\n"
        "set key outside right top noenhanced font 'sans,10'\n"
        "{}"
        "unset multiplot\n",
        front("front_rmse", &AccuracyPoint::pareto, &ImageError::rmse) +
            front("front_ssim", &AccuracyPoint::pareto_ssim, &ImageError::one_minus_ssim),
        png, scene_id, labels, panel(5, "front_rmse", "RMSE against the reference (8-bit levels)"),
        panel(7, "front_ssim", "1 - SSIM against the reference (display luma)"));
}

}  // namespace fgr
