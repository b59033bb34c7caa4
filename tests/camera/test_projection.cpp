// SPDX-License-Identifier: Apache-2.0
// Cameras beyond the pinhole (camera/projection.hpp, kernels/modes/fgr_camera.cl): small spheres
// placed in known world directions must appear where the projection's own formulas (written out
// here, apart from both implementations) put them, in the images the kernels render; stereo pairs
// must show the parallax that separation, convergence and focal length predict; the hit threshold
// must scale with the projection's pixel footprint; and the command line must refuse bad settings.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "camera/projection.hpp"
#include "child_process.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "output/still_image.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"
#include "scene/parameters.hpp"
#include "test_math.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

using test::kPi;

double radians(double degrees) { return degrees * kPi / 180.0; }

// test::inline_scene's camera: eye (0, -3, 0) looking at the origin, z up. Its basis is
// forward +y, right +x, up +z.
const glm::dvec3 kEye{0.0, -3.0, 0.0};
const glm::dvec3 kForward{0.0, 1.0, 0.0}, kRight{1.0, 0.0, 0.0}, kUp{0.0, 0.0, 1.0};

// A scene of small spheres (centre, radius) and nothing else.
struct Ball {
    glm::dvec3 centre;
    double radius;
};
Scene balls_scene(const std::vector<Ball>& balls) {
    std::string de =
        "real scene_de(vec3 p, PARAMS) {\n    (void)fgr_params;\n    real d = 1e30f;\n";
    for (const Ball& ball : balls) {
        de += fmt::format(
            "    d = fmin(d, v3_length(v3_sub(p, v3_splat({:.9e}f, {:.9e}f, {:.9e}f))) - "
            "{:.9e}f);\n",
            ball.centre.x, ball.centre.y, ball.centre.z, ball.radius);
    }
    return test::inline_scene(de + "    return d;\n}\n");
}

// The point `distance` from the eye in the direction at `azimuth` (to the right of forward) and
// `elevation` (above the horizon), in radians.
glm::dvec3 seen_at(double azimuth, double elevation, double distance) {
    const glm::dvec3 direction =
        std::cos(elevation) * (std::sin(azimuth) * kRight + std::cos(azimuth) * kForward) +
        std::sin(elevation) * kUp;
    return kEye + distance * direction;
}

// The mean pixel position (pixel centres) of the hits inside [x0, x1) x [y0, y1).
struct Centroid {
    double x = 0.0, y = 0.0;
    long count = 0;
};
Centroid hit_centroid(const Frame& frame, int width, int x0, int y0, int x1, int y1) {
    Centroid c;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            if (frame.depth[size_t(y) * width + x] < 0.0f) continue;
            c.x += x + 0.5;
            c.y += y + 0.5;
            ++c.count;
        }
    }
    if (c.count > 0) {
        c.x /= double(c.count);
        c.y /= double(c.count);
    }
    return c;
}

class ProjectionTest : public test::DeviceSuite<::testing::TestWithParam<RenderMode>> {
protected:
    Frame render(const Scene& scene, const Projection& projection, int width, int height,
                 RenderMode mode, const std::vector<std::string>& assignments = {},
                 bool stats = false) {
        FrameRequest request{width, height, scene.cameras.front().view,
                             default_param_values(scene)};
        request.projection = projection;
        if (mode == RenderMode::Brute) request.samples = sample_budget(mode).still;
        for (const auto& assignment : assignments) {
            set_param_from_text(scene, request.params, assignment);
        }
        KernelSwitches switches{preferred_packet_width(device_->info), scene.effects};
        switches.mode = mode;
        switches.stats = stats;
        Renderer renderer(*device_, *cache_, scene, switches);
        return renderer.render(request);
    }
};

