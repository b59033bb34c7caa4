// SPDX-License-Identifier: Apache-2.0
// The viewer's fly camera: conversion from and to scene views, mouse-look turns with the pole
// clamp, movement along the local axes, and the DE-driven travel speed and step limit.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "deep_zoom.hpp"
#include "mandelbulb_reference.hpp"
#include "test_scenes.hpp"
#include "viewer/fly_camera.hpp"

namespace fgr::viewer {
namespace {

constexpr float kTolerance = 1e-5f;
constexpr float kHalfPi = std::numbers::pi_v<float> / 2.0f;

void expect_near(glm::vec3 actual, glm::vec3 expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expect_orthonormal_basis(const FlyCamera& camera) {
    const glm::vec3 forward = camera.forward;
    const glm::vec3 right = camera.right();
    const glm::vec3 up = camera.up();
    for (const glm::vec3& axis : {forward, right, up}) {
        ASSERT_TRUE(std::isfinite(axis.x) && std::isfinite(axis.y) && std::isfinite(axis.z));
        EXPECT_NEAR(glm::length(axis), 1.0f, kTolerance);
    }
    EXPECT_NEAR(glm::dot(forward, right), 0.0f, kTolerance);
    EXPECT_NEAR(glm::dot(forward, up), 0.0f, kTolerance);
    EXPECT_NEAR(glm::dot(right, up), 0.0f, kTolerance);
}

// Angle between the view direction and world up, measured the well-conditioned way.
float angle_from_up(const FlyCamera& camera) {
    return std::atan2(glm::length(glm::cross(camera.forward, camera.world_up)),
                      glm::dot(camera.forward, camera.world_up));
}

// A camera at the origin looking along +y with z up: right is +x.
FlyCamera level_camera() {
    FlyCamera camera;
    camera.position = {0.0f, 0.0f, 0.0f};
    camera.forward = {0.0f, 1.0f, 0.0f};
    camera.world_up = {0.0f, 0.0f, 1.0f};
    return camera;
}

TEST(FlyCamera, FromViewTakesDirectionDistanceUpAndFov) {
    CameraView view;
    view.position = {1.0f, 2.0f, 3.0f};
    view.target = {1.0f, 6.0f, 6.0f};  // 5 away along (0, 0.8, 0.6)
    view.up = {0.0f, 0.0f, 2.0f};      // not unit: must be normalised
    view.fov_degrees = 45.0f;

    const FlyCamera camera = FlyCamera::from_view(view);
    expect_near(camera.position, {1.0f, 2.0f, 3.0f});
    expect_near(camera.forward, {0.0f, 0.8f, 0.6f});
    expect_near(camera.world_up, {0.0f, 0.0f, 1.0f});
    EXPECT_NEAR(camera.target_distance, 5.0f, kTolerance);
    EXPECT_FLOAT_EQ(camera.fov_degrees, 45.0f);
}

TEST(FlyCamera, ToViewRoundTripsFromView) {
    CameraView view;
    view.position = {-2.0f, 0.5f, 1.0f};
    view.target = {3.0f, -1.0f, 0.25f};
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = 70.0f;

    const CameraView back = FlyCamera::from_view(view).to_view();
    expect_near(back.position, view.position);
    expect_near(back.target, view.target, 1e-4f);
    expect_near(back.up, view.up);
    EXPECT_FLOAT_EQ(back.fov_degrees, 70.0f);
}

TEST(FlyCamera, ToViewPutsTargetAtTargetDistanceAlongForward) {
    FlyCamera camera = level_camera();
    camera.position = {1.0f, 1.0f, 1.0f};
    camera.target_distance = 2.5f;
    camera.fov_degrees = 30.0f;

    const CameraView view = camera.to_view();
    expect_near(view.position, {1.0f, 1.0f, 1.0f});
    expect_near(view.target, {1.0f, 3.5f, 1.0f});
    expect_near(view.up, {0.0f, 0.0f, 1.0f});
    EXPECT_FLOAT_EQ(view.fov_degrees, 30.0f);
}

TEST(FlyCamera, FromViewAlongUpTiltsAwayAndKeepsFiniteOrthonormalBasis) {
    for (const float sign : {1.0f, -1.0f}) {
        CameraView view;
        view.position = {0.0f, 0.0f, 0.0f};
        view.target = {0.0f, 0.0f, 4.0f * sign};
        view.up = {0.0f, 0.0f, 1.0f};

        const FlyCamera camera = FlyCamera::from_view(view);
        expect_orthonormal_basis(camera);
        EXPECT_NEAR(camera.target_distance, 4.0f, kTolerance);
        // Tilted exactly to the limit, on the side of the pole it was looking at.
        const float expected_angle =
            sign > 0.0f ? kMinPoleAngle : std::numbers::pi_v<float> - kMinPoleAngle;
        EXPECT_NEAR(angle_from_up(camera), expected_angle, 1e-5f) << "sign " << sign;
    }
}

TEST(FlyCamera, FromViewNearUpTiltsAwayKeepingItsHeading) {
    CameraView view;
    view.position = {0.0f, 0.0f, 0.0f};
    view.target = {0.0f, 0.001f, 1.0f};  // 0.001 rad from up, leaning towards +y
    view.up = {0.0f, 0.0f, 1.0f};

    const FlyCamera camera = FlyCamera::from_view(view);
    EXPECT_NEAR(angle_from_up(camera), kMinPoleAngle, 1e-5f);
    expect_near(camera.forward, {0.0f, std::sin(kMinPoleAngle), std::cos(kMinPoleAngle)});

    // Further from the pole than the limit: left exactly as it was.
    view.target = {0.0f, 0.1f, 1.0f};
    expect_near(FlyCamera::from_view(view).forward, glm::normalize(view.target));
}

TEST(FlyCamera, FromViewWithoutDirectionLooksAlongTheHorizon) {
    CameraView view;
    view.position = {1.0f, 1.0f, 1.0f};
    view.target = view.position;

    const FlyCamera camera = FlyCamera::from_view(view);
    expect_orthonormal_basis(camera);
    EXPECT_NEAR(glm::dot(camera.forward, camera.world_up), 0.0f, kTolerance);
    EXPECT_GT(camera.target_distance, 0.0f);
}

TEST(FlyCamera, RightAndUpFollowTheHeaderFormulas) {
    FlyCamera camera = level_camera();
    expect_near(camera.right(), {1.0f, 0.0f, 0.0f});
    expect_near(camera.up(), {0.0f, 0.0f, 1.0f});

    camera.forward = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));
    expect_near(camera.right(), {1.0f, 0.0f, 0.0f});
    expect_near(camera.up(), glm::normalize(glm::vec3(0.0f, -1.0f, 1.0f)));
}

TEST(FlyCamera, PositiveYawTurnsTowardsTheRight) {
    FlyCamera camera = level_camera();
    const glm::vec3 right_before = camera.right();
    camera.turn(kHalfPi, 0.0f);
    expect_near(camera.forward, right_before);

    camera.turn(-kHalfPi, 0.0f);
    expect_near(camera.forward, {0.0f, 1.0f, 0.0f});
}

TEST(FlyCamera, YawKeepsElevation) {
    FlyCamera camera = level_camera();
    camera.forward = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));  // 45 degrees up
    camera.turn(1.0f, 0.0f);
    EXPECT_NEAR(glm::dot(camera.forward, camera.world_up), std::sqrt(0.5f), kTolerance);
    EXPECT_NEAR(glm::length(camera.forward), 1.0f, kTolerance);
}

