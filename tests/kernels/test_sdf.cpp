// SPDX-License-Identifier: Apache-2.0
// kernels/sdf/fgr_sdf.cl, evaluated by the kernel through inline scenes, against double-precision
// C++ references: exact distance functions must match the true distance, bounds must never exceed
// it and must agree with it on which side of the surface a point lies, and the non-rigid transforms
// must stay 1-Lipschitz. Every scene is built at packet widths 1 and 16.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "random_points.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

using dvec2 = glm::dvec2;
using dvec3 = glm::dvec3;
using Reference = std::function<double(dvec3)>;

constexpr std::array kWidths{1, 16};

using test::shared_device;

// scene_de's body is `body`, an OpenCL statement list ending in a return. One build, then the
// DE at each set of points.
std::vector<std::vector<float>> kernel_de(const std::string& body,
                                          const std::vector<std::vector<glm::vec3>>& point_sets,
                                          int packet_width) {
    const Scene scene = test::inline_scene("real scene_de(vec3 p, PARAMS) {\n" + body + "\n}\n");
    ProgramCache no_disk_cache{std::filesystem::path()};
    Renderer renderer(shared_device(), no_disk_cache, scene, {packet_width, 0});
    std::vector<std::vector<float>> results;
    for (const auto& points : point_sets) {
        results.push_back(renderer.probe_de(points, default_param_values(scene)));
    }
    return results;
}

using test::random_points;

dvec3 to_double(glm::vec3 p) { return dvec3(p); }

// --- Reference geometry, written from first principles rather than from the kernel's formulas.

double segment_distance(dvec3 p, dvec3 a, dvec3 b) {
    const dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

double segment_distance_2d(dvec2 p, dvec2 a, dvec2 b) {
    return segment_distance(dvec3(p, 0.0), dvec3(a, 0.0), dvec3(b, 0.0));
}

// Box with half extents b: outside, the distance to the clamped point; inside, to the nearest face.
double box_distance(dvec3 p, dvec3 b) {
    const dvec3 nearest = glm::clamp(p, -b, b);
    if (nearest != p) return glm::length(p - nearest);
    const dvec3 margin = b - glm::abs(p);
    return -std::min({margin.x, margin.y, margin.z});
}

// Solid of revolution about z whose half-section is the polygon `outline` in (rho, z) with
// vertices on the axis at both ends; `inside` decides the sign.
double revolution_distance(dvec3 p, const std::vector<dvec2>& outline,
                           const std::function<bool(dvec2)>& inside) {
    const dvec2 q(std::hypot(p.x, p.y), p.z);
    double best = 1e300;
    for (size_t i = 0; i + 1 < outline.size(); ++i) {
        best = std::min(best, segment_distance_2d(q, outline[i], outline[i + 1]));
    }
    return inside(q) ? -best : best;
}

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
dvec3 closest_on_triangle(dvec3 p, dvec3 a, dvec3 b, dvec3 c) {
    const dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
    const dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    }
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

// Exact signed distance to a convex polyhedron given by its triangular faces, wound so that
// (b - a) x (c - a) points outwards.
double polyhedron_distance(dvec3 p, const std::vector<std::array<dvec3, 3>>& faces) {
    double surface = 1e300, deepest_plane = -1e300;
    for (const auto& [a, b, c] : faces) {
        surface = std::min(surface, glm::length(p - closest_on_triangle(p, a, b, c)));
        const dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        deepest_plane = std::max(deepest_plane, glm::dot(p - a, n));
    }
    return deepest_plane > 0.0 ? surface : -surface;
}

std::vector<std::array<dvec3, 3>> outward(std::vector<std::array<dvec3, 3>> faces) {
    for (auto& face : faces) {
        const dvec3 centroid = (face[0] + face[1] + face[2]) / 3.0;
        if (glm::dot(glm::cross(face[1] - face[0], face[2] - face[0]), centroid) < 0) {
            std::swap(face[1], face[2]);
        }
    }
    return faces;
}

std::vector<std::array<dvec3, 3>> octahedron_faces(double s) {
    std::vector<std::array<dvec3, 3>> faces;
    for (double sx : {-s, s})
        for (double sy : {-s, s})
            for (double sz : {-s, s})
                faces.push_back({dvec3(sx, 0, 0), dvec3(0, sy, 0), dvec3(0, 0, sz)});
    return outward(faces);
}

std::vector<std::array<dvec3, 3>> tetrahedron_faces(double s) {
    const std::array<dvec3, 4> v{dvec3(s, s, s), dvec3(s, -s, -s), dvec3(-s, s, -s),
                                 dvec3(-s, -s, s)};
    return outward(
        {{v[1], v[2], v[3]}, {v[0], v[2], v[3]}, {v[0], v[1], v[3]}, {v[0], v[1], v[2]}});
}

// Right-handed rotation matrices applied to a vector (the object's motion).
dvec3 rotate(dvec3 v, int axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    switch (axis) {
        case 0:
            return {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
        case 1:
            return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
        default:
            return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
    }
}

// --- Checks

enum class Quality { Exact, Bound };

struct SdfCase {
    std::string name;
    std::string body;     // OpenCL: the scene's DE
    Reference reference;  // the true signed distance (exact) or the true sign and a distance
                          // at least the true one (bound: closed form or dense sampling)
    Quality quality = Quality::Exact;
    bool check_lipschitz = false;  // also |DE(a) - DE(b)| <= (1 + 1e-3) |a - b| on random pairs
};

// Points in [-1.5, 1.5]^3 plus the origin and a few axis points, where formulas divide.
std::vector<glm::vec3> test_points() {
    auto points = random_points(300, 1.5f, 1234);
    for (glm::vec3 special : {glm::vec3(0), glm::vec3(0, 0, 0.5f), glm::vec3(0.5f, 0, 0),
                              glm::vec3(0, -0.5f, 0), glm::vec3(0, 0, -1.2f)}) {
        points.push_back(special);
    }
    return points;
}

// Pairs of points 1e-3 .. 0.3 apart, for the Lipschitz check.
std::pair<std::vector<glm::vec3>, std::vector<glm::vec3>> random_pairs() {
    auto first = random_points(400, 1.5f, 99);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> second;
    for (const auto& p : first) {
        const glm::vec3 direction =
            glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + 1e-6f);
        second.push_back(p + direction * (1e-3f + 0.3f * (unit(rng) + 1.0f) * 0.5f));
    }
    return {first, second};
}

void check_case(const SdfCase& c) {
    const auto points = test_points();
    const auto [first, second] = random_pairs();
    for (int width : kWidths) {
        const auto results = kernel_de(c.body, {points, first, second}, width);
        const auto& distances = results[0];
        for (size_t i = 0; i < points.size(); ++i) {
            const double de = distances[i];
            const double truth = c.reference(to_double(points[i]));
            const double scale = std::max({1.0, std::abs(truth), double(glm::length(points[i]))});
            const auto where = [&] {
                return c.name + " width " + std::to_string(width) + " at (" +
                       std::to_string(points[i].x) + ", " + std::to_string(points[i].y) + ", " +
                       std::to_string(points[i].z) + "): DE " + std::to_string(de) + ", true " +
                       std::to_string(truth);
            };
            ASSERT_TRUE(std::isfinite(de)) << where();
            if (c.quality == Quality::Exact) {
                ASSERT_NEAR(de, truth, 1e-5 * scale) << where();
            } else {
                ASSERT_LE(std::abs(de), std::abs(truth) + 1e-5 * scale) << where();
                if (std::abs(truth) > 1e-4) {
                    ASSERT_EQ(de > 0.0, truth > 0.0) << where();
                }
            }
        }
        if (!c.check_lipschitz) continue;
        for (size_t i = 0; i < first.size(); ++i) {
            const double separation = glm::length(first[i] - second[i]);
            // Float rounding of two DE values of order 1 allows a few 1e-7 of slack.
            ASSERT_LE(std::abs(results[1][i] - results[2][i]), (1.0 + 1e-3) * separation + 1e-6)
                << c.name << " width " << width << " pair " << i;
        }
    }
}

// The distance from p to a dense sample of a surface: never less than the true distance.
double sampled_distance(dvec3 p, const std::vector<dvec3>& surface) {
    double best2 = 1e300;
    for (const dvec3& s : surface) {
        const dvec3 d = p - s;
        best2 = std::min(best2, glm::dot(d, d));
    }
    return std::sqrt(best2);
}

// Points on the faces of the box with half extents b, `n` per edge of each face.
std::vector<dvec3> box_surface(dvec3 b, int n) {
    std::vector<dvec3> points;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (double side : {-1.0, 1.0}) {
            for (int i = 0; i <= n; ++i) {
                for (int j = 0; j <= n; ++j) {
                    dvec3 s;
                    s[axis] = side * b[axis];
                    s[u] = b[u] * (2.0 * i / n - 1.0);
                    s[v] = b[v] * (2.0 * j / n - 1.0);
                    points.push_back(s);
                }
            }
        }
    }
    return points;
}

