// SPDX-License-Identifier: Apache-2.0
// The cone-marched depth prepass (kernels/geometry/fgr_prepass.cl): camera rays started where their
// block's cone stopped must find what rays started at the eye find. Every scene the prepass
// serves, in every projection and in the path mode, renders with and without it: hit or miss
// agrees on all but 0.1% of the pixels, and where both hit the depths lie within the hit
// footprint's band round the surface of each other (see compare) for all but 0.5% of them.
//
// Why 0.5%: a march that starts anywhere but the eye samples the ray at other points, and where
// a ray passes a fractal's filaments within a footprint the hit rule then stops it elsewhere. A
// cone twice as wide as its block needs (safe, merely starting earlier) disagrees as often as the
// real one: 0.08-0.45% of depths on these views at 240x180, 0.01-0.06% of hits. An unsafe cone
// (narrowed on purpose) must fail the comparison by far, and tiles must render exactly the pixels
// of the whole image.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "camera/projection.hpp"
#include "device_suite.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr::test {
namespace {

constexpr int kPrepassWidth = 240;
constexpr int kPrepassHeight = 180;
// Of all pixels: where the hit/miss may differ. Of the pixels both hit: where the depth may lie
// outside the footprint's band.
constexpr double kMaxHitDisagreement = 0.001;
constexpr double kMaxDepthDisagreement = 0.005;

const Scene& scene_named(const std::string& id) {
    for (const Scene& scene : all_scenes()) {
        if (scene.id == id) return scene;
    }
    throw std::runtime_error("no scene " + id);
}

struct Agreement {
    long pixels = 0;
    long hit_mismatches = 0;  // hit in one render, missed in the other
    long both_hit = 0;
    long depth_outliers = 0;  // both hit, depths further apart than the footprint
    double hit_mismatch_fraction() const { return double(hit_mismatches) / double(pixels); }
    double depth_outlier_fraction() const {
        return both_hit ? double(depth_outliers) / double(both_hit) : 0.0;
    }
    std::string describe() const {
        return fmt::format(
            "{} of {} pixels hit in one render only; {} of {} depths differ by more "
            "than a footprint",
            hit_mismatches, pixels, depth_outliers, both_hit);
    }
};

// The hit rule stops a march anywhere the DE is below the footprint (per unit distance: the
// scene's hit_threshold times the pixel angle, so footprint * depth at the hit): a band that
// far from the surface, which a ray at angle theta to the surface normal crosses over
// footprint * depth / cos(theta) of its length. Two marches of the same ray agree when their
// depths lie within that band (cos taken no smaller than 0.05: at most 20 footprints for rays
// that graze the surface), the plain render's shading normal giving theta.
Agreement compare(const Frame& plain, const Frame& started, const FrameRequest& request,
                  float footprint) {
    const CameraModel model = camera_model(request.view, request.projection);
    Agreement agreement;
    agreement.pixels = static_cast<long>(plain.depth.size());
    for (size_t i = 0; i < plain.depth.size(); ++i) {
        const float a = plain.depth[i], b = started.depth[i];
        if ((a >= 0.0f) != (b >= 0.0f)) {
            ++agreement.hit_mismatches;
            continue;
        }
        if (a < 0.0f) continue;
        ++agreement.both_hit;
        const auto x = static_cast<float>(i % static_cast<size_t>(request.width)) + 0.5f;
        const auto y = static_cast<float>(i / static_cast<size_t>(request.width)) + 0.5f;
        const glm::vec3 dir =
            projected_ray_direction(model, request.width, request.height, x, y).value();
        const glm::vec3 normal(plain.normal[i * 3], plain.normal[i * 3 + 1],
                               plain.normal[i * 3 + 2]);
        const float cosine = std::max(std::fabs(glm::dot(normal, dir)), 0.05f);
        if (std::fabs(a - b) > footprint * a / cosine) ++agreement.depth_outliers;
    }
    return agreement;
}

class PrepassTest : public DeviceSuite<::testing::TestWithParam<std::string>> {
protected:
    struct Pair {
        Frame plain;
        Frame started;
        float footprint = 0.0f;
    };

