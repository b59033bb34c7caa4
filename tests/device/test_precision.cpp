// SPDX-License-Identifier: Apache-2.0
// Numerical precision: `--precision auto` picks double only for views finer than float resolves,
// the double pipeline renders an ordinary view like float at every packet width it supports, the
// kernel's double DE agrees with a long-double C++ DE to the float rounding of its result, and in
// deep zooms double's depths are a long-double march's. The assertions are about double: float's
// figures are printed beside them, never required to be bad. And fgr render, fgr view and
// fgr bench decide float or double alike.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <glm/vec2.hpp>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "camera/camera.hpp"
#include "camera/camera_path_file.hpp"
#include "child_process.hpp"
#include "deep_zoom.hpp"
#include "diagnostics/bench.hpp"
#include "mandelbulb_reference.hpp"
#include "output/still_image.hpp"
#include "render/precision.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"
#ifdef FGR_TEST_VIEWER  // built with the viewer (FGR_BUILD_VIEWER)
#include "viewer/render_worker.hpp"
#endif

namespace fgr {
namespace {

class FloatAndDouble : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        device_ = new ComputeDevice(open_device(-1));
        bulb_ = new Scene(test::built_scene("mandelbulb.so"));
    }
    static void TearDownTestSuite() {
        delete bulb_;
        delete device_;
    }
    Renderer renderer(bool double_precision) {
        return Renderer(*device_, cache_, *bulb_, {16, bulb_->effects, false, double_precision});
    }
    CameraView deep_zoom(double across = 1e-7) {
        return test::mandelbulb_deep_zoom(*bulb_, across);
    }
    // Double's depths are the surface's: a long-double sphere trace of the same rays with the same
    // hit rule (stop where DE < t * footprint) lands within two footprints of every sampled pixel
    // (both marches stop somewhere in the shell the hit rule allows, which is about a footprint
    // deep where the DE is accurate), and typically within half of one. Float's figures are
    // printed for comparison, not asserted: this is about double, whatever float does.
    void expect_depths_match_long_double(const CameraView& view) {
        constexpr int width = 96, height = 72;
        const auto params = default_param_values(*bulb_);
        const Frame in_double = renderer(true).render({width, height, view, params});
        const Frame in_float = renderer(false).render({width, height, view, params});
        const CameraBasis basis = camera_basis(view);
        const long double footprint =
            param_value(*bulb_, params, "hit_threshold") * 2.0L * basis.tan_half_fov / width;
        std::vector<double> double_errors, float_errors;  // in footprints
        for (int py = 0; py < height; py += 2) {
            for (int px = 0; px < width; px += 2) {
                const glm::vec3 dir =
                    primary_ray_direction(basis, width, height, float(px), float(py));
                long double t = 0.0L;
                for (int step = 0; step < 1000; ++step) {
                    const long double de = test::mandelbulb_de<long double>(
                        basis.eye.x + dir.x * t, basis.eye.y + dir.y * t, basis.eye.z + dir.z * t,
                        test::BulbParams{});
                    if (de < t * footprint) break;
                    t += de;
                }
                const size_t i = size_t(py) * width + size_t(px);
                ASSERT_GT(in_double.depth[i], 0.0f) << "pixel (" << px << ", " << py << ") missed";
                double_errors.push_back(double(std::abs(in_double.depth[i] - t) / (t * footprint)));
                float_errors.push_back(double(std::abs(in_float.depth[i] - t) / (t * footprint)));
            }
        }
        const auto median = [](std::vector<double> values) {
            std::nth_element(values.begin(), values.begin() + long(values.size() / 2),
                             values.end());
            return values[values.size() / 2];
        };
        const double worst = *std::max_element(double_errors.begin(), double_errors.end());
        std::printf(
            "depth against a long-double march, in footprints, over %zu pixels: double "
            "median %.3f largest %.3f; float median %.3f largest %.3g\n",
            double_errors.size(), median(double_errors), worst, median(float_errors),
            *std::max_element(float_errors.begin(), float_errors.end()));
        EXPECT_LT(worst, 2.0);
        EXPECT_LT(median(double_errors), 0.5);
    }
    static ComputeDevice* device_;
    static Scene* bulb_;
    ProgramCache cache_{std::filesystem::path()};
};
ComputeDevice* FloatAndDouble::device_ = nullptr;
Scene* FloatAndDouble::bulb_ = nullptr;

