// SPDX-License-Identifier: Apache-2.0
// The reference IFS ray tracer: kernels/geometry/fgr_ifs.cl's traversal in double precision, with
// an unbounded heap, for tests and host-side queries.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <queue>
#include <vector>

#include "scene/ifs/ifs.hpp"

namespace fgr {
namespace {

// A node: the affine map from world space into its space (x -> linear * x + offset), in which it
// is the bounding ball.
struct Node {
    bool resolved = false;  // a leaf whose entry is where the ray meets its shape
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};
    double entry = 0.0;
    double size = 0.0;
    int depth = 0;
    int top_map = -1;
    std::vector<int> path;  // map indices from the root
};

struct LaterEntry {
    bool operator()(const Node& a, const Node& b) const { return a.entry > b.entry; }
};

// Where the ray enters and leaves the ball in the node's space, if it meets it: the miss test by
// |oc x dl|^2 against R^2 |dl|^2, as kernels/geometry/fgr_ifs.cl's ifs_enter.
bool enter(const Node& node, const IfsBounds& ball, const glm::dvec3& o, const glm::dvec3& d,
           double& entry, double& exit) {
    const glm::dvec3 oc = node.linear * o + node.offset - ball.centre;
    const glm::dvec3 dl = node.linear * d;
    const double a = glm::dot(dl, dl);
    const glm::dvec3 across = glm::cross(oc, dl);
    const double room = ball.radius * ball.radius * a - glm::dot(across, across);
    if (!(room >= 0.0) || !(a > 0.0)) return false;
    const double closest = -glm::dot(oc, dl) / a;
    const double half_chord = std::sqrt(room) / a;
    entry = closest - half_chord;
    exit = closest + half_chord;
    return true;
}

// Where the ray enters a leaf's polytope, and through which plane (kernels/geometry/fgr_ifs.cl's
// ifs_polytope_enter).
bool enter_polytope(const Node& node, const IfsLeaf& leaf, const glm::dvec3& o, const glm::dvec3& d,
                    double& entry, int& face) {
    const glm::dvec3 ol = node.linear * o + node.offset;
    const glm::dvec3 dl = node.linear * d;
    double enter = -INFINITY, leave = INFINITY;
    face = 0;
    for (int i = 0; i < static_cast<int>(leaf.planes.size()); ++i) {
        const glm::dvec4& plane = leaf.planes[static_cast<size_t>(i)];
        const glm::dvec3 n(plane);
        const double along = glm::dot(n, dl);
        const double room = plane.w - glm::dot(n, ol);
        if (along == 0.0) {
            if (room < 0.0) return false;
            continue;
        }
        const double t = room / along;
        if (along < 0.0) {
            if (t > enter) {
                enter = t;
                face = i;
            }
        } else {
            leave = std::min(leave, t);
        }
    }
    entry = enter;
    return enter <= leave;
}

// Whether a leaf draws the polytope: at the depth cap (a leaf the footprint stopped draws its
// ball; kernels/geometry/fgr_ifs.cl's ifs_draws_polytope).
bool draws_polytope(const Node& node, const IfsScene& ifs, const IfsTraceRules& rules) {
    return !ifs.leaf.planes.empty() && node.depth >= rules.max_depth;
}

// Where the ray meets what a leaf draws: its ball's entry, or its polytope's.
bool leaf_hit(const Node& node, const IfsScene& ifs, const IfsTraceRules& rules,
              const glm::dvec3& o, const glm::dvec3& d, double& t) {
    if (!draws_polytope(node, ifs, rules)) {
        t = node.entry;
        return true;
    }
    int face = 0;
    return enter_polytope(node, ifs.leaf, o, d, t, face);
}

Node child_of(const Node& parent, const IfsScene& ifs, const std::vector<glm::dmat3>& inverses,
              int map) {
    Node child;
    const glm::dmat3& inverse = inverses[static_cast<size_t>(map)];
    child.linear = inverse * parent.linear;
    child.offset = inverse * (parent.offset - ifs.maps[static_cast<size_t>(map)].offset);
    child.size = parent.size * ifs.maps[static_cast<size_t>(map)].contraction;
    child.depth = parent.depth + 1;
    child.top_map = parent.top_map < 0 ? map : parent.top_map;
    child.path = parent.path;
    child.path.push_back(map);
    return child;
}

bool is_leaf(const Node& node, const IfsTraceRules& rules) {
    return node.depth >= rules.max_depth ||
           node.size <= rules.footprint * (std::max(node.entry, 0.0) + rules.travelled);
}

// The leaf's normal: world-space unit normals of the ellipsoids of its last levels at the hit
// point, averaged (kernels/geometry/fgr_ifs.cl's ifs_normal).
glm::dvec3 averaged_normal(const Node& leaf, const IfsScene& ifs, const glm::dvec3& point,
                           int levels) {
    glm::dmat3 linear = leaf.linear;
    glm::dvec3 q = leaf.linear * point + leaf.offset;
    glm::dvec3 sum{0.0};
    levels = std::min(levels, leaf.depth + 1);
    for (int level = 0; level < levels; ++level) {
        const glm::dvec3 world = glm::transpose(linear) * (q - ifs.bounds.centre);
        const double length = glm::length(world);
        if (length > 0.0) sum += world / length;
        if (level + 1 == levels) break;
        const IfsMap& map = ifs.maps[static_cast<size_t>(leaf.path[leaf.path.size() - 1 - level])];
        q = map.linear * q + map.offset;
        linear = map.linear * linear;
    }
    const double length = glm::length(sum);
    return length > 0.0 ? sum / length : glm::dvec3(0.0, 0.0, 1.0);
}

// The normal where the ray enters a resolved leaf: its polytope's face, or the averaged ball
// normals (kernels/geometry/fgr_ifs.cl's ifs_normal).
glm::dvec3 surface_normal(const Node& leaf, const IfsScene& ifs, const IfsTraceRules& rules,
                          const glm::dvec3& origin, const glm::dvec3& dir) {
    if (!draws_polytope(leaf, ifs, rules)) {
        return averaged_normal(leaf, ifs, origin + leaf.entry * dir, rules.normal_levels);
    }
    double entry = 0.0;
    int face = 0;
    enter_polytope(leaf, ifs.leaf, origin, dir, entry, face);
    return glm::normalize(glm::transpose(leaf.linear) *
                          glm::dvec3(ifs.leaf.planes[static_cast<size_t>(face)]));
}

}  // namespace

