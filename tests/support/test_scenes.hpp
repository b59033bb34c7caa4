// SPDX-License-Identifier: Apache-2.0
#pragma once
// Scenes for tests: built directly in C++ (no plugin) where a known, tiny DE is needed, or loaded
// from the plugins this build made.

#include <spdlog/spdlog.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/discovery.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/scene.hpp"

namespace fgr::test {

// Every scene this build's plugin folder holds, discovered once per test process (quietly: the
// discovery's own log lines would bury the test output).
// The formula scene the scene-wide suites take: a hybrid, so the generated loop's turns between
// formulas run at every packet width too.
inline constexpr const char* kFormulaSceneInSuites = "quaternion-bulb";

inline const std::vector<Scene>& all_scenes() {
    static const std::vector<Scene> scenes = [] {
        spdlog::set_level(spdlog::level::err);
        auto found = discover_scenes({FGR_TEST_PLUGIN_DIR}).scenes;
        spdlog::set_level(spdlog::level::info);
        // The 36 formula scenes share one generated shape of source: each is checked by `fgr check`
        // (SceneCheck.*.formula.json, packet widths included); the suites here that compile every
        // scene at every width take one of them, not all (they would double CI's time).
        std::erase_if(found, [](const Scene& scene) {
            return is_formula_file_name(scene.plugin_file) && scene.id != kFormulaSceneInSuites;
        });
        return found;
    }();
    return scenes;
}

// A plugin of this build (FGR_TEST_PLUGIN_DIR), e.g. "mandelbulb.so"; throws with the reason when
// it does not load.
inline Scene built_scene(const std::string& file) {
    LoadResult loaded = load_scene_plugin(std::filesystem::path(FGR_TEST_PLUGIN_DIR) / file);
    if (!loaded.scene) throw std::runtime_error(file + ": " + loaded.error);
    return std::move(*loaded.scene);
}

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
    Scene scene =
        inline_scene("real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_radius; }");
    ParamInfo radius;
    radius.id = "radius";
    radius.type = ParamType::Float;
    radius.min_value = 0.1f;
    radius.max_value = 2.0f;
    radius.default_value = {0.4f, 0.0f, 0.0f};
    scene.params.insert(scene.params.begin(), radius);
    return scene;
}

// The unit ball given by an inside test alone (no DE: it renders only in the brute mode).
inline Scene inside_ball_scene() {
    Scene scene = inline_scene(R"(
#define FGR_SCENE_INSIDE_ONLY
mask scene_inside(vec3 p, PARAMS) {
    (void)fgr_params;
    return v3_length(p) < 1.0f;
}
)");
    scene.default_mode = RenderMode::Brute;
    return scene;
}

}  // namespace fgr::test