TEST_F(FloatAndDouble, AutoChoosesDoubleOnlyWhenAPixelIsFinerThanFloat) {
    const CameraView canonical = bulb_->cameras.front().view;
    EXPECT_FALSE(needs_double_precision(canonical, 640));
    EXPECT_FALSE(needs_double_precision(canonical, 16384));
    EXPECT_FALSE(needs_double_precision(deep_zoom(1e-2), 96));
    EXPECT_TRUE(needs_double_precision(deep_zoom(1e-6), 96));
    EXPECT_TRUE(needs_double_precision(deep_zoom(1e-7), 96));

    DeviceInfo with_fp64, without_fp64;
    with_fp64.has_fp64 = true;
    without_fp64.name = "a float-only device";
    EXPECT_TRUE(use_double_precision(Precision::Auto, deep_zoom(), 96, with_fp64));
    EXPECT_FALSE(use_double_precision(Precision::Auto, canonical, 96, with_fp64));
    EXPECT_FALSE(use_double_precision(Precision::Float, deep_zoom(), 96, with_fp64));
    EXPECT_TRUE(use_double_precision(Precision::Double, canonical, 96, with_fp64));
    // Auto falls back to float, and the chooser says so once, naming the device; an explicit
    // double is an error.
    EXPECT_FALSE(use_double_precision(Precision::Auto, deep_zoom(), 96, without_fp64));
    EXPECT_THROW(use_double_precision(Precision::Double, canonical, 96, without_fp64),
                 std::runtime_error);
    std::vector<std::string> warnings;
    PrecisionChooser without(without_fp64, [&](const std::string& w) { warnings.push_back(w); });
    EXPECT_FALSE(without.in_double(Precision::Auto, canonical, 96));
    EXPECT_TRUE(warnings.empty()) << "float suffices there";
    EXPECT_FALSE(without.in_double(Precision::Auto, deep_zoom(), 96));
    EXPECT_FALSE(without.in_double(Precision::Auto, deep_zoom(1e-6), 96));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("a float-only device"), std::string::npos) << warnings[0];
    EXPECT_THROW(without.in_double(Precision::Double, canonical, 96), std::runtime_error);
    PrecisionChooser with(with_fp64, [&](const std::string& w) { warnings.push_back(w); });
    EXPECT_TRUE(with.in_double(Precision::Auto, deep_zoom(), 96));
    EXPECT_FALSE(with.in_double(Precision::Float, deep_zoom(), 96));
    EXPECT_EQ(warnings.size(), 1u);
}

// A deep zoom's camera with its target pushed 1 unit away: the same picture, but judged at the
// target the view looks coarse.
CameraView with_far_target(CameraView view) {
    view.target = view.position + glm::normalize(view.target - view.position);
    return view;
}

// Auto also judges at the nearest surface: the DE at a camera close to a surface finer than float
// resolves finds it, wherever the target is; an ordinary view's camera is far from everything.
TEST_F(FloatAndDouble, AutoRuleJudgesAtTheNearestSurfaceTheDEFinds) {
    const auto params = default_param_values(*bulb_);
    Renderer in_float = renderer(false);
    const CameraView far_target = with_far_target(deep_zoom(1e-7));
    ASSERT_FALSE(auto_wants_double(far_target, 640, -1.0f)) << "judged at the target: coarse";
    // Float's DE there is rough (the coordinates' own steps are 6e-8), but a distance of the
    // standoff's order, not more: small enough to call for double.
    const float near = surface_distance(in_float, far_target, params);
    EXPECT_GT(near, 0.0f);
    EXPECT_LT(near, 1.5 * test::kDeepZoomStandoff);
    EXPECT_TRUE(auto_wants_double(far_target, 640, near));
    const CameraView canonical = bulb_->cameras.front().view;
    EXPECT_FALSE(auto_wants_double(canonical, 640, surface_distance(in_float, canonical, params)));
    // A surface beyond the target changes nothing: the target is nearer.
    EXPECT_TRUE(auto_wants_double(deep_zoom(1e-7), 640, 10.0f));
}