// --- Primitives

TEST(SdfPrimitives, Sphere) {
    check_case(
        {"sd_sphere", "return sd_sphere(p, 0.8f);", [](dvec3 p) { return glm::length(p) - 0.8; }});
}

TEST(SdfPrimitives, Box) {
    check_case({"sd_box", "return sd_box(p, v3_splat(0.9f, 0.5f, 0.3f));", [](dvec3 p) {
                    return box_distance(p, {0.9, 0.5, 0.3});
                }});
}

TEST(SdfPrimitives, RoundBox) {
    // Rounding by r: the points within r of the box shrunk by r.
    check_case(
        {"sd_round_box", "return sd_round_box(p, v3_splat(0.9f, 0.5f, 0.4f), 0.15f);", [](dvec3 p) {
             return box_distance(p, {0.75, 0.35, 0.25}) - 0.15;
         }});
}

TEST(SdfPrimitives, Torus) {
    // Ring in the xy-plane: the distance to the circle of radius 0.7 minus the tube radius.
    check_case({"sd_torus", "return sd_torus(p, 0.7f, 0.25f);", [](dvec3 p) {
                    const double rho = std::hypot(p.x, p.y);
                    return std::hypot(rho - 0.7, p.z) - 0.25;
                }});
}

TEST(SdfPrimitives, Plane) {
    check_case({"sd_plane", "return sd_plane(p, v3_splat(0.6f, 0.0f, 0.8f), 0.3f);",
                [](dvec3 p) { return 0.6 * p.x + 0.8 * p.z - 0.3; }});
}

TEST(SdfPrimitives, Cylinder) {
    check_case({"sd_cylinder", "return sd_cylinder(p, 0.6f, 0.8f);", [](dvec3 p) {
                    return revolution_distance(
                        p, {{0, -0.8}, {0.6, -0.8}, {0.6, 0.8}, {0, 0.8}},
                        [](dvec2 q) { return q.x < 0.6 && std::abs(q.y) < 0.8; });
                }});
}