// Equirectangular: longitude -180..180 degrees across the width (0 at the centre, to the right
// positive), latitude 90..-90 down the height. A 2:1 image of 1 degree per pixel.
TEST_P(ProjectionTest, PanoramaShowsKnownDirectionsAtTheirPixels) {
    const int width = 360, height = 180;
    struct Case {
        double longitude, latitude;  // degrees
    };
    // Ahead, to the right and up, behind on the left and down: every quadrant and both halves.
    const std::vector<Case> cases{{10.0, 5.0}, {120.0, 30.0}, {-150.0, -40.0}};
    std::vector<Ball> balls;
    for (const Case& c : cases) {
        balls.push_back({seen_at(radians(c.longitude), radians(c.latitude), 2.0), 0.12});
    }
    Projection panorama;
    panorama.kind = ProjectionKind::Equirectangular;
    const Frame frame = render(balls_scene(balls), panorama, width, height, GetParam());
    for (const Case& c : cases) {
        const double x = (c.longitude / 180.0 + 1.0) * 0.5 * width;
        const double y = (0.5 - c.latitude / 180.0) * height;
        // Each ball covers about 7 degrees; look in a window of 12 pixels around where it belongs.
        const int x0 = std::max(0, int(x) - 12), y0 = std::max(0, int(y) - 12);
        const Centroid seen = hit_centroid(frame, width, x0, y0, std::min(width, int(x) + 12),
                                           std::min(height, int(y) + 12));
        ASSERT_GT(seen.count, 10) << "no ball near pixel (" << x << ", " << y << ") for longitude "
                                  << c.longitude << ", latitude " << c.latitude;
        // A small disc's centroid is its centre's pixel up to second-order distortion (under
        // 0.1 pixel here) and the edges' quantisation: half a pixel is a pixel's footprint.
        EXPECT_NEAR(seen.x, x, 0.5) << "longitude " << c.longitude;
        EXPECT_NEAR(seen.y, y, 0.5) << "latitude " << c.latitude;
    }
    // Nothing else was hit: the balls are all there is.
    EXPECT_LT(frame.hits, 3 * 12 * 12 * 4);
}

// Equidistant fisheye: a direction theta from the axis at azimuth psi (counter-clockwise from the
// right) lands theta / (fov / 2) of the image circle's radius from the centre.
TEST_P(ProjectionTest, FisheyeShowsDirectionsAtRadiusProportionalToTheirAngle) {
    const int width = 240, height = 200;  // circle: radius 100 pixels, centre (120, 100)
    const double half_fov = radians(135.0);
    struct Case {
        double theta, psi;  // degrees
    };
    // Near the axis, past 90 degrees (behind the camera's plane) and near the rim.
    const std::vector<Case> cases{{20.0, 40.0}, {100.0, 200.0}, {125.0, -60.0}};
    std::vector<Ball> balls;
    for (const Case& c : cases) {
        const double theta = radians(c.theta), psi = radians(c.psi);
        const glm::dvec3 direction =
            std::cos(theta) * kForward +
            std::sin(theta) * (std::cos(psi) * kRight + std::sin(psi) * kUp);
        balls.push_back({kEye + 2.0 * direction, 0.12});
    }
    Projection fisheye;
    fisheye.kind = ProjectionKind::Fisheye;
    fisheye.fisheye_fov_degrees = 270.0f;
    const Frame frame = render(balls_scene(balls), fisheye, width, height, GetParam());
    for (const Case& c : cases) {
        const double r = 100.0 * radians(c.theta) / half_fov;
        const double x = 120.0 + r * std::cos(radians(c.psi));
        const double y = 100.0 - r * std::sin(radians(c.psi));
        const Centroid seen =
            hit_centroid(frame, width, std::max(0, int(x) - 10), std::max(0, int(y) - 10),
                         std::min(width, int(x) + 10), std::min(height, int(y) + 10));
        ASSERT_GT(seen.count, 10) << "no ball near pixel (" << x << ", " << y << ") for theta "
                                  << c.theta;
        EXPECT_NEAR(seen.x, x, 0.5) << "theta " << c.theta << ", psi " << c.psi;
        EXPECT_NEAR(seen.y, y, 0.5) << "theta " << c.theta << ", psi " << c.psi;
    }
}

