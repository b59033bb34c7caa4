// SPDX-License-Identifier: Apache-2.0
// The kernel's Mandelbulb DE (packets, complex powers for integer exponents) against a plain C++
// DE written from the trigonometric formulas, in double precision, for both angle conventions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include "device/program_cache.hpp"
#include "mandelbulb_reference.hpp"
#include "random_points.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

Scene load_mandelbulb() { return test::built_scene("mandelbulb.so"); }

struct DeCase {
    int packet_width;
    test::BulbForm form;
    double power;
};

class MandelbulbDe : public ::testing::TestWithParam<DeCase> {
protected:
    static void SetUpTestSuite() {
        device_ = new ComputeDevice(open_device(-1));
        scene_ = new Scene(load_mandelbulb());
    }
    static void TearDownTestSuite() {
        delete scene_;
        delete device_;
    }

    std::vector<float> kernel_de(const std::vector<glm::vec3>& points) {
        const DeCase& c = GetParam();
        ProgramCache cache{std::filesystem::path()};
        Renderer renderer(*device_, cache, *scene_, {c.packet_width, 0});
        std::vector<float> params = default_param_values(*scene_);
        set_param_from_text(*scene_, params, "power=" + std::to_string(c.power));
        set_param_from_text(*scene_, params, "variant=" + std::to_string(static_cast<int>(c.form)));
        return renderer.probe_de(points, params);
    }

    test::BulbParams bulb() const {
        test::BulbParams params;
        params.power = GetParam().power;
        params.form = GetParam().form;
        return params;
    }

    static ComputeDevice* device_;
    static Scene* scene_;
};
ComputeDevice* MandelbulbDe::device_ = nullptr;
Scene* MandelbulbDe::scene_ = nullptr;

using test::random_points;

TEST_P(MandelbulbDe, MatchesTheTrigonometricFormulas) {
    const auto points = random_points(4000, 1.4f, 7);
    const auto distances = kernel_de(points);
    ASSERT_EQ(distances.size(), points.size());
    int close = 0;
    std::vector<double> relative_errors;
    for (size_t i = 0; i < points.size(); ++i) {
        const double expected =
            test::mandelbulb_de<double>(points[i].x, points[i].y, points[i].z, bulb());
        ASSERT_TRUE(std::isfinite(distances[i])) << "point " << i;
        const double error = std::abs(distances[i] - expected);
        relative_errors.push_back(error / std::max(std::abs(expected), 1e-3));
        close += error <= 1e-4 + 1e-3 * std::abs(expected);
    }
    // Points on the fractal's boundary escape at a different iteration for a rounding error,
    // which changes their DE discontinuously; everywhere else the two must agree closely.
    EXPECT_GE(close, static_cast<int>(points.size() * 99 / 100));
    std::nth_element(relative_errors.begin(), relative_errors.begin() + relative_errors.size() / 2,
                     relative_errors.end());
    EXPECT_LT(relative_errors[relative_errors.size() / 2], 1e-5);
}

TEST_P(MandelbulbDe, FiniteAtSingularPoints) {
    const float tiny = 1e-30f;
    // The origin, signed zeros, the polar axis (rho = 0, where atan2(0, 0) decides the angle),
    // denormal-scale and exact-bailout points: all must agree with the reference DE.
    const std::vector<glm::vec3> points{
        {0, 0, 0},    {-0.0f, 0, -0.0f}, {0, 0, 0.5f},      {0, 0, -0.5f},     {0.5f, 0, 0},
        {0, 0.5f, 0}, {tiny, 0, 0},      {0, 0, tiny},      {2, 0, 0},         {0, 0, 2},
        {1.2f, 0, 0}, {0, -1.1f, 0},     {1e-16f, 0, 0.5f}, {0, 2e-15f, -0.7f}};
    const auto distances = kernel_de(points);
    for (size_t i = 0; i < points.size(); ++i) {
        const double expected =
            test::mandelbulb_de<double>(points[i].x, points[i].y, points[i].z, bulb());
        ASSERT_TRUE(std::isfinite(distances[i])) << "point " << i;
        EXPECT_NEAR(distances[i], expected, 1e-4 + 1e-3 * std::abs(expected)) << "point " << i;
    }
    EXPECT_EQ(distances[0], 0.0f);  // the origin never escapes
    EXPECT_EQ(distances[1], 0.0f);
}

TEST_P(MandelbulbDe, FarPointsAreFarNeverNaN) {
    const float huge = 1e30f;
    const std::vector<glm::vec3> points{
        {huge, 0, 0}, {0, 0, -huge}, {huge, huge, huge}, {1e6f, -1e6f, 1e6f}, {-3e3f, 0, 0}};
    for (float distance : kernel_de(points)) {
        EXPECT_FALSE(std::isnan(distance));
        EXPECT_GT(distance, 1.0f);  // +inf is an acceptable "very far"
    }
}

INSTANTIATE_TEST_SUITE_P(Forms, MandelbulbDe,
                         ::testing::Values(DeCase{16, test::BulbForm::Colatitude, 8.0},
                                           DeCase{1, test::BulbForm::Colatitude, 8.0},
                                           DeCase{16, test::BulbForm::Latitude, 8.0},
                                           DeCase{8, test::BulbForm::Latitude, 8.0},
                                           DeCase{16, test::BulbForm::Colatitude, 7.5},
                                           DeCase{4, test::BulbForm::Latitude, 3.0},
                                           DeCase{16, test::BulbForm::Colatitude, 2.0},
                                           DeCase{16, test::BulbForm::Colatitude, 5.0},
                                           DeCase{16, test::BulbForm::Latitude, 6.0}),
                         [](const auto& test_info) {
                             const DeCase& c = test_info.param;
                             return std::string(c.form == test::BulbForm::Colatitude ? "Colatitude"
                                                                                     : "Latitude") +
                                    "Power" + std::to_string(static_cast<int>(c.power * 10)) +
                                    "Width" + std::to_string(c.packet_width);
                         });

}  // namespace
}  // namespace fgr
