// SPDX-License-Identifier: Apache-2.0
#include "scene/description_validation.hpp"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <optional>
#include <set>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "camera/view_validation.hpp"
#include "scene/effects.hpp"
#include "scene/environment_spec.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/ifs/ifs_cost.hpp"
#include "scene/kernel_api.hpp"
#include "scene/render_mode.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

// --- Limits --------------------------------------------------------------------------------------

// Sizes of the structs as ABI 1.0 defined them: the end of their last v1 field. Later minor
// versions may append fields, so these stay fixed while sizeof() may grow.
constexpr std::size_t kV1SceneDescSize =
    offsetof(fgr_scene_desc, march) + sizeof(fgr_march_settings);
constexpr std::size_t kV1ParamSize =
    offsetof(fgr_param_desc, description) + sizeof(fgr_param_desc::description);
constexpr std::size_t kV1CameraSize =
    offsetof(fgr_camera, fov_degrees) + sizeof(fgr_camera::fov_degrees);
constexpr std::size_t kV1KeyframeSize =
    offsetof(fgr_keyframe, fov_degrees) + sizeof(fgr_keyframe::fov_degrees);
constexpr std::size_t kV1CameraPathSize =
    offsetof(fgr_camera_path, keyframe_count) + sizeof(fgr_camera_path::keyframe_count);
constexpr std::size_t kV1LightSize = offsetof(fgr_light, intensity) + sizeof(fgr_light::intensity);
constexpr std::size_t kV1MarchSize =
    offsetof(fgr_march_settings, step_factor) + sizeof(fgr_march_settings::step_factor);
// ABI 1.1 appended source_length to the scene description.
constexpr std::size_t kV1_1SceneDescSize =
    offsetof(fgr_scene_desc, source_length) + sizeof(fgr_scene_desc::source_length);
// ABI 1.2 appended default_mode to the scene description and angular_radius_degrees to lights.
constexpr std::size_t kV1_2SceneDescSize =
    offsetof(fgr_scene_desc, default_mode) + sizeof(fgr_scene_desc::default_mode);
constexpr std::size_t kV1_2LightSize =
    offsetof(fgr_light, angular_radius_degrees) + sizeof(fgr_light::angular_radius_degrees);
// ABI 1.3 appended IFS maps to the scene description; fgr_ifs_map came with it.
constexpr std::size_t kV1_3SceneDescSize =
    offsetof(fgr_scene_desc, ifs_max_depth) + sizeof(fgr_scene_desc::ifs_max_depth);
constexpr std::size_t kV1_3IfsMapSize = offsetof(fgr_ifs_map, colour) + sizeof(fgr_ifs_map::colour);
// ABI 1.4 appended built-in defaults, colour modes and the length scale to the scene description;
// fgr_builtin_default came with it.
constexpr std::size_t kV1_4SceneDescSize =
    offsetof(fgr_scene_desc, scale) + sizeof(fgr_scene_desc::scale);
constexpr std::size_t kV1_4BuiltinDefaultSize =
    offsetof(fgr_builtin_default, value) + sizeof(fgr_builtin_default::value);
// ABI 1.5 appended the scene's own environment to the scene description.
constexpr std::size_t kV1_5SceneDescSize =
    offsetof(fgr_scene_desc, environment) + sizeof(fgr_scene_desc::environment);

// The limits a scene file has too are in scene_limits.hpp; these are a plugin's alone.
using scene_limits::kMaxAngularRadiusDegrees;
using scene_limits::kMaxCameraPaths;
using scene_limits::kMaxCameras;
using scene_limits::kMaxIdLength;
using scene_limits::kMaxKeyframes;
using scene_limits::kMaxLights;
using scene_limits::kMaxSourceBytes;
using scene_limits::kMaxTextLength;
using scene_limits::kMinKeyframes;

// Like kMaxTextLength, not in the ABI: it only bounds how far strnlen reads when a plugin forgot
// a terminating NUL.
constexpr std::size_t kMaxChoicesLength = 64 * 1024;

constexpr uint32_t kMaxParams = 1024;
constexpr uint32_t kMaxMarchSteps = 100000;
constexpr uint32_t kMaxDeIterations = 1000;
constexpr uint32_t kMaxBuiltinDefaults = 64;
constexpr float kMinScale = 1e-6f;
constexpr float kMaxScale = 1e6f;

// --- Failure reporting ---------------------------------------------------------------------------

// Validation stops at the first problem. Throwing keeps each check to one line; the exception
// never leaves this file (copy_scene_description catches it and returns the message).
struct InvalidDescription : std::runtime_error {
    using std::runtime_error::runtime_error;
};

template <typename... Args>
[[noreturn]] void reject(fmt::format_string<Args...> format, Args&&... args) {
    throw InvalidDescription(fmt::format(format, std::forward<Args>(args)...));
}

