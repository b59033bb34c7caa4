#pragma once
// `fgr bench accuracy SCENE`: what accuracy costs in time. Each knob that trades one for the other
// (hit threshold, max steps, DE iterations, step factor, over-relaxation, normal epsilon, samples
// per pixel, float or double) is swept on its own from the scene's defaults; every setting's
// render time is measured and its image compared with a high-quality reference render of the
// same view (tiny hit threshold, many more steps and iterations, cautious plain steps, many
// samples, double precision). The points no other point beats in both time and error form the
// Pareto front.

#include <functional>
#include <string>
#include <vector>

#include "fgr/opencl_device.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/renderer.hpp"
#include "fgr/scene.hpp"

namespace fgr {

struct ImageError {
    double rmse = 0.0;                  // over sRGB 8-bit channel values
    double psnr = 0.0;                  // 20 log10(255 / rmse) dB; 99 when identical
    double hit_mismatch_percent = 0.0;  // pixels hit in one image and missed in the other
    double mean_depth_error = 0.0;      // mean |t - t_ref| where both hit, scene units
    double mean_depth_error_relative = 0.0;  // mean |t - t_ref| / t_ref there
};

// Compares two frames of the same size.
ImageError compare_frames(const Frame& frame, const Frame& reference);

struct AccuracyPoint {
    std::string knob;   // "default", "hit_threshold", "max_steps", ..., "spp", "precision"
    std::string value;  // the knob's value ("" for the default point)
    double render_ms = 0.0;
    // Mean DE evaluations of the primary march per pixel: the work, free of timing noise.
    double steps_per_pixel = 0.0;
    ImageError error;
    bool pareto = false;  // on the time / RMSE Pareto front
};

// Marks each point no other point beats in both render time and RMSE (one of them strictly).
void mark_pareto_front(std::vector<AccuracyPoint>& points);

struct AccuracySettings {
    int width = 320;
    int height = 240;
    int reference_samples = 16;
    int repeats = 5;  // timing rounds over all settings; each setting's fastest render counts
};

// Called with (settings done, settings in all, what is being rendered).
using AccuracyProgress = std::function<void(int, int, const std::string&)>;

struct AccuracyReport {
    std::vector<AccuracyPoint> points;  // the default first
    double reference_ms = 0.0;
    std::string reference_settings;     // the reference's parameter assignments, for the record
};

AccuracyReport run_accuracy_sweep(const Scene& scene, const ComputeDevice& device,
                                  ProgramCache& cache, const AccuracySettings& settings,
                                  const AccuracyProgress& progress = {});

std::string accuracy_csv(const AccuracyReport& report);

// A gnuplot script that plots `csv` (RMSE against render time, one series per knob, the Pareto
// front as a line, the default marked) into `png`.
std::string accuracy_gnuplot(const AccuracyReport& report, const std::string& scene_id,
                             const std::string& csv, const std::string& png);

}  // namespace fgr