// An inside test says nothing about distance: for an inside-only scene the surface distance is
// unknown (-1, nothing is probed: it has no DE) and auto judges at the target alone.
TEST_F(FloatAndDouble, SurfaceDistanceOfAnInsideOnlySceneIsUnknown) {
    const Scene ball = test::inside_ball_scene();
    Renderer in_float(*device_, cache_, ball, {16, 0, false, false, RenderMode::Brute});
    const CameraView view = ball.cameras.front().view;
    EXPECT_EQ(surface_distance(in_float, view, default_param_values(ball)), -1.0f);
}

// `fgr render` under auto renders such a view in double, and says why; float stays float.
TEST_F(FloatAndDouble, RenderSwitchesToDoubleWhenTheHitsAreFinerThanFloat) {
    test::TempDir dir("fgr_precision_test");
    CameraPathFile path;
    path.scene = "mandelbulb";
    path.path.name = "far-target";
    const CameraView view = with_far_target(deep_zoom(1e-7));
    path.path.keyframes = {{0.0f, view}, {1.0f, view}};
    write_camera_path_file(dir.path() / "far.json", path);
    for (const char* precision : {"auto", "float"}) {
        const test::RunResult run = test::run_fgr(
            {"render", "mandelbulb", "--camera-path", "far.json", "--time", "0", "--width", "64",
             "--height", "48", "--precision", precision, "-o", "far.png"},
            dir.path());
        ASSERT_EQ(run.exit_code, 0) << run;
        const bool switched =
            run.err.find("finer than float resolves: rendering in double") != std::string::npos;
        EXPECT_EQ(switched, std::string(precision) == "auto") << run;
        EXPECT_EQ(run.err.find("work-item, double") != std::string::npos, switched) << run;
    }
}

TEST(PrecisionChoice, ParsesNamesAndRaisesThePacketWidthForDouble) {
    for (Precision p : {Precision::Float, Precision::Double, Precision::Auto}) {
        EXPECT_EQ(parse_precision(precision_name(p)), p);
    }
    EXPECT_THROW(parse_precision("half"), std::invalid_argument);
    EXPECT_EQ(with_precision({1, 0}, true).packet_width, kMinDoublePacketWidth);
    EXPECT_TRUE(with_precision({1, 0}, true).double_precision);
    EXPECT_EQ(with_precision({16, 0}, true).packet_width, 16);
    EXPECT_EQ(with_precision({1, 0, false, true}, false).packet_width, 1);
    EXPECT_FALSE(with_precision({1, 0, false, true}, false).double_precision);
}

// Mean |t_float - t_double| / t_double over pixels both hit: how far float's depths stray from
// double's in a view.
double float_depth_error(const Frame& in_float, const Frame& in_double, long* both) {
    double sum = 0.0;
    *both = 0;
    for (size_t i = 0; i < in_double.depth.size(); ++i) {
        if (in_float.depth[i] < 0.0f || in_double.depth[i] < 0.0f) continue;
        sum += std::abs(double(in_float.depth[i]) - double(in_double.depth[i])) /
               double(in_double.depth[i]);
        ++*both;
    }
    return *both ? sum / double(*both) : 0.0;
}

// The double pipeline renders what the float one does where float suffices: the same hits and
// depths within float's rounding, at every packet width double supports.
TEST_F(FloatAndDouble, DoubleRendersAnOrdinaryViewLikeFloat) {
    const FrameRequest canonical{96, 72, bulb_->cameras.front().view, default_param_values(*bulb_)};
    const Frame in_float = renderer(false).render(canonical);
    for (int width : {4, 8, 16}) {
        const Frame in_double =
            Renderer(*device_, cache_, *bulb_, {width, bulb_->effects, false, true})
                .render(canonical);
        long both = 0;
        EXPECT_LT(float_depth_error(in_float, in_double, &both), 1e-4) << "width " << width;
        EXPECT_NEAR(double(in_double.hits), double(in_float.hits), 0.005 * double(in_float.hits))
            << "width " << width;
        EXPECT_GT(both, 96 * 72 / 4);
    }
}