// --- Strings -------------------------------------------------------------------------------------

// Reads a NUL-terminated string of at most max_length chars; `what` names it in messages.
std::string bounded_string(const char* text, std::size_t max_length, std::string_view what) {
    if (text == nullptr) reject("{} is NULL", what);
    const std::size_t length = strnlen(text, max_length + 1);
    if (length > max_length) reject("{} longer than {} bytes", what, max_length);
    return std::string(text, length);
}

std::string optional_string(const char* text, std::size_t max_length, std::string_view what,
                            std::string fallback) {
    if (text == nullptr) return fallback;
    return bounded_string(text, max_length, what);
}

bool is_lower_or_digit(char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'); }

// [a-z][a-z0-9_]* plus '-' when allow_dash, at most kMaxIdLength chars.
bool is_identifier(std::string_view id, bool allow_dash) {
    if (id.empty() || id.size() > kMaxIdLength || !(id[0] >= 'a' && id[0] <= 'z')) return false;
    return std::all_of(id.begin(), id.end(), [&](char c) {
        return is_lower_or_digit(c) || c == '_' || (allow_dash && c == '-');
    });
}

// [a-z0-9_-]+, at most kMaxIdLength chars: camera and path names.
bool is_name(std::string_view name) {
    if (name.empty() || name.size() > kMaxIdLength) return false;
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return is_lower_or_digit(c) || c == '_' || c == '-'; });
}

// --- Numbers -------------------------------------------------------------------------------------

bool all_finite(const float* values, std::size_t count) {
    return std::all_of(values, values + count, [](float v) { return std::isfinite(v); });
}

bool is_integral(float value) { return std::trunc(value) == value; }

glm::vec3 to_vec3(const float (&values)[3]) { return {values[0], values[1], values[2]}; }

// --- Struct arrays -------------------------------------------------------------------------------

// The major version first: another major may lay out everything else differently.
void check_header(const fgr_struct_header& header, std::size_t v1_size, std::string_view what) {
    const uint32_t major = FGR_ABI_MAJOR(header.abi_version);
    if (major != FGR_ABI_VERSION_MAJOR) {
        reject("{} has ABI major version {}, host supports {}", what, major, FGR_ABI_VERSION_MAJOR);
    }
    if (header.struct_size < v1_size) {
        reject("{} struct too small ({} bytes, ABI 1.0 needs {})", what, header.struct_size,
               v1_size);
    }
}

// A plugin's array of structs, walked with the first element's struct_size as the stride so that
// plugins built against a newer minor version (bigger structs) are read correctly.
template <typename T>
class StructArray {
public:
    StructArray(const T* first, uint32_t count, std::size_t v1_size, std::string_view what)
        : bytes_(reinterpret_cast<const unsigned char*>(first)), count_(count) {
        if (count == 0) return;
        if (first == nullptr) reject("{} count is {} but the array is NULL", what, count);
        check_header(first->header, v1_size, what);
        stride_ = first->header.struct_size;
        // A stride that is not a multiple of the alignment cannot come from sizeof(); reading
        // through it would be misaligned.
        if (stride_ % alignof(T) != 0) reject("{} struct_size {} is misaligned", what, stride_);
        for (uint32_t i = 1; i < count; ++i) {
            if ((*this)[i].header.struct_size != stride_) {
                reject("{} {} has struct_size {}, the first has {}", what, i,
                       (*this)[i].header.struct_size, stride_);
            }
            check_header((*this)[i].header, v1_size, what);
        }
    }

    uint32_t size() const { return count_; }
    const T& operator[](uint32_t index) const {
        return *reinterpret_cast<const T*>(bytes_ + std::size_t{index} * stride_);
    }

private:
    const unsigned char* bytes_;
    uint32_t count_;
    std::size_t stride_ = sizeof(T);
};

void check_count(uint32_t count, uint32_t min_count, uint32_t max_count, std::string_view what) {
    if (count < min_count || count > max_count) {
        reject("{} count {} outside [{}, {}]", what, count, min_count, max_count);
    }
}

// --- Parameters ----------------------------------------------------------------------------------

ParamType param_type_from(uint32_t type, const std::string& where) {
    switch (type) {
        case FGR_PARAM_FLOAT:
            return ParamType::Float;
        case FGR_PARAM_INT:
            return ParamType::Int;
        case FGR_PARAM_BOOL:
            return ParamType::Bool;
        case FGR_PARAM_VEC3:
            return ParamType::Vec3;
        case FGR_PARAM_COLOUR:
            return ParamType::Colour;
        default:
            reject("{}: unknown type {}", where, type);
    }
}