TEST(SdfPrimitives, Capsule) {
    check_case(
        {"sd_capsule",
         "return sd_capsule(p, v3_splat(-0.5f, 0.2f, -0.3f), v3_splat(0.4f, -0.1f, 0.6f), 0.3f);",
         [](dvec3 p) {
             return segment_distance(p, {-0.5, 0.2, -0.3}, {0.4, -0.1, 0.6}) - 0.3;
         }});
}

TEST(SdfPrimitives, CappedCone) {
    // Radius 0.8 at z = -0.7 narrowing to 0.2 at z = 0.7.
    const auto radius_at = [](double z) { return 0.8 + (0.2 - 0.8) * (z + 0.7) / 1.4; };
    check_case({"sd_cone", "return sd_cone(p, 0.7f, 0.8f, 0.2f);", [radius_at](dvec3 p) {
                    return revolution_distance(
                        p, {{0, -0.7}, {0.8, -0.7}, {0.2, 0.7}, {0, 0.7}}, [radius_at](dvec2 q) {
                            return std::abs(q.y) < 0.7 && q.x < radius_at(q.y);
                        });
                }});
}

TEST(SdfPrimitives, PointedConeAndInvertedCone) {
    check_case({"sd_cone pointed", "return sd_cone(p, 0.6f, 0.7f, 0.0f);", [](dvec3 p) {
                    return revolution_distance(p, {{0, -0.6}, {0.7, -0.6}, {0, 0.6}}, [](dvec2 q) {
                        return std::abs(q.y) < 0.6 && q.x < 0.7 * (0.6 - q.y) / 1.2;
                    });
                }});
    check_case({"sd_cone inverted", "return sd_cone(p, 0.5f, 0.1f, 0.9f);", [](dvec3 p) {
                    return revolution_distance(
                        p, {{0, -0.5}, {0.1, -0.5}, {0.9, 0.5}, {0, 0.5}}, [](dvec2 q) {
                            return std::abs(q.y) < 0.5 && q.x < 0.1 + 0.8 * (q.y + 0.5);
                        });
                }});
}

TEST(SdfPrimitives, Octahedron) {
    const auto faces = octahedron_faces(0.9);
    check_case({"sd_octahedron", "return sd_octahedron(p, 0.9f);",
                [faces](dvec3 p) { return polyhedron_distance(p, faces); }});
}

TEST(SdfPrimitives, TetrahedronIsABound) {
    const auto faces = tetrahedron_faces(0.6);
    check_case({"sd_tetrahedron", "return sd_tetrahedron(p, 0.6f);",
                [faces](dvec3 p) { return polyhedron_distance(p, faces); }, Quality::Bound});
}

TEST(SdfPrimitives, TetrahedronIsExactInside) {
    // Inside a convex polyhedron the nearest face plane is the nearest surface.
    const auto faces = tetrahedron_faces(0.6);
    check_case({"sd_tetrahedron inside", "return fmin(sd_tetrahedron(p, 0.6f), 0.0f);",
                [faces](dvec3 p) { return std::min(polyhedron_distance(p, faces), 0.0); }});
}

// --- Combinators, on a sphere (d1) and a box (d2) that overlap

const std::string kPair =
    "real d1 = sd_sphere(op_translate(p, v3_splat(-0.3f, 0.0f, 0.1f)), 0.7f);\n"
    "real d2 = sd_box(op_translate(p, v3_splat(0.35f, 0.1f, 0.0f)), v3_splat(0.5f, 0.6f, 0.4f));\n";
double pair_d1(dvec3 p) { return glm::length(p - dvec3(-0.3, 0.0, 0.1)) - 0.7; }
double pair_d2(dvec3 p) { return box_distance(p - dvec3(0.35, 0.1, 0.0), {0.5, 0.6, 0.4}); }

TEST(SdfCombinators, SharpOperations) {
    check_case({"op_union", kPair + "return op_union(d1, d2);",
                [](dvec3 p) { return std::min(pair_d1(p), pair_d2(p)); }});
    check_case({"op_subtraction", kPair + "return op_subtraction(d1, d2);",
                [](dvec3 p) { return std::max(pair_d1(p), -pair_d2(p)); }});
    check_case({"op_intersection", kPair + "return op_intersection(d1, d2);",
                [](dvec3 p) { return std::max(pair_d1(p), pair_d2(p)); }});
}

TEST(SdfCombinators, UnionOfDisjointShapesIsExactOutside) {
    // Two separate balls: outside both, the nearer one's distance is the union's.
    check_case({"op_union balls",
                "return op_union(sd_sphere(op_translate(p, v3_splat(-0.8f, 0, 0)), 0.4f),"
                "                sd_sphere(op_translate(p, v3_splat(0.8f, 0, 0)), 0.5f));",
                [](dvec3 p) {
                    return std::min(glm::length(p - dvec3(-0.8, 0, 0)) - 0.4,
                                    glm::length(p - dvec3(0.8, 0, 0)) - 0.5);
                }});
}

