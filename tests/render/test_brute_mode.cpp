// SPDX-License-Identifier: Apache-2.0
// The brute-force mode (kernels/modes/fgr_mode_brute.cl): rendering from an inside test alone. Its
// depth agrees with the sphere tracer's on DE scenes, only comes closer over passes, and bisection
// halves its error per step; screen-space normals match DE normals, screen-space occlusion
// darkens creases; inside-only scenes render, from outside and inside the set, with no NaN; packet
// widths agree; and modes a scene cannot render in are refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <memory>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/program_cache.hpp"
#include "diagnostics/brute_accuracy.hpp"
#include "fgr/plugin.h"
#include "render/renderer.hpp"
#include "render_probes.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

class BruteModeTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        device_ = new ComputeDevice(open_device(-1));
        cache_ = new ProgramCache(std::filesystem::path());  // memory only: hermetic
    }
    static void TearDownTestSuite() {
        delete cache_;
        delete device_;
    }

    static std::unique_ptr<Renderer> renderer(const Scene& scene, RenderMode mode,
                                              uint64_t effects = 0, int packet_width = 0) {
        const int width = packet_width ? packet_width : preferred_packet_width(device_->info);
        return std::make_unique<Renderer>(*device_, *cache_, scene,
                                          KernelSwitches{width, effects, false, false, mode});
    }

    static FrameRequest request(const Scene& scene, int width, int height, int samples,
                                const std::vector<std::string>& assignments = {}) {
        FrameRequest result{width, height, scene.cameras.front().view, default_param_values(scene)};
        set_param_from_text(scene, result.params, "tone_map=clamp");
        for (const auto& assignment : assignments) {
            set_param_from_text(scene, result.params, assignment);
        }
        result.samples = samples;
        return result;
    }

    static ComputeDevice* device_;
    static ProgramCache* cache_;
};
ComputeDevice* BruteModeTest::device_ = nullptr;
ProgramCache* BruteModeTest::cache_ = nullptr;

bool all_finite(const Frame& frame) {
    for (float v : frame.linear) {
        if (!std::isfinite(v)) return false;
    }
    for (float v : frame.depth) {
        if (!std::isfinite(v)) return false;
    }
    return true;
}

// The distance along the ray through pixel (x, y)'s centre to the unit ball, or -1.
float ball_depth(const CameraView& view, int width, int height, int x, int y) {
    const CameraBasis basis = camera_basis(view);
    const glm::dvec3 dir(primary_ray_direction(basis, width, height, float(x), float(y)));
    const glm::dvec3 eye = basis.eye;
    const double b = glm::dot(eye, dir), c = glm::dot(eye, eye) - 1.0;
    const double discriminant = b * b - c;
    return discriminant < 0.0 ? -1.0f : static_cast<float>(-b - std::sqrt(discriminant));
}

// ---------------------------------------------------------------------------------------------
// Depth against the sphere tracer on DE scenes.

TEST_F(BruteModeTest, DepthAgreesWithTheSphereTracerOnDeScenes) {
    constexpr int kW = 200, kH = 150;
    for (const std::string file : {"mandelbulb.so", "menger.so"}) {
        SCOPED_TRACE(file);
        const Scene scene = test::built_scene(file);
        const Frame traced = renderer(scene, RenderMode::Shaded)->render(request(scene, kW, kH, 1));
        const Frame brute = renderer(scene, RenderMode::Brute)->render(request(scene, kW, kH, 32));
        ASSERT_GT(traced.hits, kW * kH / 10);
        const float angle = pixel_angle(camera_basis(scene.cameras.front().view), kW);
        const DepthAgreement a = depth_agreement(brute.depth, traced.depth, angle, 4.0f);
        RecordProperty("iou", std::to_string(a.iou()));
        RecordProperty("within_4_footprints", std::to_string(a.within_fraction()));
        EXPECT_GE(a.iou(), 0.97);
        EXPECT_GE(a.within_fraction(), 0.98);
        EXPECT_TRUE(all_finite(brute));
    }
}

// ---------------------------------------------------------------------------------------------
// Progressive passes.

