// SPDX-License-Identifier: Apache-2.0
// A camera on the surface (DE <= 0 at the eye): its rays march out of the surface instead of
// spending max_steps at the eye (kernels/geometry/fgr_march.cl). The Mandelbox's fixed point, the
// origin, has DE exactly 0; a camera there used to render blank with every ray out of steps.

#include <gtest/gtest.h>

#include <filesystem>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

constexpr int kEyeOnSurfaceWidth = 48, kEyeOnSurfaceHeight = 32;

Frame render_from(const Scene& scene, const CameraView& view, RenderMode mode, bool stats) {
    static const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    KernelSwitches switches{preferred_packet_width(device.info), scene.effects, stats};
    switches.mode = mode;
    Renderer renderer(device, cache, scene, switches);
    FrameRequest request;
    request.width = kEyeOnSurfaceWidth;
    request.height = kEyeOnSurfaceHeight;
    request.view = view;
    request.params = default_param_values(scene);
    if (mode == RenderMode::Path) request.samples = 2;
    return renderer.render(request);
}

CameraView from_origin() {
    CameraView view;
    view.position = {0.0, 0.0, 0.0};
    view.target = {1.0, -0.6, 0.4};
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = 70.0f;
    return view;
}

// Shaded: the origin is deep in the Mandelbox's solid interior (the DE is below 1e-6 for several
// units around it, exactly 0 at the fixed point), so the rays step off the eye and then meet the
// solid within a few steps: nearly every pixel hits and no ray spends max_steps at the eye. Before,
// the DE of 0 at the eye gave steps of 0 and no footprint: every ray ran out of steps and nothing
// was hit (measured after the fix: 1532 of 1536 hits, 4.4 steps a ray, 4 rays out of steps).
TEST(EyeOnSurface, MandelboxFromTheOriginRendersShadedWithoutRunningOutOfSteps) {
    const Scene mandelbox = test::built_scene("mandelbox.so");
    const Frame frame = render_from(mandelbox, from_origin(), RenderMode::Shaded, true);
    ASSERT_TRUE(frame.stats.has_value());
    const MarchStats& stats = *frame.stats;
    const int max_steps =
        static_cast<int>(param_value(mandelbox, default_param_values(mandelbox), "max_steps"));
    EXPECT_GT(frame.hits, long{kEyeOnSurfaceWidth * kEyeOnSurfaceHeight} * 9 / 10)
        << "the origin is inside the solid";
    EXPECT_LT(stats.mean_steps, 0.5 * max_steps);
    EXPECT_LE(stats.out_of_steps, long{kEyeOnSurfaceWidth * kEyeOnSurfaceHeight} / 100);
}

// The path mode's camera rays march the same way.
TEST(EyeOnSurface, MandelboxFromTheOriginRendersInThePathMode) {
    const Scene mandelbox = test::built_scene("mandelbox.so");
    const Frame frame = render_from(mandelbox, from_origin(), RenderMode::Path, false);
    EXPECT_GT(frame.hits, long{kEyeOnSurfaceWidth * kEyeOnSurfaceHeight} / 2);
}

// A camera just inside a sphere (DE -0.01 at the eye) looking at its centre: every ray starts in
// the solid. They march out of it (through the sphere, cut away at the eye as a near clip plane
// would cut it) and leave the scene. Before, every ray "hit" at the eye itself (DE < 0 is below
// any footprint), a frame of nothing but the eye.
TEST(EyeOnSurface, CameraInsideASphereLooksOutThroughIt) {
    const Scene sphere = test::sphere_scene();  // radius 0.4
    CameraView view;
    view.position = {0.0, -0.39, 0.0};
    view.target = {0.0, 0.0, 0.0};
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = 60.0f;
    const Frame frame = render_from(sphere, view, RenderMode::Shaded, true);
    ASSERT_TRUE(frame.stats.has_value());
    EXPECT_EQ(frame.stats->out_of_steps, 0);
    EXPECT_EQ(frame.hits, 0) << "the far side is left, not approached: it stops no ray";
    EXPECT_LT(frame.stats->mean_steps,
              0.25 * param_value(sphere, default_param_values(sphere), "max_steps"));
}

}  // namespace
}  // namespace fgr
