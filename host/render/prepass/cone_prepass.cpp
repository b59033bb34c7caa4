// SPDX-License-Identifier: Apache-2.0
#include "render/prepass/cone_prepass.hpp"

#include <numeric>

#include "fgr/plugin.h"

namespace fgr {
namespace {

// Blocks lie on the whole image's grid (see fgr_prepass.cl): those a span of pixels touches.
int blocks_along(int first_pixel, int pixels) {
    return (first_pixel + pixels - 1) / FGR_PREPASS_BLOCK + 1 - first_pixel / FGR_PREPASS_BLOCK;
}

int blocks_across(const CameraFrame& camera) {
    return blocks_along(camera.region_x, camera.region_width);
}

int blocks_down(const CameraFrame& camera) {
    return blocks_along(camera.region_y, camera.region_height);
}

int block_count(const CameraFrame& camera) { return blocks_across(camera) * blocks_down(camera); }

}  // namespace

bool prepass_applies(const Scene& scene, const KernelSwitches& switches) {
    const bool camera_rays_from_one_point =
        (switches.effects & (FGR_EFFECT_DEPTH_OF_FIELD | FGR_EFFECT_GLOW)) == 0;
    const bool de_mode = switches.mode == RenderMode::Shaded || switches.mode == RenderMode::Path;
    return de_mode && camera_rays_from_one_point && scene.ifs == nullptr && !scene.inside_only();
}

ConePrepass::ConePrepass(const ComputeDevice& device, const cl::Program& program,
                         const Scene& scene, const KernelSwitches& switches)
    : device_(device),
      packet_width_(switches.packet_width),
      available_(prepass_applies(scene, switches)) {
    if (available_) kernel_ = cl::Kernel(program, "fgr_prepass");
}

cl::Buffer ConePrepass::starts(const FrameRequest& request, const CameraFrame& camera,
                               const cl::Buffer& params, int group) {
    const int blocks = block_count(camera);
    const size_t bytes = sizeof(float) * FGR_PREPASS_PLANES * blocks;
    cl::Buffer buffer(device_.context, CL_MEM_READ_WRITE, bytes);
    ran_ = available_ && request.prepass.enabled;
    if (!ran_) {
        device_.queue.enqueueFillBuffer(buffer, 0.0f, 0, bytes);
        return buffer;
    }
    const TileLayout layout =
        tile_layout(packet_width_, blocks_across(camera), blocks_down(camera));
    const int packets = layout.tiles_x * layout.tiles_y;
    kernel_.setArg(FGR_PREPASS_ARG_STARTS, buffer);
    kernel_.setArg(FGR_PREPASS_ARG_BLOCK_PLANE, blocks);
    kernel_.setArg(FGR_PREPASS_ARG_PACKET_COUNT, packets);
    kernel_.setArg(FGR_PREPASS_ARG_CAMERA, camera);
    kernel_.setArg(FGR_PREPASS_ARG_PARAMS, params);
    kernel_.setArg(FGR_PREPASS_ARG_CONE_SCALE, request.prepass.cone_scale);
    const size_t global = static_cast<size_t>((packets + group - 1) / group) * group;
    device_.queue.enqueueNDRangeKernel(kernel_, cl::NullRange, cl::NDRange(global),
                                       cl::NDRange(group));
    return buffer;
}

cl::Buffer ConePrepass::hints(const FrameRequest& request, const TileLayout& layout,
                              int* has_hints) const {
    const PixelRegion region = rendered_region(request);
    const bool usable = available_ && request.prepass.enabled &&
                        request.start_hints.size() == static_cast<size_t>(region.pixels());
    *has_hints = usable ? 1 : 0;
    if (!usable) {
        return cl::Buffer(device_.context, CL_MEM_READ_ONLY, sizeof(float));
    }
    std::vector<float> plane(static_cast<size_t>(layout.plane_size()), 0.0f);
    for (int y = 0; y < region.height; ++y) {
        for (int x = 0; x < region.width; ++x) {
            plane[static_cast<size_t>(layout.index(x, y))] =
                request.start_hints[static_cast<size_t>(y) * region.width + x];
        }
    }
    return cl::Buffer(device_.context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      sizeof(float) * plane.size(), plane.data());
}

long ConePrepass::evaluations(const cl::Buffer& starts, const CameraFrame& camera) const {
    if (!ran_) return 0;
    const int blocks = block_count(camera);
    std::vector<float> steps(static_cast<size_t>(blocks));
    device_.queue.enqueueReadBuffer(starts, CL_TRUE,
                                    sizeof(float) * FGR_PREPASS_EVALUATIONS_PLANE * blocks,
                                    sizeof(float) * blocks, steps.data());
    return std::accumulate(steps.begin(), steps.end(), 0L,
                           [](long sum, float value) { return sum + static_cast<long>(value); });
}

}  // namespace fgr
