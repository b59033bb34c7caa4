// Exact IFS ray tracing (kernels/fgr_ifs.cl): the kernel against the analytic bounding sphere and
// against the double-precision reference traversal (trace_ifs_ray), at every packet width.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "fgr/camera.hpp"
#include "fgr/ifs.hpp"
#include "fgr/plugin.h"
#include "fgr/opencl_device.hpp"
#include "fgr/parameters.hpp"
#include "fgr/program_cache.hpp"
#include "fgr/renderer.hpp"

namespace fgr {
namespace {

// The Sierpinski tetrahedron with corners (1,1,1), (-1,-1,1), (1,-1,-1), (-1,1,-1): four maps
// x -> (x + v) / 2, each with its own colour; the ball about the origin through the corners.
IfsScene sierpinski() {
    IfsScene ifs;
    ifs.id = "sierpinski-test";
    ifs.name = "Sierpinski test";
    const glm::dvec3 corners[4] = {{1, 1, 1}, {-1, -1, 1}, {1, -1, -1}, {-1, 1, -1}};
    const glm::vec3 colours[4] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.9f, 0.2f}, {0.2f, 0.2f, 0.9f},
                                  {0.9f, 0.9f, 0.2f}};
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
    ifs.cameras.push_back({"default", CameraView{{2.6, -4.1, 1.9}, {0.0, 0.0, 0.0}, {0, 0, 1}, 50}});
    ifs.lights.push_back(Light{});
    return ifs;
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
    const IfsScene ifs = sierpinski();
    const Scene scene = scene_of(ifs);
    const int width = 64, height = 48;
    const CameraView views[] = {ifs.cameras[0].view,
                                CameraView{{0.9, -1.3, 1.2}, {0.5, 0.4, 0.4}, {0, 0, 1}, 40}};
    for (const CameraView& view : views) {
        for (const int depth : {2, 6, 12}) {
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
                    SCOPED_TRACE(::testing::Message() << "depth " << depth << (in_double ? " double" : " float")
                                                      << " width " << packet);
                    const Frame frame = render(scene, request, packet, false, in_double);
                    long hits = 0, disagree = 0;
                    for (int y = 0; y < height; ++y) {
                        for (int x = 0; x < width; ++x) {
                            const glm::dvec3 dir(primary_ray_direction(basis, width, height,
                                                                       float(x), float(y)));
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

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

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

}  // namespace
}  // namespace fgr
