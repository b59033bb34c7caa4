// SPDX-License-Identifier: Apache-2.0
#include "render/renderer.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <glm/geometric.hpp>
#include <mutex>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <system_error>

#include "camera/camera.hpp"
#include "camera/projection.hpp"
#include "camera/view_validation.hpp"
#include "device/kernel_layout.hpp"
#include "device/math_check.hpp"
#include "render/adaptive_sampling.hpp"
#include "render/camera_frame.hpp"
#include "render/frame_planes.hpp"
#include "render/modes/mode_kernel.hpp"
#include "render/prepass/cone_prepass.hpp"
#include "render/render_cost.hpp"
#include "render/sample_budget.hpp"
#include "scene/parameters.hpp"
#include "util/parallel_bands.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

void check_size(const FrameRequest& request) {
    if (request.region.whole()) {
        if (request.width < 1 || request.height < 1 || request.width > kMaxImageSide ||
            request.height > kMaxImageSide) {
            throw std::invalid_argument("image size must be between 1x1 and 16384x16384");
        }
        return;
    }
    if (request.width < 1 || request.height < 1 || request.width > kMaxTiledImageSide ||
        request.height > kMaxTiledImageSide) {
        throw std::invalid_argument(
            fmt::format("tiled image size must be between 1x1 and {0}x{0}", kMaxTiledImageSide));
    }
    const PixelRegion& r = request.region;
    if (r.width < 1 || r.height < 1 || r.width > kMaxImageSide || r.height > kMaxImageSide ||
        r.x < 0 || r.y < 0 || r.x > request.width - r.width || r.y > request.height - r.height) {
        throw std::invalid_argument(fmt::format(
            "region {}x{} at ({}, {}) is not inside the {}x{} image (or a side exceeds 16384)",
            r.width, r.height, r.x, r.y, request.width, request.height));
    }
}

void check_request(const Scene& scene, const FrameRequest& request) {
    check_size(request);
    check_samples(request.samples);
    if (request.first_sample < 0 || request.first_sample > kMaxSamples) {
        throw std::invalid_argument(
            fmt::format("first sample must be between 0 and {}", kMaxSamples));
    }
    if (request.params.size() != default_param_values(scene).size()) {
        throw std::invalid_argument("parameter buffer does not match the scene's parameters");
    }
    // A basis with NaN or Inf in it would give every ray NaN: an image of nothing, not of the view.
    if (const std::string problem = computed_view_problem(request.view); !problem.empty()) {
        throw std::invalid_argument("cannot render this view: " + problem);
    }
    check_projection(request.projection);
    if (!request.sample_limits.empty() &&
        request.sample_limits.size() != static_cast<size_t>(rendered_region(request).pixels())) {
        throw std::invalid_argument("sample limits do not match the rendered region's pixels");
    }
}

// A frame of `region`'s size: depth, linear colour and display image, zeroed.
Frame sized_frame(const PixelRegion& region) {
    Frame frame;
    const size_t pixels = static_cast<size_t>(region.pixels());
    frame.depth.resize(pixels);
    frame.linear.resize(pixels * 3);
    frame.image = Image8{region.width, region.height, std::vector<uint8_t>(pixels * 3)};
    return frame;
}

// sized_frame(region) on a thread of its own, or here when no thread is to be had.
std::future<Frame> claim_frame(const PixelRegion& region) {
    try {
        return std::async(std::launch::async, sized_frame, region);
    } catch (const std::system_error&) {
        return std::async(std::launch::deferred, sized_frame, region);
    }
}