// op_union_culled(d, lower, object) is fmin(d, object) wherever lower <= object, and evaluates
// `object` only for packets with a lane whose lower bound is not beyond d. Here d = p.x,
// lower = p.z, object = p.y (>= p.z), and each evaluation of the object adds 1000 to the result.
TEST(SdfCombinators, CulledUnionIsTheUnionAndEvaluatesTheObjectOnlyWhereALaneMayNeedIt) {
    const std::string body =
        "#define FGR_KERNEL_API 3\n"
        "real evaluations = fgr_real(0.0f);\n"
        "real d = p.x;\n"
        "d = op_union_culled(d, p.z, (evaluations += 1.0f, p.y));\n"
        "return d + 1000.0f * evaluations;";
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    // One 16-point packet whose lower bounds all lie beyond d, then the same with one lane near.
    std::vector<glm::vec3> beyond;
    for (int i = 0; i < 16; ++i) {
        const float x = unit(rng), lower = x + 0.01f + unit(rng);
        beyond.emplace_back(x, lower + 2.0f * unit(rng), lower);
    }
    constexpr size_t kNearLane = 5;
    std::vector<glm::vec3> one_near = beyond;
    one_near[kNearLane].z = one_near[kNearLane].x - 0.5f;
    one_near[kNearLane].y = one_near[kNearLane].x - 0.25f;  // nearer than d: the union takes it
    for (int width : kWidths) {
        const auto values = kernel_de(body, {beyond, one_near}, width);
        for (size_t i = 0; i < 16; ++i) {
            EXPECT_EQ(values[0][i], beyond[i].x) << "width " << width << ", lane " << i;
            // Width 16: the near lane's packet evaluates the object for all its lanes; width 1:
            // that lane alone.
            const bool evaluated = width == 16 || i == kNearLane;
            const float expected =
                evaluated ? std::fmin(one_near[i].x, one_near[i].y) + 1000.0f : one_near[i].x;
            EXPECT_EQ(values[1][i], expected) << "width " << width << ", lane " << i;
        }
    }
}

// --- Smooth combinators, by their properties rather than by their formula typed again. With
// d1 = p.x and d2 = p.y the kernel's operation is evaluated at chosen input values directly.

// (d1, d2) on a grid over [-1, 1]^2 in steps of 1/20, as points (d1, d2, 0).
std::vector<glm::vec3> distance_pairs() {
    std::vector<glm::vec3> points;
    for (int i = -20; i <= 20; ++i) {
        for (int j = -20; j <= 20; ++j)
            points.emplace_back(float(i) / 20.0f, float(j) / 20.0f, 0.0f);
    }
    return points;
}

// The operation `call` (an expression of d1 and d2) at every distance pair, per packet width.
std::vector<std::vector<float>> smooth_op_values(const std::string& call) {
    std::vector<std::vector<float>> values;
    for (int width : kWidths) {
        values.push_back(kernel_de("real d1 = p.x, d2 = p.y;\nreturn " + call + ";",
                                   {distance_pairs()}, width)[0]);
    }
    return values;
}

// Float evaluation of values of order 1.
constexpr double kOpSlack = 2e-6;

// A smooth union's surface contains both shapes and rounds the crease between them: it is never
// above the sharp union min(d1, d2), at most k/4 below it (where d1 = d2), equal to it once the
// two distances are k or more apart, symmetric, and does not decrease when either input grows.
// Exact values, worked by hand with the polynomial smooth minimum's other form
// min(a, b) - max(k - |a - b|, 0)^2 / (4k), at k = 0.5:
//   (0.1, 0.3): 0.1 - 0.3^2 / 2 = 0.055;  (0, 0): -0.125;  (0.2, -0.05): -0.05 - 0.25^2 / 2 =
//   -0.08125;  (-0.3, -0.3): -0.425;  (0.6, 0.05): 0.05 (0.55 apart: the sharp minimum).
TEST(SdfCombinators, SmoothUnionIsBelowTheUnionByAtMostAQuarterOfK) {
    constexpr double k = 0.5;
    const auto pairs = distance_pairs();
    const auto wide = smooth_op_values("op_smooth_union(d1, d2, 0.5f)");
    const auto narrow = smooth_op_values("op_smooth_union(d1, d2, 0.25f)");
    const auto at = [&](const std::vector<float>& values, double d1, double d2) {
        const size_t i =
            size_t(std::lround(d1 * 20.0) + 20) * 41 + size_t(std::lround(d2 * 20.0) + 20);
        return double(values[i]);
    };
    for (size_t w = 0; w < wide.size(); ++w) {
        SCOPED_TRACE("width " + std::to_string(kWidths[w]));
        const auto& values = wide[w];
        EXPECT_NEAR(at(values, 0.1, 0.3), 0.055, kOpSlack);
        EXPECT_NEAR(at(values, 0.0, 0.0), -0.125, kOpSlack);
        EXPECT_NEAR(at(values, 0.2, -0.05), -0.08125, kOpSlack);
        EXPECT_NEAR(at(values, -0.3, -0.3), -0.425, kOpSlack);
        EXPECT_NEAR(at(values, 0.6, 0.05), 0.05, kOpSlack);
        for (size_t i = 0; i < pairs.size(); ++i) {
            const double d1 = pairs[i].x, d2 = pairs[i].y, value = values[i];
            const double sharp = std::min(d1, d2);
            SCOPED_TRACE(::testing::Message() << "(d1, d2) = (" << d1 << ", " << d2 << ")");
            ASSERT_LE(value, sharp + kOpSlack);
            ASSERT_GE(value, sharp - k / 4.0 - kOpSlack);
            if (std::abs(d1 - d2) >= k) {
                ASSERT_NEAR(value, sharp, kOpSlack);
            }
            ASSERT_NEAR(value, at(values, d2, d1), kOpSlack) << "swapped";
            if (d1 < 1.0) {
                ASSERT_LE(value, at(values, d1 + 0.05, d2) + kOpSlack);
            }
            if (d2 < 1.0) {
                ASSERT_LE(value, at(values, d1, d2 + 0.05) + kOpSlack);
            }
            // A wider blend rounds more: never above the narrower one.
            ASSERT_LE(value, double(narrow[w][i]) + kOpSlack);
        }
    }
}

