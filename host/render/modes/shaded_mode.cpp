// Render mode "shaded" (kernels/fgr_mode_shaded.cl): its arguments are the scene's lights; with
// stats it writes each pixel's march steps (nodes visited in IFS scenes), whether they ran out,
// its secondary rays' DE evaluations and its IFS heap's high-water mark (planes 4 to 7), IFS
// scenes then the level each pixel's hit reached, and with aovs then the layers (albedo, normal,
// coverage, foreground; FGR_SHADED_AOV_PLANE).
#include "render/modes/shaded_mode.hpp"

#include <algorithm>

namespace fgr {
namespace {

constexpr int kShadedStatsPlanes = 4;
constexpr int kAovPlanes = 10;  // albedo (3), normal (3), coverage, foreground (3)

// Sums the stats planes (4: steps, 5: ran out of steps, 6: secondary rays' DE evaluations per
// lane, 7: IFS scenes' heap peak, or DE scenes' secondary DE evaluations per packet) over the
// image's pixels; depth (plane 3) says which pixels hit and so had their normal estimated.
MarchStats march_stats(std::span<const float> planes, const TileLayout& layout, int width,
                       int height, bool ifs) {
    const size_t plane = static_cast<size_t>(layout.plane_size());
    MarchStats stats;
    long steps = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(layout.index(x, y));
            const int pixel_steps = static_cast<int>(planes[4 * plane + i]);
            steps += pixel_steps;
            stats.max_steps = std::max(stats.max_steps, pixel_steps);
            const bool hit = planes[3 * plane + i] >= 0.0f;
            stats.de_evaluations += pixel_steps + (hit ? 4 : 0);
            stats.out_of_steps += planes[5 * plane + i] > 0.5f;
            const long secondary = static_cast<long>(planes[6 * plane + i]);
            stats.secondary_de_evaluations += secondary;
            if (!hit) stats.secondary_de_evaluations_missed += secondary;
            if (ifs) {
                const int heap = static_cast<int>(planes[7 * plane + i]);  // -1: overflowed
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
            longest = std::max(longest, planes[4 * plane + tile * layout.packet_width + lane]);
        }
        stats.packet_steps += static_cast<long>(longest);
        // DE scenes: plane 7 holds the packet's secondary DE evaluations in every lane.
        if (!ifs) {
            stats.secondary_packet_steps +=
                static_cast<long>(planes[7 * plane + tile * layout.packet_width]);
        }
    }
    stats.lane_steps = steps;
    stats.packet_width = layout.packet_width;
    return stats;
}

// The deepest and mean level of the IFS nodes the pixels hit (plane `index`; -1 where missed).
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
    // With stats: steps, out of steps, secondary rays' steps, IFS heap; IFS scenes: their level;
    // with aovs: the layers.
    return (switches.stats ? kShadedStatsPlanes : 0) + (ifs_ ? 1 : 0) +
           (switches.aovs ? kAovPlanes : 0);
}

void ShadedMode::bind(cl::Kernel& kernel, const FrameRequest&, const TileLayout&) {
    kernel.setArg(kFirstModeArgument, lights_);
    kernel.setArg(kFirstModeArgument + 1, light_count_);
}

void ShadedMode::read_back(std::span<const float> planes, const TileLayout& layout,
                           const FrameRequest& request, int samples, Frame& frame) const {
    const int width = frame.image.width, height = frame.image.height;  // the region's
    const int level_plane = kCommonPlanes + (stats_ ? kShadedStatsPlanes : 0);
    if (aovs_) {
        const int first = level_plane + (ifs_ ? 1 : 0);
        const float average = 1.0f / static_cast<float>(std::max(samples, 1));
        frame.albedo = planes_in_rows(planes, layout, first, 3, width, height, average);
        frame.normal = planes_in_rows(planes, layout, first + 3, 3, width, height, average);
        frame.alpha = planes_in_rows(planes, layout, first + 6, 1, width, height, average);
        frame.foreground = planes_in_rows(planes, layout, first + 7, 3, width, height, average);
    }
    // Stats and levels come from sample 0 (a request starting later has none).
    if (request.first_sample > 0) return;
    if (stats_) frame.stats = march_stats(planes, layout, width, height, ifs_);
    if (ifs_) frame.ifs_levels = hit_levels(planes, layout, level_plane, width, height);
}

}  // namespace fgr