void check_param_range(const ParamInfo& param, const std::string& where) {
    const int components = param_components(param.type);
    if (!std::isfinite(param.min_value) || !std::isfinite(param.max_value)) {
        reject("{}: min/max not finite", where);
    }
    if (param.min_value > param.max_value) {
        reject("{}: min {} greater than max {}", where, param.min_value, param.max_value);
    }
    for (int i = 0; i < components; ++i) {
        const float value = param.default_value[static_cast<std::size_t>(i)];
        if (!std::isfinite(value)) reject("{}: default not finite", where);
        if (value < param.min_value || value > param.max_value) {
            reject("{}: default {} outside [{}, {}]", where, value, param.min_value,
                   param.max_value);
        }
    }
}

void check_int_param(const ParamInfo& param, const std::string& where) {
    if (!is_integral(param.min_value) || !is_integral(param.max_value) ||
        !is_integral(param.default_value[0])) {
        reject("{}: int min, max and default must be integral", where);
    }
    if (param.choices.empty()) return;
    const double expected = double{param.max_value} - double{param.min_value} + 1.0;
    if (static_cast<double>(param.choices.size()) != expected) {
        reject("{}: {} choices for {} values in [{}, {}]", where, param.choices.size(), expected,
               param.min_value, param.max_value);
    }
    for (const std::string& choice : param.choices) {
        if (choice.empty()) reject("{}: empty name in choices", where);
    }
}

void check_bool_param(const ParamInfo& param, const std::string& where) {
    if (param.min_value != 0.0f || param.max_value != 1.0f) {
        reject("{}: bool needs min 0 and max 1", where);
    }
    if (param.default_value[0] != 0.0f && param.default_value[0] != 1.0f) {
        reject("{}: bool default must be 0 or 1", where);
    }
}

ParamInfo copy_param(const fgr_param_desc& desc, uint32_t index) {
    std::string where = fmt::format("parameter {}", index);
    ParamInfo param;
    param.id = bounded_string(desc.id, kMaxIdLength, where + " id");
    where = fmt::format("parameter '{}'", printable(param.id));
    // No '-': the id becomes part of a C identifier (param_<id>) in the kernel.
    if (!is_identifier(param.id, false)) reject("{}: id must match [a-z][a-z0-9_]*", where);
    param.type = param_type_from(desc.type, where);
    param.label = optional_string(desc.label, kMaxTextLength, where + " label", param.id);
    param.group = optional_string(desc.group, kMaxTextLength, where + " group", "Scene");
    param.description =
        optional_string(desc.description, kMaxTextLength, where + " description", "");
    param.min_value = desc.min_value;
    param.max_value = desc.max_value;
    // Scalars use only [0]; the unused components are zeroed rather than copied as garbage.
    const bool scalar = param_components(param.type) == 1;
    param.default_value = {desc.default_value[0], scalar ? 0.0f : desc.default_value[1],
                           scalar ? 0.0f : desc.default_value[2]};
    if (desc.choices != nullptr) {
        if (param.type != ParamType::Int) reject("{}: choices are only allowed on int", where);
        param.choices =
            split(bounded_string(desc.choices, kMaxChoicesLength, where + " choices"), '|');
    }
    check_param_range(param, where);
    if (param.type == ParamType::Int) check_int_param(param, where);
    if (param.type == ParamType::Bool) check_bool_param(param, where);
    return param;
}

std::vector<ParamInfo> copy_params(const fgr_scene_desc& desc) {
    check_count(desc.param_count, 0, kMaxParams, "parameter");
    const StructArray<fgr_param_desc> array(desc.params, desc.param_count, kV1ParamSize,
                                            "parameter");
    std::vector<ParamInfo> params;
    std::set<std::string> seen_ids;
    for (uint32_t i = 0; i < array.size(); ++i) {
        ParamInfo param = copy_param(array[i], i);
        if (is_builtin_param_id(param.id)) {
            reject("parameter '{}': id is reserved for a built-in parameter", param.id);
        }
        if (!seen_ids.insert(param.id).second) reject("parameter '{}': duplicate id", param.id);
        params.push_back(std::move(param));
    }
    return params;
}

// --- Cameras -------------------------------------------------------------------------------------

// The fields fgr_camera and fgr_keyframe share, checked as every given view is
// (view_validation.hpp).
CameraView copy_view(const float (&position)[3], const float (&target)[3], const float (&up)[3],
                     float fov_degrees, const std::string& where) {
    // The ABI's float coordinates widen exactly into the host's double position and target.
    const CameraView view{glm::dvec3(to_vec3(position)), glm::dvec3(to_vec3(target)), to_vec3(up),
                          fov_degrees};
    if (const std::string problem = view_problem(view); !problem.empty()) {
        reject("{}: {}", where, problem);
    }
    return view;
}

