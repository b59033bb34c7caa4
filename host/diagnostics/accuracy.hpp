// SPDX-License-Identifier: Apache-2.0
#pragma once
// `fgr bench accuracy SCENE`: what accuracy costs in time. Each knob that trades one for the other
// (hit threshold, max steps, DE iterations, step factor, over-relaxation, normal epsilon, samples
// per pixel, float or double) is swept on its own from the scene's defaults; every setting's
// render time is measured and its image compared with a reference render of the same view that
// differs from it only in what the knob controls, so no other error hides the knob's:
// - the geometry knobs (and float or double) against the "geometry" reference: tiny hit
//   threshold, many more steps and iterations, cautious plain steps, a fine normal stencil, double
//   precision, at the points' one sample per pixel (the same pixel-centre sample, so aliasing,
//   which no geometry knob changes, is no error);
// - samples per pixel (anti-aliasing) against the "samples" reference: the scene's default
//   geometry at many samples per pixel, so the curve shows what samples buy.
// Errors are RMSE of the 8-bit image and 1 - SSIM of its display luma
// (diagnostics/image_metrics.hpp). Among the points measured against one reference, those no other
// beats in both time and error form its Pareto front.

#include <functional>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/path_settings.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace fgr {

struct ImageError {
    double rmse = 0.0;                       // over sRGB 8-bit channel values
    double psnr = 0.0;                       // 20 log10(255 / rmse) dB; 99 when identical
    double one_minus_ssim = 0.0;             // 1 - SSIM of the display luma: 0 when identical
    double hit_mismatch_percent = 0.0;       // pixels hit in one image and missed in the other
    double mean_depth_error = 0.0;           // mean |t - t_ref| where both hit, scene units
    double mean_depth_error_relative = 0.0;  // mean |t - t_ref| / t_ref there
};

// Compares two frames of the same size, at least 11x11 (SSIM's window; std::invalid_argument
// otherwise).
ImageError compare_frames(const Frame& frame, const Frame& reference);

struct AccuracyPoint {
    std::string knob;   // "default", "hit_threshold", "max_steps", ..., "spp", "precision"
    std::string value;  // the knob's value ("" for the default point)
    std::string reference = "geometry";  // the name of the reference it is compared with
    double render_ms = 0.0;
    // Mean DE evaluations of the primary march per pixel: the work, free of timing noise.
    double steps_per_pixel = 0.0;
    ImageError error;
    bool pareto = false;       // on the time / RMSE Pareto front of its reference's points
    bool pareto_ssim = false;  // on the time / (1 - SSIM) Pareto front of its reference's points
};

// Among the points compared with the same reference, marks each point no other point beats in
// both render time and RMSE (pareto) and in both render time and 1 - SSIM (pareto_ssim), one of
// the two strictly.
void mark_pareto_front(std::vector<AccuracyPoint>& points);

struct AccuracySettings {
    int width = 320;
    int height = 240;
    int reference_samples = 64;  // of the samples reference
    int repeats = 5;  // timing rounds over all settings; each setting's fastest render counts
};

// Called with (settings done, settings in all, what is being rendered).
using AccuracyProgress = std::function<void(int, int, const std::string&)>;

struct AccuracyReference {
    std::string name;      // "geometry" or "samples", as AccuracyPoint::reference names it
    std::string settings;  // its parameter assignments, samples and precision, for the record
    double render_ms = 0.0;
};

struct AccuracyReport {
    // The default first, then the geometry knobs, float or double, and the samples per pixel from
    // 1 (the default's image, against the samples reference) up.
    std::vector<AccuracyPoint> points;
    std::vector<AccuracyReference> references;  // "geometry", then "samples"
};

AccuracyReport run_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                  ProgramCache& cache, const AccuracySettings& settings,
                                  const AccuracyProgress& progress = {});

// The same question for the path tracer's noise (render mode "path", `base` its settings): samples
// per pixel (1, 4, 16, 64), the bounce cap (1, 2, 4 at 16 spp), Russian roulette from bounce 1
// or never, and the sampling strategies (no MIS, no light sampling, uniform environment
// sampling), each against one "path" reference: the default settings at reference_samples
// samples per pixel (at least 256) with 32 bounces and another seed, so a point's error is its
// noise plus the bias of a bounce cap it has and the reference does not.
AccuracyReport run_path_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                       ProgramCache& cache, const AccuracySettings& settings,
                                       const PathSettings& base,
                                       const AccuracyProgress& progress = {});

std::string accuracy_csv(const AccuracyReport& report);

// A gnuplot script that plots `csv` into `png`: two panels, RMSE and 1 - SSIM against render time,
// one series per knob (samples per pixel against their own reference, dashed), the geometry
// knobs' Pareto front as a line, the default marked.
std::string accuracy_gnuplot(const AccuracyReport& report, const std::string& scene_id,
                             const std::string& csv, const std::string& png);

}  // namespace fgr
