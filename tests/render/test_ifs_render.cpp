// SPDX-License-Identifier: Apache-2.0
// Exact IFS ray tracing (kernels/geometry/fgr_ifs.cl): the kernel against the analytic bounding
// sphere and against the double-precision reference traversal (trace_ifs_ray), at every packet
// width.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <memory>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "render/environment.hpp"
#include "render/renderer.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

// The Sierpinski tetrahedron with corners (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1): four maps
// x -> (x + v) / 2, each with its own colour; the ball about the origin through the corners.
IfsScene sierpinski() {
    IfsScene ifs;
    ifs.id = "sierpinski-test";
    ifs.name = "Sierpinski test";
    const glm::dvec3 corners[4] = {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}, {-1, 1, -1}};
    const glm::vec3 colours[4] = {
        {0.9f, 0.2f, 0.2f}, {0.2f, 0.9f, 0.2f}, {0.2f, 0.2f, 0.9f}, {0.9f, 0.9f, 0.2f}};
    for (int i = 0; i < 4; ++i) {
        IfsMap map;
        map.linear = glm::dmat3(0.5);
        map.offset = corners[i] * 0.5;
        map.colour = colours[i];
        map.contraction = 0.5;
        ifs.maps.push_back(map);
    }
    ifs.bounds = {glm::dvec3(0.0), std::sqrt(3.0)};
    ifs.default_depth = 5;
    ifs.max_depth = 12;
    ifs.cameras.push_back(
        {"default", CameraView{{2.6, -4.1, 1.9}, {0.0, 0.0, 0.0}, {0, 0, 1}, 50}});
    ifs.lights.push_back(Light{});
    return ifs;
}

// A file from this build's plugin folder (plugins/ifs/).
IfsScene shipped_ifs(const std::string& file) {
    return read_ifs_file(std::filesystem::path(FGR_TEST_PLUGIN_DIR) / file);
}

Scene scene_of(const IfsScene& ifs) { return ifs_scene_to_scene(ifs, ifs.id + ".ifs.json"); }

class IfsRenderTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { device_ = new ComputeDevice(open_device(-1)); }
    static void TearDownTestSuite() { delete device_; }

    Frame render(const Scene& scene, const FrameRequest& request, int packet_width,
                 bool stats = false, bool double_precision = false) {
        try {
            Renderer renderer(*device_, cache_, scene,
                              {packet_width, scene.effects, stats, double_precision});
            return renderer.render(request);
        } catch (const KernelBuildError& error) {
            ADD_FAILURE() << error.build_log();

            throw;
        }
    }

    static ComputeDevice* device_;
    ProgramCache cache_{std::filesystem::path()};
};
ComputeDevice* IfsRenderTest::device_ = nullptr;

// Depth 0 is the bounding ball itself: every pixel's hit distance is the analytic sphere's, and
// every pixel whose ray meets the sphere (by more than a pixel's footprint) hits.
TEST_F(IfsRenderTest, DepthZeroIsTheBoundingSphereExactly) {
    const IfsScene ifs = sierpinski();
    const Scene scene = scene_of(ifs);
    const int width = 64, height = 48;
    FrameRequest request{width, height, ifs.cameras[0].view, default_param_values(scene)};
    set_param_from_text(scene, request.params, "ifs_depth=0");
    const Frame frame = render(scene, request, 16);
    const CameraBasis basis = camera_basis(ifs.cameras[0].view);
    long hits = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::dvec3 d(primary_ray_direction(basis, width, height, float(x), float(y)));
            const glm::dvec3 o = basis.eye;
            const double b = glm::dot(o, d), c = glm::dot(o, o) - 3.0;
            const double discriminant = b * b - c;
            const float t = frame.depth[size_t(y * width + x)];
            if (discriminant < 0.0) {
                EXPECT_LT(t, 0.0f) << x << "," << y;
                continue;
            }
            ++hits;
            const double expected = -b - std::sqrt(discriminant);
            EXPECT_NEAR(t, expected, 2e-5 * expected) << x << "," << y;
        }
    }
    EXPECT_GT(hits, width * height / 10);
}

