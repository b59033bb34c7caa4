// SPDX-License-Identifier: Apache-2.0
#pragma once
// The limits and naming rules every scene keeps, whatever it comes from: a plugin's description
// (description_validation.cpp) or a JSON scene file (scene_json.cpp). The host enforces them;
// they are not part of the plugin ABI.

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "camera/view.hpp"

namespace fgr {

namespace scene_limits {

// Scene ids, parameter ids, camera and camera path names.
inline constexpr std::size_t kMaxIdLength = 63;
// Free text (names, labels, descriptions): it also bounds how far strnlen reads when a plugin
// forgot a terminating NUL.
inline constexpr std::size_t kMaxTextLength = 4096;
// A scene's OpenCL source (and so a whole text scene file, whose source it is).
inline constexpr std::size_t kMaxSourceBytes = std::size_t{4} << 20;

inline constexpr std::uint32_t kMaxCameras = 256;
inline constexpr std::uint32_t kMaxCameraPaths = 256;
inline constexpr std::uint32_t kMinKeyframes = 2;
inline constexpr std::uint32_t kMaxKeyframes = kMaxPathKeyframes;
inline constexpr std::uint32_t kMaxLights = 16;
inline constexpr float kMaxAngularRadiusDegrees = 45.0f;

// What a refusal says after a bad scene id or camera (path) name it quotes.
inline constexpr std::string_view kSceneIdRule = "must match [a-z][a-z0-9_-]*";
inline constexpr std::string_view kCameraNameRule = "must match [a-z0-9_-]+";

}  // namespace scene_limits

// Scene ids match [a-z][a-z0-9_-]*, camera and camera path names [a-z0-9_-]+, both at most
// kMaxIdLength characters.
bool is_scene_id(std::string_view id);
bool is_camera_name(std::string_view name);

}  // namespace fgr
