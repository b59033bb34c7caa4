// SPDX-License-Identifier: Apache-2.0
#pragma once
// IFS scenes: fractals given as iterated function systems of affine maps, read from JSON files
// (`*.ifs.json` in any plugin folder) and rendered exactly by ray tracing the hierarchy of
// bounding spheres the maps generate (Hart and DeFanti, "Efficient Antialiased Rendering of 3-D
// Linear Fractals", SIGGRAPH 1991), not by a distance estimator.

#include <cstddef>
#include <filesystem>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace fgr {

// The newest IFS file format version this build reads.
constexpr int kIfsFormatVersion = 1;
// Limits on what a file may ask for: beyond them a file is refused, not rendered slowly.
constexpr int kIfsMaxMaps = 64;
constexpr int kIfsMaxDepth = 24;
// Files larger than this are refused before they are parsed.
constexpr std::size_t kIfsMaxFileBytes = 4u << 20;
// Nodes the kernel's heap holds per ray (FGR_IFS_HEAP); a ray that would overflow it is traced
// again depth first, exactly, and counted in the stats. Measured: the shipped scenes at their
// deepest, from every camera, peak at 11 to 35 nodes at 640x480 and at 42 (the sponge face on) at
// 1920x1080; 64 leaves half as much again.
constexpr int kIfsHeapCapacity = 64;
// Levels whose ellipsoid normals are averaged into an IFS surface normal (FGR_IFS_NORMAL_LEVELS):
// measured on the faces of the Menger sponge and the Sierpinski tetrahedron (320x240, default
// views), whose true normals are known, the mean error falls from 38 and 52 degrees with the
// leaf's own ellipsoid to 21 and 34 with 8 levels, and no further beyond (test_ifs_render.cpp).
constexpr int kIfsNormalLevels = 8;

// One affine map w(x) = linear * x + offset, contractive.
struct IfsMap {
    glm::dmat3 linear{1.0};  // column-major, as glm: linear[c][r]
    glm::dvec3 offset{0.0};
    glm::vec3 colour{0.75f, 0.72f, 0.68f};  // linear RGB albedo of the points this map makes
    double contraction = 0.0;               // largest singular value of `linear`, < 1
};

// A ball B = {x : |x - centre| <= radius} with w_i(B) inside B for every map, so the attractor
// lies in B and in every image of B under compositions of the maps.
struct IfsBounds {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
};

// What a leaf node draws: the bounding ball itself (Hart and DeFanti's spheres: no shape is
// assumed), or a convex polytope inside it, given as half-spaces n . x <= h (a box, a
// tetrahedron), whose level-n images are then the level-n solid the IFS builds from it (the DE
// scenes' level-n sponge or tetrahedron), with exact face normals.
struct IfsLeaf {
    std::string shape = "ball";      // "ball", "box" or "tetrahedron"
    std::vector<glm::dvec4> planes;  // empty for the ball; else (n, h) with |n| = 1
};
// Half-spaces a leaf polytope may have (a box has 6).
constexpr int kIfsMaxLeafPlanes = 8;

struct IfsScene {
    int version = kIfsFormatVersion;
    std::string id;
    std::string name;
    std::string description;
    std::vector<IfsMap> maps;
    int default_depth = 6;
    int max_depth = 12;
    // The file or plugin gave no default depth (set_ifs_depths): the default is the maximum,
    // lowered where the maps make that costly (settle_ifs_default_depth), and the footprint rule
    // stops rays sooner.
    bool default_depth_from_cost = false;
    std::vector<NamedCamera> cameras;  // [0] is the default view
    std::vector<CameraPath> camera_paths;
    std::vector<Light> lights;
    std::string environment;  // the path mode's when the user names none; "" for the sky
    IfsBounds bounds;         // computed from the maps by ifs_bounding_sphere
    IfsLeaf leaf;
};

// A file fgr refuses, with a one-line reason that names the file (and the map, where one is at
// fault).
class IfsError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether `file` is named like an IFS scene file (`NAME.ifs.json`).
bool is_ifs_file_name(const std::filesystem::path& file);

// Parses and validates an IFS file's text; `origin` names it in error messages. Throws IfsError.
IfsScene parse_ifs_json(const std::string& text, const std::string& origin);

// Reads, parses and validates an IFS file. Throws IfsError.
IfsScene read_ifs_file(const std::filesystem::path& file);