// The kernel traces what the reference traversal (double precision, unbounded heap) traces: at
// several depths, from afar and from close up (where the footprint rule stops detail), the same
// pixels hit at the same distances, at every packet width. In double precision every pixel
// agrees (none disagreed in float either; a ray grazing an ellipsoid within float's rounding
// could, so float may differ in 3 of 3072 pixels).
TEST_F(IfsRenderTest, KernelHitsAndDistancesMatchTheReferenceTraversal) {
    // Ball leaves (the Sierpinski maps alone) and polytope leaves (the shipped sponge's cubes),
    // each from afar and from close up.
    std::vector<std::pair<IfsScene, CameraView>> cases;
    const IfsScene balls = sierpinski();
    cases.emplace_back(balls, balls.cameras[0].view);
    cases.emplace_back(balls, CameraView{{0.9, -1.3, 1.2}, {0.5, 0.4, 0.4}, {0, 0, 1}, 40});
    const IfsScene cubes = shipped_ifs("menger.ifs.json");
    ASSERT_FALSE(cubes.leaf.planes.empty());
    cases.emplace_back(cubes, cubes.cameras[0].view);
    cases.emplace_back(cubes, CameraView{{0.3, -1.6, 0.5}, {0.1, 0.0, 0.2}, {0, 0, 1}, 60});
    const int width = 64, height = 48;
    for (const auto& [ifs, view] : cases) {
        const Scene scene = scene_of(ifs);
        for (const int depth : {2, 5, ifs.max_depth}) {
            FrameRequest request{width, height, view, default_param_values(scene)};
            set_param_from_text(scene, request.params, "ifs_depth=" + std::to_string(depth));
            const CameraBasis basis = camera_basis(view);
            IfsTraceRules rules;
            rules.max_depth = depth;
            rules.footprint = double(param_value(scene, request.params, "hit_threshold") *
                                     pixel_angle(basis, width));
            rules.reach = param_value(scene, request.params, "max_distance");
            for (const bool in_double : {true, false}) {
                // Double lanes come 4 or more to a work-item (kMinDoublePacketWidth).
                for (const int packet : {16, in_double ? 4 : 1}) {
                    SCOPED_TRACE(::testing::Message()
                                 << "depth " << depth << (in_double ? " double" : " float")
                                 << " width " << packet);
                    const Frame frame = render(scene, request, packet, false, in_double);
                    long hits = 0, disagree = 0;
                    for (int y = 0; y < height; ++y) {
                        for (int x = 0; x < width; ++x) {
                            const glm::dvec3 dir(
                                primary_ray_direction(basis, width, height, float(x), float(y)));
                            const IfsRayHit expected =
                                trace_ifs_ray(ifs, basis.eye, glm::normalize(dir), rules);
                            const float t = frame.depth[size_t(y * width + x)];
                            hits += expected.hit;
                            if (expected.hit != (t >= 0.0f)) {
                                ++disagree;
                                continue;
                            }
                            if (!expected.hit) continue;
                            const double error = std::abs(t - expected.t) / expected.t;
                            // Double: what the float depth plane stores (a few ulps of a grazing
                            // entry). Float: 1.3e-6 at worst measured (the textbook discriminant
                            // b^2 - ac gave 6e-2 at depth 6 from close up).
                            EXPECT_LT(error, in_double ? 1e-6 : 1e-5) << "pixel " << x << "," << y;
                        }
                    }
                    EXPECT_GT(hits, width * height / 20);
                    EXPECT_LE(disagree, in_double ? 0 : 3) << "of " << width * height << " pixels";
                }
            }
        }
    }
}

// Packets only group rays: each lane is traced alone, so the image is the same bytes at every
// packet width, shadows included.
TEST_F(IfsRenderTest, EveryPacketWidthRendersTheSameImage) {
    const IfsScene ifs = sierpinski();
    Scene scene = scene_of(ifs);
    scene.effects = FGR_EFFECT_SHADOWS;
    // 70x45: partial tiles at the right and bottom edges.
    const FrameRequest request{70, 45, ifs.cameras[0].view, default_param_values(scene)};
    const Frame one = render(scene, request, 1);
    ASSERT_GT(one.hits, 70 * 45 / 10);
    for (const int packet : {4, 8, 16}) {
        const Frame packed = render(scene, request, packet);
        EXPECT_EQ(packed.image.rgb, one.image.rgb) << "width " << packet;
        EXPECT_EQ(packed.depth, one.depth) << "width " << packet;
    }
}