// Outside the image circle nothing is rendered: black, missed, and (stats) no march steps, even
// from inside a closed room every ray inside the circle hits.
TEST_P(ProjectionTest, FisheyeLeavesPixelsOutsideItsCircleBlackAndUnmarched) {
    if (GetParam() != RenderMode::Shaded) GTEST_SKIP() << "stats planes: the shaded mode's";
    const Scene room = test::inline_scene(
        "real scene_de(vec3 p, PARAMS) { (void)fgr_params; return 6.0f - v3_length(p); }");
    Projection fisheye;
    fisheye.kind = ProjectionKind::Fisheye;
    const int width = 64, height = 48;
    const Frame frame = render(room, fisheye, width, height, RenderMode::Shaded, {}, true);
    long outside = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double dx = (x + 0.5 - 32.0) / 24.0, dy = (y + 0.5 - 24.0) / 24.0;
            const size_t i = size_t(y) * width + x;
            if (dx * dx + dy * dy <= 1.0) {
                EXPECT_GE(frame.depth[i], 0.0f) << "pixel " << x << ", " << y << " in the circle";
                continue;
            }
            ++outside;
            EXPECT_LT(frame.depth[i], 0.0f) << "pixel " << x << ", " << y;
            EXPECT_EQ(frame.linear[3 * i] + frame.linear[3 * i + 1] + frame.linear[3 * i + 2], 0.0f)
                << "pixel " << x << ", " << y;
        }
    }
    ASSERT_GT(outside, 0);
    EXPECT_EQ(frame.hits, long(width) * height - outside);
    // The same circle in a square image: the same pixels inside it (the 8 columns either side
    // are all outside), so the same march steps in all, unless pixels outside cost steps.
    const Frame square = render(room, fisheye, height, height, RenderMode::Shaded, {}, true);
    ASSERT_TRUE(frame.stats.has_value() && square.stats.has_value());
    EXPECT_EQ(square.hits, frame.hits);
    EXPECT_NEAR(frame.stats->mean_steps * double(frame.stats->pixels),
                square.stats->mean_steps * double(square.stats->pixels), 0.5);
}

// A stereo pair side by side: each eye W/2 x H, eyes `separation` apart along right, off-axis
// frusta converging at `convergence`. A point at depth d (along forward) has horizontal disparity
// x_left - x_right = f * separation * (1 / d - 1 / convergence) pixels, f = (W / 2) /
// (2 tan(fov / 2)) the focal length in pixels; zero at the convergence distance and no vertical
// disparity anywhere (toe-in would give some off the axis).
TEST_P(ProjectionTest, StereoEyesDifferByTheExpectedParallax) {
    const int eye_width = 160, height = 120;
    const double separation = 0.3, convergence = 3.0;
    const double f = eye_width / (2.0 * std::tan(radians(60.0) / 2.0));
    struct Case {
        double depth, right, up;  // of the ball's centre from the eye, along the view's basis
    };
    // Nearer than, at and beyond the convergence plane; off the axis up and down, left and right.
    const std::vector<Case> cases{{1.5, -0.35, 0.25}, {3.0, 0.6, -0.5}, {6.0, 0.0, 1.2}};
    for (const ProjectionKind kind :
         {ProjectionKind::StereoSideBySide, ProjectionKind::StereoTopBottom}) {
        for (const Case& c : cases) {
            const glm::dvec3 centre = kEye + c.depth * kForward + c.right * kRight + c.up * kUp;
            Projection stereo;
            stereo.kind = kind;
            stereo.eye_separation = separation;
            stereo.convergence = convergence;
            const bool sbs = kind == ProjectionKind::StereoSideBySide;
            const int width = sbs ? 2 * eye_width : eye_width;
            const int full_height = sbs ? height : 2 * height;
            const Frame frame = render(balls_scene({{centre, 0.05 * c.depth}}), stereo, width,
                                       full_height, GetParam());
            const Centroid left = hit_centroid(frame, width, 0, 0, eye_width, height);
            const Centroid right = sbs ? hit_centroid(frame, width, eye_width, 0, width, height)
                                       : hit_centroid(frame, width, 0, height, width, 2 * height);
            ASSERT_GT(left.count, 10) << projection_name(kind) << " depth " << c.depth;
            ASSERT_GT(right.count, 10) << projection_name(kind) << " depth " << c.depth;
            const double right_x = sbs ? right.x - eye_width : right.x;
            const double right_y = sbs ? right.y : right.y - height;
            const double expected = f * separation * (1.0 / c.depth - 1.0 / convergence);
            // Each eye's centroid is off its centre's projection by the same perspective
            // elongation to within a tenth of a pixel; the rest is quantisation.
            EXPECT_NEAR(left.x - right_x, expected, 0.5)
                << projection_name(kind) << " depth " << c.depth;
            // Pixel centres (shaded, brute) leave only the discs' quantisation, the same in both
            // eyes; the path tracer's one jittered sample per pixel moves each eye's edge pixels
            // at random, about 0.1 pixel rms per centroid.
            const double vertical_tolerance = GetParam() == RenderMode::Path ? 0.45 : 0.25;
            EXPECT_NEAR(left.y, right_y, vertical_tolerance)
                << projection_name(kind) << " depth " << c.depth;
            // And each eye sees it where its own off-axis pinhole puts it.
            const double left_x = 0.5 * eye_width + f * (c.right + 0.5 * separation) / c.depth -
                                  f * 0.5 * separation / convergence;
            EXPECT_NEAR(left.x, left_x, 0.5) << projection_name(kind) << " depth " << c.depth;
            EXPECT_NEAR(left.y, 0.5 * height - f * c.up / c.depth, 0.5)
                << projection_name(kind) << " depth " << c.depth;
        }
    }
}

