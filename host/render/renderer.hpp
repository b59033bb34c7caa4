// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rendering one scene on one OpenCL device: builds (or fetches from the cache) the scene's
// program once, then renders frames whose camera and parameters change freely without a rebuild.

#include <functional>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "camera/projection.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "image/display.hpp"
#include "image/image_io.hpp"
#include "render/launch_bands.hpp"
#include "render/path_settings.hpp"
#include "scene/scene.hpp"

namespace fgr {

class ModeKernel;
class ConePrepass;
class FramePlanes;

// A rectangle of an image, in pixels from its top-left corner.
struct PixelRegion {
    int x = 0;
    int y = 0;
    int width = 0;  // 0 (with height 0): the whole image
    int height = 0;
    bool whole() const { return width == 0 && height == 0; }
    long pixels() const { return long(width) * long(height); }
};

// The cone-marched depth prepass (kernels/geometry/fgr_prepass.cl): camera rays start where a cone
// marched for their 8x8 block of pixels came near the surface instead of at the eye. On by
// default wherever it applies (prepass_applies in host/render/prepass/cone_prepass.hpp);
// `cone_scale` below 1 narrows the cones below what their blocks need, which is unsafe and only
// there for tests to show they catch it.
struct PrepassSettings {
    bool enabled = true;
    float cone_scale = 1.0f;
};

struct FrameRequest {
    int width = 640;  // of the whole image: directions, footprints and random numbers follow it
    int height = 480;
    CameraView view;
    std::vector<float> params;  // laid out as default_param_values(scene)
    // Per pixel: 1 is the pixel centre; more are jittered and averaged (what one is in each mode,
    // how many a still takes and the limits: render/sample_budget.hpp).
    int samples = 1;
    // Index of the first sample rendered: samples first_sample .. first_sample + samples - 1, so
    // a caller can accumulate one sample at a time and get the same image as one long render
    // (sample 0 is the pixel centre, later ones are jittered).
    int first_sample = 0;
    // Called after each finished launch with (samples done, samples in all), when set: a sample
    // a launch, or up to the mode's launch_samples (the path tracer's regrouped packets trace
    // several).
    std::function<void(int, int)> on_sample{};
    // Called as the frame renders, when set, with the launches done and the launches in all (0 of
    // them when the first starts): a launch a sample (or a few, see on_sample), or, in a frame of
    // few samples and many pixels, each launch split into bands of tiles, so that it reports its
    // progress too.
    std::function<void(long done, long total)> on_progress{};
    // Polled between launches and bands of tiles, when set: returning true abandons the frame
    // (Frame::cancelled), so an interactive caller never waits for a slow frame it no longer wants.
    std::function<bool()> cancel{};
    // How soon `cancel` must be obeyed (render/launch_bands.hpp): at once, in bands of every
    // launch, or, for a batch render a signal may stop, within a fraction of a second, so that
    // its launches stay whole where they are short.
    CancelResponse cancel_response = CancelResponse::Interactive;
    // Render mode "path" only: bounces, strategies and the environment.
    PathSettings path{};
    // Polled after each finished launch (see on_sample), when set: returning true ends the render
    // there with the samples done so far (Frame::samples), e.g. at a time budget.
    std::function<bool()> enough{};
    // How pixels map to rays: pinhole, panoramas, stereo pairs (camera/projection.hpp).
    Projection projection{};
    // The part of the image to render (tiled stills); the frame then holds only it, each pixel
    // exactly as an untiled render of the whole image gives it. Its sides are at most
    // kMaxImageSide; the whole image's at most kMaxTiledImageSide.
    PixelRegion region{};
    PrepassSettings prepass{};
    // Per pixel of the region, row-major: how far each camera ray may start, reprojected from an
    // earlier frame (render/prepass/reprojection.hpp; 0: no hint), taken where the prepass applies
    // and the DE at the hinted point is clear of the surface. Empty: none.
    std::vector<float> start_hints{};
    // Render mode "path": per pixel of the region, row-major, the pixel takes only the samples
    // whose index is below this (adaptive sampling; render/adaptive_sampling.hpp hands these out
    // round by round). Empty: every pixel takes every sample.
    std::vector<float> sample_limits{};
};

// The primary rays' work, from sample 0 of a render built with KernelSwitches::stats.
struct MarchStats {
    long pixels = 0;
    double mean_steps = 0.0;  // DE evaluations of the primary march per pixel
    int max_steps = 0;        // the most any pixel took
    // march steps plus the normal's four DE taps at every hit, and the cone prepass's
    long de_evaluations = 0;
    long prepass_de_evaluations = 0;  // the cone prepass's alone (0: it did not run)
    // Lane utilisation of the primary march: the steps the lanes needed (lane_steps, summed over
    // pixels) against those their packets took (packet_steps, each packet's longest lane, summed
    // over packets; every one costs packet_width lanes).
    long lane_steps = 0;
    long packet_steps = 0;
    int packet_width = 1;
    // The same for the secondary rays (shadow, reflection, refraction) of DE scenes: their lane
    // steps are secondary_de_evaluations.
    long secondary_packet_steps = 0;
    long out_of_steps = 0;  // rays that used max_steps without hitting or leaving the scene
    // Shaded mode: DE evaluations of shadow, reflection and refraction rays, summed over the
    // lanes that took part, and the part of them spent for pixels whose camera ray missed
    // (none: secondary rays start only from hits).
    long secondary_de_evaluations = 0;
    long secondary_de_evaluations_missed = 0;
    // IFS scenes: the most nodes any ray's heap held, and the rays whose heap would have
    // overflowed (kIfsHeapCapacity) and were traced depth first instead.
    int heap_peak = 0;
    long heap_overflows = 0;
    double out_of_steps_percent() const {
        return pixels ? 100.0 * double(out_of_steps) / double(pixels) : 0.0;
    }
};

// How busy the lanes of a packet are (path mode with stats): the DE evaluations lanes took part
// in, against those the packets made times their width. Coherent camera rays keep packets full;
// diffuse bounces scatter the lanes, which then wait for each other.
struct LaneStats {
    int packet_width = 1;
    double lane_evaluations = 0.0;    // per lane that needed it
    double packet_evaluations = 0.0;  // per packet (each costs packet_width lanes)
    double utilisation() const {
        return packet_evaluations > 0.0
                   ? lane_evaluations / (packet_evaluations * double(packet_width))
                   : 0.0;
    }
};

// How adaptive sampling went (render/adaptive_sampling.hpp): what it spent and the error it
// reached, by its own estimate.
struct AdaptiveReport {
    float threshold = 0.0f;
    int rounds = 0;
    int cap = 0;           // the samples fixed sampling would have taken (--spp)
    int min_samples = 0;   // what every pixel took in the first round
    float min_spp = 0.0f;  // samples per pixel: least, mean, most
    double mean_spp = 0.0;
    float max_spp = 0.0f;
    double share_converged = 0.0;  // pixels whose estimated relative error is at most threshold
    double mean_error = 0.0;       // estimated relative standard error, over pixels
    double error_p95 = 0.0;        // its 95th percentile
    double saved() const { return cap > 0 ? 1.0 - mean_spp / double(cap) : 0.0; }
};

// How deep an IFS image went (shaded mode): the levels of the nodes its pixels hit, which the
// depth slider caps and the pixel footprint stops short of where detail would be sub-pixel.
struct IfsLevels {
    int deepest = -1;   // -1: no pixel hit
    double mean = 0.0;  // over the pixels that hit
};

struct Frame {
    Image8 image;                   // sRGB, gamma-encoded; the region's size when one was asked for
    std::vector<float> linear;      // row-major linear RGB, averaged over samples, before exposure
    std::vector<float> depth;       // row-major distance along the ray; -1 where the ray missed
                                    // (written by sample 0 only: all -1 when first_sample > 0)
    long hits = 0;                  // pixels whose ray met the surface
    double render_ms = 0.0;         // kernel, read-back and encoding; no build, no file output
    bool cancelled = false;         // FrameRequest::cancel stopped it: no pixels
    bool double_precision = false;  // rendered with double lanes (KernelSwitches)
    std::optional<MarchStats> stats;  // when the renderer was built with stats
    int samples = 0;  // per pixel in this frame (fewer than asked when `enough` said so)
    // The first hit's albedo and shading normal (row-major RGB / XYZ), coverage (the fraction of
    // the samples whose camera ray met the surface) and the foreground (linear RGB of those
    // samples alone, summed and divided by all samples: the colour without the background,
    // premultiplied by coverage), for compositing and denoising (alpha and EXR layers). Albedo
    // and normal are averages over all samples too, misses counting as zero. Filled by the path
    // and brute modes always (brute: albedo, normal) and in every mode when the renderer was
    // built with KernelSwitches::aovs; empty otherwise. The brute mode samples each pixel's
    // centre only, so its coverage is 0 or 1.
    std::vector<float> albedo;
    std::vector<float> normal;
    std::vector<float> alpha;
    std::vector<float> foreground;
    // Path mode: per pixel (row-major) the samples it received, which differ between pixels under
    // adaptive sampling, and the estimated variance of the pixel's linear RGB estimate (of the
    // mean over its samples, not of one sample; 3 floats a pixel), which guides adaptive sampling
    // and the denoiser. The variance comes from the two halves of the samples (odd and even
    // indices): it is itself noisy (a few degrees of freedom a pixel), unbiased, and -1 in all
    // three channels where a pixel had fewer than two samples (no estimate). Empty where a mode
    // does not estimate them (shaded and brute).
    std::vector<float> samples_per_pixel;
    std::vector<float> variance;
    // The linear colour as rendered, when `linear` holds a denoised image of it (3 floats a
    // pixel); empty otherwise.
    std::vector<float> raw_linear;
    std::optional<LaneStats> lane_stats;     // path mode built with stats
    std::optional<AdaptiveReport> adaptive;  // path mode with PathSettings::noise_threshold > 0
    std::optional<IfsLevels> ifs_levels;     // IFS scenes in the shaded mode
    // Render mode "brute" built with stats: inside tests per pixel, all passes of this frame.
    std::optional<double> inside_tests_per_pixel;
};

// Sides of what one launch renders (an image, or a region of a tiled one); larger would not fit
// device buffers on small machines.
constexpr int kMaxImageSide = 16384;
// Sides of a tiled image, rendered a region at a time: 2^20 pixels (a terapixel), far past any
// print, and small enough that every pixel index fits 40 bits and a row's bytes a size_t.
constexpr int kMaxTiledImageSide = 1 << 20;

// The region `request` renders: its own, or the whole image.
PixelRegion rendered_region(const FrameRequest& request);

// Throws std::invalid_argument, naming the scene and what it can do, when `scene` cannot render
// in `mode`: inside-only scenes render only in the brute mode, which IFS scenes cannot.
void check_mode_supported(const Scene& scene, RenderMode mode);

// Renderer::probe_de_pairs: each point's DE as the first of a pair and as the second.
struct PairedDistances {
    std::vector<float> first, second;
};

class Renderer {
public:
    // Throws KernelBuildError when the scene's source does not compile, std::invalid_argument
    // when the scene cannot render in the switches' mode (check_mode_supported).
    Renderer(const ComputeDevice& device, ProgramCache& cache, const Scene& scene,
             const KernelSwitches& switches);
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) = delete;  // holds references to its device and scene

