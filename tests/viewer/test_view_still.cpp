// SPDX-License-Identifier: Apache-2.0
// The viewer's view as a view file and the still of a view (viewer/view_still.hpp), without a
// window or a device: the view of the viewer's state keeps the state through the file, and the
// still the viewer renders a view with is the one `fgr render` makes of that view (the same
// request, settings and output, and the same view saved again), in the shaded mode and in the
// path tracer's with each kind of environment; a thumbnail is the image shrunk by boxes; saved
// files never take a name twice.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli/commands.hpp"
#include "cli/view_options.hpp"
#include "scene/effects.hpp"
#include "scene/parameters.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"
#include "viewer/view_still.hpp"

namespace fgr::viewer {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const Scene> mandelbulb() {
    static const auto scene = std::make_shared<const Scene>(test::built_scene("mandelbulb.so"));
    return scene;
}

// A state away from the defaults in everything a view holds.
ViewState shaded_state() {
    ViewState state;
    state.scene = mandelbulb();
    const Scene& scene = *state.scene;
    state.effects = apply_effect_changes(scene.effects, "+shadows,+fog,-ambient_occlusion");
    state.view =
        CameraView{{0.3, -2.2, 0.9000000000000001}, {0.0, 1e-9, 0.1}, {0.0f, 0.1f, 1.0f}, 50.5f};
    state.projection.kind = ProjectionKind::Fisheye;
    state.projection.fisheye_fov_degrees = 200.0f;
    state.params = default_param_values(scene);
    set_param_from_text(scene, state.params, "power=7.25");
    set_param_from_text(scene, state.params, "iterations=9");
    state.width = 48;
    state.height = 32;
    state.precision = Precision::Double;
    state.mode = RenderMode::Shaded;
    return state;
}

ViewState path_state() {
    ViewState state = shaded_state();
    state.mode = RenderMode::Path;
    state.projection = Projection{};
    state.path.max_bounces = 3;
    state.path.roulette_depth = 2;
    state.path.radiance_clamp = 4.0f;
    state.path.mis = false;
    state.path.scene_lights = false;
    state.path.seed = 5;
    return state;
}

// The path settings but their environment, which compares by identity.
PathSettings without_environment(PathSettings settings) {
    settings.environment = nullptr;
    return settings;
}

void expect_same_request(const FrameRequest& a, const FrameRequest& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.view, b.view);
    EXPECT_EQ(a.params, b.params);
    EXPECT_EQ(a.samples, b.samples);
    EXPECT_EQ(a.first_sample, b.first_sample);
    EXPECT_EQ(a.projection, b.projection);
    EXPECT_EQ(a.prepass.enabled, b.prepass.enabled);
    EXPECT_EQ(a.prepass.cone_scale, b.prepass.cone_scale);
    EXPECT_EQ(without_environment(a.path), without_environment(b.path));
    ASSERT_EQ(a.path.environment == nullptr, b.path.environment == nullptr);
    if (a.path.environment) {
        EXPECT_EQ(a.path.environment->description, b.path.environment->description);
        EXPECT_EQ(a.path.environment->tables.data, b.path.environment->tables.data);
        EXPECT_EQ(a.path.environment->rotation_degrees, b.path.environment->rotation_degrees);
        EXPECT_EQ(a.path.environment->intensity, b.path.environment->intensity);
        ASSERT_EQ(a.path.environment->sun.has_value(), b.path.environment->sun.has_value());
        if (a.path.environment->sun) {
            EXPECT_EQ(a.path.environment->sun->direction, b.path.environment->sun->direction);
        }
    }
}

