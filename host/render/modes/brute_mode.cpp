// SPDX-License-Identifier: Apache-2.0
#include "render/modes/brute_mode.hpp"

namespace fgr {

BruteMode::BruteMode(const ComputeDevice& device, const cl::Program& program, const Scene& scene,
                     const KernelSwitches& switches)
    : device_(device),
      shade_kernel_(program, "fgr_brute_shade"),
      lights_(upload_floats(device, scene_light_values(scene))),
      light_count_(static_cast<cl_int>(scene.lights.size())),
      stats_(switches.stats),
      aovs_(switches.aovs) {}

int BruteMode::extra_planes(const KernelSwitches& switches) const {
    return FGR_BRUTE_SURFACE_PLANES + (switches.stats ? FGR_BRUTE_STATS_PLANES : 0);
}

void BruteMode::bind(cl::Kernel& kernel, const FrameRequest& request, const TileLayout& layout) {
    const int floats = layout.plane_size();
    const PixelRegion region = rendered_region(request);
    const bool same_image =
        floats == state_floats_ && region.width == state_width_ && region.height == state_height_;
    if (!same_image) {
        state_ = cl::Buffer(device_.context, CL_MEM_READ_WRITE, sizeof(float) * floats);
        state_floats_ = floats;
        state_width_ = region.width;
        state_height_ = region.height;
        // A continued render (first sample > 0) of a new size has nothing to continue from.
        device_.queue.enqueueFillBuffer(state_, -1.0f, 0, sizeof(float) * floats);
    }
    kernel.setArg(FGR_BRUTE_ARG_STATE, state_);
    shade_kernel_.setArg(FGR_BRUTE_SHADE_ARG_STATE, state_);
    shade_kernel_.setArg(FGR_BRUTE_SHADE_ARG_LIGHTS, lights_);
    shade_kernel_.setArg(FGR_BRUTE_SHADE_ARG_LIGHT_COUNT, light_count_);
}

void BruteMode::read_back(std::span<const float> planes, const TileLayout& layout,
                          const FrameRequest&, int, Frame& frame) const {
    const int width = frame.image.width, height = frame.image.height;  // the region's
    frame.albedo = planes_in_rows(planes, layout, FGR_BRUTE_ALBEDO_PLANE, 3, width, height);
    frame.normal = planes_in_rows(planes, layout, FGR_BRUTE_NORMAL_PLANE, 3, width, height);
    if (aovs_) {
        // Every pass samples the pixel's centre: it is covered or not, and its colour is the
        // surface's where covered.
        const size_t pixels = frame.depth.size();
        frame.alpha.resize(pixels);
        frame.foreground.resize(pixels * 3);
        for (size_t i = 0; i < pixels; ++i) {
            const bool covered = frame.depth[i] >= 0.0f;
            frame.alpha[i] = covered ? 1.0f : 0.0f;
            for (size_t c = 0; c < 3; ++c) {
                frame.foreground[i * 3 + c] = covered ? frame.linear[i * 3 + c] : 0.0f;
            }
        }
    }
    const size_t plane = static_cast<size_t>(layout.plane_size());
    const size_t stats_plane = FGR_BRUTE_STATS_PLANE;
    if (!stats_) return;
    double tests = 0.0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            tests += planes[stats_plane * plane + static_cast<size_t>(layout.index(x, y))];
        }
    }
    frame.inside_tests_per_pixel = tests / (double(width) * double(height));
}

}  // namespace fgr