// The colour planes (times `average`) and depth of each pixel of `region` into `frame` (sized by
// sized_frame), in rows, and the hits.
void unpack_common_planes(std::span<const float> planes, const TileLayout& layout,
                          const PixelRegion& region, float average, Frame& frame) {
    const size_t plane = static_cast<size_t>(layout.plane_size());
    const std::vector<int> columns = layout.column_offsets(region.width);
    const size_t width = static_cast<size_t>(region.width);
    std::atomic<long> hits = 0;
    in_parallel_rows(
        static_cast<size_t>(region.height), width, [&](size_t first_row, size_t last_row) {
            long band_hits = 0;
            for (size_t y = first_row; y < last_row; ++y) {
                const size_t row = static_cast<size_t>(layout.row_offset(static_cast<int>(y)));
                for (size_t x = 0; x < width; ++x) {
                    const size_t source = row + static_cast<size_t>(columns[x]);
                    const size_t pixel = y * width + x;
                    for (size_t c = 0; c < 3; ++c) {
                        frame.linear[pixel * 3 + c] =
                            planes[(FGR_COLOUR_PLANE + c) * plane + source] * average;
                    }
                    frame.depth[pixel] = planes[FGR_DEPTH_PLANE * plane + source];
                    band_hits += frame.depth[pixel] >= 0.0f;
                }
            }
            hits += band_hits;
        });
    frame.hits = hits;
}

// Work-items per work-group. Fixed rather than left to the driver so that the warm-up launch in
// the constructor compiles exactly the work-group function later frames use (PoCL specialises
// its code per local size), keeping JIT time out of render_ms.
int work_group_size(const ComputeDevice& device) { return device.info.is_cpu ? 8 : 64; }

// The bands each launch of `per_launch` samples is split into (render/launch_bands.hpp), its
// work weighed by the frame's estimated cost (render/render_cost.hpp), so that a costly launch of
// few pixels (an IFS scene whose rays open many nodes) is split too. The viewer's frames, whose
// bands do not follow the work, skip the estimate (an IFS scene's searches a depth).
int frame_bands(const FrameRequest& request, const PixelRegion& region, const Scene& scene,
                RenderMode mode, int per_launch) {
    const BandNeeds needs{static_cast<bool>(request.on_progress), static_cast<bool>(request.cancel),
                          request.cancel_response};
    if (!bands_follow_work(needs)) return launch_bands(0.0, needs);  // no estimate needed
    const double weight = std::max(
        1.0, estimate_render_cost(scene, request, mode).steps_per_sample / kPlainSampleSteps);
    const double pixel_samples =
        double(region.width) * region.height * std::min(per_launch, request.samples);
    return launch_bands(pixel_samples * weight, needs);
}

cl::NDRange global_range(int items, int group) {
    return cl::NDRange(static_cast<size_t>((items + group - 1) / group) * group);
}

// Logs each distinct warning once per process: every renderer on a device meets the same
// self-test verdict.
void warn_once(const std::string& message) {
    static std::mutex mutex;
    static std::set<std::string> said;
    std::lock_guard lock(mutex);
    if (said.insert(message).second) spdlog::warn("{}", message);
}

// The probes evaluate the DE: an inside-only scene has none (std::logic_error, saying `to_do`).
void require_distance_estimator(const Scene& scene, const char* to_do) {
    if (scene.inside_only()) {
        throw std::logic_error(
            fmt::format("scene '{}' has no distance estimator to {} (it defines only scene_inside)",
                        scene.id, to_do));
    }
}

Frame cancelled_frame() {
    Frame cancelled;
    cancelled.cancelled = true;
    return cancelled;
}

}  // namespace

void check_mode_supported(const Scene& scene, RenderMode mode) {
    if (mode == RenderMode::Brute && scene.ifs) {
        throw std::invalid_argument(fmt::format(
            "the IFS scene '{}' cannot render in the brute mode: it is ray traced exactly and has "
            "neither an inside test nor a distance estimator (use --mode shaded or path)",
            scene.id));
    }
    if (mode != RenderMode::Brute && scene.inside_only()) {
        throw std::invalid_argument(fmt::format(
            "scene '{}' has no distance estimator (its source defines only scene_inside): it "
            "renders only with --mode brute, not {}",
            scene.id, render_mode_name(mode)));
    }
}