TEST(FlyCamera, PositivePitchLooksUp) {
    FlyCamera camera = level_camera();
    camera.turn(0.0f, 0.5f);
    expect_near(camera.forward, {0.0f, std::cos(0.5f), std::sin(0.5f)});

    camera.turn(0.0f, -1.0f);
    expect_near(camera.forward, {0.0f, std::cos(0.5f), -std::sin(0.5f)});
}

TEST(FlyCamera, PitchIsClampedAwayFromThePoles) {
    FlyCamera camera = level_camera();
    camera.turn(0.0f, 3.0f);
    EXPECT_NEAR(angle_from_up(camera), kMinPoleAngle, 1e-5f);
    EXPECT_GT(camera.forward.y, 0.0f);  // did not flip over the top
    expect_orthonormal_basis(camera);

    camera.turn(0.0f, -10.0f);
    EXPECT_NEAR(angle_from_up(camera), std::numbers::pi_v<float> - kMinPoleAngle, 1e-5f);
    EXPECT_GT(camera.forward.y, 0.0f);
    expect_orthonormal_basis(camera);

    // Many small steps cannot creep past the limit either.
    for (int i = 0; i < 1000; ++i) {
        camera.turn(0.01f, 0.01f);
        ASSERT_GE(angle_from_up(camera), kMinPoleAngle - 1e-5f) << "step " << i;
    }
}