std::string copy_name(const char* name, const std::string& where) {
    std::string copy = bounded_string(name, kMaxIdLength, where + " name");
    if (!is_name(copy)) {
        reject("{}: name '{}' {}", where, printable(copy), scene_limits::kCameraNameRule);
    }
    return copy;
}

std::vector<NamedCamera> copy_cameras(const fgr_scene_desc& desc) {
    check_count(desc.camera_count, 1, kMaxCameras, "camera");
    const StructArray<fgr_camera> array(desc.cameras, desc.camera_count, kV1CameraSize, "camera");
    std::vector<NamedCamera> cameras;
    std::set<std::string> seen_names;
    for (uint32_t i = 0; i < array.size(); ++i) {
        const fgr_camera& camera = array[i];
        NamedCamera copy;
        copy.name = copy_name(camera.name, fmt::format("camera {}", i));
        const std::string where = fmt::format("camera '{}'", copy.name);
        if (!seen_names.insert(copy.name).second) reject("{}: duplicate name", where);
        copy.view = copy_view(camera.position, camera.target, camera.up, camera.fov_degrees, where);
        cameras.push_back(std::move(copy));
    }
    return cameras;
}

std::vector<Keyframe> copy_keyframes(const fgr_camera_path& path, const std::string& where) {
    check_count(path.keyframe_count, kMinKeyframes, kMaxKeyframes, where + " keyframe");
    const StructArray<fgr_keyframe> array(path.keyframes, path.keyframe_count, kV1KeyframeSize,
                                          where + " keyframe");
    std::vector<Keyframe> keyframes;
    for (uint32_t i = 0; i < array.size(); ++i) {
        const fgr_keyframe& keyframe = array[i];
        const std::string keyframe_where = fmt::format("{} keyframe {}", where, i);
        if (!std::isfinite(keyframe.time)) reject("{}: time not finite", keyframe_where);
        if (!keyframes.empty() && !(keyframe.time > keyframes.back().time)) {
            reject("{}: time {} not after {}", keyframe_where, keyframe.time,
                   keyframes.back().time);
        }
        keyframes.push_back(
            {keyframe.time, copy_view(keyframe.position, keyframe.target, keyframe.up,
                                      keyframe.fov_degrees, keyframe_where)});
    }
    return keyframes;
}

std::vector<CameraPath> copy_camera_paths(const fgr_scene_desc& desc) {
    check_count(desc.camera_path_count, 0, kMaxCameraPaths, "camera path");
    const StructArray<fgr_camera_path> array(desc.camera_paths, desc.camera_path_count,
                                             kV1CameraPathSize, "camera path");
    std::vector<CameraPath> paths;
    std::set<std::string> seen_names;
    for (uint32_t i = 0; i < array.size(); ++i) {
        CameraPath copy;
        copy.name = copy_name(array[i].name, fmt::format("camera path {}", i));
        const std::string where = fmt::format("camera path '{}'", copy.name);
        if (!seen_names.insert(copy.name).second) reject("{}: duplicate name", where);
        copy.keyframes = copy_keyframes(array[i], where);
        paths.push_back(std::move(copy));
    }
    return paths;
}

// --- Lights, effects, march settings -------------------------------------------------------------

// ABI 1.2: the angular radius of a directional light's disc, read only when the light's struct
// covers it (0, a delta light, otherwise). Checked for point lights too, which ignore it.
float copy_angular_radius(const fgr_light& light, const std::string& where) {
    if (light.header.struct_size < kV1_2LightSize) return 0.0f;
    const float degrees = light.angular_radius_degrees;
    if (!(degrees >= 0.0f && degrees <= kMaxAngularRadiusDegrees)) {
        reject("{}: angular_radius_degrees {} outside [0, {}]", where, degrees,
               kMaxAngularRadiusDegrees);
    }
    if (light.type != FGR_LIGHT_DIRECTIONAL) return 0.0f;
    return static_cast<float>(double{degrees} * (std::numbers::pi / 180.0));
}

Light copy_light(const fgr_light& light, uint32_t index) {
    const std::string where = fmt::format("light {}", index);
    if (light.type != FGR_LIGHT_DIRECTIONAL && light.type != FGR_LIGHT_POINT) {
        reject("{}: unknown type {}", where, light.type);
    }
    if (!all_finite(light.vector, 3) || !all_finite(light.colour, 3) ||
        !std::isfinite(light.intensity)) {
        reject("{}: numbers not finite", where);
    }
    Light copy;
    copy.type = light.type == FGR_LIGHT_DIRECTIONAL ? LightType::Directional : LightType::Point;
    copy.vector = to_vec3(light.vector);
    copy.colour = to_vec3(light.colour);
    copy.intensity = light.intensity;
    if (copy.colour.r < 0.0f || copy.colour.g < 0.0f || copy.colour.b < 0.0f) {
        reject("{}: negative colour", where);
    }
    if (copy.intensity < 0.0f) reject("{}: negative intensity {}", where, copy.intensity);
    if (copy.type == LightType::Directional) {
        // Normalised here so the kernel never has to. In double: the squared length of a float
        // vector with tiny (1e-22) or huge (1e20) components under- or overflows float.
        const glm::dvec3 direction(copy.vector);
        const double length = glm::length(direction);
        if (!(length > 0.0)) reject("{}: zero direction", where);
        copy.vector = glm::vec3(direction / length);
    }
    copy.angular_radius = copy_angular_radius(light, where);
    return copy;
}