// The view of `state` keeps it through the file, and `fgr render VIEW` (apply_view, then the
// request and still job it makes of the options) renders the view as the viewer does.
void expect_fgr_render_renders_the_view_alike(const ViewState& state,
                                              const EnvironmentChoice& environment) {
    const Scene& scene = *state.scene;
    const ViewFile view = view_of_state(state, environment, 3);
    EXPECT_EQ(parse_view_file(view_file_text(view)), view) << view_file_text(view);

    const ViewStill still = still_of_view(scene, view, 0);
    EXPECT_EQ(still.request.width, state.width);
    EXPECT_EQ(still.request.height, state.height);
    EXPECT_EQ(still.request.view, state.view);
    EXPECT_EQ(still.request.params, state.params);
    EXPECT_EQ(still.request.projection.kind, state.projection.kind);
    EXPECT_EQ(still.request.samples, 3);
    EXPECT_EQ(still.settings.effects, state.effects);
    EXPECT_EQ(still.settings.mode, state.mode);
    EXPECT_EQ(still.settings.precision, state.precision);
    if (state.mode == RenderMode::Path) {
        EXPECT_EQ(without_environment(still.request.path), without_environment(state.path));
        ASSERT_NE(still.request.path.environment, nullptr) << "the environment is not prepared";
    }
    EXPECT_EQ(still.output.embedded_view, view_file_text(view));

    RenderOptions options;
    options.output = "still.png";
    apply_view(options, view);
    FrameRequest request = scene_request(scene, options);
    request.view = overridden_view(scene.cameras.front().view, options.view_override);
    const StillJob job = still_job(scene, request, options);
    expect_same_request(still.request, job.request);
    EXPECT_EQ(still.settings.packet_width, job.settings.packet_width);
    EXPECT_EQ(still.settings.effects, job.settings.effects);
    EXPECT_EQ(still.settings.stats, job.settings.stats);
    EXPECT_EQ(still.settings.precision, job.settings.precision);
    EXPECT_EQ(still.settings.mode, job.settings.mode);
    EXPECT_EQ(still.settings.aovs, job.settings.aovs);
    EXPECT_EQ(still.output.bit_depth, options.bit_depth);
    EXPECT_EQ(still.output.alpha, options.alpha);
    const DisplayTransform display = display_transform(scene, job.request.params);
    EXPECT_EQ(still.output.display.exposure, display.exposure);
    EXPECT_EQ(still.output.display.tone_map, display.tone_map);
    // And the view `fgr render` would save (and embed in its image) is the viewer's.
    EXPECT_EQ(view_of_render(scene, request, options), view);
}

TEST(ViewerViewFile, FgrRenderRendersTheShadedViewAsTheViewerDoes) {
    expect_fgr_render_renders_the_view_alike(shaded_state(), EnvironmentChoice{});
}

TEST(ViewerViewFile, FgrRenderRendersThePathTracedViewAsTheViewerDoes) {
    EnvironmentChoice studio;
    studio.kind = EnvironmentKind::Studio;
    studio.rotation_degrees = 30.0f;
    studio.intensity = 0.75f;
    EnvironmentChoice sky;
    sky.sky.turbidity = 4.5f;
    sky.sun_from_scene = false;
    sky.sky.sun_elevation_degrees = 20.0f;
    sky.sky.sun_azimuth_degrees = 100.0f;
    EnvironmentChoice uniform;
    uniform.kind = EnvironmentKind::Uniform;
    uniform.radiance = {0.5f, 0.25f, 1.0f / 3.0f};
    for (const EnvironmentChoice& environment : {EnvironmentChoice{}, studio, sky, uniform}) {
        SCOPED_TRACE(environment_argument(environment));
        expect_fgr_render_renders_the_view_alike(path_state(), environment);
    }
}

// Under a scene's own environment (the user chose none) the view names that one, and `fgr render`
// renders it so; one the user chose wins over it.
TEST(ViewerViewFile, AViewUnderTheScenesOwnEnvironmentNamesIt) {
    Scene own = *mandelbulb();
    own.environment = "uniform:0.5";
    ViewState state = path_state();
    state.scene = std::make_shared<const Scene>(own);
    EXPECT_EQ(view_of_state(state, EnvironmentChoice{}, 1).path->environment, "uniform:0.5");
    expect_fgr_render_renders_the_view_alike(state, EnvironmentChoice{});
    EnvironmentChoice chosen;
    chosen.kind = EnvironmentKind::Studio;
    chosen.given = true;
    EXPECT_EQ(view_of_state(state, chosen, 1).path->environment, "studio");
}