// Jittered samples land in the same places in double as in float (the sample hash is 32-bit in
// both): a 3-sample image agrees with float's to within rounding. With a 64-bit hash in double,
// later samples landed far outside their pixels and the mean brightness fell by a quarter.
TEST_F(FloatAndDouble, DoubleJittersSamplesLikeFloat) {
    FrameRequest request{64, 48, bulb_->cameras.front().view, default_param_values(*bulb_)};
    request.samples = 3;
    const Frame in_float = renderer(false).render(request);
    const Frame in_double = renderer(true).render(request);
    ASSERT_EQ(in_float.linear.size(), in_double.linear.size());
    double float_sum = 0.0, double_sum = 0.0, worst = 0.0;
    for (size_t i = 0; i < in_float.linear.size(); ++i) {
        float_sum += in_float.linear[i];
        double_sum += in_double.linear[i];
        worst = std::max(worst, double(std::abs(in_float.linear[i] - in_double.linear[i])));
    }
    EXPECT_NEAR(double_sum, float_sum, 0.002 * float_sum);
    EXPECT_LT(worst, 0.2) << "a pixel's samples went elsewhere";
}

// The kernel's double DE (colatitude form, complex powers) against the trigonometric formula in
// long double, at points near the surface. The kernel returns its DE as a float, which rounds it
// to 2^-24 = 6e-8 of itself; the error relative to DE + 1e-3 must stay under 1e-7, leaving the
// double computation itself 4e-8 (a float-precision DE is 1e5 times further off). Float's figure
// is printed for comparison only.
TEST_F(FloatAndDouble, DoubleDeAgreesWithALongDoubleReference) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.2f, 1.2f);
    std::vector<glm::vec3> points;
    while (points.size() < 2000) {
        const glm::vec3 p(unit(rng), unit(rng), unit(rng));
        const long double de = test::mandelbulb_de<long double>(p.x, p.y, p.z, test::BulbParams{});
        if (de > 1e-4L && de < 0.05L) points.push_back(p);  // near, not on, the surface
    }
    const auto params = default_param_values(*bulb_);
    const std::vector<float> in_double = renderer(true).probe_de(points, params);
    const std::vector<float> in_float = renderer(false).probe_de(points, params);
    double worst_double = 0.0, worst_float = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
        const long double reference = test::mandelbulb_de<long double>(
            points[i].x, points[i].y, points[i].z, test::BulbParams{});
        const double scale = double(reference) + 1e-3;
        worst_double = std::max(worst_double, double(std::abs(in_double[i] - reference)) / scale);
        worst_float = std::max(worst_float, double(std::abs(in_float[i] - reference)) / scale);
    }
    std::printf("DE vs long double, worst error / (DE + 1e-3): double %.3g, float %.3g\n",
                worst_double, worst_float);
    EXPECT_LT(worst_double, 1e-7);
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

// How a deep zoom's depth map looks: the share of horizontally adjacent hit pixels with exactly
// the same depth (float rounds neighbouring rays onto the same points: flat blocks), and the
// median |second difference| of depth relative to depth (a smooth surface gives a small one,
// float's rounding noise a large one).
struct DepthTexture {
    double equal_neighbours = 0.0;
    double median_roughness = 0.0;
};

DepthTexture depth_texture(const Frame& frame, int width, int height) {
    long pairs = 0, equal = 0;
    std::vector<double> roughness;
    for (int y = 0; y < height; ++y) {
        for (int x = 1; x + 1 < width; ++x) {
            const float* row = frame.depth.data() + size_t(y) * size_t(width);
            const float a = row[x - 1], b = row[x], c = row[x + 1];
            if (a < 0.0f || b < 0.0f || c < 0.0f) continue;
            ++pairs;
            equal += a == b;
            roughness.push_back(std::abs(double(a) - 2.0 * double(b) + double(c)) / double(b));
        }
    }
    if (roughness.empty()) return {};
    std::nth_element(roughness.begin(), roughness.begin() + long(roughness.size() / 2),
                     roughness.end());
    return {double(equal) / double(pairs), roughness[roughness.size() / 2]};
}

// A deep zoom 1e-6 and 1e-7 units across at the surface: pixels of 1e-8 and 1e-9, where float's
// step near the bulb is 6e-8 (the views are past what float resolves: auto picks double). Double
// fills the view with surface and gives neighbouring rays their own depths: two rays 1e-9 apart
// meet the surface at depths that differ by about 1e-9 times its slope, which double (2e-22 at
// these depths) resolves, so equal neighbours can only be coincidences (under 1%). Float's
// figures are printed for comparison only (rounding rays onto its grid gives it flat blocks).
TEST_F(FloatAndDouble, DeepZoomInDoubleGivesNeighbouringRaysTheirOwnDepths) {
    constexpr int width = 96, height = 72;
    for (double across : {1e-6, 1e-7}) {
        const FrameRequest request{width, height, deep_zoom(across), default_param_values(*bulb_)};
        ASSERT_TRUE(needs_double_precision(request.view, width)) << across;
        const Frame in_double = renderer(true).render(request);
        ASSERT_EQ(in_double.hits, width * height) << "the view is filled by the surface";
        const DepthTexture fine = depth_texture(in_double, width, height);
        const DepthTexture coarse = depth_texture(renderer(false).render(request), width, height);
        std::printf(
            "%g across: equal neighbours double %.4f (float %.3f), roughness double %.3g "
            "(float %.3g)\n",
            across, fine.equal_neighbours, coarse.equal_neighbours, fine.median_roughness,
            coarse.median_roughness);
        EXPECT_LT(fine.equal_neighbours, 0.01) << across;
    }
}