TEST_F(BruteModeTest, DepthNeverIncreasesFromPassToPass) {
    constexpr int kW = 96, kH = 72, kPasses = 12;
    const Scene scene = test::built_scene("mandelbulb.so");
    auto brute = renderer(scene, RenderMode::Brute);
    // Few samples per pass, so that later passes still find closer hits.
    FrameRequest req = request(scene, kW, kH, 1, {"brute_samples=4", "brute_bisection=4"});
    std::vector<float> previous;
    long improved = 0, new_hits = 0;
    for (int pass = 0; pass < kPasses; ++pass) {
        req.first_sample = pass;
        const Frame frame = brute->render(req);
        ASSERT_EQ(frame.depth.size(), size_t(kW * kH));
        if (!previous.empty()) {
            for (size_t i = 0; i < previous.size(); ++i) {
                if (previous[i] < 0.0f) {
                    new_hits += frame.depth[i] >= 0.0f;
                    continue;
                }
                ASSERT_GE(frame.depth[i], 0.0f)
                    << "pixel " << i << " lost its hit in pass " << pass;
                ASSERT_LE(frame.depth[i], previous[i]) << "pixel " << i << " in pass " << pass;
                improved += frame.depth[i] < previous[i];
            }
        }
        previous = frame.depth;
    }
    // The passes do work: hits come closer and new ones appear.
    EXPECT_GT(improved, 100);
    EXPECT_GT(new_hits, 10);
    // The passes of one call give the image of the passes made one call at a time.
    const Frame whole =
        brute->render(request(scene, kW, kH, kPasses, {"brute_samples=4", "brute_bisection=4"}));
    EXPECT_EQ(whole.depth, previous);
}

TEST_F(BruteModeTest, BisectionHalvesTheDepthErrorPerStep) {
    constexpr int kW = 64, kH = 48;
    const Scene scene = test::inside_ball_scene();
    auto brute = renderer(scene, RenderMode::Brute);
    const CameraView view = scene.cameras.front().view;
    std::vector<double> errors;
    for (int steps = 0; steps <= 12; ++steps) {
        // One pass of 8 strata over [0, 6]: a bracket of 0.75 that bisection then halves.
        const Frame frame = brute->render(request(
            scene, kW, kH, 1,
            {"max_distance=6", "brute_samples=8", "brute_bisection=" + std::to_string(steps)}));
        double sum = 0.0;
        long count = 0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                const float exact = ball_depth(view, kW, kH, x, y);
                const float found = frame.depth[y * kW + x];
                if (exact < 0.0f || found < 0.0f) continue;
                // The depth kept is the solid end of the bracket: never in front of the surface.
                EXPECT_GE(found, exact - 1e-5f);
                sum += found - exact;
                ++count;
            }
        }
        ASSERT_GT(count, 500);
        errors.push_back(sum / double(count));
    }
    for (size_t k = 0; k + 1 < errors.size(); ++k) {
        const double ratio = errors[k + 1] / errors[k];
        RecordProperty("error_" + std::to_string(k), std::to_string(errors[k]));
        // The error is uniform over a bracket that each step halves: its mean halves too (a few
        // hundred pixels' mean, well within 0.4 .. 0.6).
        EXPECT_GT(ratio, 0.4) << "step " << k;
        EXPECT_LT(ratio, 0.6) << "step " << k;
    }
    EXPECT_LT(errors.back(), 0.75 / 4096.0);
}

// ---------------------------------------------------------------------------------------------
// Screen-space shading.

double degrees_between(glm::vec3 a, glm::vec3 b) {
    return glm::degrees(
        std::acos(std::clamp(double(glm::dot(glm::normalize(a), glm::normalize(b))), -1.0, 1.0)));
}