    Frame render(const FrameRequest& request);

    // The scene's DE at each point, evaluated by the kernel (same packets, same maths).
    std::vector<float> probe_de(std::span<const glm::vec3> points,
                                const std::vector<float>& params);
    // The same at double points (a deep zoom's camera): a double kernel sees them to about 2^-48
    // of their size (sent as a float and the float of the rest), a float kernel as floats.
    std::vector<float> probe_de(std::span<const glm::dvec3> points,
                                const std::vector<float>& params);

    // The shading normal at each point, with finite-difference stencil size eps.
    std::vector<glm::vec3> probe_normals(std::span<const glm::vec3> points,
                                         const std::vector<float>& params, float eps);
    // The scene's DE at each point through scene_de_pair (kernels/geometry/fgr_geometry.cl), the
    // point's packet paired with another's: as the first point of a pair, and as the second.
    PairedDistances probe_de_pairs(std::span<const glm::vec3> points,
                                   const std::vector<float>& params);

    const BuildReport& build_report() const { return build_report_; }
    const Scene& scene() const { return scene_; }
    const KernelSwitches& switches() const { return switches_; }

private:
    // One tiny launch of each kernel, so the driver's just-in-time work is done before the first
    // timed frame (counted in build_report().build_ms).
    void warm_up();
    cl::Buffer upload(const std::vector<float>& values);
    // Launches `kernel` (the render kernel or the mode's resolve kernel) over `items` work-items
    // (a tile each, or a pair of tiles for a render kernel that pairs them), in `bands` launches,
    // calling `band_done` (if set) after each; false when `cancel` (if set), polled before each,
    // asked to stop.
    bool launch_tiles(cl::Kernel& kernel, int items, int group, const std::function<bool()>& cancel,
                      int bands = 1, const std::function<void()>& band_done = {});
    // Points as the probes take them (FGR_PROBE_POINT_PLANES: x, y, z as the nearest floats,
    // then x, y, z of what the floats miss of the double points), padded to whole packets, and
    // the packet count.
    cl::Buffer upload_points(std::span<const glm::dvec3> points, int* packets, int* plane);
    // Runs a probe kernel (its arguments FGR_PROBE_ARG_*, the kernel's own set by
    // `set_extra_args`) over `points`; returns its `outputs` planes of *plane floats each.
    std::vector<float> run_probe(cl::Kernel& kernel, std::span<const glm::dvec3> points,
                                 const std::vector<float>& params, int outputs,
                                 const std::function<void(cl::Kernel&)>& set_extra_args,
                                 int* plane);