Image16 linear_image16(const Frame& frame, float exposure) {
    Image16 image{frame.image.width, frame.image.height, {}};
    image.rgb.reserve(frame.linear.size());
    for (float value : frame.linear) {
        const float scaled = value * exposure;
        const float clamped = scaled > 0.0f ? std::min(scaled, 1.0f) : 0.0f;  // NaN to 0
        image.rgb.push_back(static_cast<uint16_t>(std::lround(clamped * 65535.0f)));
    }
    return image;
}

DisplayTransform display_transform(const Scene& scene, const std::vector<float>& params) {
    return {param_value(scene, params, "exposure"),
            static_cast<ToneMap>(param_value(scene, params, "tone_map"))};
}

Image8 display_image(const Scene& scene, const std::vector<float>& params,
                     const std::vector<float>& linear, int width, int height, float scale) {
    DisplayTransform display = display_transform(scene, params);
    display.exposure *= scale;
    return display_image(linear, display, width, height);
}

std::vector<int> TileLayout::column_offsets(int width) const {
    std::vector<int> offsets(static_cast<size_t>(std::max(width, 0)));
    for (int x = 0; x < width; ++x) offsets[static_cast<size_t>(x)] = column_offset(x);
    return offsets;
}

PixelRegion rendered_region(const FrameRequest& request) {
    if (!request.region.whole()) return request.region;
    return {0, 0, request.width, request.height};
}

TileLayout tile_layout(int packet_width, int width, int height) {
    const int tile_w = FGR_TILE_WIDTH(packet_width);
    const int tile_h = FGR_TILE_HEIGHT(packet_width);
    return {packet_width, tile_w, tile_h, (width + tile_w - 1) / tile_w,
            (height + tile_h - 1) / tile_h};
}