// Smooth intersection rounds the crease of max(d1, d2) from inside: never below it, at most k/4
// above it (where d1 = d2), equal to it once the distances are k apart. By hand at k = 0.5:
//   (0.1, 0.3): 0.3 + 0.3^2 / 2 = 0.345;  (0.2, 0.2): 0.325;  (-0.4, 0.3): 0.3 (0.7 apart).
// Smooth subtraction (shape 1 minus shape 2) is the same about max(d1, -d2):
//   (0.2, 0.1): max 0.2, d1 and -d2 0.3 apart: 0.2 + 0.2^2 / 2 = 0.22;  (0.1, -0.1): 0.225;
//   (0.5, 0.3): 0.5 (0.8 apart).
TEST(SdfCombinators, SmoothIntersectionAndSubtractionAreAboveTheSharpOnesByAtMostAQuarterOfK) {
    constexpr double k = 0.5;
    const auto pairs = distance_pairs();
    const auto intersection = smooth_op_values("op_smooth_intersection(d1, d2, 0.5f)");
    const auto subtraction = smooth_op_values("op_smooth_subtraction(d1, d2, 0.5f)");
    const auto at = [&](const std::vector<float>& values, double d1, double d2) {
        const size_t i =
            size_t(std::lround(d1 * 20.0) + 20) * 41 + size_t(std::lround(d2 * 20.0) + 20);
        return double(values[i]);
    };
    for (size_t w = 0; w < intersection.size(); ++w) {
        SCOPED_TRACE("width " + std::to_string(kWidths[w]));
        EXPECT_NEAR(at(intersection[w], 0.1, 0.3), 0.345, kOpSlack);
        EXPECT_NEAR(at(intersection[w], 0.2, 0.2), 0.325, kOpSlack);
        EXPECT_NEAR(at(intersection[w], -0.4, 0.3), 0.3, kOpSlack);
        EXPECT_NEAR(at(subtraction[w], 0.2, 0.1), 0.22, kOpSlack);
        EXPECT_NEAR(at(subtraction[w], 0.1, -0.1), 0.225, kOpSlack);
        EXPECT_NEAR(at(subtraction[w], 0.5, 0.3), 0.5, kOpSlack);
        for (size_t i = 0; i < pairs.size(); ++i) {
            const double d1 = pairs[i].x, d2 = pairs[i].y;
            SCOPED_TRACE(::testing::Message() << "(d1, d2) = (" << d1 << ", " << d2 << ")");
            for (const auto& [values, a, b, name] :
                 {std::tuple{&intersection[w], d1, d2, "intersection"},
                  std::tuple{&subtraction[w], d1, -d2, "subtraction"}}) {
                const double value = (*values)[i], sharp = std::max(a, b);
                ASSERT_GE(value, sharp - kOpSlack) << name;
                ASSERT_LE(value, sharp + k / 4.0 + kOpSlack) << name;
                if (std::abs(a - b) >= k) {
                    ASSERT_NEAR(value, sharp, kOpSlack) << name;
                }
            }
        }
    }
}

// On real shapes (a sphere and a box that overlap, a wide blend so many pairs straddle the
// fillets) each smooth operation stays 1-Lipschitz, so the march may step by it.
TEST(SdfCombinators, SmoothOperationsAreOneLipschitz) {
    const auto [first, second] = random_pairs();
    for (const char* op : {"op_smooth_union", "op_smooth_subtraction", "op_smooth_intersection"}) {
        for (int width : kWidths) {
            const auto values =
                kernel_de(kPair + "return " + op + "(d1, d2, 0.5f);", {first, second}, width);
            for (size_t i = 0; i < first.size(); ++i) {
                const double separation = glm::length(first[i] - second[i]);
                ASSERT_LE(std::abs(values[0][i] - values[1][i]), (1.0 + 1e-3) * separation + 1e-6)
                    << op << " width " << width << " pair " << i;
            }
        }
    }
}

TEST(SdfCombinators, SmoothOperationsWithZeroRadiusAreSharp) {
    check_case({"op_smooth_union k=0", kPair + "return op_smooth_union(d1, d2, 0.0f);",
                [](dvec3 p) { return std::min(pair_d1(p), pair_d2(p)); }});
    check_case({"op_smooth_subtraction k=0", kPair + "return op_smooth_subtraction(d1, d2, 0.0f);",
                [](dvec3 p) { return std::max(pair_d1(p), -pair_d2(p)); }});
    check_case({"op_smooth_intersection k=0",
                kPair + "return op_smooth_intersection(d1, d2, 0.0f);",
                [](dvec3 p) { return std::max(pair_d1(p), pair_d2(p)); }});
}

// --- Transforms

TEST(SdfTransforms, TranslatedSphere) {
    check_case({"op_translate",
                "return sd_sphere(op_translate(p, v3_splat(0.3f, -0.2f, 0.5f)), 0.7f);",
                [](dvec3 p) { return glm::length(p - dvec3(0.3, -0.2, 0.5)) - 0.7; }});
}

TEST(SdfTransforms, RotatedSphereTurnsCounterClockwise) {
    // An off-centre ball rotated about each axis: its centre moves by the right-handed rotation.
    const dvec3 centre(0.6, 0.2, -0.3);
    const std::array<std::string, 3> names{"op_rotate_x", "op_rotate_y", "op_rotate_z"};
    for (int axis = 0; axis < 3; ++axis) {
        const dvec3 moved = rotate(centre, axis, 0.7);
        check_case({names[axis],
                    "return sd_sphere(op_translate(" + names[axis] +
                        "(p, 0.7f), v3_splat(0.6f, 0.2f, -0.3f)), 0.5f);",
                    [moved](dvec3 p) { return glm::length(p - moved) - 0.5; }});
    }
}

