// SPDX-License-Identifier: Apache-2.0
// Render mode "shaded" (kernels/modes/fgr_mode_shaded.cl): its arguments are the scene's lights;
// with stats it writes each pixel's march steps (nodes visited in IFS scenes), whether they ran
// out, its secondary rays' DE evaluations and either its IFS heap's high-water mark or its packet's
// secondary DE evaluations, IFS scenes then the level each pixel's hit reached, and with aovs
// then the layers (albedo, normal, coverage, foreground). Each plane's index is
// FGR_SHADED_*_PLANE in kernels/shared/fgr_layout_planes.h.
#include "render/modes/shaded_mode.hpp"

#include <algorithm>

namespace fgr {
namespace {

// Sums the stats planes (steps, ran out of steps, secondary rays' DE evaluations per lane, IFS
// scenes' heap peak or DE scenes' secondary DE evaluations per packet) over the image's pixels;
// depth says which pixels hit and so had their normal estimated.
MarchStats march_stats(std::span<const float> planes, const TileLayout& layout, int width,
                       int height, bool ifs) {
    const size_t plane = static_cast<size_t>(layout.plane_size());
    MarchStats stats;
    long steps = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(layout.index(x, y));
            const int pixel_steps = static_cast<int>(planes[FGR_SHADED_STEPS_PLANE * plane + i]);
            steps += pixel_steps;
            stats.max_steps = std::max(stats.max_steps, pixel_steps);
            const bool hit = planes[FGR_DEPTH_PLANE * plane + i] >= 0.0f;
            stats.de_evaluations += pixel_steps + (hit ? 4 : 0);
            stats.out_of_steps += planes[FGR_SHADED_OUT_OF_STEPS_PLANE * plane + i] > 0.5f;
            const long secondary =
                static_cast<long>(planes[FGR_SHADED_SECONDARY_STEPS_PLANE * plane + i]);
            stats.secondary_de_evaluations += secondary;
            if (!hit) stats.secondary_de_evaluations_missed += secondary;
            if (ifs) {
                // The most nodes the ray's heap held; -1: it overflowed.
                const int heap = static_cast<int>(planes[FGR_SHADED_HEAP_PEAK_PLANE * plane + i]);
                stats.heap_peak = std::max(stats.heap_peak, heap);
                stats.heap_overflows += heap < 0;
            }
            ++stats.pixels;
        }
    }
    stats.mean_steps = stats.pixels ? double(steps) / double(stats.pixels) : 0.0;
    // A packet's march costs its longest lane's steps in every lane (padding lanes, past the
    // image's edge, take none).
    for (int tile = 0; tile < layout.tiles_x * layout.tiles_y; ++tile) {
        float longest = 0.0f;
        for (int lane = 0; lane < layout.packet_width; ++lane) {
            longest = std::max(
                longest,
                planes[FGR_SHADED_STEPS_PLANE * plane + tile * layout.packet_width + lane]);
        }
        stats.packet_steps += static_cast<long>(longest);
        // DE scenes: the packet's secondary DE evaluations, the same in every lane.
        if (!ifs) {
            stats.secondary_packet_steps +=
                static_cast<long>(planes[FGR_SHADED_SECONDARY_PACKET_STEPS_PLANE * plane +
                                         tile * layout.packet_width]);
        }
    }
    stats.lane_steps = steps;
    stats.packet_width = layout.packet_width;
    return stats;
}

// The deepest and mean level of the IFS nodes the pixels hit (plane `index`, the level plane; -1
// where missed).
IfsLevels hit_levels(std::span<const float> planes, const TileLayout& layout, int index, int width,
                     int height) {
    const size_t offset = static_cast<size_t>(index) * static_cast<size_t>(layout.plane_size());
    IfsLevels levels;
    long sum = 0, hits = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const int level =
                static_cast<int>(planes[offset + static_cast<size_t>(layout.index(x, y))]);
            if (level < 0) continue;
            levels.deepest = std::max(levels.deepest, level);
            sum += level;
            ++hits;
        }
    }
    levels.mean = hits ? double(sum) / double(hits) : 0.0;
    return levels;
}

}  // namespace

ShadedMode::ShadedMode(const ComputeDevice& device, const Scene& scene,
                       const KernelSwitches& switches)
    : lights_(upload_floats(device, scene_light_values(scene))),
      light_count_(static_cast<cl_int>(scene.lights.size())),
      ifs_(scene.ifs != nullptr),
      stats_(switches.stats),
      aovs_(switches.aovs) {}

int ShadedMode::extra_planes(const KernelSwitches& switches) const {
    // With stats: the work behind each pixel; IFS scenes: their level; with aovs: the layers.
    return FGR_SHADED_AOV_PLANE(switches.stats, ifs_) - FGR_COMMON_PLANES +
           (switches.aovs ? FGR_SHADED_AOV_PLANES : 0);
}

void ShadedMode::bind(cl::Kernel& kernel, const FrameRequest&, const TileLayout&) {
    kernel.setArg(FGR_SHADED_ARG_LIGHTS, lights_);
    kernel.setArg(FGR_SHADED_ARG_LIGHT_COUNT, light_count_);
}

void ShadedMode::read_back(std::span<const float> planes, const TileLayout& layout,
                           const FrameRequest& request, int samples, Frame& frame) const {
    const int width = frame.image.width, height = frame.image.height;  // the region's
    if (aovs_) {
        const int first = FGR_SHADED_AOV_PLANE(stats_, ifs_);
        const float average = 1.0f / static_cast<float>(std::max(samples, 1));
        const auto layer = [&](int offset, int count) {
            return planes_in_rows(planes, layout, first + offset, count, width, height, average);
        };
        frame.albedo = layer(FGR_SHADED_AOV_ALBEDO, 3);
        frame.normal = layer(FGR_SHADED_AOV_NORMAL, 3);
        frame.alpha = layer(FGR_SHADED_AOV_COVERAGE, 1);
        frame.foreground = layer(FGR_SHADED_AOV_FOREGROUND, 3);
    }
    // Stats and levels come from sample 0 (a request starting later has none).
    if (request.first_sample > 0) return;
    if (stats_) frame.stats = march_stats(planes, layout, width, height, ifs_);
    if (ifs_) {
        frame.ifs_levels =
            hit_levels(planes, layout, FGR_SHADED_LEVEL_PLANE(stats_), width, height);
    }
}

}  // namespace fgr