Renderer::Renderer(const ComputeDevice& device, ProgramCache& cache, const Scene& scene,
                   const KernelSwitches& switches)
    : device_(device), scene_(scene), switches_(switches) {
    check_mode_supported(scene, switches.mode);
    switches_.packet_width = trusted_packet_width(device, cache, switches.double_precision,
                                                  switches.packet_width, warn_once);
    program_ = cache.build(device, assemble_program(scene, switches_), &build_report_);
    tiles_per_item_ = pairs_tiles(scene, switches_) ? 2 : 1;
    render_kernel_ = cl::Kernel(program_, "fgr_render");
    probe_kernel_ = cl::Kernel(program_, "fgr_probe_de");
    normal_kernel_ = cl::Kernel(program_, "fgr_probe_normal");
    pair_probe_kernel_ = cl::Kernel(program_, "fgr_probe_de_pair");
    mode_ = make_mode_kernel(switches_, device, program_, scene);
    prepass_ = std::make_unique<ConePrepass>(device, program_, scene, switches_);
    planes_ = std::make_unique<FramePlanes>(device, FramePlanes::preferred_view(device.info));
    warm_up();
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;

void Renderer::warm_up() {
    FrameRequest tiny;
    tiny.width = 1;
    tiny.height = 1;
    tiny.view = scene_.cameras.front().view;
    tiny.params = default_param_values(scene_);
    // A specialised kernel renders only the values compiled into it.
    set_specialised_values(scene_, switches_.specialised, tiny.params);
    const auto start = std::chrono::steady_clock::now();
    render(tiny);
    if (!scene_.inside_only()) {  // an inside-only scene has no DE to probe
        const glm::vec3 origin(0.0f);
        probe_de(std::span(&origin, 1), tiny.params);
        probe_normals(std::span(&origin, 1), tiny.params, 1e-3f);
    }
    build_report_.build_ms += elapsed_ms(start);
}

cl::Buffer Renderer::upload(const std::vector<float>& values) {
    return cl::Buffer(device_.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      values.size() * sizeof(float), const_cast<float*>(values.data()));
}

bool Renderer::launch_tiles(cl::Kernel& kernel, int items, int group,
                            const std::function<bool()>& cancel, int bands,
                            const std::function<void()>& band_done) {
    if (bands <= 1) {
        if (cancel && cancel()) return false;
        device_.queue.enqueueNDRangeKernel(kernel, cl::NullRange, global_range(items, group),
                                           cl::NDRange(group));
        // A cancel is polled before the next launch: this one must end first.
        if (band_done || cancel) device_.queue.finish();
        if (band_done) band_done();
        return true;
    }
    // Bands of whole work-groups, offset through the global work offset (get_global_id includes
    // it), so cancelling costs at most one band.
    const int band = band_tiles(items, group, bands);
    for (int first = 0; first < items; first += band) {
        if (cancel && cancel()) return false;
        device_.queue.enqueueNDRangeKernel(kernel, cl::NDRange(first),
                                           global_range(std::min(band, items - first), group),
                                           cl::NDRange(group));
        device_.queue.finish();
        if (band_done) band_done();
    }
    return !(cancel && cancel());
}

Frame Renderer::render(const FrameRequest& request) {
    check_request(scene_, request);
    // A specialised kernel reads some parameters as the constants it was built with.
    if (const std::string mismatch =
            specialisation_mismatch(scene_, switches_.specialised, request.params);
        !mismatch.empty()) {
        throw std::invalid_argument(
            fmt::format("cannot render '{}' with this kernel: {}", scene_.id, mismatch));
    }
    if (switches_.mode == RenderMode::Path && request.path.noise_threshold > 0.0f) {
        return render_adaptive(*this, request);  // rounds of plain renders
    }
    const PixelRegion region = rendered_region(request);
    const TileLayout layout = tile_layout(switches_.packet_width, region.width, region.height);
    const int plane = layout.plane_size();
    const auto start = std::chrono::steady_clock::now();

    cl::Buffer params = upload(request.params);
    const int plane_count = FGR_COMMON_PLANES + mode_->extra_planes(switches_);
    const size_t plane_floats = static_cast<size_t>(plane) * static_cast<size_t>(plane_count);
    const cl::Buffer& planes = planes_->reserve(plane_floats);
    const int tiles = layout.tiles_x * layout.tiles_y;
    const CameraFrame camera =
        camera_frame(request.view, request.projection, request.width, request.height, region);
    const int group = work_group_size(device_);
    const cl::Buffer starts = prepass_->starts(request, camera, params, group);
    int has_hints = 0;
    const cl::Buffer hints = prepass_->hints(request, layout, &has_hints);
    cl::Kernel* resolve = mode_->resolve_kernel();
    for (cl::Kernel* kernel : {&render_kernel_, resolve}) {
        if (kernel == nullptr) continue;
        kernel->setArg(FGR_RENDER_ARG_PLANES, planes);
        kernel->setArg(FGR_RENDER_ARG_PLANE_SIZE, plane);
        kernel->setArg(FGR_RENDER_ARG_TILE_COUNT, tiles);
        kernel->setArg(FGR_RENDER_ARG_CAMERA, camera);
        kernel->setArg(FGR_RENDER_ARG_PARAMS, params);
        kernel->setArg(FGR_RENDER_ARG_MARCH_STARTS, starts);
        kernel->setArg(FGR_RENDER_ARG_MARCH_HINTS, hints);
        kernel->setArg(FGR_RENDER_ARG_HAS_HINTS, has_hints);
    }
    mode_->bind(render_kernel_, request, layout);
    // Samples accumulate in the planes, one or more a launch (the mode's launch_samples), in
    // order (in-order queue). The launch of sample 0 overwrites them; a request starting later
    // starts from zeroed planes instead.
    if (request.first_sample > 0) {
        const auto bytes = [plane](int count) { return sizeof(float) * count * plane; };
        device_.queue.enqueueFillBuffer(planes, 0.0f, bytes(FGR_COLOUR_PLANE),
                                        bytes(FGR_COLOUR_PLANES));
        device_.queue.enqueueFillBuffer(planes, -1.0f, bytes(FGR_DEPTH_PLANE), bytes(1));
        if (plane_count > FGR_COMMON_PLANES) {
            device_.queue.enqueueFillBuffer(planes, 0.0f, bytes(FGR_COMMON_PLANES),
                                            bytes(plane_count - FGR_COMMON_PLANES));
        }
    }
    mode_->write_inputs(device_.queue, planes, layout, request);
    // The frame's host memory is claimed on a thread of its own while the device renders: zeroing
    // fresh pages (a page fault each on first touch) took 2.4 ms of a 640x480 shaded frame after
    // the render, and a launch that reports progress waits for the device before it returns.
    std::future<Frame> claiming = claim_frame(region);
    int done = 0;
    // A mode may trace several samples a launch (the path tracer's regrouped packets).
    const int per_launch = std::max(1, mode_->launch_samples(request));
    const int sample_launches = (request.samples + per_launch - 1) / per_launch;
    const int bands = frame_bands(request, region, scene_, switches_.mode, per_launch);
    const int items = (tiles + tiles_per_item_ - 1) / tiles_per_item_;  // the render kernel's
    // The launches in all, as launch_tiles makes them.
    const int band = band_tiles(items, group, bands);
    const long launches = static_cast<long>(sample_launches) * ((items + band - 1) / band);
    long launched = 0;
    std::function<void()> band_done;
    if (request.on_progress) {
        request.on_progress(0, launches);
        band_done = [&] { request.on_progress(++launched, launches); };
    }
    while (done < request.samples) {
        const int count = std::min(per_launch, request.samples - done);
        mode_->bind_launch(render_kernel_, count);
        render_kernel_.setArg(FGR_RENDER_ARG_SAMPLE, request.first_sample + done);
        if (!launch_tiles(render_kernel_, items, group, request.cancel, bands, band_done)) {
            return cancelled_frame();
        }
        done += count;
        if (request.on_sample || request.enough) {
            device_.queue.finish();  // report each launch's samples as they complete
            if (request.on_sample) request.on_sample(done, request.samples);
            if (request.enough && done < request.samples && request.enough()) break;
        }
    }
    if (resolve != nullptr) {
        resolve->setArg(FGR_RENDER_ARG_SAMPLE, request.first_sample + done);
        if (!launch_tiles(*resolve, tiles, group, request.cancel)) return cancelled_frame();
    }
    device_.queue.flush();
    Frame frame = claiming.get();
    const std::span<const float> host = planes_->read(plane_floats);
    frame.double_precision = switches_.double_precision;
    frame.samples = done;
    unpack_common_planes(host, layout, region,
                         mode_->sums_samples() ? 1.0f / static_cast<float>(done) : 1.0f, frame);
    mode_->read_back(host, layout, request, done, frame);
    fill_display_image(frame.linear, display_transform(scene_, request.params), frame.image);
    if (frame.stats) {
        frame.stats->prepass_de_evaluations = prepass_->evaluations(starts, camera);
        frame.stats->de_evaluations += frame.stats->prepass_de_evaluations;
    }
    frame.render_ms = elapsed_ms(start);
    return frame;
}

cl::Buffer Renderer::upload_points(std::span<const glm::dvec3> points, int* packets, int* plane) {
    const int width = switches_.packet_width;
    *packets = static_cast<int>((points.size() + width - 1) / width);
    *plane = *packets * width;
    std::vector<float> coordinates(static_cast<size_t>(*plane) * FGR_PROBE_POINT_PLANES, 0.0f);
    for (size_t i = 0; i < points.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            const auto hi = static_cast<float>(points[i][c]);
            coordinates[(FGR_PROBE_POINT_PLANE + c) * *plane + i] = hi;
            coordinates[(FGR_PROBE_POINT_REST_PLANE + c) * *plane + i] =
                static_cast<float>(points[i][c] - double(hi));
        }
    }
    return upload(coordinates);
}

