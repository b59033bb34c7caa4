// SPDX-License-Identifier: Apache-2.0
#pragma once
// Views in fgr's JSON files (camera path files, IFS and formula scene files): read and checked as
// plugins' cameras are, and written so they read back exactly.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "camera/view.hpp"

namespace fgr::json_fields {

// A view's "position" and "target" (required), "up" (default +z) and "fov" (horizontal degrees,
// default 60), checked by view_problem (view_validation.hpp).
CameraView view_from(const nlohmann::json& entry, const std::string& where);

// A view's "position", "target", "up" and "fov", as view_from reads them.
nlohmann::json view_json(const CameraView& view);
// A camera path's keyframes: each view with its "time".
nlohmann::json keyframes_json(const std::vector<Keyframe>& keyframes);

}  // namespace fgr::json_fields