TEST(FlyCamera, NonFiniteTurnIsIgnored) {
    FlyCamera camera = level_camera();
    camera.turn(std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity());
    expect_near(camera.forward, {0.0f, 1.0f, 0.0f});
}

TEST(FlyCamera, MoveGoesAlongRightForwardAndWorldUp) {
    FlyCamera camera = level_camera();
    camera.forward = glm::normalize(glm::vec3(0.0f, 1.0f, 1.0f));  // up is not world up here
    const glm::vec3 start{1.0f, 2.0f, 3.0f};

    camera.position = start;
    camera.move({1.0f, 0.0f, 0.0f}, 2.0f);
    expect_near(camera.position, start + camera.right() * 2.0f);

    camera.position = start;
    camera.move({0.0f, 1.0f, 0.0f}, 2.0f);
    expect_near(camera.position, start + camera.forward * 2.0f);

    camera.position = start;
    camera.move({0.0f, 0.0f, 1.0f}, 2.0f);
    expect_near(camera.position, start + glm::vec3(0.0f, 0.0f, 2.0f));

    camera.position = start;
    camera.move({0.0f, -3.0f, 0.0f}, 0.5f);  // normalised: the length of `local` is ignored
    expect_near(camera.position, start - camera.forward * 0.5f);
}

TEST(FlyCamera, MoveNormalisesDiagonals) {
    FlyCamera camera = level_camera();
    camera.move({1.0f, 1.0f, 0.0f}, 2.0f);
    expect_near(camera.position, glm::vec3(std::sqrt(2.0f), std::sqrt(2.0f), 0.0f));
    EXPECT_NEAR(glm::length(camera.position), 2.0f, kTolerance);
}

TEST(FlyCamera, ZeroLocalDoesNotMove) {
    FlyCamera camera = level_camera();
    camera.position = {1.0f, 2.0f, 3.0f};
    camera.move({0.0f, 0.0f, 0.0f}, 5.0f);
    EXPECT_EQ(camera.position, glm::dvec3(1.0f, 2.0f, 3.0f));
}

TEST(FlyCameraSpeed, TravelSpeedIsProportionalToDe) {
    EXPECT_DOUBLE_EQ(travel_speed(0.5f, 1.0f), 0.5f);
    EXPECT_DOUBLE_EQ(travel_speed(0.5f, 2.0f), 1.0f);
    EXPECT_DOUBLE_EQ(travel_speed(2.0f, 0.25f), 0.5f);
    EXPECT_DOUBLE_EQ(travel_speed(4.0f, 1.0f) / travel_speed(1.0f, 1.0f), 4.0f);
}