// In the deep zooms double's depths are the surface's: a long-double sphere trace of the same
// rays with the same hit rule lands within two pixel footprints of them. Float's do not.
TEST_F(FloatAndDouble, DeepZoomDoubleDepthsMatchALongDoubleMarch) {
    for (double across : {1e-6, 1e-7}) expect_depths_match_long_double(deep_zoom(across));
}

// The integer shift (dx, dy), within max_shift, that best maps image `a` onto `b`
// (b(x + dx, y + dy) ~ a(x, y)) by the mean absolute difference of luminance over the overlap.
// max_shift_y 0 measures motion along rows only, which an edge across the image pins down (a 2D
// search would slide along the edge instead).
glm::ivec2 best_matching_offset(const Frame& a, const Frame& b, int width, int height,
                                int max_shift, int max_shift_y) {
    const auto luminance = [&](const Frame& frame, int x, int y) {
        const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
        return 0.2126 * frame.linear[i] + 0.7152 * frame.linear[i + 1] +
               0.0722 * frame.linear[i + 2];
    };
    glm::ivec2 best(0);
    double best_error = std::numeric_limits<double>::infinity();
    for (int dy = -max_shift_y; dy <= max_shift_y; ++dy) {
        for (int dx = -max_shift; dx <= max_shift; ++dx) {
            double error = 0.0;
            int count = 0;
            for (int y = std::max(0, -dy); y < std::min(height, height - dy); ++y) {
                for (int x = std::max(0, -dx); x < std::min(width, width - dx); ++x) {
                    error += std::abs(luminance(a, x, y) - luminance(b, x + dx, y + dy));
                    ++count;
                }
            }
            if (error / count < best_error) {
                best_error = error / count;
                best = {dx, dy};
            }
        }
    }
    return best;
}

// A camera path 1e-8 units across, 2e-6 in front of the Mandelbulb's surface, sliding sideways by
// 2 pixels a frame: rendered in double at consecutive times, every frame differs from the one
// before and the image moves by at most a few pixels each time, adding up to the path's travel.
// A float eye (or a float spline) would hold the image still for frames and then jump by float's
// step near the bulb, 6e-8: hundreds of pixels.
TEST_F(FloatAndDouble, DeepZoomCameraPathMovesTheImageContinuously) {
    constexpr int width = 48, height = 36, frames = 12;
    constexpr double across = 1e-8, pixels_per_frame = 2.0;
    const CameraView start = deep_zoom(across);
    const glm::dvec3 right(camera_basis(start).right);
    const glm::dvec3 per_second = right * (across / width) * pixels_per_frame * double(frames);
    CameraPath path;
    path.name = "deep slide";
    for (int key = 0; key < 4; ++key) {  // evenly spaced in a line: Catmull-Rom moves uniformly
        CameraView view = start;
        view.position += per_second * double(key - 1);
        view.target += per_second * double(key - 1);
        path.keyframes.push_back({float(key), view});
    }
    const auto params = default_param_values(*bulb_);
    Renderer in_double = renderer(true);
    std::vector<Frame> rendered;
    glm::dvec3 previous_eye(0.0);
    for (int i = 0; i <= frames; ++i) {
        const CameraView view = evaluate_camera_path(path, 1.0 + double(i) / frames);
        EXPECT_NE(view.position, previous_eye) << "frame " << i << ": the eye did not move";
        previous_eye = view.position;
        rendered.push_back(in_double.render({width, height, view, params}));
        ASSERT_EQ(rendered.back().hits, width * height) << "the view is filled by the surface";
    }
    int travelled = 0;
    for (int i = 1; i <= frames; ++i) {
        EXPECT_NE(rendered[i - 1].linear, rendered[i].linear) << "frame " << i << " did not move";
        const glm::ivec2 shift =
            best_matching_offset(rendered[i - 1], rendered[i], width, height, 8, 0);
        std::printf("frame %d: image shift %d %d\n", i, shift.x, shift.y);
        EXPECT_LE(std::abs(shift.x), 3) << "frame " << i;
        EXPECT_LE(std::abs(shift.y), 1) << "frame " << i;
        travelled += shift.x;
    }
    // The camera slides right, so the image slides left, 24 pixels in all.
    EXPECT_NEAR(-travelled, pixels_per_frame * frames, 4.0);
}