// The ball of radius 1 seen from 3 away fills most of the frame: its normals vary smoothly.
TEST_F(BruteModeTest, ScreenSpaceNormalsMatchDeNormalsOnSmoothSurfaces) {
    constexpr int kW = 160, kH = 120;
    Scene scene = test::sphere_scene();
    const FrameRequest req = request(scene, kW, kH, 8, {"radius=1"});
    const Frame frame = renderer(scene, RenderMode::Brute)->render(req);
    ASSERT_EQ(frame.normal.size(), size_t(kW * kH * 3));
    auto shaded = renderer(scene, RenderMode::Shaded);
    const CameraBasis basis = camera_basis(req.view);
    std::vector<glm::vec3> points, normals;
    for (int y = 2; y < kH - 2; ++y) {
        for (int x = 2; x < kW - 2; ++x) {
            // Away from the silhouette: every pixel within two has a hit.
            bool interior = true;
            for (int v = -2; v <= 2 && interior; ++v) {
                for (int u = -2; u <= 2; ++u) interior &= frame.depth[(y + v) * kW + x + u] >= 0.0f;
            }
            if (!interior) continue;
            const int i = y * kW + x;
            const glm::vec3 dir = primary_ray_direction(basis, kW, kH, float(x), float(y));
            points.push_back(glm::vec3(basis.eye) + dir * frame.depth[i]);
            normals.push_back(
                {frame.normal[i * 3], frame.normal[i * 3 + 1], frame.normal[i * 3 + 2]});
        }
    }
    ASSERT_GT(points.size(), 3000u);
    const std::vector<glm::vec3> de_normals = shaded->probe_normals(points, req.params, 1e-4f);
    std::vector<double> angles;
    for (size_t i = 0; i < points.size(); ++i) {
        angles.push_back(degrees_between(normals[i], de_normals[i]));
    }
    std::sort(angles.begin(), angles.end());
    const double worst = angles.back();
    RecordProperty("median_degrees", std::to_string(angles[angles.size() / 2]));
    RecordProperty("worst_degrees", std::to_string(worst));
    std::printf("normals: median %.4f, 99%% %.4f, worst %.4f degrees\n", angles[angles.size() / 2],
                angles[angles.size() * 99 / 100], worst);
    // Central differences of neighbours 0.02 apart are second-order accurate; what remains is
    // the DE surface's own tilt: it is taken where DE < k t (k the footprint per unit distance,
    // 0.0072 rad here), whose normal leans from the DE's gradient by up to k (0.4 degrees).
    EXPECT_LT(worst, 1.0);
}

glm::vec3 at(const std::vector<float>& rgb, int pixel) {
    return {rgb[pixel * 3], rgb[pixel * 3 + 1], rgb[pixel * 3 + 2]};
}

// A cube resting on a floor, lit by the ambient term alone (the one light has intensity 0): a
// pixel's colour is albedo * ambient * occlusion. As in the effects tests of the DE occlusions.
Scene brute_crease_scene() {
    Scene scene = test::inline_scene(R"(
real scene_de(vec3 p, PARAMS) {
    (void)fgr_params;
    real ground = sd_plane(p, v3_splat(0.0f, 0.0f, 1.0f), -0.5f);
    real cube = sd_box(op_translate(p, v3_splat(0.0f, 0.0f, -0.1f)), v3_splat(0.4f, 0.4f, 0.4f));
    return op_union(ground, cube);
}
)");
    CameraView& view = scene.cameras.front().view;
    view.position = {0.0f, -1.6f, 2.4f};
    view.target = {0.0f, 0.0f, -0.3f};
    scene.lights.front().intensity = 0.0f;
    return scene;
}

TEST_F(BruteModeTest, ScreenSpaceOcclusionDarkensACreaseMoreThanAnOpenFace) {
    constexpr int kW = 160, kH = 120;
    const Scene scene = brute_crease_scene();
    // A radius of about 12 pixels at the crease.
    const FrameRequest req = request(scene, kW, kH, 8, {"max_distance=8", "ao_radius=0.25"});
    const Frame plain = renderer(scene, RenderMode::Brute)->render(req);
    const Frame occluded =
        renderer(scene, RenderMode::Brute, FGR_EFFECT_AMBIENT_OCCLUSION)->render(req);
    const CameraBasis basis = camera_basis(req.view);
    std::vector<int> crease, open;
    for (int y = 0; y < kH; ++y) {
        for (int x = 0; x < kW; ++x) {
            const int i = y * kW + x;
            if (plain.depth[i] < 0.0f) continue;
            const glm::vec3 p =
                glm::vec3(basis.eye) +
                primary_ray_direction(basis, kW, kH, float(x), float(y)) * plain.depth[i];
            // The DE's surface is taken a footprint (about 0.02 here) off the solid.
            const bool floor = std::abs(p.z + 0.5f) < 0.05f;
            // Floor just in front of the cube's front face (y = -0.4), and the middle of its top.
            if (floor && p.y > -0.47f && p.y < -0.43f && std::abs(p.x) < 0.3f) crease.push_back(i);
            if (std::abs(p.z - 0.3f) < 0.05f && std::abs(p.x) < 0.25f && std::abs(p.y) < 0.25f) {
                open.push_back(i);
            }
        }
    }
    ASSERT_GT(crease.size(), 20u);
    ASSERT_GT(open.size(), 200u);
    const auto kept = [&](const std::vector<int>& pixels) {
        double sum = 0.0;
        for (int i : pixels) sum += at(occluded.linear, i).g / at(plain.linear, i).g;
        return sum / double(pixels.size());
    };
    const double crease_kept = kept(crease), open_kept = kept(open);
    RecordProperty("crease_kept", std::to_string(crease_kept));
    RecordProperty("open_kept", std::to_string(open_kept));
    EXPECT_GT(open_kept, 0.95);
    EXPECT_LT(crease_kept, open_kept - 0.1);
}