// The shipped Sierpinski and Menger IFS files draw the DE scenes' solids: at the same depth (the
// DE's `iterations`), from the DE scene's camera, the same pixels hit (IoU >= 0.98) at the same
// distances (within 1% on 98% of the pixels both hit). The DE marcher stops within hit_threshold
// footprints of its surface, which thickens every edge by as much, so both render at 0.02
// footprints here (at the default of 1, a pixel's rim around every small tetrahedron leaves an
// IoU of 0.72 to 0.84 at 192x144; measured 0.983 to 0.9985 at 0.02).
TEST_F(IfsRenderTest, ShippedSierpinskiAndMengerMatchTheirDistanceEstimatedScenes) {
    for (const auto& [ifs_file, de_file] : {std::pair{"sierpinski.ifs.json", "sierpinski.so"},
                                            std::pair{"menger.ifs.json", "menger.so"}}) {
        const Scene exact = scene_of(shipped_ifs(ifs_file));
        const Scene de = test::built_scene(de_file);
        const int width = 128, height = 96;
        for (const int depth : {2, 3, 4}) {
            SCOPED_TRACE(::testing::Message() << ifs_file << " depth " << depth);
            FrameRequest traced{width, height, de.cameras[0].view, default_param_values(exact)};
            set_param_from_text(exact, traced.params, "ifs_depth=" + std::to_string(depth));
            set_param_from_text(exact, traced.params, "hit_threshold=0.02");
            FrameRequest marched{width, height, de.cameras[0].view, default_param_values(de)};
            set_param_from_text(de, marched.params, "iterations=" + std::to_string(depth));
            set_param_from_text(de, marched.params, "hit_threshold=0.02");
            set_param_from_text(de, marched.params, "max_steps=2000");
            const Frame a = render(exact, traced, 16), b = render(de, marched, 16);
            long both = 0, either = 0, same_depth = 0;
            for (size_t i = 0; i < a.depth.size(); ++i) {
                const bool hit_a = a.depth[i] >= 0.0f, hit_b = b.depth[i] >= 0.0f;
                both += hit_a && hit_b;
                either += hit_a || hit_b;
                if (hit_a && hit_b)
                    same_depth += std::abs(a.depth[i] - b.depth[i]) < 0.01f * b.depth[i];
            }
            ASSERT_GT(either, width * height / 10);
            EXPECT_GE(double(both) / double(either), 0.98);
            EXPECT_GE(double(same_depth) / double(both), 0.98);
        }
    }
}

// Ball leaves have no face to take a normal from: the seed averages the ellipsoid normals of the
// deepest levels. On the Menger sponge's outer faces (true normals: the axes), seen from its
// default camera with ball leaves, averaging 8 levels brings the mean error from 38 degrees (the
// leaf's own ball) to 21 (measured; no better beyond 6 levels at this depth).
TEST(IfsNormals, AveragingLevelsBringsBallNormalsTowardsTheFaces) {
    IfsScene sponge = shipped_ifs("menger.ifs.json");
    sponge.leaf = IfsLeaf{};  // balls
    const int width = 160, height = 120;
    const CameraBasis basis = camera_basis(sponge.cameras[0].view);
    auto mean_error = [&](int levels) {
        double sum = 0.0;
        long faces = 0;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                const glm::dvec3 dir = glm::normalize(
                    glm::dvec3(primary_ray_direction(basis, width, height, float(x), float(y))));
                IfsTraceRules rules;
                rules.max_depth = sponge.max_depth;
                rules.footprint = pixel_angle(basis, width);
                rules.normal_levels = levels;
                const IfsRayHit hit = trace_ifs_ray(sponge, basis.eye, dir, rules);
                if (!hit.hit) continue;
                const glm::dvec3 p = basis.eye + hit.t * dir;
                for (int axis = 0; axis < 3; ++axis) {
                    glm::dvec3 face(0.0);
                    face[axis] = p[axis] > 0.0 ? 1.0 : -1.0;
                    // On an outer face (within the leaf's size) that faces the camera.
                    if (std::abs(std::abs(p[axis]) - 1.0) > 0.003 * hit.t) continue;
                    if (glm::dot(face, dir) >= 0.0) continue;
                    sum += glm::degrees(std::acos(std::min(1.0, glm::dot(face, hit.normal))));
                    ++faces;
                }
            }
        }
        EXPECT_GT(faces, width * height / 20);
        return sum / double(faces);
    };
    const double own = mean_error(1), averaged = mean_error(kIfsNormalLevels);
    EXPECT_GT(own, 30.0);
    EXPECT_LT(averaged, 24.0);
    EXPECT_LT(averaged, 0.7 * own);
}

