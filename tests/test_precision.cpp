// Numerical precision: `--precision auto` picks double only for views finer than float resolves,
// the double pipeline renders an ordinary view like float at every packet width it supports, and
// the kernel's double DE agrees with a long-double C++ DE far more closely than the float one.
#include <cmath>
#include <filesystem>
#include <random>
#include <set>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "fgr/camera.hpp"
#include "fgr/parameters.hpp"
#include "fgr/renderer.hpp"
#include "mandelbulb_reference.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

class Precision : public ::testing::Test {
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
    // A view 1e-6 units across, 2e-5 in front of the surface point the canonical view's centre
    // pixel sees: a pixel spans ~1e-8, a tenth of float's step at coordinates near 1.
    CameraView deep_zoom() {
        const CameraView canonical = bulb_->cameras.front().view;
        FrameRequest request{65, 49, canonical, default_param_values(*bulb_)};
        const Frame frame = renderer(true).render(request);
        const float t = frame.depth[static_cast<size_t>(24 * 65 + 32)];
        EXPECT_GT(t, 0.0f);
        const CameraBasis basis = camera_basis(canonical);
        const glm::vec3 direction = primary_ray_direction(basis, 65, 49, 32.5f, 24.5f);
        const glm::vec3 surface = basis.eye + direction * t;
        CameraView view = canonical;
        view.position = surface - direction * 2e-6f;
        view.target = surface;
        view.fov_degrees = glm::degrees(2.0f * std::atan(0.5e-7f / 2e-6f));
        return view;
    }
    static ComputeDevice* device_;
    static Scene* bulb_;
    ProgramCache cache_{std::filesystem::path()};
};
ComputeDevice* Precision::device_ = nullptr;
Scene* Precision::bulb_ = nullptr;

TEST_F(Precision, AutoChoosesDoubleOnlyWhenAPixelIsFinerThanFloat) {
    EXPECT_FALSE(needs_double_precision(bulb_->cameras.front().view, 640));
    EXPECT_FALSE(needs_double_precision(bulb_->cameras.front().view, 16384));
    EXPECT_TRUE(needs_double_precision(deep_zoom(), 96));
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
TEST_F(Precision, DoubleRendersAnOrdinaryViewLikeFloat) {
    const FrameRequest canonical{96, 72, bulb_->cameras.front().view, default_param_values(*bulb_)};
    const Frame in_float = renderer(false).render(canonical);
    for (int width : {4, 8, 16}) {
        const Frame in_double =
            Renderer(*device_, cache_, *bulb_, {width, bulb_->effects, false, true}).render(canonical);
        long both = 0;
        EXPECT_LT(float_depth_error(in_float, in_double, &both), 1e-4) << "width " << width;
        EXPECT_NEAR(double(in_double.hits), double(in_float.hits), 0.005 * double(in_float.hits))
            << "width " << width;
        EXPECT_GT(both, 96 * 72 / 4);
    }
}

// The kernel's double DE (colatitude form, complex powers) against the trigonometric formula in
// long double, at points near the surface: within 1e-6 of the DE plus 1e-9 (the result comes back
// as float, so ~6e-8 relative is the floor). The float kernel is only held to 5e-2.
TEST_F(Precision, DoubleDeAgreesWithALongDoubleReference) {
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
        const long double reference =
            test::mandelbulb_de<long double>(points[i].x, points[i].y, points[i].z, test::BulbParams{});
        const double scale = double(reference) + 1e-3;  // error / scale < 1e-6: within 1e-6 DE + 1e-9
        worst_double = std::max(worst_double, double(std::abs(in_double[i] - reference)) / scale);
        worst_float = std::max(worst_float, double(std::abs(in_float[i] - reference)) / scale);
    }
    std::printf("DE vs long double, worst relative error: double %.3g, float %.3g\n", worst_double,
                worst_float);
    EXPECT_LT(worst_double, 1e-6);
    EXPECT_LT(worst_float, 5e-2);
    EXPECT_LT(worst_double, worst_float);
}

}  // namespace
}  // namespace fgr