    const ComputeDevice& device_;
    const Scene& scene_;
    KernelSwitches switches_;
    BuildReport build_report_;
    cl::Program program_;
    cl::Kernel render_kernel_;
    cl::Kernel probe_kernel_;
    cl::Kernel normal_kernel_;
    cl::Kernel pair_probe_kernel_;
    int tiles_per_item_ = 1;  // the render kernel's tiles a work-item: 2 where it pairs them
    std::unique_ptr<ModeKernel> mode_;      // the render mode's own arguments and planes
    std::unique_ptr<ConePrepass> prepass_;  // where camera rays start
    std::unique_ptr<FramePlanes> planes_;   // what the kernels write, kept between frames
};

// Linear RGB planes (tile-major, as the kernel stores them) to an sRGB image in rows.
struct TileLayout {
    int packet_width;
    int tile_w;
    int tile_h;
    int tiles_x;
    int tiles_y;
    int plane_size() const { return tiles_x * tiles_y * packet_width; }
    // Index in a plane of pixel (x, y): row_offset(y) + column_offset(x), split so that a loop
    // over a region's pixels divides once a row and once a column, not twice a pixel.
    int index(int x, int y) const { return row_offset(y) + column_offset(x); }
    int row_offset(int y) const {
        return (y / tile_h) * tiles_x * packet_width + (y % tile_h) * tile_w;
    }
    int column_offset(int x) const { return (x / tile_w) * packet_width + x % tile_w; }
    // column_offset(x) for x = 0 .. width - 1.
    std::vector<int> column_offsets(int width) const;
};
TileLayout tile_layout(int packet_width, int width, int height);

// The frame's linear colour times `exposure`, clamped to [0, 1], at 16 bits: scene-referred output
// for compositing or grading elsewhere (no tone mapping, no sRGB curve).
Image16 linear_image16(const Frame& frame, float exposure);

// The scene's display transform (image/display.hpp): its `exposure` and `tone_map` parameters.
DisplayTransform display_transform(const Scene& scene, const std::vector<float>& params);

// Linear RGB rows (times `scale`, e.g. 1 / samples for a sum) to what a screen shows through the
// scene's display transform.
Image8 display_image(const Scene& scene, const std::vector<float>& params,
                     const std::vector<float>& linear, int width, int height, float scale = 1.0f);

}  // namespace fgr
