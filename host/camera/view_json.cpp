// SPDX-License-Identifier: Apache-2.0
#include "camera/view_json.hpp"

#include "camera/view_validation.hpp"
#include "util/json_fields.hpp"

namespace fgr::json_fields {

using nlohmann::json;

json view_json(const CameraView& view) {
    return {{"position", vec3_json(view.position)},
            {"target", vec3_json(view.target)},
            {"up", vec3_json(view.up)},
            {"fov", view.fov_degrees}};
}

json keyframes_json(const std::vector<Keyframe>& keyframes) {
    json entries = json::array();
    for (const Keyframe& keyframe : keyframes) {
        json entry = view_json(keyframe.view);
        entry["time"] = keyframe.time;
        entries.push_back(entry);
    }
    return entries;
}

CameraView view_from(const json& entry, const std::string& where) {
    CameraView view;
    view.position = dvec3_from(entry, "position", where);
    view.target = dvec3_from(entry, "target", where);
    view.up = entry.contains("up") ? glm::vec3(dvec3_from(entry, "up", where)) : glm::vec3(0, 0, 1);
    if (entry.contains("fov")) {
        view.fov_degrees = static_cast<float>(finite_double(entry.at("fov"), where + " \"fov\""));
    }
    // The check plugins' cameras and keyframes get (view_validation.hpp).
    if (const std::string problem = view_problem(view); !problem.empty()) {
        fail(where + ": " + problem);
    }
    return view;
}

}  // namespace fgr::json_fields