// ---------------------------------------------------------------------------------------------
// Scenes without a DE.

std::vector<Scene> inside_only_scenes() {
    std::vector<Scene> scenes;
    for (const Scene& scene : test::all_scenes()) {
        if (scene.inside_only()) scenes.push_back(scene);
    }
    return scenes;
}

TEST_F(BruteModeTest, InsideOnlyScenesRenderEveryCameraWithoutNaN) {
    const std::vector<Scene> scenes = inside_only_scenes();
    ASSERT_GE(scenes.size(), 2u);
    ASSERT_TRUE(std::any_of(scenes.begin(), scenes.end(),
                            [](const Scene& s) { return s.id == "stereographic-julia"; }));
    constexpr int kW = 96, kH = 72;
    for (const Scene& scene : scenes) {
        SCOPED_TRACE(scene.id);
        EXPECT_EQ(scene.default_mode, RenderMode::Brute);
        EXPECT_FALSE(scene.has_distance_estimator());
        auto brute = renderer(scene, RenderMode::Brute, scene.effects);
        for (const NamedCamera& camera : scene.cameras) {
            SCOPED_TRACE(camera.name);
            FrameRequest req = request(scene, kW, kH, 4);
            req.view = camera.view;
            const Frame frame = brute->render(req);
            EXPECT_TRUE(all_finite(frame));
            // Non-trivial: the set covers part of the frame, not none or all of it.
            EXPECT_GT(frame.hits, kW * kH / 20);
            EXPECT_LT(frame.hits, kW * kH);
        }
    }
}

