// SPDX-License-Identifier: Apache-2.0
#pragma once
// The host's own copy of a scene description: everything a plugin described, validated and owned
// by the host, so the plugin's memory is never touched after loading.

#include <array>
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "camera/view.hpp"
#include "scene/render_mode.hpp"

namespace fgr {

struct IfsScene;  // scene/ifs/ifs.hpp

enum class ParamType { Float, Int, Bool, Vec3, Colour };

struct ParamInfo {
    std::string id;
    std::string label{};  // optional: the loader falls back to the id
    std::string group{};  // optional: the loader falls back to "Scene"
    std::string description{};
    ParamType type = ParamType::Float;
    float min_value = 0.0f;
    float max_value = 1.0f;
    std::array<float, 3> default_value{};
    std::vector<std::string> choices{};  // Int only: names of min..max, empty when not an enum
    bool builtin = false;                // a quality knob the host adds to every scene
    bool scene_default = false;          // builtin whose default the scene gave (ABI 1.4)
    // Enums only: which choices the scene offers (ABI 1.4 colour_modes), empty when all are. A
    // value not offered is refused and not listed, but keeps its number (the kernel's).
    std::vector<bool> offered{};
};

// Whether an enum parameter offers its choice `index` (every choice when `offered` is empty).
bool choice_offered(const ParamInfo& param, std::size_t index);
// The offered choices' names, "a|b|c".
std::string offered_choices_text(const ParamInfo& param);

// Floats a parameter occupies in the kernel's parameter buffer.
int param_components(ParamType type);
const char* param_type_name(ParamType type);

enum class LightType { Directional, Point };

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 vector{0.0f, 0.0f, 1.0f};  // towards the light (directional) or position (point)
    glm::vec3 colour{1.0f};
    float intensity = 1.0f;
    // Directional lights: the angular radius of the light's disc (ABI 1.2), 0 for a point-like
    // light and always 0 for point lights. The path mode samples the disc; the shaded mode ignores
    // it.
    float angular_radius = 0.0f;  // radians
};

struct MarchSettings {
    uint32_t max_steps = 256;
    float max_distance = 10.0f;
    float hit_threshold = 1.0f;  // in pixel footprints
    uint32_t de_iterations = 12;
    float step_factor = 1.0f;  // rays advance step_factor * DE
};

struct Scene {
    std::string id;
    std::string name;
    std::string description;
    // Words to find the scene by (`fgr list`): a formula scene's families and traits. Plugins
    // have none (ABI 1.x carries no tags).
    std::vector<std::string> tags;
    std::string source;       // OpenCL C source of the DE or inside test (and optional colour)
    std::string source_name;  // file name shown in compiler messages
    std::filesystem::path plugin_file;
    std::vector<ParamInfo> params;     // the scene's own, then the built-in quality knobs
    std::vector<NamedCamera> cameras;  // [0] is the default view
    std::vector<CameraPath> camera_paths;
    std::vector<Light> lights;
    uint64_t effects = 0;
    MarchSettings march;
    RenderMode default_mode = RenderMode::Shaded;  // what the scene asks for (ABI 1.2)
    // The scene's length scale (ABI 1.4): the distance-like built-ins' defaults follow it (see
    // set_scene_scale). 1 unless the scene gives one.
    float scale = 1.0f;
    // The environment the path mode lights the scene with when the user names none (ABI 1.5, a
    // scene file's "environment"): sky, studio, uniform, uniform:V or uniform:R,G,B, checked by
    // check_scene_environment (scene/environment_spec.hpp); "" for none, the sky.
    std::string environment;
    // The maps of a scene read from an IFS file (scene/ifs/ifs.hpp); null for distance-estimated
    // scenes.
    std::shared_ptr<const IfsScene> ifs;

    // Whether the source defines only an inside test (`#define FGR_SCENE_INSIDE_ONLY`, see
    // kernels/geometry/fgr_geometry.cl): such a scene renders only in the brute-force mode.
    bool inside_only() const;
    // A distance estimator to march: not for IFS scenes (traced exactly) nor inside-only ones.
    bool has_distance_estimator() const;
    // Whether the source gives the DE at two points in one call (`#define FGR_SCENE_HAS_DE_PAIR`
    // and scene_de_pair, see kernels/geometry/fgr_geometry.cl).
    bool pairs_distances() const;

    const ParamInfo* find_param(const std::string& param_id) const;
    const NamedCamera* find_camera(const std::string& camera_name) const;
    const CameraPath* find_camera_path(const std::string& path_name) const;
};

// Appends the built-in quality parameters (max_steps, max_distance, hit_threshold, iterations,
// step_factor) with defaults from the scene's march settings.
void add_builtin_params(Scene& scene);

// Sets the scene's length scale and with it the defaults of the distance-like built-ins
// (ao_radius, glow_radius and aperture scale with it, the per-length rates fog_density and
// absorption inversely), each clamped to its range. Call after add_builtin_params and before any
// scene-given default replaces one of them.
void set_scene_scale(Scene& scene, float scale);

// The built-ins whose defaults are the scene's march settings: a scene gives them there.
bool is_march_builtin_id(std::string_view id);

// Whether some mode the scene offers reads the parameter, so a list or a panel shows it. A scene's
// own parameters always apply; of the built-ins, an IFS scene (traced exactly, shaded and path
// modes) reads no DE iterations, step_factor, over_relaxation, normal_epsilon nor brute-force
// settings, and an inside-only scene (brute force alone) no max_steps, step_factor,
// over_relaxation nor normal_epsilon.
bool param_applies(const Scene& scene, const ParamInfo& param);

// Whether `id` names one of those built-in parameters (a scene may not declare it).
bool is_builtin_param_id(std::string_view id);

// How many built-in parameters add_builtin_params appends.
std::size_t builtin_param_count();

}  // namespace fgr
