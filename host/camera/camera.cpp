// SPDX-License-Identifier: Apache-2.0
#include "camera/camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <stdexcept>
#include <vector>

namespace fgr {
namespace {

constexpr float kMinFovDegrees = 1.0f;
constexpr float kMaxFovDegrees = 179.0f;

// Below this length a vector is treated as having no usable direction.
constexpr float kDegenerateLength = 1e-6f;
// An up candidate whose component orthogonal to the view direction is shorter than this (for a
// unit candidate) is too close to parallel to define a stable roll.
constexpr float kMinOrthogonalUp = 1e-3f;

// The first candidate that is usable once its component along `forward` (unit) is removed,
// normalised; a world axis when none is.
glm::vec3 orthogonal_up(const std::vector<glm::vec3>& candidates, glm::vec3 forward) {
    for (const glm::vec3& candidate : candidates) {
        const float length = glm::length(candidate);
        if (!(length > kDegenerateLength)) {
            continue;  // also skips NaN
        }
        const glm::vec3 unit = candidate / length;
        const glm::vec3 orthogonal = unit - forward * glm::dot(unit, forward);
        if (glm::length(orthogonal) > kMinOrthogonalUp) {
            return glm::normalize(orthogonal);
        }
    }
    const glm::vec3 axis = least_aligned_axis(forward);
    return glm::normalize(axis - forward * glm::dot(axis, forward));
}

// The smallest fov a path may take beside a keyframe whose fov is `narrowest`: 1 degree, or half
// that keyframe's when it is narrower still (a deep zoom's fov can be 1e-4 degrees; a floor of 1
// degree would widen it ten thousand times).
float min_fov_degrees(float narrowest) { return std::min(kMinFovDegrees, 0.5f * narrowest); }

// Makes `view` presentable: up unit and orthogonal to the view direction (trying the candidates in
// order), fov within [min_fov, kMaxFovDegrees].
CameraView finish_view(CameraView view, const std::vector<glm::vec3>& up_candidates,
                       float min_fov) {
    const glm::dvec3 direction = view.target - view.position;
    const double distance = glm::length(direction);
    // Relative to the view's size: a deep zoom's position and target may be 1e-9 apart.
    if (distance > 0.0 && std::isfinite(distance)) {
        view.up = orthogonal_up(up_candidates, glm::vec3(direction / distance));
    }
    view.fov_degrees = std::clamp(view.fov_degrees, min_fov, kMaxFovDegrees);
    return view;
}

// Uniform Catmull-Rom between p1 (s = 0) and p2 (s = 1). Written so that s = 0 yields p1 exactly,
// which keeps the path exact at keyframe times.
// S is the arithmetic's precision: double for positions, so points 1e-9 apart still interpolate
// smoothly.
template <typename T, typename S>
T catmull_rom(const T& p0, const T& p1, const T& p2, const T& p3, S s) {
    const S s2 = s * s;
    const S s3 = s2 * s;
    return S(0.5) * (S(2) * p1 + (p2 - p0) * s + (S(2) * p0 - S(5) * p1 + S(4) * p2 - p3) * s2 +
                     (S(3) * p1 - p0 - S(3) * p2 + p3) * s3);
}

// The view between keyframes i and i + 1 at local parameter s in [0, 1).
CameraView interpolate_segment(const std::vector<Keyframe>& keys, std::size_t i, double s) {
    // The end keyframes stand in for their missing outer neighbours.
    const CameraView& v0 = keys[i == 0 ? 0 : i - 1].view;
    const CameraView& v1 = keys[i].view;
    const CameraView& v2 = keys[i + 1].view;
    const CameraView& v3 = keys[std::min(i + 2, keys.size() - 1)].view;

    CameraView view;
    view.position = catmull_rom(v0.position, v1.position, v2.position, v3.position, s);
    view.target = catmull_rom(v0.target, v1.target, v2.target, v3.target, s);
    const auto s_float = static_cast<float>(s);
    view.fov_degrees =
        catmull_rom(v0.fov_degrees, v1.fov_degrees, v2.fov_degrees, v3.fov_degrees, s_float);
    // Opposite ups blend to nothing halfway; the segment's own ups then decide the roll.
    const glm::vec3 blended_up = (1.0f - s_float) * v1.up + s_float * v2.up;
    return finish_view(view, {blended_up, s < 0.5 ? v1.up : v2.up, s < 0.5 ? v2.up : v1.up},
                       min_fov_degrees(std::min(v1.fov_degrees, v2.fov_degrees)));
}

}  // namespace

glm::vec3 least_aligned_axis(glm::vec3 direction) {
    const glm::vec3 magnitude = glm::abs(direction);
    if (magnitude.x <= magnitude.y && magnitude.x <= magnitude.z) {
        return {1.0f, 0.0f, 0.0f};
    }
    if (magnitude.y <= magnitude.z) {
        return {0.0f, 1.0f, 0.0f};
    }
    return {0.0f, 0.0f, 1.0f};
}

bool up_defines_roll(glm::vec3 forward, glm::vec3 up) {
    const float up_length = glm::length(up);
    if (!(up_length > 0.0f) || !std::isfinite(up_length)) return false;
    return glm::length(glm::cross(forward, up)) > kMinUpSine * up_length;
}

CameraBasis camera_basis(const CameraView& view) {
    CameraBasis basis;
    basis.eye = view.position;
    // The difference in double (a deep zoom's target - position is far below float's resolution
    // of the coordinates), normalised in float: for float coordinates the difference is exact in
    // double, so its rounding is float's own subtraction and float views keep their basis bit for
    // bit.
    basis.forward = glm::normalize(glm::vec3(view.target - view.position));
    glm::vec3 side = glm::cross(basis.forward, view.up);
    if (!up_defines_roll(basis.forward, view.up)) {
        // Looking along the up hint: any roll is as good as another, but it must be finite.
        side = glm::cross(basis.forward, least_aligned_axis(basis.forward));
    }
    basis.right = glm::normalize(side);
    basis.up = glm::cross(basis.right, basis.forward);
    basis.tan_half_fov = std::tan(glm::radians(view.fov_degrees) / 2.0f);
    return basis;
}

float pixel_angle(const CameraBasis& basis, int width) {
    return 2.0f * basis.tan_half_fov / static_cast<float>(width);
}

glm::vec3 primary_ray_direction(const CameraBasis& basis, int width, int height, float px,
                                float py) {
    const auto w = static_cast<float>(width);
    const auto h = static_cast<float>(height);
    // The reference renderer's formula, operation for operation, so both trace the same rays.
    const float u = (2.0f * (px + 0.5f) / w - 1.0f) * basis.tan_half_fov;
    const float v = (1.0f - 2.0f * (py + 0.5f) / h) * basis.tan_half_fov * h / w;
    return glm::normalize(basis.forward + basis.right * u + basis.up * v);
}

CameraView evaluate_camera_path(const CameraPath& path, double time) {
    const std::vector<Keyframe>& keys = path.keyframes;
    if (keys.empty()) {
        throw std::invalid_argument("camera path '" + path.name + "' has no keyframes");
    }
    // Written so a NaN time lands on the first keyframe rather than indexing out of range.
    if (!(time > keys.front().time)) {
        const CameraView& first = keys.front().view;
        return finish_view(first, {first.up}, min_fov_degrees(first.fov_degrees));
    }
    if (time >= keys.back().time) {
        const CameraView& last = keys.back().view;
        return finish_view(last, {last.up}, min_fov_degrees(last.fov_degrees));
    }
    const auto after = std::upper_bound(keys.begin(), keys.end(), time,
                                        [](double t, const Keyframe& key) { return t < key.time; });
    const auto i = static_cast<std::size_t>(after - keys.begin()) - 1;
    const double start = keys[i].time;
    const double s = (time - start) / (double(keys[i + 1].time) - start);
    return interpolate_segment(keys, i, s);
}

bool finer_than_float(float footprint, float magnitude) {
    const float float_step = std::max(magnitude, std::numeric_limits<float>::min()) *
                             std::numeric_limits<float>::epsilon();
    return footprint < 16.0f * float_step;
}

bool needs_double_precision(const CameraView& view, int width) {
    const CameraBasis basis = camera_basis(view);
    const auto footprint =
        static_cast<float>(glm::length(view.target - view.position) * pixel_angle(basis, width));
    return finer_than_float(footprint, static_cast<float>(std::max(glm::length(view.position),
                                                                   glm::length(view.target))));
}

}  // namespace fgr
