#include "fgr/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "fgr/parameters.hpp"
#include "fgr/precision.hpp"

namespace fgr {
namespace {

struct Setting {
    std::string knob;
    std::string value;
    std::vector<std::string> assignments;
    int samples = 1;
    bool double_precision = false;
};

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
    const auto clamp_to = [&](const char* id, double value) { return defaults.clamp_to(id, value); };
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
    for (int samples : {2, 4, 8}) settings.push_back({"spp", number(samples), {}, samples});
    settings.push_back({"precision", "double", {}, 1, true});
    return settings;
}

// The reference: a tenth of the default hit threshold, cautious plain steps, four times the
// steps, twice the iterations, a fine normal stencil, many samples (and double precision, where
// the device has it).
std::vector<std::string> reference_assignments(const Scene& scene) {
    const DefaultParams defaults(scene);
    const auto value_of = [&](const char* id) { return defaults.value_of(id); };
    const auto clamp_to = [&](const char* id, double value) { return defaults.clamp_to(id, value); };
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
    for (AccuracyPoint& point : points) {
        point.pareto = std::none_of(points.begin(), points.end(), [&](const AccuracyPoint& other) {
            return other.render_ms <= point.render_ms && other.error.rmse <= point.error.rmse &&
                   (other.render_ms < point.render_ms || other.error.rmse < point.error.rmse);
        });
    }
}

AccuracyReport run_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                  ProgramCache& cache, const AccuracySettings& settings,
                                  const AccuracyProgress& progress) {
    // Both renderers count march steps, the sweep's measure of work that timing noise cannot
    // blur. Devices without cl_khr_fp64 skip the double point and render the reference in float.
    PrecisionRenderers renderers(device, cache, scene,
                                 {preferred_packet_width(device.info), scene.effects, true});
    const bool has_double = device.info.has_fp64;
    std::vector<Setting> sweep = sweep_settings(scene);
    if (!has_double) {
        std::erase_if(sweep, [](const Setting& setting) { return setting.double_precision; });
    }
    const int total = static_cast<int>(sweep.size()) + 1;
    AccuracyReport report;
    const std::vector<std::string> reference = reference_assignments(scene);
    for (const std::string& assignment : reference) {
        report.reference_settings += (report.reference_settings.empty() ? "" : " ") + assignment;
    }
    report.reference_settings += fmt::format(" spp={} precision={}", settings.reference_samples,
                                             has_double ? "double" : "float");
    if (progress) progress(0, total, "reference");
    const Frame truth = renderers.get(has_double).render(
        request_for(scene, settings, reference, settings.reference_samples));
    report.reference_ms = truth.render_ms;
    // Timing rounds go over every setting in turn, so a slow spell on a shared machine slows
    // all settings alike instead of one; each setting keeps its fastest render. The error comes
    // from the first round (the images do not change between rounds).
    for (int round = 0; round < settings.repeats; ++round) {
        if (round > 0 && progress) {
            progress(total - 1, total, fmt::format("timing round {}/{}", round + 1, settings.repeats));
        }
        for (size_t i = 0; i < sweep.size(); ++i) {
            const Setting& setting = sweep[i];
            if (round == 0 && progress) {
                progress(int(i) + 1, total,
                         setting.value.empty() ? setting.knob : setting.knob + "=" + setting.value);
            }
            const Frame frame = renderers.get(setting.double_precision)
                                    .render(request_for(scene, settings, setting.assignments,
                                                        setting.samples));
            if (round == 0) {
                report.points.push_back({setting.knob, setting.value, frame.render_ms,
                                         frame.stats ? frame.stats->mean_steps : 0.0,
                                         compare_frames(frame, truth)});
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
        "knob,value,render_ms,rmse,psnr_db,hit_mismatch_percent,mean_depth_error,"
        "mean_depth_error_relative,pareto,steps_per_pixel\n";
    for (const AccuracyPoint& point : report.points) {
        csv += fmt::format("{},{},{:.3f},{:.4f},{:.2f},{:.4f},{:.6g},{:.6g},{},{:.3f}\n",
                           point.knob, point.value, point.render_ms, point.error.rmse,
                           point.error.psnr, point.error.hit_mismatch_percent,
                           point.error.mean_depth_error, point.error.mean_depth_error_relative,
                           point.pareto ? 1 : 0, point.steps_per_pixel);
    }
    return csv;
}

std::string accuracy_gnuplot(const AccuracyReport& report, const std::string& scene_id,
                             const std::string& csv, const std::string& png) {
    std::vector<std::string> knobs;
    for (const AccuracyPoint& point : report.points) {
        if (point.knob != "default" &&
            std::find(knobs.begin(), knobs.end(), point.knob) == knobs.end()) {
            knobs.push_back(point.knob);
        }
    }
    std::string script = fmt::format(
        "# generated by fgr bench accuracy\n"
        "set terminal pngcairo size 960,640 font 'sans,11'\n"
        "set output '{}'\n"
        "set datafile separator ','\n"
        "set title 'what accuracy costs in time: {}' noenhanced\n"
        "set label 'reference: {}' at screen 0.01,0.02 font 'sans,9' noenhanced\n"
        "set xlabel 'render time (ms)'\n"
        "set ylabel 'RMSE against the reference (8-bit levels)'\n"
        "set logscale xy\n"
        "set grid\n"
        "set bmargin 6\n"
        "set key outside right top noenhanced\n"
        "plot '{}' skip 1 using (strcol(9) eq '1' ? $3 : NaN):4 smooth unique with lines lw 2 "
        "lc rgb '#888888' title 'Pareto front'",
        png, scene_id, report.reference_settings, csv);
    int style = 1;
    for (const std::string& knob : knobs) {
        script += fmt::format(
            ", \\\n     '{0}' skip 1 using (strcol(1) eq '{1}' ? $3 : NaN):4 with linespoints "
            "pt {2} ps 1.3 title '{1}', \\\n     '{0}' skip 1 using (strcol(1) eq '{1}' ? $3 : "
            "NaN):4:2 with labels offset 0.8,0.6 font 'sans,8' notitle",
            csv, knob, style++ + 4);
    }
    script += fmt::format(
        ", \\\n     '{}' skip 1 using (strcol(1) eq 'default' ? $3 : NaN):4 with points pt 7 ps "
        "2.2 lc rgb 'black' title 'defaults'\n",
        csv);
    return script;
}

}  // namespace fgr