// Dilation by the hit threshold: a ray passing a sphere of radius r at distance D (its centre
// alpha from the ray) hits where D sin(alpha) - r < footprint * t, t ~ D cos(alpha), footprint =
// hit_threshold * pixel angle: the sphere looks as wide as asin(r / D) + about footprint. With
// hit_threshold 8, an equirectangular pixel (2 pi / 360 per pixel: 0.14 radians) widens a ball
// by 8 degrees; a pinhole's 2 tan(30 deg) / 360 would widen it by 1.5.
TEST_P(ProjectionTest, HitThresholdScalesWithThePanoramasPixelFootprint) {
    if (GetParam() == RenderMode::Path) GTEST_SKIP() << "jittered: the edge is noisy";
    const int width = 360, height = 180;
    const double distance = 2.0, radius = 0.2;
    const Scene scene = balls_scene({{seen_at(0.0, 0.0, distance), radius}});
    Projection panorama;
    panorama.kind = ProjectionKind::Equirectangular;
    const Frame frame = render(scene, panorama, width, height, GetParam(), {"hit_threshold=8"});
    // The widest run of hits along the equator's row, in degrees (one pixel each).
    int hits_on_row = 0;
    for (int x = 0; x < width; ++x) hits_on_row += frame.depth[size_t(height / 2) * width + x] >= 0;
    const double half_width_degrees = 0.5 * hits_on_row;
    const double footprint = 8.0 * 2.0 * kPi / width;
    // tan(alpha) = (r/D + footprint) / ... : solve D sin(a) - r = footprint D cos(a).
    const double expected =
        std::asin((radius / distance) / std::hypot(1.0, footprint)) + std::atan(footprint);
    // Sphere tracing samples the ray near its closest approach only to within a step, which
    // narrows the dilation by up to about a degree; a pixel's quantisation adds half of one.
    EXPECT_NEAR(half_width_degrees, expected * 180.0 / kPi, 2.0)
        << "hits across the equator: " << hits_on_row;
}

INSTANTIATE_TEST_SUITE_P(Modes, ProjectionTest,
                         ::testing::Values(RenderMode::Shaded, RenderMode::Path, RenderMode::Brute),
                         [](const ::testing::TestParamInfo<RenderMode>& mode) {
                             return std::string(render_mode_name(mode.param));
                         });

// --- The host's mirror ---------------------------------------------------------------------------

TEST(ProjectionHost, PixelAngleFollowsTheProjection) {
    CameraView view{{0.0, -3.0, 0.0}, {0.0, 0.0, 0.0}, {0.0f, 0.0f, 1.0f}, 60.0f};
    Projection projection;
    const float pinhole = pixel_angle(camera_model(view, projection), 400, 200);
    EXPECT_NEAR(pinhole, 2.0 * std::tan(radians(30.0)) / 400.0, 1e-7);
    projection.kind = ProjectionKind::Equirectangular;
    EXPECT_NEAR(pixel_angle(camera_model(view, projection), 400, 200), 2.0 * kPi / 400.0, 1e-7);
    projection.kind = ProjectionKind::Fisheye;
    projection.fisheye_fov_degrees = 200.0f;
    EXPECT_NEAR(pixel_angle(camera_model(view, projection), 400, 200), radians(200.0) / 200.0,
                1e-7);
    projection.kind = ProjectionKind::StereoSideBySide;
    EXPECT_NEAR(pixel_angle(camera_model(view, projection), 400, 200), 2.0 * pinhole, 1e-7);
    projection.kind = ProjectionKind::StereoTopBottom;
    EXPECT_NEAR(pixel_angle(camera_model(view, projection), 400, 200), pinhole, 1e-7);
}

