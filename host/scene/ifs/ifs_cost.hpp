// SPDX-License-Identifier: Apache-2.0
#pragma once
// What tracing an IFS scene's rays costs, estimated from its maps alone before anything is
// rendered: how many nodes of the tree of bounding balls a ray takes out of its heap, given the
// maps' count and contraction factors, the depth cap and the footprint rule that stops a ray's
// descent at nodes smaller than its pixel.
//
// The model. A ray looking for its nearest hit takes out every node it enters before that hit.
// At a level where the children's balls fill no more room than their parent's (the sum of the
// maps' s_i^3 at most 1) a ray meets a few nodes per level, whatever the depth; where they fill
// more (the balls overlap, and a set whose similarity dimension is above 3 fills space) the nodes
// covering any point multiply by that sum at every level, and so do the nodes a ray takes out. A
// node stops being opened at the depth cap or once it is smaller than the pixel's footprint at
// the camera's distance. The estimate follows the sizes the maps make level by level (grouped by
// size, so 64 maps at depth 24 cost a few thousand steps, not 64^24) and adds up, level by level,
// the nodes still opened times that overlap, at most all of them.

#include "scene/ifs/ifs.hpp"

namespace fgr {

// Nodes a ray opens at each level where the balls do not overlap more than their parent's: a
// ray meets its hit's own ancestors and a few neighbours. Measured with trace_ifs_ray on the
// shipped scenes (tests/scene/test_ifs_cost.cpp): their mean over the rays that hit stays below
// this times the levels reached.
inline constexpr double kIfsNodesPerLevel = 4.0;

struct IfsCost {
    double nodes_per_ray = 0.0;  // nodes a ray takes out (estimated), at most every node there is
    double tests_per_ray = 0.0;  // ball tests: the children of every node opened
    int levels = 0;              // the deepest level a ray opens (the depth cap or the footprint)
    double overlap = 0.0;        // the sum of the maps' s_i^3: above 1, the balls pile up
    double dimension = 0.0;      // similarity dimension: D with the sum of s_i^D equal to 1
};

// The cost of a ray of a `footprint`-radian pixel (hit threshold times the pixel's angle) from
// `distance` (the camera's distance to the bounding ball, at least a thousandth of its radius) at
// depth cap `depth`.
IfsCost estimate_ifs_cost(const IfsScene& ifs, int depth, double footprint, double distance);

// The deepest depth, at most `depth`, whose estimate stays within `nodes_per_ray`.
int deepest_affordable_ifs_depth(const IfsScene& ifs, int depth, double footprint, double distance,
                                 double nodes_per_ray);

// Nodes a ray of the default view may open at the default depth a file or plugin left to fgr:
// a sixty-fourth of what the kernel lets a ray visit at the default max_steps (256 x 256).
inline constexpr double kIfsDefaultDepthNodes = 1024.0;

// When the scene's default depth was not given (IfsScene::default_depth_from_cost): lowers it from
// the maximum to the deepest whose estimate, for a 640-pixel-wide image of its first camera at
// the default hit threshold, stays within kIfsDefaultDepthNodes. Needs the maps validated and
// the cameras set.
void settle_ifs_default_depth(IfsScene& scene);

}  // namespace fgr
