// SPDX-License-Identifier: Apache-2.0
#pragma once
// A viewpoint typed on the command line (`--eye X,Y,Z --target X,Y,Z [--up X,Y,Z] [--fov DEG]`
// of fgr render, view and bench): the texts parsed, and laid over a scene's camera.

#include <glm/vec3.hpp>
#include <optional>
#include <string>

#include "camera/view.hpp"

namespace fgr {

// The options as typed; each one left out keeps the camera's own value.
struct ViewOverrideText {
    std::optional<std::string> eye;
    std::optional<std::string> target;
    std::optional<std::string> up;
    std::optional<std::string> fov;

    bool empty() const { return !eye && !target && !up && !fov; }
};

struct ViewOverride {
    std::optional<glm::dvec3> eye;  // double, as camera path files keep positions
    std::optional<glm::dvec3> target;
    std::optional<glm::vec3> up;
    std::optional<float> fov_degrees;  // horizontal
};

// Parses each option given. Throws std::invalid_argument with one line naming the option and what
// it needs: a vector is three finite numbers "X,Y,Z"; the fov a number of degrees in (0, 180).
ViewOverride parse_view_override(const ViewOverrideText& text);

// `base` with the fields the override gives replaced. Throws std::invalid_argument when the view
// cannot be rendered (view_problem: eye at the target, up zero or parallel to the view
// direction...), saying why and with which eye, target, up and fov.
CameraView apply_view_override(const CameraView& base, const ViewOverride& override_view);

}  // namespace fgr