// Path mode traces IFS geometry through the same seam. At depth 0 the scene is its bounding ball:
// a convex diffuse surface of albedo 0.6 under a uniform sky of radiance 1 returns 0.6 in every
// hit pixel (the mean within 3 standard errors), and the first hit's normal layer is the ball's
// normal where the pixel's ray meets it (median 0.024 degrees measured; under 0.25 asked).
// Measured: 0.59946 +- 0.00052. The shipped sponge at depth 2, seen face on, shows its front
// face's exact normal (+y) in 90% of the pixels it covers (the rest: the holes' walls).
TEST_F(IfsRenderTest, PathModeTracesIfsGeometry) {
    IfsScene ball = sierpinski();
    for (IfsMap& map : ball.maps) map.colour = glm::vec3(0.6f);
    const Scene scene = scene_of(ball);
    KernelSwitches switches;
    switches.packet_width = 16;
    switches.mode = RenderMode::Path;
    Renderer renderer(*device_, cache_, scene, switches);
    FrameRequest request{48, 36, ball.cameras[0].view, default_param_values(scene)};
    set_param_from_text(scene, request.params, "ifs_depth=0");
    request.samples = 16;
    request.path.scene_lights = false;
    EnvironmentChoice uniform;
    uniform.kind = EnvironmentKind::Uniform;
    uniform.radiance = glm::vec3(1.0f);
    request.path.environment = prepare_environment(uniform, scene);
    const Frame frame = renderer.render(request);
    const CameraBasis basis = camera_basis(ball.cameras[0].view);
    double sum = 0.0, sum2 = 0.0;
    std::vector<double> normal_errors;
    for (int y = 0; y < request.height; ++y) {
        for (int x = 0; x < request.width; ++x) {
            const size_t pixel = size_t(y * request.width + x);
            if (frame.alpha[pixel] < 1.0f) continue;
            const double value = frame.linear[3 * pixel];
            sum += value;
            sum2 += value * value;
            const glm::dvec3 dir = glm::normalize(glm::dvec3(
                primary_ray_direction(basis, request.width, request.height, float(x), float(y))));
            const double b = glm::dot(basis.eye, dir), c = glm::dot(basis.eye, basis.eye) - 3.0;
            if (b * b - c < 0.0) continue;
            const glm::dvec3 expected =
                glm::normalize(basis.eye + (-b - std::sqrt(b * b - c)) * dir);
            const glm::dvec3 normal(frame.normal[3 * pixel], frame.normal[3 * pixel + 1],
                                    frame.normal[3 * pixel + 2]);
            normal_errors.push_back(
                glm::degrees(std::acos(std::min(1.0, glm::dot(expected, glm::normalize(normal))))));
        }
    }
    const double n = double(normal_errors.size());
    ASSERT_GT(n, 200.0);
    const double mean = sum / n, error = std::sqrt((sum2 / n - mean * mean) / (n - 1.0));
    EXPECT_NEAR(mean, 0.6, 3.0 * error + 1e-6) << "standard error " << error;
    std::nth_element(normal_errors.begin(), normal_errors.begin() + normal_errors.size() / 2,
                     normal_errors.end());
    EXPECT_LT(normal_errors[normal_errors.size() / 2], 0.25);

    const IfsScene sponge = shipped_ifs("menger.ifs.json");
    const Scene sponge_scene = scene_of(sponge);
    Renderer sponge_renderer(*device_, cache_, sponge_scene, switches);
    FrameRequest face{48, 36, sponge.cameras[1].view, default_param_values(sponge_scene)};
    ASSERT_EQ(sponge.cameras[1].name, "face");
    set_param_from_text(sponge_scene, face.params, "ifs_depth=2");
    face.path = request.path;
    const Frame faced = sponge_renderer.render(face);
    long hits = 0, front = 0;
    for (size_t pixel = 0; pixel < faced.alpha.size(); ++pixel) {
        if (faced.alpha[pixel] < 1.0f) continue;
        ++hits;
        front += faced.normal[3 * pixel + 1] > 0.9998f;  // within 1.1 degrees of +y
    }
    ASSERT_GT(hits, 200);
    EXPECT_GT(double(front) / double(hits), 0.8) << front << " of " << hits;
}

