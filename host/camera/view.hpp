// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a camera stands and looks: a view, a named one, and a path of keyframed views. Plain data
// that scenes carry and every front end edits; camera.hpp turns a view into rays.

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace fgr {

// Position and target are double so a view can zoom far below float's resolution (the plugin ABI
// stays float; the host converts when it copies a description).
struct CameraView {
    glm::dvec3 position{0.0};
    glm::dvec3 target{0.0};
    glm::vec3 up{0.0f, 0.0f, 1.0f};
    float fov_degrees = 60.0f;  // horizontal
    bool operator==(const CameraView&) const = default;
};

struct NamedCamera {
    std::string name;
    CameraView view;
};

struct Keyframe {
    float time = 0.0f;
    CameraView view;
};

// The most keyframes a camera path may have, wherever it comes from (a scene, an IFS file, a
// camera path file): a path of more is refused before its keyframes are read.
inline constexpr std::size_t kMaxPathKeyframes = 10000;

struct CameraPath {
    std::string name;
    std::vector<Keyframe> keyframes;  // at least two, strictly increasing time
    float duration() const { return keyframes.back().time - keyframes.front().time; }
};

}  // namespace fgr
