// SPDX-License-Identifier: Apache-2.0
#include "camera/projection.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <stdexcept>
#include <utility>

namespace fgr {
namespace {

constexpr float kPi = 3.14159265358979f;

struct NamedKind {
    const char* name;
    ProjectionKind kind;
};
constexpr std::array<NamedKind, 6> kNames{{
    {"pinhole", ProjectionKind::Pinhole},
    {"equirectangular", ProjectionKind::Equirectangular},
    {"panorama", ProjectionKind::Equirectangular},  // alias
    {"fisheye", ProjectionKind::Fisheye},
    {"stereo-sbs", ProjectionKind::StereoSideBySide},
    {"stereo-tb", ProjectionKind::StereoTopBottom},
}};

// A point of the image within the view (a stereo pair's eye) it belongs to: the kernel's
// camera_view_point.
struct ViewPoint {
    float x, y;           // in the view's pixels
    float width, height;  // the view's size
    float eye_side;       // -1 left eye, +1 right eye, 0 mono
};

ViewPoint view_point(const CameraModel& model, int width, int height, float px, float py) {
    ViewPoint point{px, py, float(width), float(height), 0.0f};
    if (model.kind == ProjectionKind::StereoSideBySide) {
        point.width *= 0.5f;
        const bool right = std::floor(px) >= point.width;
        point.x -= right ? point.width : 0.0f;
        point.eye_side = right ? 1.0f : -1.0f;
    } else if (model.kind == ProjectionKind::StereoTopBottom) {
        point.height *= 0.5f;
        const bool right = std::floor(py) >= point.height;
        point.y -= right ? point.height : 0.0f;
        point.eye_side = right ? 1.0f : -1.0f;
    }
    return point;
}

}  // namespace

const char* projection_name(ProjectionKind kind) {
    for (const NamedKind& named : kNames) {
        if (named.kind == kind) return named.name;
    }
    return "pinhole";
}

ProjectionKind parse_projection_kind(const std::string& name) {
    for (const NamedKind& named : kNames) {
        if (name == named.name) return named.kind;
    }
    throw std::invalid_argument(fmt::format(
        "unknown projection '{}': expected pinhole, equirectangular (or panorama), fisheye, "
        "stereo-sbs or stereo-tb",
        name));
}

bool is_stereo(ProjectionKind kind) {
    return kind == ProjectionKind::StereoSideBySide || kind == ProjectionKind::StereoTopBottom;
}

void check_projection(const Projection& projection) {
    if (!(projection.fisheye_fov_degrees > 0.0f && projection.fisheye_fov_degrees <= 360.0f)) {
        throw std::invalid_argument(
            fmt::format("--fisheye-fov {} is out of range: expected degrees in (0, 360]",
                        projection.fisheye_fov_degrees));
    }
    if (projection.eye_separation &&
        !(*projection.eye_separation >= 0.0 && std::isfinite(*projection.eye_separation))) {
        throw std::invalid_argument(
            fmt::format("--eye-separation {} is out of range: expected a distance >= 0",
                        *projection.eye_separation));
    }
    if (projection.convergence &&
        !(*projection.convergence > 0.0 && std::isfinite(*projection.convergence))) {
        throw std::invalid_argument(fmt::format(
            "--convergence {} is out of range: expected a distance > 0", *projection.convergence));
    }
}

CameraModel camera_model(const CameraView& view, const Projection& projection) {
    CameraModel model;
    model.basis = camera_basis(view);
    model.kind = projection.kind;
    model.fisheye_half_fov = glm::radians(projection.fisheye_fov_degrees) * 0.5f;
    const double distance = glm::length(view.target - view.position);
    model.eye_separation =
        float(projection.eye_separation.value_or(distance * kDefaultSeparationFraction));
    model.convergence = float(projection.convergence.value_or(distance));
    return model;
}

float pixel_angle(const CameraModel& model, int width, int height) {
    switch (model.kind) {
        case ProjectionKind::Equirectangular:
            return 2.0f * kPi / float(width);
        case ProjectionKind::Fisheye:
            return 2.0f * model.fisheye_half_fov / float(std::min(width, height));
        case ProjectionKind::StereoSideBySide:
            return 2.0f * model.basis.tan_half_fov / (0.5f * float(width));
        case ProjectionKind::StereoTopBottom:
        case ProjectionKind::Pinhole:
            break;
    }
    return pixel_angle(model.basis, width);
}

std::optional<glm::vec3> projected_ray_direction(const CameraModel& model, int width, int height,
                                                 float px, float py) {
    const CameraBasis& b = model.basis;
    const ViewPoint point = view_point(model, width, height, px, py);
    if (model.kind == ProjectionKind::Equirectangular) {
        const float longitude = (2.0f * point.x / point.width - 1.0f) * kPi;
        const float latitude = (1.0f - 2.0f * point.y / point.height) * 0.5f * kPi;
        return std::cos(latitude) *
                   (std::sin(longitude) * b.right + std::cos(longitude) * b.forward) +
               std::sin(latitude) * b.up;
    }
    if (model.kind == ProjectionKind::Fisheye) {
        const float radius = 0.5f * std::min(point.width, point.height);
        const float dx = (point.x - 0.5f * point.width) / radius;
        const float dy = (0.5f * point.height - point.y) / radius;
        const float r = std::sqrt(dx * dx + dy * dy);
        if (r > 1.0f) return std::nullopt;
        const float theta = r * model.fisheye_half_fov;
        const float across = r > 1e-7f ? std::sin(theta) / r : model.fisheye_half_fov;
        return glm::normalize(std::cos(theta) * b.forward + across * (dx * b.right + dy * b.up));
    }
    // Pinhole and each stereo eye: an off-axis frustum whose centre line crosses the view's axis
    // at the convergence distance.
    const float shift = -point.eye_side * 0.5f * model.eye_separation / model.convergence;
    const float u = (2.0f * point.x / point.width - 1.0f) * b.tan_half_fov + shift;
    const float v =
        (1.0f - 2.0f * point.y / point.height) * b.tan_half_fov * point.height / point.width;
    return glm::normalize(b.forward + b.right * u + b.up * v);
}

glm::dvec3 projected_ray_origin(const CameraModel& model, int width, int height, float px,
                                float py) {
    const ViewPoint point = view_point(model, width, height, px, py);
    return model.basis.eye +
           glm::dvec3(model.basis.right) * double(point.eye_side * 0.5f * model.eye_separation);
}

}  // namespace fgr