TEST(FlyCameraSpeed, TravelSpeedHasAFloor) {
    EXPECT_DOUBLE_EQ(travel_speed(0.0f, 1.0f), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(1e-13, 1.0), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(-1.0f, 1.0f), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(1.0f, 0.0f), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(std::numeric_limits<float>::quiet_NaN(), 1.0f), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(1.0f, std::numeric_limits<float>::quiet_NaN()), kMinSpeed);
    EXPECT_DOUBLE_EQ(travel_speed(std::numeric_limits<float>::infinity(), 1.0f), kMinSpeed);
}

TEST(FlyCameraSpeed, LimitStepCapsAtHalfTheDe) {
    EXPECT_DOUBLE_EQ(limit_step(1.0f, 0.5f), 0.25f);
    EXPECT_DOUBLE_EQ(limit_step(0.1f, 0.5f), 0.1f);  // already short enough
    EXPECT_DOUBLE_EQ(limit_step(0.25f, 0.5f), 0.25f);
    EXPECT_DOUBLE_EQ(limit_step(-1.0f, 0.5f), -0.25f);  // backwards too
}

TEST(FlyCameraSpeed, LimitStepIgnoresUnusableDe) {
    EXPECT_DOUBLE_EQ(limit_step(1.0f, 0.0f), 1.0f);
    EXPECT_DOUBLE_EQ(limit_step(1.0f, -2.0f), 1.0f);
    EXPECT_DOUBLE_EQ(limit_step(1.0f, std::numeric_limits<float>::quiet_NaN()), 1.0f);
    EXPECT_DOUBLE_EQ(limit_step(1.0f, std::numeric_limits<float>::infinity()), 1.0f);
}

// Flying in at a deep zoom: the camera 1e-8 from the Mandelbulb's surface (near the bulb float's
// step is 6e-8) moves every frame, at the DE times the speed factor (no floor overrides it there),
// each step shorter than the distance estimate, so it closes in on the surface without crossing
// it. The DE is the long-double reference at the camera's double position (it underestimates the
// distance ahead here: the view meets the surface at a slant).
TEST(FlyCameraSpeed, FliesAtADeepZoom) {
    const Scene bulb = test::built_scene("mandelbulb.so");
    FlyCamera camera = FlyCamera::from_view(test::mandelbulb_deep_zoom(bulb, 1e-8, 1e-8));
    const auto de_at = [](glm::dvec3 p) {
        return double(test::mandelbulb_de<long double>(p.x, p.y, p.z, test::BulbParams{}));
    };
    const double first_de = de_at(camera.position);
    ASSERT_GT(first_de, 0.0);
    ASSERT_LT(first_de, 1.01e-8);
    constexpr double dt = 1.0 / 60.0;
    double travelled = 0.0;
    for (int frame = 0; frame < 120; ++frame) {
        const double de = de_at(camera.position);
        ASSERT_GT(de, 0.0) << "frame " << frame << " crossed the surface";
        EXPECT_DOUBLE_EQ(travel_speed(de, 1.0), de) << "the floor must lie below a deep zoom's DE";
        const double step = limit_step(travel_speed(de, 1.0) * dt, de);
        const glm::dvec3 before = camera.position;
        camera.move({0.0f, 1.0f, 0.0f}, step);
        const double moved = glm::length(camera.position - before);
        ASSERT_GT(moved, 0.0) << "frame " << frame << ": the position did not change";
        // Double's rounding of coordinates near 1 (1e-16) is 1e-5 of such a step.
        EXPECT_NEAR(moved, step, 1e-4 * step) << "frame " << frame;
        EXPECT_LT(moved, de) << "frame " << frame;
        EXPECT_EQ(camera.to_view().position, camera.position);
        travelled += moved;
    }
    // Two seconds at factor 1 cover more than the first DE, and the camera is nearer the surface.
    EXPECT_GT(travelled, first_de);
    EXPECT_LT(de_at(camera.position), first_de);
}

}  // namespace
}  // namespace fgr::viewer