std::vector<float> Renderer::run_probe(cl::Kernel& kernel, std::span<const glm::dvec3> points,
                                       const std::vector<float>& params, int outputs,
                                       const std::function<void(cl::Kernel&)>& set_extra_args,
                                       int* plane) {
    int packets = 0;
    cl::Buffer input = upload_points(points, &packets, plane);
    cl::Buffer params_buffer = upload(params);
    const size_t output_floats = static_cast<size_t>(*plane) * outputs;
    cl::Buffer output(device_.context, CL_MEM_WRITE_ONLY, sizeof(float) * output_floats);
    kernel.setArg(FGR_PROBE_ARG_POINTS, input);
    kernel.setArg(FGR_PROBE_ARG_PLANE_SIZE, *plane);
    kernel.setArg(FGR_PROBE_ARG_PACKET_COUNT, packets);
    kernel.setArg(FGR_PROBE_ARG_OUT, output);
    kernel.setArg(FGR_PROBE_ARG_PARAMS, params_buffer);
    set_extra_args(kernel);  // the kernel's own arguments, after those
    const int group = work_group_size(device_);
    device_.queue.enqueueNDRangeKernel(kernel, cl::NullRange, global_range(packets, group),
                                       cl::NDRange(group));
    std::vector<float> planes(output_floats);
    device_.queue.enqueueReadBuffer(output, CL_TRUE, 0, sizeof(float) * planes.size(),
                                    planes.data());
    return planes;
}

