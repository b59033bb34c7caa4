// SPDX-License-Identifier: Apache-2.0
// Camera basis, primary rays and keyframed camera paths.

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "camera/camera.hpp"

namespace fgr {
namespace {

constexpr float kTolerance = 1e-5f;

// The reference view: from (2, -2, 1) at the origin, z up, tan(fov / 2) = 0.5.
CameraView canonical_view() {
    CameraView view;
    view.position = {2.0f, -2.0f, 1.0f};
    view.target = {0.0f, 0.0f, 0.0f};
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = static_cast<float>(2.0 * std::atan(0.5) * 180.0 / std::numbers::pi);
    return view;
}

void expect_near(glm::vec3 actual, glm::vec3 expected, float tolerance = kTolerance) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expect_orthonormal(const CameraBasis& basis) {
    EXPECT_NEAR(glm::length(basis.forward), 1.0f, kTolerance);
    EXPECT_NEAR(glm::length(basis.right), 1.0f, kTolerance);
    EXPECT_NEAR(glm::length(basis.up), 1.0f, kTolerance);
    EXPECT_NEAR(glm::dot(basis.forward, basis.right), 0.0f, kTolerance);
    EXPECT_NEAR(glm::dot(basis.forward, basis.up), 0.0f, kTolerance);
    EXPECT_NEAR(glm::dot(basis.right, basis.up), 0.0f, kTolerance);
    // The handedness rays are built with: image right and up as seen looking along forward.
    expect_near(glm::cross(basis.right, basis.forward), basis.up);
}

CameraView view_at(glm::vec3 position, glm::vec3 target, glm::vec3 up, float fov) {
    CameraView view;
    view.position = position;
    view.target = target;
    view.up = up;
    view.fov_degrees = fov;
    return view;
}

// Four keyframes at uneven times; every up is orthogonal to its view direction.
CameraPath winding_path() {
    CameraPath path;
    path.name = "winding";
    path.keyframes = {
        {0.0f, view_at({4, 0, 0}, {0, 0, 0}, {0, 0, 1}, 60.0f)},
        {1.5f, view_at({0, 4, 1}, {0, 0, 1}, {0, 0, 1}, 45.0f)},
        {2.0f, view_at({-3, 0, 2}, {0, 0, 0}, glm::normalize(glm::vec3{0, 1, 0}), 30.0f)},
        {5.0f, view_at({0, -5, 0}, {1, 0, 0}, {0, 0, -1}, 90.0f)},
    };
    return path;
}

glm::vec3 view_direction(const CameraView& view) {
    return glm::normalize(view.target - view.position);
}

TEST(CameraBasis, IsOrthonormalForAssortedViews) {
    expect_orthonormal(camera_basis(canonical_view()));
    expect_orthonormal(camera_basis(view_at({1, 2, 3}, {-4, 0.5f, 2}, {0.3f, 0.1f, 1}, 70.0f)));
    expect_orthonormal(camera_basis(view_at({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 20.0f)));
}

TEST(CameraBasis, MatchesTheCanonicalViewNumbers) {
    const CameraBasis basis = camera_basis(canonical_view());
    const float root2 = std::sqrt(2.0f);
    expect_near(basis.eye, {2.0f, -2.0f, 1.0f});
    expect_near(basis.forward, glm::vec3{-2.0f, 2.0f, -1.0f} / 3.0f);
    expect_near(basis.right, glm::vec3{1.0f, 1.0f, 0.0f} / root2);
    expect_near(basis.up, glm::vec3{-1.0f, 1.0f, 4.0f} / (3.0f * root2));
    EXPECT_NEAR(basis.tan_half_fov, 0.5f, kTolerance);
    EXPECT_NEAR(pixel_angle(basis, 400), 1.0f / 400.0f, 1e-8f);
}

TEST(CameraBasis, UpHintAlongTheViewDirectionStillGivesAFiniteBasis) {
    const CameraBasis basis = camera_basis(view_at({0, 0, 5}, {0, 0, 0}, {0, 0, 1}, 60.0f));
    expect_orthonormal(basis);
}

TEST(PrimaryRay, CentreOfAnOddSizedImageIsForward) {
    const CameraBasis basis = camera_basis(canonical_view());
    expect_near(primary_ray_direction(basis, 101, 51, 50.0f, 25.0f), basis.forward);
}

TEST(PrimaryRay, CornerPixelsMatchAHandComputation) {
    // 4 x 2 image: the top-left centre has u = -0.375, v = 0.125; bottom-right the negatives.
    const CameraBasis basis = camera_basis(canonical_view());
    expect_near(primary_ray_direction(basis, 4, 2, 0.0f, 0.0f),
                {-0.893985719f, 0.400788757f, -0.200394378f});
    expect_near(primary_ray_direction(basis, 4, 2, 3.0f, 1.0f),
                {-0.345989094f, 0.839186056f, -0.419593028f});
}

TEST(PrimaryRay, TopLeftLooksLeftAndUp) {
    const CameraBasis basis = camera_basis(canonical_view());
    const glm::vec3 ray = primary_ray_direction(basis, 640, 480, 0.0f, 0.0f);
    EXPECT_NEAR(glm::length(ray), 1.0f, kTolerance);
    EXPECT_LT(glm::dot(ray, basis.right), 0.0f);
    EXPECT_GT(glm::dot(ray, basis.up), 0.0f);
}

TEST(CameraPathEvaluation, ReturnsEachKeyframeAtItsTime) {
    const CameraPath path = winding_path();
    for (const Keyframe& key : path.keyframes) {
        SCOPED_TRACE(key.time);
        const CameraView view = evaluate_camera_path(path, key.time);
        expect_near(view.position, key.view.position);
        expect_near(view.target, key.view.target);
        expect_near(view.up, key.view.up);
        EXPECT_NEAR(view.fov_degrees, key.view.fov_degrees, kTolerance);
    }
}

TEST(CameraPathEvaluation, KeyframeWithALeaningUpGivesTheKeyframesBasis) {
    // Up (0, 0, 1) is not orthogonal to a view looking down; the returned up is, yet the camera
    // it describes is the same.
    CameraPath path;
    path.keyframes = {{0.0f, canonical_view()},
                      {1.0f, view_at({3, 0, 1}, {0, 0, 0}, {0, 0, 1}, 50)}};
    const CameraBasis expected = camera_basis(canonical_view());
    const CameraBasis actual = camera_basis(evaluate_camera_path(path, 0.0f));
    expect_near(actual.forward, expected.forward);
    expect_near(actual.right, expected.right);
    expect_near(actual.up, expected.up);
}

TEST(CameraPathEvaluation, IsContinuous) {
    const CameraPath path = winding_path();
    const float dt = 1e-4f;
    for (float t = -0.5f; t < 5.5f; t += 0.01f) {
        SCOPED_TRACE(t);
        const CameraView a = evaluate_camera_path(path, t);
        const CameraView b = evaluate_camera_path(path, t + dt);
        EXPECT_LT(glm::length(a.position - b.position), 1e-2f);
        EXPECT_LT(glm::length(a.target - b.target), 1e-2f);
        EXPECT_LT(glm::length(a.up - b.up), 1e-2f);
        EXPECT_LT(std::abs(a.fov_degrees - b.fov_degrees), 1e-1f);
    }
    // Across each keyframe, where a segment hands over to the next.
    for (const Keyframe& key : path.keyframes) {
        const CameraView before = evaluate_camera_path(path, key.time - dt);
        const CameraView after = evaluate_camera_path(path, key.time + dt);
        EXPECT_LT(glm::length(before.position - after.position), 1e-2f);
        EXPECT_LT(glm::length(before.up - after.up), 1e-2f);
    }
}

TEST(CameraPathEvaluation, ClampsBeforeTheFirstAndAfterTheLastKeyframe) {
    const CameraPath path = winding_path();
    const CameraView& first = path.keyframes.front().view;
    const CameraView& last = path.keyframes.back().view;
    expect_near(evaluate_camera_path(path, -10.0f).position, first.position);
    expect_near(evaluate_camera_path(path, -10.0f).target, first.target);
    expect_near(evaluate_camera_path(path, 1e6f).position, last.position);
    expect_near(evaluate_camera_path(path, 1e6f).target, last.target);
    EXPECT_NEAR(evaluate_camera_path(path, 1e6f).fov_degrees, last.fov_degrees, kTolerance);
    expect_near(evaluate_camera_path(path, std::nanf("")).position, first.position);
}

TEST(CameraPathEvaluation, TwoKeyPathStaysOnTheStraightSegment) {
    CameraPath path;
    const glm::vec3 start{0, 0, 0};
    const glm::vec3 end{4, 2, -2};
    path.keyframes = {{1.0f, view_at(start, {0, 10, 0}, {0, 0, 1}, 40.0f)},
                      {3.0f, view_at(end, {0, 10, 0}, {0, 0, 1}, 60.0f)}};
    expect_near(evaluate_camera_path(path, 2.0f).position, (start + end) / 2.0f);
    EXPECT_NEAR(evaluate_camera_path(path, 2.0f).fov_degrees, 50.0f, 1e-4f);
    const glm::vec3 along = glm::normalize(end - start);
    for (float t = 1.0f; t <= 3.0f; t += 0.125f) {
        const glm::vec3 offset = glm::vec3(evaluate_camera_path(path, t).position) - start;
        const float distance_along = glm::dot(offset, along);
        EXPECT_NEAR(glm::length(offset - along * distance_along), 0.0f, kTolerance);
        EXPECT_GE(distance_along, -kTolerance);
        EXPECT_LE(distance_along, glm::length(end - start) + kTolerance);
    }
}

// Interior values of the winding path, worked by hand. A uniform Catmull-Rom segment from p1 to p2
// at s = 1/2 is (-p0 + 9 p1 + 9 p2 - p3) / 16, at s = 1/4 (-9 p0 + 111 p1 + 29 p2 - 3 p3) / 128,
// the end keyframes standing in for their missing neighbours. A straight lerp would give the plain
// midpoints instead, e.g. (2, 2, 0.5) and (-1.5, 2, 1.5) for the positions below.
TEST(CameraPathEvaluation, InteriorValuesAreCatmullRomNotALerp) {
    const CameraPath path = winding_path();
    // First segment (t 0 -> 1.5) at t = 0.75: p0 = p1 = (4, 0, 0), p2 = (0, 4, 1), p3 = (-3, 0, 2).
    const CameraView first = evaluate_camera_path(path, 0.75f);
    expect_near(first.position, {35.0f / 16.0f, 36.0f / 16.0f, 7.0f / 16.0f});
    // Middle segment (t 1.5 -> 2) at t = 1.75: p0 = (4, 0, 0), p1 = (0, 4, 1), p2 = (-3, 0, 2),
    // p3 = (0, -5, 0); targets (0, 0, 0), (0, 0, 1), (0, 0, 0), (1, 0, 0); fovs 60, 45, 30, 90.
    const CameraView middle = evaluate_camera_path(path, 1.75f);
    expect_near(middle.position, {-31.0f / 16.0f, 41.0f / 16.0f, 27.0f / 16.0f});
    expect_near(middle.target, {-1.0f / 16.0f, 0.0f, 9.0f / 16.0f});
    EXPECT_NEAR(middle.fov_degrees, 525.0f / 16.0f, 1e-4f);  // 32.8125; a lerp gives 37.5
    // The same segment a quarter of the way in (t = 1.625).
    expect_near(evaluate_camera_path(path, 1.625f).position,
                {-123.0f / 128.0f, 459.0f / 128.0f, 169.0f / 128.0f});
}

TEST(CameraPathEvaluation, UpStaysUnitAndOrthogonalToTheViewDirection) {
    CameraPath path = winding_path();
    // Opposite ups on neighbouring keys blend through zero: the fallback must take over.
    path.keyframes[1].view.up = {0, 0, -1};
    for (float t = 0.0f; t <= 5.0f; t += 0.01f) {
        SCOPED_TRACE(t);
        const CameraView view = evaluate_camera_path(path, t);
        EXPECT_NEAR(glm::length(view.up), 1.0f, kTolerance);
        EXPECT_NEAR(glm::dot(view.up, view_direction(view)), 0.0f, kTolerance);
    }
}

TEST(CameraPathEvaluation, FovOvershootIsClamped) {
    // Catmull-Rom overshoots between two equal values whose outer neighbours are lower.
    CameraPath path;
    path.keyframes = {{0.0f, view_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 100.0f)},
                      {1.0f, view_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 178.0f)},
                      {2.0f, view_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 178.0f)},
                      {3.0f, view_at({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 100.0f)}};
    EXPECT_FLOAT_EQ(evaluate_camera_path(path, 1.5f).fov_degrees, 179.0f);
}

TEST(CameraPathEvaluation, SingleKeyframeIsReturnedAndEmptyPathThrows) {
    CameraPath path;
    path.name = "empty";
    EXPECT_THROW(evaluate_camera_path(path, 0.0f), std::invalid_argument);
    path.keyframes = {{2.0f, view_at({1, 1, 1}, {0, 0, 0}, {0, 0, 1}, 35.0f)}};
    expect_near(evaluate_camera_path(path, 7.0f).position, {1, 1, 1});
}

}  // namespace
}  // namespace fgr