std::vector<Light> copy_lights(const fgr_scene_desc& desc) {
    // A scene is lit by its lights alone in the shaded mode: none, or a count over a NULL array
    // (FGR_SCENE over an empty list, or a list forgotten), is refused saying what is missing.
    if (desc.light_count == 0) reject("light count is 0: a scene needs at least one light");
    if (desc.lights == nullptr) {
        reject(
            "light count is {} but the array is NULL: a scene needs at least one light (point "
            "`lights` at an array of them)",
            desc.light_count);
    }
    check_count(desc.light_count, 1, kMaxLights, "light");
    const StructArray<fgr_light> array(desc.lights, desc.light_count, kV1LightSize, "light");
    std::vector<Light> lights;
    for (uint32_t i = 0; i < array.size(); ++i) lights.push_back(copy_light(array[i], i));
    return lights;
}

uint64_t copy_effects(uint64_t effects) {
    const uint64_t unknown = effects & ~uint64_t{FGR_EFFECT_ALL_V1};
    if (unknown != 0) reject("unknown effect bits {:#x}", unknown);
    return effects;
}

MarchSettings copy_march(const fgr_march_settings& march) {
    check_header(march.header, kV1MarchSize, "march settings");
    if (march.max_steps < 1 || march.max_steps > kMaxMarchSteps) {
        reject("march settings: max_steps {} outside [1, {}]", march.max_steps, kMaxMarchSteps);
    }
    if (!std::isfinite(march.max_distance) || !(march.max_distance > 0.0f)) {
        reject("march settings: max_distance {} must be finite and > 0", march.max_distance);
    }
    if (!std::isfinite(march.hit_threshold) || !(march.hit_threshold > 0.0f)) {
        reject("march settings: hit_threshold {} must be finite and > 0", march.hit_threshold);
    }
    if (march.de_iterations < 1 || march.de_iterations > kMaxDeIterations) {
        reject("march settings: de_iterations {} outside [1, {}]", march.de_iterations,
               kMaxDeIterations);
    }
    if (!(march.step_factor >= 0.0f && march.step_factor <= 1.0f)) {
        reject("march settings: step_factor {} outside [0, 1]", march.step_factor);
    }
    // 0, what an initialiser that leaves the field out gives, means full steps.
    const float step_factor = march.step_factor > 0.0f ? march.step_factor : 1.0f;
    return {march.max_steps, march.max_distance, march.hit_threshold, march.de_iterations,
            step_factor};
}

// The march settings become the built-in parameters' defaults, so they must also fit those
// parameters' ranges (e.g. max_distance 1e7 passes "> 0" but not [0.001, 1e6]).
void check_builtin_defaults(const Scene& scene) {
    for (const ParamInfo& param : scene.params) {
        if (!param.builtin) continue;
        const float value = param.default_value[0];
        if (value < param.min_value || value > param.max_value) {
            reject("march settings: {} {} outside the built-in range [{}, {}]", param.id, value,
                   param.min_value, param.max_value);
        }
    }
}

// --- The scene -----------------------------------------------------------------------------------

// The major version first: a 2.x description may be smaller than 1.0's and still be valid 2.x.
void check_scene_header(const fgr_scene_desc& desc) {
    const uint32_t major = FGR_ABI_MAJOR(desc.header.abi_version);
    if (major != FGR_ABI_VERSION_MAJOR) {
        reject("ABI major version {}, host supports {}", major, FGR_ABI_VERSION_MAJOR);
    }
    if (desc.header.struct_size < kV1SceneDescSize) {
        reject("description struct too small ({} bytes)", desc.header.struct_size);
    }
}

// The source: NUL-terminated (ABI 1.0, or source_length 0), or at most source_length bytes, ending
// early at a NUL, so a source without one is never read past its end.
std::string copy_source(const fgr_scene_desc& desc) {
    const uint64_t length = desc.header.struct_size >= kV1_1SceneDescSize ? desc.source_length : 0;
    if (length == 0) return bounded_string(desc.source, kMaxSourceBytes, "source");
    if (desc.source == nullptr) reject("source is NULL");
    // A NUL-terminated source of the largest size has one byte more than it.
    if (length > kMaxSourceBytes + 1) {
        reject("source longer than {} bytes (source_length {})", kMaxSourceBytes, length);
    }
    const std::size_t bytes = strnlen(desc.source, static_cast<std::size_t>(length));
    if (bytes > kMaxSourceBytes) reject("source longer than {} bytes", kMaxSourceBytes);
    return std::string(desc.source, bytes);
}