std::vector<float> Renderer::probe_de(std::span<const glm::vec3> points,
                                      const std::vector<float>& params) {
    const std::vector<glm::dvec3> wide(points.begin(), points.end());
    return probe_de(std::span<const glm::dvec3>(wide), params);
}

std::vector<float> Renderer::probe_de(std::span<const glm::dvec3> points,
                                      const std::vector<float>& params) {
    require_distance_estimator(scene_, "probe");
    if (points.empty()) return {};
    int plane = 0;
    std::vector<float> distances = run_probe(
        probe_kernel_, points, params, FGR_PROBE_DE_PLANES, [](cl::Kernel&) {}, &plane);
    distances.resize(points.size());
    return distances;
}

std::vector<glm::vec3> Renderer::probe_normals(std::span<const glm::vec3> points,
                                               const std::vector<float>& params, float eps) {
    require_distance_estimator(scene_, "take normals from");
    if (points.empty()) return {};
    int plane = 0;
    const std::vector<glm::dvec3> wide(points.begin(), points.end());
    const std::vector<float> planes = run_probe(
        normal_kernel_, wide, params, FGR_PROBE_NORMAL_PLANES,
        [eps](cl::Kernel& kernel) { kernel.setArg(FGR_PROBE_ARG_EPS, eps); }, &plane);
    std::vector<glm::vec3> normals(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        normals[i] = {planes[i], planes[plane + i], planes[2 * static_cast<size_t>(plane) + i]};
    }
    return normals;
}

PairedDistances Renderer::probe_de_pairs(std::span<const glm::vec3> points,
                                         const std::vector<float>& params) {
    require_distance_estimator(scene_, "probe");
    if (points.empty()) return {};
    int plane = 0;
    const std::vector<glm::dvec3> wide(points.begin(), points.end());
    const std::vector<float> planes = run_probe(
        pair_probe_kernel_, wide, params, FGR_PROBE_DE_PAIR_PLANES, [](cl::Kernel&) {}, &plane);
    PairedDistances distances;
    distances.first.assign(planes.begin(), planes.begin() + static_cast<long>(points.size()));
    distances.second.assign(planes.begin() + plane,
                            planes.begin() + plane + static_cast<long>(points.size()));
    return distances;
}

}  // namespace fgr