TEST(SdfTransforms, RotatedBox) {
    check_case({"op_rotate_z box",
                "return sd_box(op_rotate_z(p, 0.5f), v3_splat(0.8f, 0.3f, 0.4f));", [](dvec3 p) {
                    return box_distance(rotate(p, 2, -0.5), {0.8, 0.3, 0.4});
                }});
}

TEST(SdfTransforms, ScaledSphere) {
    // sd(p / s) * s: the ball at c of radius r becomes the ball at s c of radius s r.
    check_case({"op_scale",
                "return op_scale_distance(sd_sphere(op_translate(op_scale_point(p, 1.7f), "
                "v3_splat(0.2f, 0.1f, -0.3f)), 0.4f), 1.7f);",
                [](dvec3 p) { return glm::length(p - 1.7 * dvec3(0.2, 0.1, -0.3)) - 1.7 * 0.4; }});
}

TEST(SdfTransforms, ElongatedSphereIsARoundBox) {
    // A ball of radius 0.3 stretched by (0.4, 0.2, 0.1) is the box of those half extents grown by
    // 0.3: exact outside, a bound inside (the stretched core reads as the ball's centre).
    const auto round_box = [](dvec3 p) { return box_distance(p, {0.4, 0.2, 0.1}) - 0.3; };
    const std::string stretched = "sd_sphere(op_elongate(p, v3_splat(0.4f, 0.2f, 0.1f)), 0.3f)";
    check_case({"op_elongate outside", "return fmax(" + stretched + ", 0.0f);",
                [round_box](dvec3 p) { return std::max(round_box(p), 0.0); }});
    check_case({"op_elongate", "return " + stretched + ";", round_box, Quality::Bound});
}

TEST(SdfTransforms, RoundAndOnion) {
    check_case(
        {"op_round", "return op_round(sd_box(p, v3_splat(0.5f, 0.3f, 0.2f)), 0.2f);", [](dvec3 p) {
             return box_distance(p, {0.5, 0.3, 0.2}) - 0.2;
         }});
    check_case({"op_onion", "return op_onion(sd_sphere(p, 0.8f), 0.1f);",
                [](dvec3 p) { return std::abs(glm::length(p) - 0.8) - 0.1; }});
}

// The exact distance to balls of radius r at the lattice points i * period, i within limits.
double lattice_balls(dvec3 p, dvec3 period, glm::ivec3 limits, double r) {
    double best = 1e300;
    for (int i = -limits.x; i <= limits.x; ++i)
        for (int j = -limits.y; j <= limits.y; ++j)
            for (int k = -limits.z; k <= limits.z; ++k)
                best = std::min(best, glm::length(p - dvec3(i, j, k) * period) - r);
    return best;
}

TEST(SdfTransforms, InfiniteRepetition) {
    // Period 0 on z: not repeated there. 20 cells either way covers the test points.
    check_case({"op_repeat", "return sd_sphere(op_repeat(p, v3_splat(0.8f, 1.1f, 0.0f)), 0.3f);",
                [](dvec3 p) {
                    return lattice_balls(p, {0.8, 1.1, 0.0}, {20, 20, 0}, 0.3);
                }});
}

TEST(SdfTransforms, LimitedRepetition) {
    check_case({"op_repeat_limited",
                "return sd_sphere(op_repeat_limited(p, v3_splat(0.6f, 0.7f, 0.5f), "
                "v3_splat(2.0f, 1.0f, 0.0f)), 0.2f);",
                [](dvec3 p) {
                    return lattice_balls(p, {0.6, 0.7, 0.5}, {2, 1, 0}, 0.2);
                }});
}

// The twisted box of the tests: half extents (0.3, 0.3, 0.8), 1.4 radians per unit of height,
// evaluated inside the cylinder of its corners' radius and extended outside it.
const std::string kTwistedBox =
    "const float rate = 1.4f, reach = 0.43f;\n"
    "real excess;\n"
    "vec3 q = op_clamp_to_cylinder(p, reach, 0.8f, &excess);\n"
    "real d = sd_box(op_twist(q, rate), v3_splat(0.3f, 0.3f, 0.8f));\n"
    "return op_extend_from_clamp(d / op_twist_lipschitz(rate, reach), excess);";

TEST(SdfTransforms, TwistIsABound) {
    const double rate = 1.4;
    std::vector<dvec3> surface;
    for (dvec3 s : box_surface({0.3, 0.3, 0.8}, 120)) surface.push_back(rotate(s, 2, rate * s.z));
    check_case({"op_twist", kTwistedBox,
                [&surface, rate](dvec3 p) {
                    const double sign =
                        box_distance(rotate(p, 2, -rate * p.z), {0.3, 0.3, 0.8}) > 0 ? 1 : -1;
                    return sign * sampled_distance(p, surface);
                },
                Quality::Bound, true});
}

// A bar of half extents (0.9, 0.25, 0.1) bent with curvature 0.7, evaluated in a box reaching
// 0.5 towards the bend's axis.
const std::string kBentBar =
    "const float curvature = 0.7f, reach = 0.5f;\n"
    "real excess;\n"
    "vec3 q = op_clamp_to_box(p, v3_splat(0.95f, 0.3f, reach), &excess);\n"
    "real d = sd_box(op_bend(q, curvature), v3_splat(0.9f, 0.25f, 0.1f));\n"
    "return op_extend_from_clamp(d / op_bend_lipschitz(curvature, reach), excess);";