// ABI 1.2: the render mode the scene asks for by name, read only when the struct covers it; NULL
// or "" (and every older plugin) mean shaded.
RenderMode copy_default_mode(const fgr_scene_desc& desc) {
    if (desc.header.struct_size < kV1_2SceneDescSize || desc.default_mode == nullptr) {
        return RenderMode::Shaded;
    }
    const std::string name = bounded_string(desc.default_mode, kMaxIdLength, "default_mode");
    if (name.empty()) return RenderMode::Shaded;
    for (const RenderModeInfo& info : render_modes()) {
        if (info.name == name) return info.mode;
    }
    reject("default_mode '{}' is not a render mode (choose {})", printable(name),
           render_mode_choices());
}

// --- The scene's own defaults, colour modes and scale (ABI 1.4) ---------------------------------

bool covers_v1_4(const fgr_scene_desc& desc) {
    return desc.header.struct_size >= kV1_4SceneDescSize;
}

// The length scale: 0 (and every older plugin) means 1.
float copy_scale(const fgr_scene_desc& desc) {
    if (!covers_v1_4(desc) || desc.scale == 0.0f) return 1.0f;
    if (!(desc.scale >= kMinScale && desc.scale <= kMaxScale)) {
        reject("scale {} outside [{}, {}] (0 means 1)", desc.scale, kMinScale, kMaxScale);
    }
    return desc.scale;
}

ParamInfo& builtin_named(Scene& scene, const std::string& id, uint32_t index) {
    for (ParamInfo& param : scene.params) {
        if (param.builtin && param.id == id) return param;
    }
    reject("built-in default {}: '{}' is not a built-in parameter (`fgr list SCENE` shows them)",
           index, printable(id));
}

// One scene-given default, checked as a plugin parameter's default is: finite, in range, whole
// for ints, 0 or 1 for bools.
void set_builtin_default(ParamInfo& param, const float (&value)[3]) {
    const int components = param_components(param.type);
    if (!all_finite(value, static_cast<std::size_t>(components))) {
        reject("built-in parameter '{}': scene default not finite", param.id);
    }
    for (int c = 0; c < components; ++c) {
        const float component = value[c];
        if (component < param.min_value || component > param.max_value) {
            reject("built-in parameter '{}': scene default {} outside [{}, {}]", param.id,
                   component, param.min_value, param.max_value);
        }
        if (param.type != ParamType::Float && param.type != ParamType::Vec3 &&
            param.type != ParamType::Colour && !is_integral(component)) {
            reject("built-in parameter '{}': scene default {} is not a whole number", param.id,
                   component);
        }
    }
    for (int c = 0; c < 3; ++c) param.default_value[c] = c < components ? value[c] : 0.0f;
    param.scene_default = true;
}

void copy_builtin_defaults(const fgr_scene_desc& desc, Scene& scene) {
    if (!covers_v1_4(desc) || desc.builtin_default_count == 0) return;
    check_count(desc.builtin_default_count, 0, kMaxBuiltinDefaults, "built-in default");
    const StructArray<fgr_builtin_default> array(desc.builtin_defaults, desc.builtin_default_count,
                                                 kV1_4BuiltinDefaultSize, "built-in default");
    std::set<std::string> seen;
    for (uint32_t i = 0; i < array.size(); ++i) {
        const std::string id =
            bounded_string(array[i].id, kMaxIdLength, fmt::format("built-in default {} id", i));
        if (is_march_builtin_id(id)) {
            reject(
                "built-in parameter '{}': its default comes from the march settings, not "
                "builtin_defaults",
                id);
        }
        ParamInfo& param = builtin_named(scene, id, i);
        if (!seen.insert(id).second) reject("built-in parameter '{}': default given twice", id);
        set_builtin_default(param, array[i].value);
    }
}

