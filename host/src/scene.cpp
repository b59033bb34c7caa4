#include "fgr/scene.hpp"

#include <algorithm>

namespace fgr {

int param_components(ParamType type) {
    switch (type) {
        case ParamType::Float:
        case ParamType::Int:
        case ParamType::Bool:
            return 1;
        case ParamType::Vec3:
        case ParamType::Colour:
            return 3;
    }
    return 1;
}

const char* param_type_name(ParamType type) {
    switch (type) {
        case ParamType::Float:
            return "float";
        case ParamType::Int:
            return "int";
        case ParamType::Bool:
            return "bool";
        case ParamType::Vec3:
            return "vec3";
        case ParamType::Colour:
            return "colour";
    }
    return "unknown";
}

namespace {

// Linear search: scenes have a handful of parameters and cameras, and lookups happen per command,
// not per pixel.
template <typename Item, typename Key>
const Item* find_by(const std::vector<Item>& items, const std::string& wanted, Key key) {
    auto found = std::find_if(items.begin(), items.end(),
                              [&](const Item& item) { return key(item) == wanted; });
    return found == items.end() ? nullptr : &*found;
}

ParamInfo builtin_param(std::string id, std::string label, ParamType type, float min_value,
                        float max_value, float default_value, std::string description) {
    ParamInfo param;
    param.id = std::move(id);
    param.label = std::move(label);
    param.group = "Quality";
    param.description = std::move(description);
    param.type = type;
    param.min_value = min_value;
    param.max_value = max_value;
    param.default_value = {default_value, 0.0f, 0.0f};
    param.builtin = true;
    return param;
}

}  // namespace

const ParamInfo* Scene::find_param(const std::string& param_id) const {
    return find_by(params, param_id, [](const ParamInfo& param) { return param.id; });
}

const NamedCamera* Scene::find_camera(const std::string& camera_name) const {
    return find_by(cameras, camera_name, [](const NamedCamera& camera) { return camera.name; });
}

const CameraPath* Scene::find_camera_path(const std::string& path_name) const {
    return find_by(camera_paths, path_name, [](const CameraPath& path) { return path.name; });
}

bool is_builtin_param_id(std::string_view id) {
    Scene probe;
    add_builtin_params(probe);
    return probe.find_param(std::string(id)) != nullptr;
}

void add_builtin_params(Scene& scene) {
    const MarchSettings& march = scene.march;
    scene.params.push_back(builtin_param("max_steps", "Max steps", ParamType::Int, 1.0f, 100000.0f,
                                         static_cast<float>(march.max_steps),
                                         "distance estimator evaluations per ray at most"));
    scene.params.push_back(builtin_param("max_distance", "Max distance", ParamType::Float, 0.001f,
                                         1e6f, march.max_distance,
                                         "rays stop beyond this distance from the camera"));
    scene.params.push_back(builtin_param("hit_threshold", "Hit threshold", ParamType::Float, 0.001f,
                                         1000.0f, march.hit_threshold,
                                         "hit when DE < threshold * pixel footprint"));
    scene.params.push_back(builtin_param("iterations", "Iterations", ParamType::Int, 1.0f, 1000.0f,
                                         static_cast<float>(march.de_iterations),
                                         "distance estimator iterations"));
    scene.params.push_back(builtin_param("step_factor", "Step factor", ParamType::Float, 0.05f,
                                         1.0f, march.step_factor,
                                         "rays advance step_factor * DE (< 1 for estimated DEs)"));
}

}  // namespace fgr
