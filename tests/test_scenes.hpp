#pragma once
// Scenes built directly in C++ (no plugin) for tests that need a known, tiny DE.

#include <string>

#include "fgr/scene.hpp"

namespace fgr::test {

inline Scene inline_scene(std::string source) {
    Scene scene;
    scene.id = "inline";
    scene.name = "Inline";
    scene.source = std::move(source);
    scene.source_name = "inline.cl";
    CameraView view;
    view.position = {0.0f, -3.0f, 0.0f};
    view.target = {0.0f, 0.0f, 0.0f};
    view.up = {0.0f, 0.0f, 1.0f};
    view.fov_degrees = 60.0f;
    scene.cameras.push_back({"front", view});
    scene.lights.push_back(Light{});
    add_builtin_params(scene);
    return scene;
}

// A sphere of radius `radius` at the origin.
inline Scene sphere_scene() {
    Scene scene = inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }");
    ParamInfo radius;
    radius.id = "radius";
    radius.type = ParamType::Float;
    radius.min_value = 0.1f;
    radius.max_value = 2.0f;
    radius.default_value = {0.4f, 0.0f, 0.0f};
    scene.params.insert(scene.params.begin(), radius);
    return scene;
}

}  // namespace fgr::test