// The values of the `colour_mode` enum the scene offers: bit i is choice i; 0 means all.
void copy_colour_modes(const fgr_scene_desc& desc, Scene& scene) {
    if (!covers_v1_4(desc) || desc.colour_modes == 0) return;
    const uint32_t modes = desc.colour_modes;
    if (const uint32_t unknown = modes & ~uint32_t{FGR_COLOUR_MODES_ALL_V1_4}) {
        reject("colour_modes {:#x}: unknown bits {:#x}", modes, unknown);
    }
    auto param = std::find_if(scene.params.begin(), scene.params.end(), [](const ParamInfo& p) {
        return !p.builtin && p.id == "colour_mode";
    });
    if (param == scene.params.end() || param->choices.empty()) {
        reject(
            "colour_modes {:#x} given, but the scene has no colour_mode enum parameter "
            "(FGR_COLOUR_PARAMS)",
            modes);
    }
    if ((modes >> param->choices.size()) != 0) {
        reject("colour_modes {:#x}: parameter 'colour_mode' has only {} choices", modes,
               param->choices.size());
    }
    param->offered.assign(param->choices.size(), false);
    for (std::size_t i = 0; i < param->choices.size(); ++i) param->offered[i] = (modes >> i) & 1u;
    const auto default_index = static_cast<std::size_t>(param->default_value[0] - param->min_value);
    if (!choice_offered(*param, default_index)) {
        reject("parameter 'colour_mode': default '{}' is not among the colour modes offered ({})",
               param->choices[default_index], offered_choices_text(*param));
    }
}

// ABI 1.5: the environment the path mode lights the scene with when the user names none, read
// only when the struct covers it; NULL and "" (and every older plugin) mean none, the sky.
std::string copy_environment(const fgr_scene_desc& desc) {
    if (desc.header.struct_size < kV1_5SceneDescSize || desc.environment == nullptr) return "";
    const std::string text = bounded_string(desc.environment, kMaxIdLength, "environment");
    try {
        check_scene_environment(text);
    } catch (const std::invalid_argument& error) {
        reject("{}", error.what());
    }
    return text;
}

// Everything ABI 1.4 added, applied to a scene that has its built-in parameters: the scale first
// (it moves defaults), then the scene's own defaults over it, then the colour modes.
void copy_v1_4_fields(const fgr_scene_desc& desc, Scene& scene) {
    set_scene_scale(scene, copy_scale(desc));
    copy_builtin_defaults(desc, scene);
    copy_colour_modes(desc, scene);
}

// --- IFS scenes (ABI 1.3) ------------------------------------------------------------------------

// Whether the plugin hands over IFS maps: only when its struct has the fields.
bool is_ifs_description(const fgr_scene_desc& desc) {
    return desc.header.struct_size >= kV1_3SceneDescSize && desc.ifs_map_count != 0;
}

// A depth field: 0 is "not given".
std::optional<int> copy_depth(uint32_t depth, std::string_view what) {
    if (depth > static_cast<uint32_t>(kIfsMaxDepth)) {
        reject("{} {} outside [0, {}]", what, depth, kIfsMaxDepth);
    }
    return depth == 0 ? std::nullopt : std::optional<int>(static_cast<int>(depth));
}

// w(x)_r = matrix[4r] x + matrix[4r+1] y + matrix[4r+2] z + matrix[4r+3]; glm is column-major.
IfsMap copy_ifs_map(const fgr_ifs_map& given) {
    IfsMap map;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) map.linear[c][r] = given.matrix[4 * r + c];
        map.offset[r] = given.matrix[4 * r + 3];
    }
    map.colour = to_vec3(given.colour);
    return map;
}

// The maps and depths, checked as an IFS file's are (validate_ifs_maps), and the parts every
// scene has. The scene's own source and parameters must be absent; march settings are checked but
// not used (IFS scenes are traced, not marched); effects are those exact tracing supports.
Scene copy_ifs_checked(const fgr_scene_desc& desc, Scene named) {
    if (desc.source != nullptr && !copy_source(desc).empty()) {
        reject(
            "IFS maps and a source: a scene with ifs_map_count {} is an IFS scene, whose source "
            "must be NULL or empty",
            desc.ifs_map_count);
    }
    if (desc.param_count != 0) {
        reject(
            "IFS scenes have no parameters of their own (param_count {}): they get ifs_depth and "
            "the built-in ones",
            desc.param_count);
    }
    IfsScene ifs;
    ifs.id = named.id;
    ifs.name = named.name;
    ifs.description = named.description;
    check_count(desc.ifs_map_count, 1, static_cast<uint32_t>(kIfsMaxMaps), "IFS map");
    const StructArray<fgr_ifs_map> maps(desc.ifs_maps, desc.ifs_map_count, kV1_3IfsMapSize,
                                        "IFS map");
    for (uint32_t i = 0; i < maps.size(); ++i) ifs.maps.push_back(copy_ifs_map(maps[i]));
    const std::optional<int> default_depth =
        copy_depth(desc.ifs_default_depth, "ifs_default_depth");
    const std::optional<int> max_depth = copy_depth(desc.ifs_max_depth, "ifs_max_depth");
    set_ifs_depths(ifs, default_depth, max_depth);
    if (ifs.default_depth > ifs.max_depth) {
        reject("ifs_default_depth {} is above ifs_max_depth {}", ifs.default_depth, ifs.max_depth);
    }
    try {
        validate_ifs_maps(ifs, "IFS map");
    } catch (const IfsError& error) {
        reject("{}", error.what());
    }
    ifs.cameras = copy_cameras(desc);
    ifs.camera_paths = copy_camera_paths(desc);
    ifs.lights = copy_lights(desc);
    settle_ifs_default_depth(ifs);
    const uint64_t effects = copy_effects(desc.effects);
    if (const uint64_t unsupported = effects & ~kIfsEffects) {
        reject(
            "IFS scenes cannot have {}: exact IFS tracing has no distance estimate (they can "
            "have {})",
            effect_names(unsupported), effect_names(kIfsEffects));
    }
    (void)copy_march(desc.march);
    const RenderMode mode = copy_default_mode(desc);
    Scene scene = ifs_scene_to_scene(ifs, std::filesystem::path());
    scene.effects = effects;
    scene.default_mode = mode;
    copy_v1_4_fields(desc, scene);
    scene.environment = copy_environment(desc);
    return scene;
}