// --- One rule in the three front ends ------------------------------------------------------------
//
// fgr render (render_still), fgr view (the viewer's RenderWorker) and fgr bench (run_benchmark)
// decide float or double for a view by the same rule, so they agree on every view. Each is asked
// for the views below at 64x48 under auto.

struct RuleCase {
    std::string name;
    CameraView view;
    bool in_double;  // what the rule decides
};

// The deep zoom's camera turned round: 2e-6 from the surface, looking away from it at a target 1
// unit away. The DE at the camera still bounds what is in view from below, so the rule errs
// towards double here.
CameraView looking_away(const CameraView& view) {
    CameraView away = view;
    away.target = view.position - glm::normalize(view.target - view.position);
    return away;
}

#ifdef FGR_TEST_VIEWER
// The precision fgr view renders `view` in: the last frame of the render thread, refined.
bool viewer_renders_in_double(const std::shared_ptr<const Scene>& scene, const CameraView& view,
                              int width, int height) {
    viewer::RenderWorker worker(-1, 0, viewer::QualitySettings{33.0, 1, 0.1f});
    viewer::ViewState state;
    state.scene = scene;
    state.effects = scene->effects;
    state.view = view;
    state.params = default_param_values(*scene);
    state.width = width;
    state.height = height;
    state.precision = Precision::Auto;
    state.generation = 1;
    worker.submit(state);
    std::optional<bool> in_double;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto frame = worker.take_frame()) in_double = frame->double_precision;
        const viewer::WorkerStatus status = worker.status();
        EXPECT_TRUE(status.error.empty()) << status.error;
        if (status.idle && status.idle_generation == 1 && in_double) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    EXPECT_TRUE(in_double.has_value()) << "the viewer rendered no frame";
    return in_double.value_or(false);
}
#endif

TEST_F(FloatAndDouble, RenderViewAndBenchDecideAlike) {
    constexpr int width = 64, height = 48;
    const CameraView deep = deep_zoom(1e-7);
    const std::vector<RuleCase> cases = {
        {"canonical", bulb_->cameras.front().view, false},
        {"deep zoom (its target on the surface)", deep, true},
        {"camera 2e-6 from the surface, target 1 unit away", with_far_target(deep), true},
        {"camera 2e-6 from the surface, looking away", looking_away(deep), true},
    };
    const auto params = default_param_values(*bulb_);
    for (const RuleCase& rule : cases) {
        SCOPED_TRACE(rule.name);
        // fgr render
        StillSettings still;
        still.effects = bulb_->effects;
        const Frame rendered =
            render_still(*bulb_, {width, height, rule.view, params}, *device_, cache_, still);
        EXPECT_EQ(rendered.double_precision, rule.in_double) << "fgr render";

#ifdef FGR_TEST_VIEWER
        // fgr view
        auto scene = std::make_shared<const Scene>(*bulb_);
        EXPECT_EQ(viewer_renders_in_double(scene, rule.view, width, height), rule.in_double)
            << "fgr view";
#endif

        // fgr bench, along a path that holds the view
        Scene benched = *bulb_;
        benched.camera_paths.push_back({"rule", {{0.0f, rule.view}, {1.0f, rule.view}}});
        BenchSettings settings;
        settings.width = width;
        settings.height = height;
        settings.frames = 2;
        settings.path = "rule";
        const BenchReport report = run_benchmark(benched, *device_, cache_, settings);
        ASSERT_EQ(report.runs.size(), 1u);
        EXPECT_EQ(report.runs[0].double_frames, rule.in_double ? 2 : 0) << "fgr bench";
    }
}

}  // namespace
}  // namespace fgr
