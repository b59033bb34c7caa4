// SPDX-License-Identifier: Apache-2.0
#pragma once
// Pinhole camera geometry: the orthonormal basis of a view, the primary ray through a pixel, and
// smooth interpolation of a view along a keyframed camera path.

#include <glm/vec3.hpp>

#include "camera/view.hpp"

namespace fgr {

struct CameraBasis {
    glm::dvec3 eye{0.0};  // double: a deep zoom's eye moves by less than float's step
    glm::vec3 forward{0.0f, 1.0f, 0.0f};
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float tan_half_fov = 1.0f;  // of the horizontal field of view
};

// The world axis least aligned with `direction`: always far from parallel to it, so a usable
// fallback up vector.
glm::vec3 least_aligned_axis(glm::vec3 direction);

// Whether `up` defines the roll of a camera looking along the unit vector `forward`: its length
// is a finite, non-zero float and its component across `forward` is more than kMinUpSine of it.
// camera_basis keeps an up that does; view_problem (view_validation.hpp) refuses a camera or
// keyframe whose up does not.
constexpr float kMinUpSine = 1e-6f;
bool up_defines_roll(glm::vec3 forward, glm::vec3 up);

// forward = normalize(target - position), right = normalize(cross(forward, view.up)),
// up = cross(right, forward). An up hint that does not define the roll (up_defines_roll) is
// replaced by a world axis, so a computed view looking along its up still gets a finite basis;
// given views with such an up are refused before they get here (view_validation.hpp).
CameraBasis camera_basis(const CameraView& view);

// Angle (radians, small-angle approximation) one pixel subtends at the image centre.
float pixel_angle(const CameraBasis& basis, int width);

// Unit direction of the ray through image point (px, py), pixel (0, 0) being the top-left one and
// (px + 0.5, py + 0.5) its centre. Square pixels: the vertical extent follows from the aspect.
glm::vec3 primary_ray_direction(const CameraBasis& basis, int width, int height, float px,
                                float py);

// Whether float is too coarse for this view: true when one pixel's footprint at the target is
// less than 16 float steps (ulps) of the coordinates there, as in a deep zoom, where float
// positions would round neighbouring pixels' rays onto the same points. `--precision auto`
// renders such views in double.
bool needs_double_precision(const CameraView& view, int width);

// The rule behind it: whether a pixel footprint is under 16 float steps of coordinates of size
// `magnitude` (the largest coordinate length involved).
bool finer_than_float(float footprint, float magnitude);

// The view at `time` along a path (clamped to the first and last keyframe times). Position, target
// and fov follow a uniform Catmull-Rom spline through the keyframes in each segment's local
// parameter (position and target in double, so a path can fly a deep zoom), the end keyframes
// doubling as their own outer neighbours; fov is kept in [1, 179], the lower bound lowered to half
// the segment's narrower keyframe fov for deep zooms' narrow views. Up is a normalised lerp of the
// segment's ups, made orthogonal to the resulting view direction. At a keyframe's time position,
// target and fov are that keyframe's, and the basis is the one the keyframe itself gives. Throws
// std::invalid_argument for a path without keyframes.
CameraView evaluate_camera_path(const CameraPath& path, double time);

}  // namespace fgr