TEST(ProjectionHost, StereoDefaultsFollowTheDistanceToTheTarget) {
    CameraView view{{0.0, -3.0, 0.0}, {0.0, 0.0, 0.0}, {0.0f, 0.0f, 1.0f}, 60.0f};
    Projection stereo;
    stereo.kind = ProjectionKind::StereoSideBySide;
    const CameraModel model = camera_model(view, stereo);
    EXPECT_NEAR(model.eye_separation, 3.0 / 30.0, 1e-6);
    EXPECT_NEAR(model.convergence, 3.0, 1e-6);
    // The eyes sit half the separation either side of the view's position.
    EXPECT_NEAR(projected_ray_origin(model, 200, 100, 10.5f, 50.5f).x, -0.05, 1e-6);
    EXPECT_NEAR(projected_ray_origin(model, 200, 100, 150.5f, 50.5f).x, 0.05, 1e-6);
    // The target itself is at zero parallax: both eyes see it at their centre.
    const glm::vec3 left = *projected_ray_direction(model, 200, 100, 50.0f, 50.0f);
    EXPECT_NEAR(left.x / left.y, 0.05 / 3.0, 1e-6);
}

TEST(ProjectionHost, NamesAndRangesAreChecked) {
    EXPECT_EQ(parse_projection_kind("panorama"), ProjectionKind::Equirectangular);
    EXPECT_EQ(parse_projection_kind("stereo-tb"), ProjectionKind::StereoTopBottom);
    EXPECT_THROW(parse_projection_kind("cylinder"), std::invalid_argument);
    Projection projection;
    projection.fisheye_fov_degrees = 360.0f;
    EXPECT_NO_THROW(check_projection(projection));
    projection.fisheye_fov_degrees = 361.0f;
    EXPECT_THROW(check_projection(projection), std::invalid_argument);
    projection.fisheye_fov_degrees = 0.0f;
    EXPECT_THROW(check_projection(projection), std::invalid_argument);
    projection = Projection{};
    projection.eye_separation = -0.1;
    EXPECT_THROW(check_projection(projection), std::invalid_argument);
    projection = Projection{};
    projection.convergence = 0.0;
    EXPECT_THROW(check_projection(projection), std::invalid_argument);
}

// --- The command line ----------------------------------------------------------------------------

TEST(ProjectionCli, BadProjectionSettingsAreOneLineErrorsAndWriteNothing) {
    test::TempDir dir("fgr_projection_cli");
    const std::vector<std::vector<std::string>> bad{
        {"--projection", "cylinder"},
        {"--projection", "fisheye", "--fisheye-fov", "0"},
        {"--projection", "fisheye", "--fisheye-fov", "400"},
        {"--stereo", "sbs", "--eye-separation", "-1"},
        {"--stereo", "tb", "--convergence", "0"},
        {"--stereo", "sideways"},
        {"--projection", "panorama", "--eye-separation", "0.1"},
        {"--projection", "pinhole", "--fisheye-fov", "90"},
    };
    for (const std::vector<std::string>& options : bad) {
        std::vector<std::string> args{"render",  "mandelbulb", "-o",       "out.png",
                                      "--width", "16",         "--height", "16"};
        args.insert(args.end(), options.begin(), options.end());
        const test::RunResult result = test::run_fgr(args, dir.path());
        const std::string where = test::describe("fgr", args);
        EXPECT_TRUE(result.exited && result.exit_code != 0) << where << ": " << result;
        std::string err = result.err;
        if (!err.empty() && err.back() == '\n') err.pop_back();
        EXPECT_EQ(err.rfind("fgr: error: ", 0), 0u) << where << ": " << result;
        EXPECT_EQ(err.find('\n'), std::string::npos) << where << ": " << result;
        EXPECT_FALSE(std::filesystem::exists(dir.path() / "out.png")) << where;
    }
}

TEST(ProjectionCli, RendersAPanoramaAndAStereoPair) {
    test::TempDir dir("fgr_projection_cli");
    for (const std::vector<std::string>& options :
         {std::vector<std::string>{"--projection", "panorama"},
          std::vector<std::string>{"--stereo", "sbs", "--eye-separation", "0.1"}}) {
        std::vector<std::string> args{"render",  "mandelbulb", "-o",       "out.png",
                                      "--width", "32",         "--height", "16"};
        args.insert(args.end(), options.begin(), options.end());
        const test::RunResult result = test::run_fgr(args, dir.path());
        EXPECT_TRUE(result.exited && result.exit_code == 0) << result;
        EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.png"));
        std::filesystem::remove(dir.path() / "out.png");
    }
}

}  // namespace
}  // namespace fgr
