// SPDX-License-Identifier: Apache-2.0
// An IFS file's scene as the rest of fgr sees it: a Scene with the maps attached (Scene::ifs), the
// depth slider, and kernel source generated from the maps (ifs_source.hpp).
#include <algorithm>
#include <glm/geometric.hpp>
#include <memory>

#include "fgr/plugin.h"
#include "scene/ifs/ifs.hpp"
#include "scene/ifs/ifs_source.hpp"
#include "scene/scene_json.hpp"

namespace fgr {
namespace {

// Rays need to reach across the bounding sphere from every view the scene names: the farthest
// camera or keyframe's distance to the centre plus the sphere's diameter, at least 10, at most
// the built-in parameter's 1e6.
float max_distance_for(const IfsScene& ifs) {
    double farthest = 0.0;
    const auto include = [&](const CameraView& view) {
        farthest = std::max(farthest, glm::length(view.position - ifs.bounds.centre));
    };
    for (const NamedCamera& camera : ifs.cameras) include(camera.view);
    for (const CameraPath& path : ifs.camera_paths) {
        for (const Keyframe& keyframe : path.keyframes) include(keyframe.view);
    }
    return static_cast<float>(std::clamp(farthest + 2.0 * ifs.bounds.radius, 10.0, 1e6));
}

ParamInfo depth_param(const IfsScene& ifs) {
    ParamInfo param;
    param.id = "ifs_depth";
    param.label = "Depth";
    param.group = "IFS";
    param.description =
        "the most levels of maps applied before a node's bounding ellipsoid counts as the "
        "surface; nodes smaller than a pixel stop sooner";
    param.type = ParamType::Int;
    param.min_value = 0.0f;
    param.max_value = static_cast<float>(ifs.max_depth);
    param.default_value = {static_cast<float>(ifs.default_depth), 0.0f, 0.0f};
    return param;
}

}  // namespace

Scene ifs_scene_to_scene(const IfsScene& ifs, const std::filesystem::path& file) {
    Scene scene = scene_json::scene_of_file(ifs, ifs_kernel_source(ifs), ".ifs.cl", file);
    scene.effects = FGR_EFFECT_SHADOWS;  // exact any-hit shadow rays are cheap
    scene.march.max_distance = max_distance_for(ifs);
    scene.default_mode = RenderMode::Shaded;
    scene.params.push_back(depth_param(ifs));
    add_builtin_params(scene);
    scene.ifs = std::make_shared<const IfsScene>(ifs);
    return scene;
}

}  // namespace fgr