TEST(SdfTransforms, BendIsABound) {
    const double k = 0.7;
    // Straight coordinates (x, y, z) of the bar land on the arc at angle k x, radius 1/k - z.
    const auto bend = [k](dvec3 s) {
        const double angle = k * s.x, r = 1.0 / k - s.z;
        return dvec3(r * std::sin(angle), s.y, 1.0 / k - r * std::cos(angle));
    };
    const auto unbend = [k](dvec3 p) {
        const double below = 1.0 / k - p.z;
        return dvec3(std::atan2(p.x, below) / k, p.y, 1.0 / k - std::hypot(p.x, below));
    };
    std::vector<dvec3> surface;
    for (dvec3 s : box_surface({0.9, 0.25, 0.1}, 120)) surface.push_back(bend(s));
    check_case(
        {"op_bend", kBentBar,
         [&](dvec3 p) {
             // Points beyond the bend's axis are far outside the bar.
             const bool inside = p.z < 1.0 / k && box_distance(unbend(p), {0.9, 0.25, 0.1}) < 0;
             return (inside ? -1 : 1) * sampled_distance(p, surface);
         },
         Quality::Bound, true});
}

TEST(SdfTransforms, SineDisplacement) {
    const std::string body = "return op_displace_sine(sd_sphere(p, 0.7f), p, 0.1f, 6.0f);";
    check_case({"op_displace_sine", body,
                [](dvec3 p) {
                    const double wave = std::sin(6 * p.x) * std::sin(6 * p.y) * std::sin(6 * p.z);
                    return (glm::length(p) - 0.7 + 0.1 * wave) / (1.0 + 0.1 * 6.0 * std::sqrt(3.0));
                },
                Quality::Exact, true});
    check_case(
        {"op_displace_sine strong",
         "return op_displace_sine(sd_box(p, v3_splat(0.5f, 0.6f, 0.4f)), p, 0.3f, 9.0f);",
         [](dvec3 p) {
             const double wave = std::sin(9 * p.x) * std::sin(9 * p.y) * std::sin(9 * p.z);
             return (box_distance(p, {0.5, 0.6, 0.4}) + 0.3 * wave) / (1.0 + 2.7 * std::sqrt(3.0));
         },
         Quality::Exact, true});
}

// --- Robustness

// Degenerate shapes and parameters, summed so a NaN anywhere shows.
const std::string kDegenerate =
    "real excess;\n"
    "real d = sd_sphere(p, 0.0f) + sd_box(p, v3_splat(0, 0, 0)) + sd_round_box(p, v3_splat(0, 0, "
    "0), 0.0f)\n"
    "  + sd_torus(p, 0.0f, 0.0f) + sd_cylinder(p, 0.0f, 0.0f) + sd_capsule(p, v3_splat(0, 0, 0), "
    "v3_splat(0, 0, 0), 0.0f)\n"
    "  + sd_cone(p, 0.0f, 0.0f, 0.0f) + sd_cone(p, 0.5f, 0.0f, 0.0f) + sd_octahedron(p, 0.0f)\n"
    "  + sd_tetrahedron(p, 0.0f) + sd_plane(p, v3_splat(0, 0, 1), 0.0f)\n"
    "  + op_smooth_union(p.x, p.y, 0.0f) + op_smooth_subtraction(p.x, p.y, 0.0f)\n"
    "  + op_smooth_intersection(p.x, p.y, 0.0f)\n"
    "  + sd_sphere(op_repeat(p, v3_splat(0, 0, 0)), 0.1f) + sd_sphere(op_repeat_limited(p, "
    "v3_splat(0, 1, 0), v3_splat(0, 0, 0)), 0.1f)\n"
    "  + sd_sphere(op_elongate(p, v3_splat(0, 0, 0)), 0.1f) + op_onion(sd_sphere(p, 0.0f), 0.0f)\n"
    "  + sd_box(op_twist(op_clamp_to_cylinder(p, 0.0f, 0.0f, &excess), 0.0f), v3_splat(0.1f, 0.1f, "
    "0.1f)) / op_twist_lipschitz(0.0f, 0.0f)\n"
    "  + op_extend_from_clamp(sd_sphere(op_clamp_to_ball(p, 0.0f, &excess), 0.0f), excess)\n"
    "  + sd_sphere(op_bend(p, 0.0f), 0.5f) / op_bend_lipschitz(0.0f, 0.0f) + sd_sphere(op_bend(p, "
    "-2.0f), 0.2f)\n"
    "  + op_displace_sine(sd_sphere(p, 0.5f), p, 0.0f, 0.0f)\n"
    "  + sd_sphere(op_rotate_x(op_rotate_y(op_rotate_z(p, 0.0f), 3.14159265f), -1.0f), 0.3f);\n"
    "return d;";

TEST(SdfRobustness, FiniteAtTheOriginAxesAndFarAwayForEveryWidth) {
    std::vector<glm::vec3> points{
        {0, 0, 0},          {-0.0f, -0.0f, -0.0f}, {0, 0, 1},    {0, 0, -1},    {1, 0, 0},
        {0, 1, 0},          {1e-30f, 0, 0},        {1e6f, 0, 0}, {0, -1e6f, 0}, {0, 0, 1e6f},
        {1e6f, 1e6f, -1e6f}};
    const auto more = random_points(21, 2.0f, 17);  // not a multiple of any width: a partial packet
    points.insert(points.end(), more.begin(), more.end());
    std::vector<float> narrow;
    for (int width : {1, 4, 8, 16}) {
        const auto distances = kernel_de(kDegenerate, {points}, width)[0];
        for (size_t i = 0; i < points.size(); ++i) {
            ASSERT_TRUE(std::isfinite(distances[i])) << "width " << width << " point " << i;
        }
        // The same maths in every lane layout.
        if (narrow.empty()) narrow = distances;
        for (size_t i = 0; i < points.size(); ++i) {
            EXPECT_NEAR(distances[i], narrow[i], 1e-5f * std::max(1.0f, std::abs(narrow[i])))
                << "width " << width << " point " << i;
        }
    }
}

