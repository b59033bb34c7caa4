// SPDX-License-Identifier: Apache-2.0
#include "camera/view_validation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "camera/camera.hpp"

namespace fgr {
namespace {

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
// Position and target are double on the host; the kernel gets them as floats (plus the rest), so
// they must be finite as floats too.
bool finite(glm::dvec3 v) { return finite(glm::vec3(v)); }

// A unit vector within float rounding.
bool unit(glm::vec3 v) { return finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-3f; }

// Finite numbers, an fov a pinhole camera has, and a view direction float can normalise: what
// every view needs, given or computed.
std::string direction_problem(const CameraView& view) {
    if (!finite(view.position) || !finite(view.target) || !finite(view.up) ||
        !std::isfinite(view.fov_degrees)) {
        return "numbers not finite";
    }
    if (!(view.fov_degrees > 0.0f && view.fov_degrees < 180.0f)) {
        return fmt::format("fov {} outside (0, 180)", view.fov_degrees);
    }
    if (view.position == view.target) return "position equals target";
    // camera_basis normalises target - position (taken in double) in float, as the kernel's rays
    // are: its squared length must neither underflow nor overflow.
    if (!unit(glm::normalize(glm::vec3(view.target - view.position)))) {
        const double distance = glm::length(glm::dvec3(view.target) - glm::dvec3(view.position));
        return fmt::format("position and target {:.3g} apart: too {} for a camera basis in float",
                           distance, distance < 1.0 ? "close together" : "far apart");
    }
    return {};
}

std::string basis_problem(const CameraView& view) {
    const CameraBasis basis = camera_basis(view);
    const bool orthonormal = unit(basis.forward) && unit(basis.right) && unit(basis.up) &&
                             std::abs(glm::dot(basis.forward, basis.right)) < 1e-3f &&
                             std::abs(glm::dot(basis.forward, basis.up)) < 1e-3f &&
                             std::abs(glm::dot(basis.right, basis.up)) < 1e-3f;
    if (!orthonormal || !finite(basis.eye) || !std::isfinite(basis.tan_half_fov)) {
        return "camera basis not finite";
    }
    return {};
}

}  // namespace

std::string view_problem(const CameraView& view) {
    if (std::string problem = direction_problem(view); !problem.empty()) return problem;
    const glm::vec3 forward = glm::normalize(glm::vec3(view.target - view.position));
    if (!up_defines_roll(forward, view.up)) {
        if (std::isinf(glm::length(view.up))) return "up too long for float (its length overflows)";
        return "up is zero or parallel to the view direction";
    }
    return basis_problem(view);
}

std::string computed_view_problem(const CameraView& view) {
    if (std::string problem = direction_problem(view); !problem.empty()) return problem;
    return basis_problem(view);
}

}  // namespace fgr
