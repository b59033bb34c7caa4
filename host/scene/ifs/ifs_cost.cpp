// SPDX-License-Identifier: Apache-2.0
// The IFS cost estimate (ifs_cost.hpp): the nodes a ray opens, level by level, from the maps'
// contraction factors, the depth cap and the footprint rule.
#include "scene/ifs/ifs_cost.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "camera/camera.hpp"

namespace fgr {
namespace {

// Size classes the estimate groups nodes into: log(size / R) from 0 down to the smallest size a
// node is still opened at, in this many steps.
constexpr int kSizeClasses = 1024;

// D with sum_i s_i^D = 1 (the sum falls as D grows), by bisection; at most 1000.
double similarity_dimension(const std::vector<IfsMap>& maps) {
    const auto sum = [&](double d) {
        double total = 0.0;
        for (const IfsMap& map : maps) total += std::pow(map.contraction, d);
        return total;
    };
    double low = 0.0, high = 1000.0;
    if (sum(high) >= 1.0) return high;
    for (int i = 0; i < 100; ++i) {
        const double middle = 0.5 * (low + high);
        (sum(middle) > 1.0 ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

}  // namespace

IfsCost estimate_ifs_cost(const IfsScene& ifs, int depth, double footprint, double distance) {
    IfsCost cost;
    double smallest = 1.0, largest = 0.0;
    for (const IfsMap& map : ifs.maps) {
        cost.overlap += map.contraction * map.contraction * map.contraction;
        smallest = std::min(smallest, map.contraction);
        largest = std::max(largest, map.contraction);
    }
    cost.dimension = similarity_dimension(ifs.maps);
    const double radius = ifs.bounds.radius;
    distance = std::max(distance, 1e-3 * radius);
    // A node is opened while log(size / R) stays above `stop` (and its level below the depth):
    // the footprint's, or, with no footprint, the smallest size `depth` levels can make.
    const double deepest = depth * std::log(std::max(smallest, 1e-300));
    const double by_footprint =
        footprint > 0.0 ? std::log(footprint * distance / radius) : -INFINITY;
    const double stop = std::max(by_footprint, deepest - 1.0);
    cost.nodes_per_ray = 1.0;
    if (depth <= 0 || !(stop < 0.0) || ifs.maps.empty()) return cost;
    const double step = -stop / kSizeClasses;
    std::vector<int> shift;  // each map's size change, in classes
    std::vector<double> volume_factor;
    for (const IfsMap& map : ifs.maps) {
        shift.push_back(
            static_cast<int>(std::lround(-std::log(std::max(map.contraction, 1e-300)) / step)));
        volume_factor.push_back(map.contraction * map.contraction * map.contraction);
    }
    const auto classes = static_cast<std::size_t>(kSizeClasses) + 1;
    // Nodes opened at this level, and their balls' volumes over the root's, by size class.
    std::vector<double> count(classes, 0.0), volume(classes, 0.0);
    std::vector<double> next_count(classes), next_volume(classes);
    count[0] = 1.0;
    volume[0] = 1.0;
    double opened = 0.0;
    for (int level = 0; level < depth; ++level) {
        double level_count = 0.0, level_volume = 0.0;
        for (std::size_t c = 0; c < classes; ++c) {
            level_count += count[c];
            level_volume += volume[c];
        }
        if (level_count <= 0.0) break;
        opened += std::min(level_count, kIfsNodesPerLevel * std::max(1.0, level_volume));
        cost.levels = level + 1;
        std::fill(next_count.begin(), next_count.end(), 0.0);
        std::fill(next_volume.begin(), next_volume.end(), 0.0);
        for (std::size_t c = 0; c < classes; ++c) {
            if (count[c] <= 0.0) continue;
            for (std::size_t i = 0; i < shift.size(); ++i) {
                const std::size_t child = c + static_cast<std::size_t>(shift[i]);
                // Smaller than the footprint: a leaf, taken out but not opened.
                if (child >= kSizeClasses) continue;
                next_count[child] += count[c];
                next_volume[child] += volume[c] * volume_factor[i];
            }
        }
        count.swap(next_count);
        volume.swap(next_volume);
        if (opened > 1e300) break;
    }
    cost.nodes_per_ray = opened + 1.0;  // and the leaf hit
    cost.tests_per_ray = opened * static_cast<double>(ifs.maps.size());
    return cost;
}

int deepest_affordable_ifs_depth(const IfsScene& ifs, int depth, double footprint, double distance,
                                 double nodes_per_ray) {
    // The estimate grows with the depth (each level adds nodes): the deepest that fits, by
    // bisection.
    int low = 0, high = depth;
    while (low < high) {
        const int middle = (low + high + 1) / 2;
        if (estimate_ifs_cost(ifs, middle, footprint, distance).nodes_per_ray <= nodes_per_ray) {
            low = middle;
        } else {
            high = middle - 1;
        }
    }
    return low;
}

void settle_ifs_default_depth(IfsScene& scene) {
    if (!scene.default_depth_from_cost || scene.cameras.empty()) return;
    const CameraView& view = scene.cameras.front().view;
    const double footprint = pixel_angle(camera_basis(view), 640);
    const double distance = glm::length(view.position - scene.bounds.centre) - scene.bounds.radius;
    scene.default_depth = deepest_affordable_ifs_depth(scene, scene.max_depth, footprint, distance,
                                                       kIfsDefaultDepthNodes);
}

}  // namespace fgr
