// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's free-flying camera: a position, a unit forward direction and the scene's world up.
// Mouse look turns forward about world up (yaw) and about the camera's right axis (pitch), never
// closer than kMinPoleAngle to straight up or down, so the view basis stays well defined.

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace fgr::viewer {

// Closest the view direction may come to world up or down, in radians (about 1 degree).
constexpr float kMinPoleAngle = 0.0175f;

struct FlyCamera {
    glm::dvec3 position{0.0};  // double: it flies deep zooms, steps far below float's
    // resolution of the coordinates
    glm::vec3 forward{0.0f, 1.0f, 0.0f};   // unit length
    glm::vec3 world_up{0.0f, 0.0f, 1.0f};  // unit length
    float fov_degrees = 60.0f;             // horizontal
    double target_distance = 1.0;          // how far ahead to_view() puts the target (> 0)

    // From a scene camera: forward towards its target, its up as world up (a forward within
    // kMinPoleAngle of that up is tilted away from it), target_distance = |target - position|.
    static FlyCamera from_view(const CameraView& view);

    // position, position + forward * target_distance, world_up, fov.
    CameraView to_view() const;

    // Unit vectors: right = normalize(cross(forward, world_up)); up = cross(right, forward).
    glm::vec3 right() const;
    glm::vec3 up() const;

    // Turns by yaw_radians about world up (positive turns right) and pitch_radians about right
    // (positive looks up), pitch clamped so forward stays kMinPoleAngle away from the poles.
    void turn(float yaw_radians, float pitch_radians);

    // Moves by `distance` along right * local.x + forward * local.y + world_up * local.z, with
    // `local` normalised first (a zero `local` does nothing). In double: a step of 1e-12 still
    // moves a camera at distance 1 from the origin.
    void move(glm::vec3 local, double distance);
};

// Movement speed in scene units per second: the distance estimate at the camera times
// speed_factor (so one second at factor 1 closes the gap to the surface), at least kMinSpeed.
// The floor only catches a failed probe: it lies far below a deep zoom's distances (1e-9) and far
// above double's step at the scenes' scale (about 1e-16), so a camera can still fly there.
constexpr double kMinSpeed = 1e-12;
double travel_speed(double de_at_camera, double speed_factor);

// Caps one frame's step at half the distance estimate, so a slow frame cannot carry the camera
// through the surface; a non-finite or non-positive DE leaves the step as it is.
double limit_step(double step, double de_at_camera);

}  // namespace fgr::viewer
