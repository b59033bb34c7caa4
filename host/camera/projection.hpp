// SPDX-License-Identifier: Apache-2.0
#pragma once
// Cameras beyond the pinhole: how image pixels map to rays. The kernel's camera
// (kernels/modes/fgr_camera.cl: camera_view_point, primary_direction, camera_origin) does the same
// maths per lane; these host versions are its mirror, for tests and for the pixel footprint
// every mode's hit threshold is scaled by.
//
// Layouts:
//   pinhole          the view's horizontal fov across the image's width
//   equirectangular  the whole sphere: longitude -180..180 degrees across the width (the view's
//                    direction at the centre, behind the camera at both edges), latitude 90..-90
//                    down the height; a 2:1 image has square pixels. The fov is not used.
//   fisheye          equidistant: the angle from the view's direction grows in proportion to the
//                    distance from the image's centre, reaching fisheye_fov / 2 at the radius of
//                    the image circle (half the shorter side). Pixels outside the circle are not
//                    rendered: black, and missed (depth -1).
//   stereo-sbs       a stereo pair side by side: left eye in the left half, right eye in the right
//                    half, each eye a pinhole with the view's fov across its half width.
//   stereo-tb        the same top/bottom: left eye on top, each eye the full width, half height.
// Stereo eyes sit eye_separation apart along the camera's right vector, centred on the view's
// position, looking along the same forward direction with off-axis (asymmetric) frusta that meet
// on the plane at distance `convergence`: zero parallax there, and no vertical parallax anywhere.

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "camera/camera.hpp"
#include "camera/view.hpp"
#include "fgr_layout_camera.h"

namespace fgr {

// The kernel's camera_frame.projection (kernels/shared/fgr_layout_camera.h).
enum class ProjectionKind {
    Pinhole = FGR_PROJECTION_PINHOLE,
    Equirectangular = FGR_PROJECTION_EQUIRECTANGULAR,
    Fisheye = FGR_PROJECTION_FISHEYE,
    StereoSideBySide = FGR_PROJECTION_STEREO_SBS,
    StereoTopBottom = FGR_PROJECTION_STEREO_TB,
};

constexpr float kDefaultFisheyeFovDegrees = 180.0f;
// The default eye separation is this fraction of the distance to the view's target (a common
// stereographers' rule of thumb: 1/30 of the distance to the nearest subject).
constexpr double kDefaultSeparationFraction = 1.0 / 30.0;

struct Projection {
    ProjectionKind kind = ProjectionKind::Pinhole;
    float fisheye_fov_degrees = kDefaultFisheyeFovDegrees;  // in (0, 360]
    std::optional<double> eye_separation;  // world units, >= 0; default: distance / 30
    std::optional<double> convergence;     // world units, > 0; default: distance to the target
    bool operator==(const Projection&) const = default;
};

// The name used on the command line and in the viewer ("pinhole", "equirectangular",
// "fisheye", "stereo-sbs", "stereo-tb").
const char* projection_name(ProjectionKind kind);
// The kind for a name or alias ("panorama" for equirectangular); std::invalid_argument naming the
// known ones for anything else.
ProjectionKind parse_projection_kind(const std::string& name);
// std::invalid_argument with a one-line reason for values out of range.
void check_projection(const Projection& projection);
bool is_stereo(ProjectionKind kind);

// A projection with its defaults resolved against a view: what the kernel's camera gets.
struct CameraModel {
    CameraBasis basis;
    ProjectionKind kind = ProjectionKind::Pinhole;
    float fisheye_half_fov = 0.0f;  // radians
    float eye_separation = 0.0f;
    float convergence = 1.0f;
};
CameraModel camera_model(const CameraView& view, const Projection& projection);

// One pixel's angular footprint (radians), the scale of every mode's hit threshold: pinhole
// 2 tan(fov / 2) / width (at the centre); equirectangular 2 pi / width; fisheye
// fov / min(width, height) (the fov across the image circle's diameter); stereo the pinhole's
// over each eye's width (side by side: half the image's).
float pixel_angle(const CameraModel& model, int width, int height);

// The unit direction of the ray through image point (px, py) (pixel (0, 0)'s centre is
// (0.5, 0.5)); nullopt outside a fisheye's image circle.
std::optional<glm::vec3> projected_ray_direction(const CameraModel& model, int width, int height,
                                                 float px, float py);
// Where that ray starts: the view's position, or a stereo pair's eye.
glm::dvec3 projected_ray_origin(const CameraModel& model, int width, int height, float px,
                                float py);

}  // namespace fgr