TEST(ViewerViewFile, ProjectionKeepsOnlyTheSettingsOfItsKind) {
    ViewState state = shaded_state();
    state.projection.kind = ProjectionKind::Pinhole;  // the fisheye's angle stays behind
    state.projection.eye_separation = 0.25;
    EXPECT_EQ(view_of_state(state, {}, 1).projection, Projection{});
    state.projection.kind = ProjectionKind::StereoTopBottom;
    const Projection stereo = view_of_state(state, {}, 1).projection;
    EXPECT_EQ(stereo.eye_separation, 0.25);
    EXPECT_EQ(stereo.fisheye_fov_degrees, Projection{}.fisheye_fov_degrees);
}

TEST(ViewerViewFile, AViewTheSceneCannotTakeIsOneLine) {
    ViewFile view = view_of_state(shaded_state(), {}, 1);
    view.parameters.push_back({"no_such_parameter", ViewParameter::Kind::Number, "1"});
    EXPECT_THROW(still_of_view(*mandelbulb(), view, 0), std::exception);
    view = view_of_state(path_state(), {}, 1);
    view.path->environment = "/no/such/map.hdr";
    try {
        still_of_view(*mandelbulb(), view, 0);
        ADD_FAILURE() << "a missing environment map rendered";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("/no/such/map.hdr"), std::string::npos)
            << error.what();
        EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << error.what();
    }
}

TEST(ViewerViewFile, ThumbnailIsTheImageShrunkByBoxes) {
    // 4 x 2 pixels, each channel its own ramp: shrunk to 2 x 1, each pixel is the mean of a 2 x 2
    // box (rounded to nearest).
    Image8 image{4, 2, {}, {}};
    for (int i = 0; i < 4 * 2 * 3; ++i) image.rgb.push_back(static_cast<uint8_t>(i * 10));
    const Image8 small = shrunk_image(image, 2);
    ASSERT_EQ(small.width, 2);
    ASSERT_EQ(small.height, 1);
    // Pixel 0 covers pixels 0, 1, 4, 5; its red is the mean of 0, 30, 120, 150.
    EXPECT_EQ(small.rgb[0], 75);
    EXPECT_EQ(small.rgb[1], 85);
    EXPECT_EQ(small.rgb[3], 135);  // pixels 2, 3, 6, 7: 60, 90, 180, 210
    // Narrower images are kept; odd sizes keep their aspect, at least a pixel high.
    EXPECT_EQ(shrunk_image(image, 8).rgb, image.rgb);
    Image8 wide{640, 3, std::vector<uint8_t>(640 * 3 * 3, 200), {}};
    const Image8 strip = shrunk_image(wide, kViewThumbnailWidth);
    EXPECT_EQ(strip.width, kViewThumbnailWidth);
    EXPECT_EQ(strip.height, 1);
    EXPECT_EQ(strip.rgb, std::vector<uint8_t>(kViewThumbnailWidth * 3, 200));
}

TEST(ViewerViewFile, SavedFilesNeverTakeANameTwice) {
    test::TempDir dir("fgr_view_names");
    std::set<fs::path> taken;
    const fs::path first = unused_file(dir.path(), "fgr-x-1", kViewFileSuffix, taken);
    EXPECT_EQ(first, dir.path() / "fgr-x-1.fgrview.json");
    taken.insert(first);  // asked for, not written yet
    const fs::path second = unused_file(dir.path(), "fgr-x-1", kViewFileSuffix, taken);
    EXPECT_EQ(second, dir.path() / "fgr-x-1-2.fgrview.json");
    std::ofstream(second) << "{}";  // written by another viewer
    EXPECT_EQ(unused_file(dir.path(), "fgr-x-1", kViewFileSuffix, taken),
              dir.path() / "fgr-x-1-3.fgrview.json");
    EXPECT_EQ(view_thumbnail_file(second), dir.path() / "fgr-x-1-2.fgrview.png");
}

}  // namespace
}  // namespace fgr::viewer
