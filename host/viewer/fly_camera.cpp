// SPDX-License-Identifier: Apache-2.0
#include "viewer/fly_camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "camera/camera.hpp"

namespace fgr::viewer {
namespace {

// Below this length a vector is treated as having no usable direction.
constexpr float kDegenerateLength = 1e-6f;

constexpr float kHalfPi = std::numbers::pi_v<float> / 2.0f;
// Highest elevation above (or below) the horizon the view direction may reach.
constexpr float kMaxElevation = kHalfPi - kMinPoleAngle;

const glm::vec3 kDefaultUp{0.0f, 0.0f, 1.0f};

bool usable(glm::vec3 vector) {
    const float length = glm::length(vector);
    return std::isfinite(length) && length > kDegenerateLength;
}

// A view direction split into a compass heading and an angle above the horizon. Turning works on
// these two rather than on the vector so that yaw never changes elevation, pitch never changes
// heading, and clamping the elevation is exact.
struct Heading {
    glm::vec3 horizontal;  // unit, orthogonal to world up
    float elevation;       // radians, positive above the horizon
};

Heading split_direction(glm::vec3 direction, glm::vec3 world_up) {
    const float along_up = glm::dot(direction, world_up);
    const glm::vec3 horizontal = direction - world_up * along_up;
    if (usable(horizontal)) {
        return {glm::normalize(horizontal), std::atan2(along_up, glm::length(horizontal))};
    }
    // Straight up or down (or no direction at all) has no heading of its own; any will do.
    const glm::vec3 axis = least_aligned_axis(world_up);
    const glm::vec3 any_heading = glm::normalize(axis - world_up * glm::dot(axis, world_up));
    const float vertical = along_up > 0.0f ? kHalfPi : (along_up < 0.0f ? -kHalfPi : 0.0f);
    return {any_heading, vertical};
}

// The unit direction of `heading`, its elevation kept kMinPoleAngle away from the poles.
glm::vec3 join_direction(const Heading& heading, glm::vec3 world_up) {
    const float elevation = std::clamp(heading.elevation, -kMaxElevation, kMaxElevation);
    return heading.horizontal * std::cos(elevation) + world_up * std::sin(elevation);
}

}  // namespace

FlyCamera FlyCamera::from_view(const CameraView& view) {
    FlyCamera camera;
    camera.position = view.position;
    camera.fov_degrees = view.fov_degrees;
    camera.world_up = usable(view.up) ? glm::normalize(view.up) : kDefaultUp;

    // In double: a deep zoom's target may lie closer than float resolves at the coordinates.
    const glm::dvec3 to_target = view.target - view.position;
    const double distance = glm::length(to_target);
    const bool has_direction = std::isfinite(distance) && distance > 0.0;
    if (has_direction) {
        camera.target_distance = distance;
    }
    // Without a target direction, look along the horizon.
    const glm::vec3 direction = has_direction ? glm::vec3(to_target / distance) : glm::vec3(0.0f);
    camera.forward = join_direction(split_direction(direction, camera.world_up), camera.world_up);
    return camera;
}

CameraView FlyCamera::to_view() const {
    CameraView view;
    view.position = position;
    view.target = position + glm::dvec3(forward) * target_distance;
    view.up = world_up;
    view.fov_degrees = fov_degrees;
    return view;
}

glm::vec3 FlyCamera::right() const {
    const glm::vec3 side = glm::cross(forward, world_up);
    if (usable(side)) {
        return glm::normalize(side);
    }
    // Only reachable when forward was set by hand along world up: keep the basis finite.
    return glm::normalize(glm::cross(forward, least_aligned_axis(forward)));
}

glm::vec3 FlyCamera::up() const { return glm::cross(right(), forward); }

void FlyCamera::turn(float yaw_radians, float pitch_radians) {
    // A broken input device must not leave the camera looking nowhere.
    const float yaw = std::isfinite(yaw_radians) ? yaw_radians : 0.0f;
    const float pitch = std::isfinite(pitch_radians) ? pitch_radians : 0.0f;

    Heading heading = split_direction(forward, world_up);
    // Rotating the heading towards its right (cross(heading, up)) is a clockwise turn seen from
    // above, which is what a positive yaw means.
    const glm::vec3 heading_right = glm::cross(heading.horizontal, world_up);
    heading.horizontal = heading.horizontal * std::cos(yaw) + heading_right * std::sin(yaw);
    heading.elevation += pitch;
    forward = join_direction(heading, world_up);
}

void FlyCamera::move(glm::vec3 local, double distance) {
    if (!usable(local) || !std::isfinite(distance)) {
        return;
    }
    const glm::vec3 unit = glm::normalize(local);
    position += glm::dvec3(right() * unit.x + forward * unit.y + world_up * unit.z) * distance;
}

double travel_speed(double de_at_camera, double speed_factor) {
    const double speed = de_at_camera * speed_factor;
    // Written so that NaN (a DE probe that failed) and infinities fall back to the floor too.
    if (!std::isfinite(speed) || !(speed > kMinSpeed)) {
        return kMinSpeed;
    }
    return speed;
}

double limit_step(double step, double de_at_camera) {
    if (!std::isfinite(de_at_camera) || !(de_at_camera > 0.0)) {
        return step;
    }
    // The magnitude is what matters: a step backwards can reach a surface behind the camera.
    const double half_de = 0.5 * de_at_camera;
    return std::clamp(step, -half_de, half_de);
}

}  // namespace fgr::viewer