    // The scene's default view and mode rendered without and with the prepass.
    Pair render_pair(const Scene& scene, FrameRequest request, float cone_scale = 1.0f,
                     RenderMode mode = RenderMode::Shaded, int packet_width = 16) {
        // With layers: the normals compare() needs.
        Renderer renderer(*device_, *cache_, scene,
                          KernelSwitches{packet_width, scene.effects, false, false, mode, true});
        Pair pair;
        request.prepass.enabled = false;
        pair.plain = renderer.render(request);
        request.prepass.enabled = true;
        request.prepass.cone_scale = cone_scale;
        pair.started = renderer.render(request);
        const CameraModel model = camera_model(request.view, request.projection);
        pair.footprint = param_value(scene, request.params, "hit_threshold") *
                         pixel_angle(model, request.width, request.height);
        return pair;
    }

    static FrameRequest default_request(const Scene& scene) {
        FrameRequest request;
        request.width = kPrepassWidth;
        request.height = kPrepassHeight;
        request.view = scene.cameras.front().view;
        request.params = default_param_values(scene);
        return request;
    }
};

// Every scene with a DE and default effects the prepass serves: the prepass is on by default for
// all of them.
TEST_P(PrepassTest, StartedRaysFindWhatRaysFromTheEyeFind) {
    const Scene& scene = scene_named(GetParam());
    const FrameRequest request = default_request(scene);
    const Pair pair = render_pair(scene, request);
    const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
    SCOPED_TRACE(agreement.describe());
    EXPECT_LE(agreement.hit_mismatch_fraction(), kMaxHitDisagreement);
    EXPECT_LE(agreement.depth_outlier_fraction(), kMaxDepthDisagreement);
    EXPECT_GT(agreement.both_hit, agreement.pixels / 20);  // the view shows the surface
}

INSTANTIATE_TEST_SUITE_P(Scenes, PrepassTest,
                         ::testing::Values("mandelbulb", "julia", "mandelbox", "menger",
                                           "sierpinski", "sdf-gallery", "benchmark"),
                         [](const auto& param_info) {
                             std::string name = param_info.param;
                             for (char& c : name) {
                                 if (c == '-') c = '_';
                             }
                             return name;
                         });

class PrepassViews : public PrepassTest {};

// The cones follow each projection's rays: panoramas bend them across a block, a stereo pair's
// blocks on the seam hold two eyes.
TEST_F(PrepassViews, EveryProjectionAgrees) {
    const Scene& scene = scene_named("mandelbulb");
    for (ProjectionKind kind : {ProjectionKind::Equirectangular, ProjectionKind::Fisheye,
                                ProjectionKind::StereoSideBySide}) {
        FrameRequest request = default_request(scene);
        request.projection.kind = kind;
        const Pair pair = render_pair(scene, request);
        const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
        SCOPED_TRACE(
            fmt::format("projection {}: {}", static_cast<int>(kind), agreement.describe()));
        EXPECT_LE(agreement.hit_mismatch_fraction(), kMaxHitDisagreement);
        EXPECT_LE(agreement.depth_outlier_fraction(), kMaxDepthDisagreement);
        EXPECT_GT(agreement.both_hit, agreement.pixels / 50);
    }
}

// Every packet width runs the prepass (one cone per lane; width 1 is the layout GPUs get, run
// here so it cannot rot) and starts its rays from it alike.
TEST_F(PrepassViews, EveryPacketWidthAgrees) {
    const Scene& scene = scene_named("mandelbulb");
    for (int width : {1, 4, 8}) {
        const FrameRequest request = default_request(scene);
        const Pair pair = render_pair(scene, request, 1.0f, RenderMode::Shaded, width);
        const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
        SCOPED_TRACE(fmt::format("{} rays per work-item: {}", width, agreement.describe()));
        EXPECT_LE(agreement.hit_mismatch_fraction(), kMaxHitDisagreement);
        EXPECT_LE(agreement.depth_outlier_fraction(), kMaxDepthDisagreement);
        EXPECT_GT(agreement.both_hit, agreement.pixels / 20);
    }
}

// The path tracer's camera rays start from the prepass too: its first hits (the depth plane)
// agree as the shaded mode's do.
TEST_F(PrepassViews, PathModeFirstHitsAgree) {
    const Scene& scene = scene_named("mandelbulb");
    FrameRequest request = default_request(scene);
    const Pair pair = render_pair(scene, request, 1.0f, RenderMode::Path);
    const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
    SCOPED_TRACE(agreement.describe());
    EXPECT_LE(agreement.hit_mismatch_fraction(), kMaxHitDisagreement);
    EXPECT_LE(agreement.depth_outlier_fraction(), kMaxDepthDisagreement);
}

// A cone narrower than its block needs starts the block's outer rays past surface they would
// have hit. One of no width (the block's centre ray alone) is caught on every scene, on hits or
// depths by many times the limits; one a tenth as wide as it should be (0.8 pixels for a block of
// 8) on the Sierpinski tetrahedron's thin edges.
TEST_F(PrepassViews, AConeTooNarrowForItsBlockIsCaught) {
    const auto caught = [](const Agreement& agreement) {
        return agreement.hit_mismatch_fraction() > 2 * kMaxHitDisagreement ||
               agreement.depth_outlier_fraction() > 2 * kMaxDepthDisagreement;
    };
    for (const char* id : {"mandelbulb", "sierpinski", "sdf-gallery", "benchmark"}) {
        const Scene& scene = scene_named(id);
        const FrameRequest request = default_request(scene);
        const Pair pair = render_pair(scene, request, 0.0f);
        const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
        EXPECT_TRUE(caught(agreement)) << id << ": " << agreement.describe();
    }
    const Scene& scene = scene_named("sierpinski");
    const FrameRequest request = default_request(scene);
    const Pair pair = render_pair(scene, request, 0.1f);
    const Agreement agreement = compare(pair.plain, pair.started, request, pair.footprint);
    EXPECT_TRUE(caught(agreement)) << agreement.describe();
}

// Blocks lie on the whole image's grid, so a region (a tile of a tiled still) starts each pixel's
// rays where the whole image does: the same pixels, bit for bit, at an offset off the block grid.
TEST_F(PrepassViews, RegionsRenderTheWholeImagesPixels) {
    const Scene& scene = scene_named("mandelbulb");
    Renderer renderer(*device_, *cache_, scene,
                      KernelSwitches{16, scene.effects, false, false, RenderMode::Shaded});
    const FrameRequest whole = default_request(scene);
    const Frame frame = renderer.render(whole);
    FrameRequest part = whole;
    part.region = {37, 21, 61, 45};
    const Frame region = renderer.render(part);
    long differing = 0;
    for (int y = 0; y < part.region.height; ++y) {
        for (int x = 0; x < part.region.width; ++x) {
            const size_t in_region = static_cast<size_t>(y) * part.region.width + x;
            const size_t in_whole =
                static_cast<size_t>(y + part.region.y) * whole.width + x + part.region.x;
            differing += region.depth[in_region] != frame.depth[in_whole];
            for (int c = 0; c < 3; ++c) {
                differing +=
                    region.image.rgb[in_region * 3 + c] != frame.image.rgb[in_whole * 3 + c];
            }
        }
    }
    EXPECT_EQ(differing, 0);
}

// The prepass does the work it claims: fewer DE evaluations per pixel in all (cones included),
// and it counts its cones.
TEST_F(PrepassViews, TheStatsCountTheConesAndFewerEvaluations) {
    const Scene& scene = scene_named("mandelbulb");
    Renderer renderer(*device_, *cache_, scene,
                      KernelSwitches{16, scene.effects, true, false, RenderMode::Shaded});
    FrameRequest request = default_request(scene);
    request.prepass.enabled = false;
    const Frame plain = renderer.render(request);
    request.prepass.enabled = true;
    const Frame started = renderer.render(request);
    ASSERT_TRUE(plain.stats && started.stats);
    EXPECT_EQ(plain.stats->prepass_de_evaluations, 0);
    // One cone per 8x8 block takes at least one step.
    EXPECT_GE(started.stats->prepass_de_evaluations,
              long{(kPrepassWidth / 8) * (kPrepassHeight / 8)});
    EXPECT_LT(started.stats->de_evaluations, plain.stats->de_evaluations * 17 / 20);
}

}  // namespace
}  // namespace fgr::test