// The gallery scene combines everything above; its objects sit in 2.5-unit slots, so the generic
// stability suite's samples (spread over the whole view) rarely land near one. Here pairs are
// packed around every slot, for the defaults and every parameter at both ends of its range.
TEST(SdfGallery, OneLipschitzAroundEveryObjectForEveryParameterExtreme) {
    const auto plugin = std::filesystem::path(FGR_TEST_PLUGIN_DIR) / "sdf-gallery.so";
    if (!std::filesystem::exists(plugin)) GTEST_SKIP() << "sdf-gallery plugin not built";
    LoadResult loaded = load_scene_plugin(plugin);
    ASSERT_TRUE(loaded.scene) << loaded.error;
    const Scene& scene = *loaded.scene;
    ProgramCache no_disk_cache{std::filesystem::path()};
    Renderer renderer(shared_device(), no_disk_cache, scene, {16, 0});

    std::mt19937 rng(23);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::vector<glm::vec3> first, second;
    for (int slot = 0; slot < 24; ++slot) {
        const glm::vec3 centre((float(slot % 6) - 2.5f) * 2.5f, (float(slot / 6) - 1.5f) * 2.5f,
                               1.05f);
        for (int i = 0; i < 60; ++i) {
            const glm::vec3 p = centre + 1.2f * glm::vec3(unit(rng), unit(rng), unit(rng));
            const glm::vec3 direction =
                glm::normalize(glm::vec3(unit(rng), unit(rng), unit(rng)) + 1e-6f);
            first.push_back(p);
            second.push_back(p + direction * (2e-3f + 0.2f * (unit(rng) + 1.0f) * 0.5f));
        }
    }
    const auto offsets = param_offsets(scene);
    std::vector<std::pair<std::string, std::vector<float>>> settings{
        {"defaults", default_param_values(scene)}};
    for (size_t i = 0; i < scene.params.size(); ++i) {
        if (scene.params[i].builtin) continue;
        for (float extreme : {scene.params[i].min_value, scene.params[i].max_value}) {
            auto values = default_param_values(scene);
            values[offsets[i]] = extreme;
            settings.emplace_back(scene.params[i].id + "=" + std::to_string(extreme), values);
        }
    }
    for (const auto& [name, values] : settings) {
        const auto de_first = renderer.probe_de(first, values);
        const auto de_second = renderer.probe_de(second, values);
        for (size_t i = 0; i < first.size(); ++i) {
            ASSERT_TRUE(std::isfinite(de_first[i]) && std::isfinite(de_second[i])) << name;
            const double separation = glm::length(first[i] - second[i]);
            ASSERT_LE(std::abs(de_first[i] - de_second[i]), (1.0 + 1e-3) * separation + 2e-6)
                << name << ", slot " << i / 60 << ", pair " << i;
        }
    }
}

// The benchmark scene unions its objects with op_union_culled. Its DE must equal, bit for bit,
// the same source with every culled union made a plain fmin: at single points (width 1, where
// each lane culls alone) and in packets of 16 points a few hundredths apart (width 16, where
// whole packets cull), spread over the scene and packed round each object, whose bounding
// spheres and boxes are where a lower bound that is too high would show.
TEST(SdfGallery, TheBenchmarkScenesCulledUnionsChangeNoDistance) {
    const Scene culled = test::built_scene("benchmark.so");
    Scene plain = culled;
    plain.source =
        "#undef op_union_culled\n#define op_union_culled(d, lower, object) fmin((d), (object))\n" +
        culled.source;
    std::mt19937 rng(59);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const std::array<glm::vec3, 5> centres{
        glm::vec3(-1.7f, 0.5f, 0.72f), glm::vec3(1.5f, 0.7f, 0.62f), glm::vec3(0.1f, -1.5f, 0.55f),
        glm::vec3(0.2f, 1.9f, 0.8f), glm::vec3(0.0f, 0.0f, 0.8f)};
    std::vector<glm::vec3> points;
    for (int cluster = 0; cluster < 2000; ++cluster) {
        // Round an object (the last centre: the whole scene, 3 units about).
        const size_t object = size_t(cluster) % centres.size();
        const float reach = object + 1 == centres.size() ? 3.0f : 1.3f;
        const glm::vec3 centre =
            centres[object] + reach * glm::vec3(unit(rng), unit(rng), unit(rng));
        for (int i = 0; i < 16; ++i)
            points.push_back(centre + 0.03f * glm::vec3(unit(rng), unit(rng), unit(rng)));
    }
    for (int width : kWidths) {
        ProgramCache no_disk_cache{std::filesystem::path()};
        Renderer with_culling(shared_device(), no_disk_cache, culled, {width, 0});
        Renderer without(shared_device(), no_disk_cache, plain, {width, 0});
        const auto values = default_param_values(culled);
        const auto expected = without.probe_de(points, values);
        const auto actual = with_culling.probe_de(points, values);
        int differing = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            if (actual[i] != expected[i] && ++differing <= 3) {
                ADD_FAILURE() << "width " << width << " at (" << points[i].x << ", " << points[i].y
                              << ", " << points[i].z << "): " << actual[i] << " against "
                              << expected[i];
            }
        }
        EXPECT_EQ(differing, 0) << "width " << width << " of " << points.size() << " points";
    }
}

}  // namespace
}  // namespace fgr