// Checks an IFS scene's maps and depths, wherever they came from (an IFS file or a plugin's
// fgr_ifs_map array), as docs/sdk/ifs.md's "Validation" says: 1 to kIfsMaxMaps maps, each with
// finite numbers of at most 1e6 in size, colour components in [0, 1], contractive (largest singular
// value below 1) and invertible (smallest above 1e-9 times the largest); depths in [0,
// kIfsMaxDepth] with the default at most the maximum. Sets each map's `contraction` and the scene's
// `bounds` (ifs_bounding_sphere), which must stay within 1e5 of the origin. Throws IfsError with a
// one-line reason that names the map ("<map_word> 2 is not contractive (...)") but no file: callers
// add it.
void validate_ifs_maps(IfsScene& scene, std::string_view map_word = "map");

// Sets the depth slider's default and maximum from what a file or plugin gave, either, both or
// neither: the maximum defaults to kIfsMaxDepth, the default to the maximum, which
// settle_ifs_default_depth then lowers where the maps would make it costly; the pixel footprint
// stops each ray where detail falls below a pixel, so only a map that shrinks slowly goes deep.
// Range checks are validate_ifs_maps's.
void set_ifs_depths(IfsScene& scene, std::optional<int> default_depth,
                    std::optional<int> max_depth);

// Largest singular value of a 3x3 matrix (the most a map stretches any vector).
double largest_singular_value(const glm::dmat3& m);

// All three singular values, largest first (one-sided Jacobi: accurate for the small ones too, so
// a nearly singular map is told apart from a merely small one).
glm::dvec3 singular_values(const glm::dmat3& m);

// A bounding ball for the maps' attractor (see IfsBounds), from each map's contraction factor
// s_i and where it sends the centre c: B(c, R) contains w_i(B(c, R)) when
// |w_i(c) - c| + s_i R <= R, so R = max_i |w_i(c) - c| / (1 - s_i); c is chosen to make R small.
IfsBounds ifs_bounding_sphere(const std::vector<IfsMap>& maps);

// What a ray meets in an IFS scene, traced as kernels/geometry/fgr_ifs.cl traces it but in double
// precision and without a heap limit: the reference its tests compare the kernel with.
struct IfsRayHit {
    bool hit = false;
    double t = 0.0;          // along the ray, where it enters the leaf
    int depth = 0;           // the leaf's level (0: the bounding ball)
    int top_map = -1;        // the first map on the leaf's path (-1 at the root)
    glm::dvec3 normal{0.0};  // averaged over the leaf's deepest levels, as the kernel does
    long visited = 0;        // nodes taken out of the heap
    long heap_peak = 0;      // the most nodes the heap held
};

// The IFS ray's rules (the kernel's): a node is a leaf at `max_depth` or once its size bound
// (radius times its maps' contraction factors) is at most footprint * (entry + travelled); a leaf
// counts where the ray enters it ahead of the origin and within `reach`; normals average the
// ellipsoid normals of the leaf's last `normal_levels` levels.
struct IfsTraceRules {
    int max_depth = 6;
    double footprint = 0.0;  // hit_threshold * pixel angle (radians); 0: depth alone decides
    double travelled = 0.0;
    double reach = 1e30;
    int normal_levels = kIfsNormalLevels;
    long max_nodes = 0;  // nodes taken out before the ray gives up, as the kernel's; 0: no limit
};

IfsRayHit trace_ifs_ray(const IfsScene& ifs, const glm::dvec3& origin, const glm::dvec3& dir,
                        const IfsTraceRules& rules);

// A lower bound of the distance from p to the attractor, at least two thirds of the true distance
// (or of the distance to the `max_depth` level's balls): the smallest distance to a node's
// bounding ball, found best first over the node tree, stopping at a node whose radius is at most
// a quarter of its distance. Zero inside a node at the depth limit. What the viewer's fly speed and
// the auto precision rule read as "the DE at the camera" for IFS scenes, whose kernel has no DE.
double ifs_distance_bound(const IfsScene& ifs, const glm::dvec3& p, int max_depth);

// The fgr scene an IFS file describes: its cameras, paths and lights, the built-in parameters
// plus the depth slider `ifs_depth`, and generated OpenCL C source holding the maps.
Scene ifs_scene_to_scene(const IfsScene& ifs, const std::filesystem::path& file);

}  // namespace fgr