// A heap too small for the view is never silent and never wrong: rays that would overflow it are
// traced again depth first, which finds the same hits at the same distances, and the stats count
// them. Here the heap holds 4 nodes instead of kIfsHeapCapacity.
TEST_F(IfsRenderTest, AFullHeapFallsBackToAnExactDepthFirstTrace) {
    const IfsScene sponge = shipped_ifs("menger.ifs.json");
    const Scene roomy = scene_of(sponge);
    Scene cramped = roomy;
    const std::string heap_line = "#define FGR_IFS_HEAP " + std::to_string(kIfsHeapCapacity) + "\n";
    const size_t at = cramped.source.find(heap_line);
    ASSERT_NE(at, std::string::npos);
    cramped.source.replace(at, heap_line.size(), "#define FGR_IFS_HEAP 4\n");
    FrameRequest request{64, 48, sponge.cameras[0].view, default_param_values(roomy)};
    set_param_from_text(roomy, request.params, "ifs_depth=4");
    const Frame full = render(roomy, request, 16, true);
    const Frame fallen_back = render(cramped, request, 16, true);
    ASSERT_GT(full.hits, 64 * 48 / 10);
    EXPECT_EQ(full.stats->heap_overflows, 0);
    EXPECT_LE(full.stats->heap_peak, kIfsHeapCapacity);
    EXPECT_GT(fallen_back.stats->heap_overflows, full.hits / 4);
    EXPECT_EQ(fallen_back.depth, full.depth);
    EXPECT_EQ(fallen_back.image.rgb, full.image.rgb);
}

// The viewer's fly speed and the auto precision rule read "the DE at the camera": for an IFS, a
// bound from the node tree. It never exceeds the distance to any point of the attractor (here 10^4
// chaos-game points of the sponge), comes within 1.5x of the nearest of them from outside, and
// inside the sponge's central tunnel (where the bounding ball's own distance is negative) it is
// the way to the tunnel's walls, 1/3 away.
TEST(IfsDistanceBound, IsALowerBoundThatTheViewerCanFlyBy) {
    const IfsScene sponge = shipped_ifs("menger.ifs.json");
    std::vector<glm::dvec3> points;
    glm::dvec3 x(0.0);
    uint32_t state = 12345u;
    for (int i = 0; i < 10100; ++i) {
        state = state * 1664525u + 1013904223u;
        const IfsMap& map = sponge.maps[(state >> 16) % sponge.maps.size()];
        x = map.linear * x + map.offset;
        if (i >= 100) points.push_back(x);
    }
    const glm::dvec3 probes[] = {
        {3, 2, 1}, {0, 0.9, 0}, {0.1, -0.5, 0.05}, {1.2, 1.2, -1.3}, {0, 0, 5}};
    for (const glm::dvec3& p : probes) {
        double nearest = 1e30;
        for (const glm::dvec3& q : points) nearest = std::min(nearest, glm::length(p - q));
        const double bound = ifs_distance_bound(sponge, p, sponge.max_depth);
        EXPECT_LE(bound, nearest) << p.x << " " << p.y << " " << p.z;
        EXPECT_GE(bound, nearest / 1.5 - 0.02) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_NEAR(ifs_distance_bound(sponge, {0, 0.9, 0}, sponge.max_depth), 1.0 / 3.0, 0.12);
}

}  // namespace
}  // namespace fgr