double ifs_distance_bound(const IfsScene& ifs, const glm::dvec3& p, int max_depth) {
    // A node in world space: its ball's centre and radius (R times its maps' contractions).
    struct Ball {
        glm::dmat3 linear{1.0};
        glm::dvec3 offset{0.0};
        double radius = 0.0;
        int depth = 0;
        double bound = 0.0;  // max(|p - centre| - radius, 0)
    };
    const auto later = [](const Ball& a, const Ball& b) { return a.bound > b.bound; };
    std::priority_queue<Ball, std::vector<Ball>, decltype(later)> heap(later);
    const auto bound_of = [&](Ball& ball) {
        const glm::dvec3 centre = ball.linear * ifs.bounds.centre + ball.offset;
        ball.bound = std::max(glm::length(p - centre) - ball.radius, 0.0);
    };
    Ball root;
    root.radius = ifs.bounds.radius;
    bound_of(root);
    heap.push(root);
    // Enough for any view; the bound stays valid (the smallest waiting) when it runs out.
    constexpr int kMaxNodes = 20000;
    for (int popped = 0; popped < kMaxNodes && !heap.empty(); ++popped) {
        const Ball ball = heap.top();
        if (ball.depth >= max_depth || ball.radius <= 0.25 * ball.bound) return ball.bound;
        heap.pop();
        for (const IfsMap& map : ifs.maps) {
            Ball child;
            child.linear = ball.linear * map.linear;
            child.offset = ball.linear * map.offset + ball.offset;
            child.radius = ball.radius * map.contraction;
            child.depth = ball.depth + 1;
            bound_of(child);
            heap.push(child);
        }
    }
    return heap.empty() ? 0.0 : heap.top().bound;
}

IfsRayHit trace_ifs_ray(const IfsScene& ifs, const glm::dvec3& origin, const glm::dvec3& dir,
                        const IfsTraceRules& rules) {
    std::vector<glm::dmat3> inverses;
    inverses.reserve(ifs.maps.size());
    for (const IfsMap& map : ifs.maps) inverses.push_back(glm::inverse(map.linear));
    IfsRayHit result;
    Node root;
    root.size = ifs.bounds.radius;
    double entry = 0.0, exit = 0.0;
    if (!enter(root, ifs.bounds, origin, dir, entry, exit) || exit <= 0.0 || entry > rules.reach) {
        return result;
    }
    root.entry = entry;
    std::priority_queue<Node, std::vector<Node>, LaterEntry> heap;
    heap.push(root);
    result.heap_peak = 1;
    while (!heap.empty() && (rules.max_nodes <= 0 || result.visited < rules.max_nodes)) {
        Node node = heap.top();
        heap.pop();
        ++result.visited;
        if (node.resolved) {
            result.hit = true;
            result.t = node.entry;
            result.depth = node.depth;
            result.top_map = node.top_map;
            result.normal = surface_normal(node, ifs, rules, origin, dir);
            return result;
        }
        if (is_leaf(node, rules)) {
            double t = 0.0;
            if (!leaf_hit(node, ifs, rules, origin, dir, t) || !(t > 0.0) || t > rules.reach)
                continue;
            node.entry = t;
            node.resolved = true;
            heap.push(std::move(node));
            result.heap_peak = std::max(result.heap_peak, static_cast<long>(heap.size()));
            continue;
        }
        for (int map = 0; map < static_cast<int>(ifs.maps.size()); ++map) {
            Node child = child_of(node, ifs, inverses, map);
            if (!enter(child, ifs.bounds, origin, dir, entry, exit) || exit <= 0.0 ||
                entry > rules.reach) {
                continue;
            }
            child.entry = entry;
            heap.push(std::move(child));
            result.heap_peak = std::max(result.heap_peak, static_cast<long>(heap.size()));
        }
    }
    return result;
}

}  // namespace fgr