// --- The whole description -----------------------------------------------------------------------

// `declared_id` gets the scene id as soon as it is known valid, for the refusal to name it.
Scene copy_checked(const fgr_scene_desc& desc, std::string& declared_id) {
    check_scene_header(desc);
    Scene scene;
    scene.id = bounded_string(desc.id, kMaxIdLength, "scene id");
    if (!is_identifier(scene.id, true)) {
        reject("scene id '{}' {}", printable(scene.id), scene_limits::kSceneIdRule);
    }
    declared_id = scene.id;
    scene.name = bounded_string(desc.name, kMaxTextLength, "scene name");
    if (scene.name.empty()) reject("scene name is empty");
    scene.description = bounded_string(desc.description, kMaxTextLength, "scene description");
    if (is_ifs_description(desc)) return copy_ifs_checked(desc, std::move(scene));
    scene.source = copy_source(desc);
    if (scene.source.empty()) reject("source is empty");
    declared_kernel_api(scene.source);  // refuses a version this fgr does not have
    scene.source_name =
        optional_string(desc.source_name, kMaxTextLength, "source name", scene.id + ".cl");
    scene.params = copy_params(desc);
    scene.cameras = copy_cameras(desc);
    scene.camera_paths = copy_camera_paths(desc);
    scene.lights = copy_lights(desc);
    scene.effects = copy_effects(desc.effects);
    scene.march = copy_march(desc.march);
    scene.default_mode = copy_default_mode(desc);
    if (scene.inside_only()) {
        // An inside test alone renders only by brute force, whatever the description asks.
        if (scene.default_mode == RenderMode::Path) {
            reject(
                "default_mode 'path' needs a distance estimator: this source defines "
                "FGR_SCENE_INSIDE_ONLY (use \"brute\" or NULL)");
        }
        scene.default_mode = RenderMode::Brute;
    }
    add_builtin_params(scene);
    check_builtin_defaults(scene);
    copy_v1_4_fields(desc, scene);
    scene.environment = copy_environment(desc);
    return scene;
}

LoadResult failure(std::string reason, std::string declared_id) {
    return LoadResult{std::nullopt, std::move(reason), std::move(declared_id)};
}

}  // namespace

// A plugin's text as it may appear in a refusal: bytes outside printable ASCII become \xNN, so a
// newline or a terminal escape in a bad id cannot break the one-line reason.
std::string printable(std::string_view text) {
    std::string out;
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte < 0x7f) {
            out += c;
        } else {
            out += fmt::format("\\x{:02x}", byte);
        }
    }
    return out;
}

std::vector<ParamInfo> copy_param_descriptions(std::span<const fgr_param_desc> descriptions) {
    std::vector<ParamInfo> params;
    for (size_t i = 0; i < descriptions.size(); ++i) {
        try {
            params.push_back(copy_param(descriptions[i], static_cast<uint32_t>(i)));
        } catch (const InvalidDescription& invalid) {
            throw std::invalid_argument(invalid.what());
        }
    }
    return params;
}

bool is_scene_id(std::string_view id) { return is_identifier(id, true); }

bool is_camera_name(std::string_view name) { return is_name(name); }

LoadResult copy_scene_description(const fgr_scene_desc* desc) {
    if (desc == nullptr) return failure("description is NULL", {});
    std::string declared_id;
    try {
        return LoadResult{copy_checked(*desc, declared_id), {}};
    } catch (const InvalidDescription& invalid) {
        return failure(invalid.what(), declared_id);
    } catch (const std::exception& error) {
        return failure(fmt::format("could not copy description: {}", error.what()), declared_id);
    }
}

}  // namespace fgr