TEST_F(BruteModeTest, ACameraInsideTheSetSeesItsCavitiesWithoutNaN) {
    // And a DE scene whose DE is negative inside (an escape-time DE is negative only in a dust
    // of the set's interior, so a camera just past its surface is not inside).
    std::vector<Scene> scenes = inside_only_scenes();
    scenes.push_back(test::built_scene("menger.so"));
    constexpr int kW = 64, kH = 48;
    for (const Scene& scene : scenes) {
        SCOPED_TRACE(scene.id);
        auto brute = renderer(scene, RenderMode::Brute, scene.effects);
        // Move the camera along its centre ray to just past the surface it sees there.
        const FrameRequest outside = request(scene, kW, kH, 8);
        const Frame seen = brute->render(outside);
        const float centre = seen.depth[(kH / 2) * kW + kW / 2];
        ASSERT_GT(centre, 0.0f);
        const CameraBasis basis = camera_basis(outside.view);
        const float pixel = centre * pixel_angle(basis, kW);
        CameraView inside = outside.view;
        const glm::dvec3 step = glm::dvec3(basis.forward) * double(centre + 2.0f * pixel);
        inside.position += step;
        inside.target += step;
        ASSERT_FALSE(test::eye_inside(*brute, scene, outside.view));
        ASSERT_TRUE(test::eye_inside(*brute, scene, inside));
        for (const char* solid : {"auto", "set", "complement"}) {
            SCOPED_TRACE(solid);
            FrameRequest req = request(scene, kW, kH, 4, {std::string("brute_solid=") + solid});
            req.view = inside;
            const Frame frame = brute->render(req);
            EXPECT_TRUE(all_finite(frame));
            if (std::string(solid) == "set") {
                // Inside the solid every ray starts in it: the whole frame is the cut at near.
                EXPECT_EQ(frame.hits, kW * kH);
            } else {
                // "auto" and "complement" take the set's complement as solid from in here: the
                // walls of the cavity the camera sits in.
                EXPECT_GT(frame.hits, kW * kH / 2);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Packet widths, every DE scene, refusals.

TEST_F(BruteModeTest, PacketWidthsAgreePerPixel) {
    constexpr int kW = 64, kH = 48;
    std::vector<Scene> scenes = inside_only_scenes();
    scenes.push_back(test::built_scene("mandelbulb.so"));
    for (const Scene& scene : scenes) {
        SCOPED_TRACE(scene.id);
        const FrameRequest req = request(scene, kW, kH, 4);
        const Frame reference = renderer(scene, RenderMode::Brute, scene.effects, 1)->render(req);
        for (int width : {4, 8, 16}) {
            SCOPED_TRACE(width);
            const Frame frame =
                renderer(scene, RenderMode::Brute, scene.effects, width)->render(req);
            long differing = 0;
            for (size_t i = 0; i < frame.depth.size(); ++i) {
                const float a = frame.depth[i], b = reference.depth[i];
                const bool same = (a < 0.0f) == (b < 0.0f) &&
                                  std::abs(a - b) <= 1e-5f * std::max(1.0f, std::abs(b));
                differing += !same;
            }
            // The same random strata in every width, the same tests: the same hits, to the
            // rounding of vector against scalar maths (measured: no pixel differs), and images
            // within one 8-bit level.
            EXPECT_EQ(differing, 0);
            int worst_level = 0;
            for (size_t i = 0; i < frame.image.rgb.size(); ++i) {
                worst_level = std::max(
                    worst_level, std::abs(int(frame.image.rgb[i]) - int(reference.image.rgb[i])));
            }
            EXPECT_LE(worst_level, 1);
        }
    }
}

TEST_F(BruteModeTest, EveryDeSceneRendersInTheBruteMode) {
    constexpr int kW = 64, kH = 48;
    for (const Scene& scene : test::all_scenes()) {
        if (!scene.has_distance_estimator()) continue;
        SCOPED_TRACE(scene.id);
        const FrameRequest req = request(scene, kW, kH, 8);
        const Frame traced = renderer(scene, RenderMode::Shaded)->render(req);
        const Frame brute = renderer(scene, RenderMode::Brute, scene.effects)->render(req);
        EXPECT_TRUE(all_finite(brute));
        EXPECT_GT(brute.hits, 0);
        // The same surface: within 5% of the sphere tracer's hits.
        EXPECT_NEAR(double(brute.hits), double(traced.hits), 0.05 * double(traced.hits) + 8.0);
    }
}

TEST_F(BruteModeTest, ModesAScenesCannotRenderInAreRefused) {
    const Scene ball = test::inside_ball_scene();
    for (RenderMode mode : {RenderMode::Shaded, RenderMode::Path}) {
        try {
            renderer(ball, mode);
            ADD_FAILURE() << "an inside-only scene rendered in " << render_mode_name(mode);
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find("--mode brute"), std::string::npos)
                << error.what();
        }
    }
    for (const Scene& scene : test::all_scenes()) {
        if (!scene.ifs) continue;
        SCOPED_TRACE(scene.id);
        EXPECT_THROW(renderer(scene, RenderMode::Brute), std::invalid_argument);
    }
    auto brute = renderer(ball, RenderMode::Brute);
    const glm::vec3 origin(0.0f);
    EXPECT_THROW(brute->probe_de(std::span(&origin, 1), default_param_values(ball)),
                 std::logic_error);
}

TEST(InsideOnlyDeclaration, OnlyAnUncommentedDefineCounts) {
    const auto declared = [](const std::string& source) {
        Scene scene;
        scene.source = source;
        return scene.inside_only();
    };
    EXPECT_TRUE(declared("#define FGR_SCENE_INSIDE_ONLY\n"));
    EXPECT_TRUE(declared("real x;\n  #  define FGR_SCENE_INSIDE_ONLY 1\n"));
    EXPECT_FALSE(declared("// #define FGR_SCENE_INSIDE_ONLY\n"));
    EXPECT_FALSE(declared("/* a scene could say\n#define FGR_SCENE_INSIDE_ONLY\n*/\n"));
    EXPECT_FALSE(declared("#define FGR_SCENE_INSIDE_ONLY_NOT\n"));
    EXPECT_FALSE(declared("real scene_de(vec3 p, PARAMS); /* FGR_SCENE_INSIDE_ONLY */\n"));
}

}  // namespace
}  // namespace fgr
