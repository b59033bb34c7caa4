// SPDX-License-Identifier: Apache-2.0
#include "scene/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <regex>
#include <stdexcept>
#include <string_view>

#include "scene/kernel_api.hpp"

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
                        float max_value, float default_value, std::string description,
                        std::string group = "Quality") {
    ParamInfo param;
    param.id = std::move(id);
    param.label = std::move(label);
    param.group = std::move(group);
    param.description = std::move(description);
    param.type = type;
    param.min_value = min_value;
    param.max_value = max_value;
    param.default_value = {default_value, 0.0f, 0.0f};
    param.builtin = true;
    return param;
}

ParamInfo effect_param(std::string id, std::string label, ParamType type, float min_value,
                       float max_value, float default_value, std::string description) {
    return builtin_param(std::move(id), std::move(label), type, min_value, max_value, default_value,
                         std::move(description), "Effects");
}

ParamInfo colour_param(std::string id, std::string label, glm::vec3 value,
                       std::string description) {
    ParamInfo param = effect_param(std::move(id), std::move(label), ParamType::Colour, 0.0f, 1.0f,
                                   0.0f, std::move(description));
    param.default_value = {value.r, value.g, value.b};
    return param;
}

// The distance-like built-ins whose defaults follow the scene's length scale (Scene::scale):
// lengths scale with it, rates per unit length inversely. Their add_effect_params defaults are
// those of a scene of scale 1.
struct ScaledBuiltin {
    std::string_view id;
    bool per_length;  // a rate per unit length (fog_density, absorption): divided by the scale
};
constexpr ScaledBuiltin kScaledBuiltins[] = {
    {"ao_radius", false},  {"glow_radius", false}, {"aperture", false},
    {"fog_density", true}, {"absorption", true},
};

// Distance from the default camera to what it looks at: where depth of field focuses by default.
float default_focus_distance(const Scene& scene) {
    if (scene.cameras.empty()) return 1.0f;
    const CameraView& view = scene.cameras.front().view;
    // In float, as the plugin gave it: the default (and the images using it) stay as they were.
    return std::clamp(glm::length(glm::vec3(view.target) - glm::vec3(view.position)), 0.001f, 1e5f);
}

// The knobs of the effects and of the colour pipeline. They exist in every scene; an effect that
// is not compiled in never reads its parameters, so they cost nothing.
void add_effect_params(Scene& scene) {
    ParamInfo tone_map = effect_param("tone_map", "Tone mapping", ParamType::Int, 0.0f, 2.0f, 2.0f,
                                      "linear to display: clamp, Reinhard, or ACES filmic");
    tone_map.choices = {"clamp", "reinhard", "aces"};
    auto& params = scene.params;
    params.push_back(effect_param("exposure", "Exposure", ParamType::Float, 0.01f, 100.0f, 1.0f,
                                  "linear colour is multiplied by this before tone mapping"));
    params.push_back(std::move(tone_map));
    params.push_back(effect_param("shadow_sharpness", "Shadow sharpness", ParamType::Float, 1.0f,
                                  128.0f, 12.0f, "soft shadows: higher is a narrower penumbra"));
    params.push_back(effect_param("ao_radius", "Occlusion radius", ParamType::Float, 1e-9f, 100.0f,
                                  0.1f,
                                  "sampled occlusion: how far along the normal it probes; brute "
                                  "mode: the screen-space occlusion's radius"));
    params.push_back(colour_param("glow_colour", "Glow colour", {0.45f, 0.65f, 1.0f},
                                  "colour rays that miss pick up near the surface"));
    params.push_back(effect_param("glow_strength", "Glow strength", ParamType::Float, 0.0f, 20.0f,
                                  1.0f, "glow at zero distance from the surface"));
    params.push_back(effect_param("glow_radius", "Glow radius", ParamType::Float, 1e-9f, 10.0f,
                                  0.05f, "distance over which glow falls to 1/e"));
    params.push_back(colour_param("fog_colour", "Fog colour", {0.10f, 0.12f, 0.17f},
                                  "colour distant surfaces fade to"));
    params.push_back(effect_param("fog_density", "Fog density", ParamType::Float, 0.0f, 1e9f, 0.15f,
                                  "fog: fraction of light lost per unit distance"));
    params.push_back(effect_param("reflection_bounces", "Reflection bounces", ParamType::Int, 1.0f,
                                  8.0f, 1.0f, "mirror bounces followed per ray"));
    params.push_back(effect_param("transmission", "Transmission", ParamType::Float, 0.0f, 1.0f,
                                  0.6f,
                                  "refraction: light passing into surfaces (scenes may set "
                                  "it per material)"));
    params.push_back(effect_param("ior", "Index of refraction", ParamType::Float, 0.25f, 3.0f, 1.5f,
                                  "refraction: 1.33 water, 1.5 glass, 2.4 diamond; below 1 "
                                  "the solid is the thinner medium (0.75: air in water)"));
    // Lengths (and per-length rates) reach down (and up) to deep-zoom scales: a scene a
    // thousandth the size needs a thousandth the radius and a thousand times the density.
    params.push_back(effect_param("absorption", "Absorption", ParamType::Float, 0.0f, 1e9f, 1.0f,
                                  "refraction: light absorbed per unit length inside, tinted"));
    params.push_back(effect_param("aperture", "Aperture", ParamType::Float, 0.0f, 10.0f, 0.05f,
                                  "depth of field: lens radius"));
    params.push_back(effect_param("focus_distance", "Focus distance", ParamType::Float, 1e-9f, 1e5f,
                                  default_focus_distance(scene),
                                  "depth of field: distance of the sharp plane"));
}

// The source with its comments blanked out (newlines kept), so a commented-out #define is none.
std::string without_comments(std::string_view source) {
    std::string out;
    out.reserve(source.size());
    for (size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "//") == 0) {
            while (i < source.size() && source[i] != '\n') ++i;
            if (i < source.size()) out += '\n';
        } else if (source.compare(i, 2, "/*") == 0) {
            const size_t end = source.find("*/", i + 2);
            const size_t stop = end == std::string_view::npos ? source.size() : end + 2;
            for (; i < stop; ++i) {
                if (source[i] == '\n') out += '\n';
            }
            out += ' ';
            --i;
        } else {
            out += source[i];
        }
    }
    return out;
}

// The line `#define NAME` (NAME a plain identifier), for declares.
std::regex define_directive(const std::string& name) {
    return std::regex("^[ \t]*#[ \t]*define[ \t]+" + name + "\\b", std::regex::multiline);
}

// Whether the source says `#define NAME` on a line of its own, outside comments; `directive` is
// define_directive(name), built once by the caller.
bool declares(std::string_view source, std::string_view name, const std::regex& directive) {
    if (source.find(name) == std::string_view::npos) return false;
    const std::string code = without_comments(source);
    return std::regex_search(code, directive);
}

}  // namespace

int declared_kernel_api(std::string_view source) {
    static const std::regex directive(
        R"(^[ \t]*#[ \t]*define[ \t]+FGR_KERNEL_API[ \t]+([^ \t\r\n]+)[ \t\r]*$)",
        std::regex::multiline);
    if (source.find("FGR_KERNEL_API") == std::string_view::npos) return 1;
    const std::string code = without_comments(source);
    std::smatch match;
    if (!std::regex_search(code, match, directive)) return 1;
    const std::string value = match[1].str();
    const bool is_number = value.size() <= 3 && std::all_of(value.begin(), value.end(), [](char c) {
                               return c >= '0' && c <= '9';
                           });
    const int version = is_number ? std::stoi(value) : 0;
    if (version < 1 || version > kKernelApiLatest) {
        throw std::invalid_argument(fmt::format(
            "the source is written for kernel API '{}', and this fgr has kernel APIs 1 to {}{}",
            value, kKernelApiLatest, version > kKernelApiLatest ? ": update fgr" : ""));
    }
    return version;
}

std::vector<std::string> declared_specialisable(std::string_view source) {
    static const std::regex directive(R"(^[ \t]*#[ \t]*define[ \t]+FGR_SPECIALISABLE\b([^\r\n]*)$)",
                                      std::regex::multiline);
    std::vector<std::string> ids;
    if (source.find("FGR_SPECIALISABLE") == std::string_view::npos) return ids;
    const std::string code = without_comments(source);
    std::smatch match;
    if (!std::regex_search(code, match, directive)) return ids;
    const std::string list = match[1].str();
    size_t at = 0;
    while (at < list.size()) {
        at = list.find_first_not_of(" \t\r", at);
        if (at == std::string::npos) break;
        const size_t end = std::min(list.find_first_of(" \t\r", at), list.size());
        ids.push_back(list.substr(at, end - at));
        at = end;
    }
    return ids;
}

namespace {

// The knobs of the brute-force mode (kernels/modes/fgr_mode_brute.cl); other modes never read them.
void add_brute_force_params(Scene& scene) {
    const std::string group = "Brute force";
    scene.params.push_back(builtin_param("brute_samples", "Samples per pass", ParamType::Int, 1.0f,
                                         1024.0f, 24.0f,
                                         "brute force: inside tests along each ray per pass, "
                                         "stratified between near and the best hit so far",
                                         group));
    scene.params.push_back(builtin_param("brute_bisection", "Bisection steps", ParamType::Int, 0.0f,
                                         40.0f, 24.0f,
                                         "brute force: steps refining each new hit, each halving "
                                         "its depth's uncertainty",
                                         group));
    scene.params.push_back(
        builtin_param("brute_near", "Near distance", ParamType::Float, 0.0f, 1e6f, 0.0f,
                      "brute force: sampling starts this far from the camera", group));
    ParamInfo solid = builtin_param("brute_solid", "Solid", ParamType::Int, 0.0f, 2.0f, 0.0f,
                                    "brute force: what rays hit: auto (the state they do not "
                                    "start in), the set, or its complement (interior renderings)",
                                    group);
    solid.choices = {"auto", "set", "complement"};
    scene.params.push_back(std::move(solid));
}

}  // namespace

bool choice_offered(const ParamInfo& param, std::size_t index) {
    return param.offered.empty() || (index < param.offered.size() && param.offered[index]);
}

std::string offered_choices_text(const ParamInfo& param) {
    std::string names;
    for (std::size_t i = 0; i < param.choices.size(); ++i) {
        if (choice_offered(param, i)) names += (names.empty() ? "" : "|") + param.choices[i];
    }
    return names;
}

bool Scene::inside_only() const {
    static const std::regex directive = define_directive("FGR_SCENE_INSIDE_ONLY");
    return declares(source, "FGR_SCENE_INSIDE_ONLY", directive);
}

bool Scene::pairs_distances() const {
    static const std::regex directive = define_directive("FGR_SCENE_HAS_DE_PAIR");
    return declares(source, "FGR_SCENE_HAS_DE_PAIR", directive);
}

bool Scene::has_distance_estimator() const { return ifs == nullptr && !inside_only(); }

const ParamInfo* Scene::find_param(const std::string& param_id) const {
    return find_by(params, param_id, [](const ParamInfo& param) { return param.id; });
}

const NamedCamera* Scene::find_camera(const std::string& camera_name) const {
    return find_by(cameras, camera_name, [](const NamedCamera& camera) { return camera.name; });
}

const CameraPath* Scene::find_camera_path(const std::string& path_name) const {
    return find_by(camera_paths, path_name, [](const CameraPath& path) { return path.name; });
}

std::size_t builtin_param_count() {
    Scene probe;
    add_builtin_params(probe);
    return probe.params.size();
}

bool is_builtin_param_id(std::string_view id) {
    Scene probe;
    add_builtin_params(probe);
    return probe.find_param(std::string(id)) != nullptr;
}

bool is_march_builtin_id(std::string_view id) {
    for (const std::string_view march :
         {"max_steps", "max_distance", "hit_threshold", "iterations", "step_factor"}) {
        if (id == march) return true;
    }
    return false;
}

bool param_applies(const Scene& scene, const ParamInfo& param) {
    if (!param.builtin) return true;
    const std::string_view id = param.id;
    // What marching a distance estimator reads, and the normal's finite differences.
    const bool marching = id == "step_factor" || id == "over_relaxation" || id == "normal_epsilon";
    if (scene.ifs != nullptr) {
        // The tracer reads max_steps (its node budget), max_distance and hit_threshold; there is
        // no brute-force mode for maps.
        return !marching && id != "iterations" && !id.starts_with("brute_");
    }
    if (scene.inside_only()) return !marching && id != "max_steps";
    return true;
}

void set_scene_scale(Scene& scene, float scale) {
    scene.scale = scale;
    Scene unit;
    add_effect_params(unit);
    for (const ScaledBuiltin& scaled : kScaledBuiltins) {
        const ParamInfo* unit_param = unit.find_param(std::string(scaled.id));
        auto param =
            std::find_if(scene.params.begin(), scene.params.end(),
                         [&](const ParamInfo& p) { return p.builtin && p.id == scaled.id; });
        if (unit_param == nullptr || param == scene.params.end()) continue;
        const float unit_default = unit_param->default_value[0];
        const float value = scaled.per_length ? unit_default / scale : unit_default * scale;
        param->default_value[0] = std::clamp(value, param->min_value, param->max_value);
    }
}

void add_builtin_params(Scene& scene) {
    const MarchSettings& march = scene.march;
    scene.params.push_back(builtin_param("max_steps", "Max steps", ParamType::Int, 1.0f, 100000.0f,
                                         static_cast<float>(march.max_steps),
                                         "distance estimator evaluations per ray at most"));
    scene.params.push_back(builtin_param("max_distance", "Max distance", ParamType::Float, 1e-9f,
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
    scene.params.push_back(builtin_param(
        "over_relaxation", "Over-relaxation", ParamType::Float, 1.0f, 1.95f, 1.6f,
        "steps of over_relaxation * step_factor * DE while consecutive safe balls overlap, "
        "falling back to plain steps when they do not (1: plain sphere tracing)"));
    scene.params.push_back(builtin_param("normal_epsilon", "Normal epsilon", ParamType::Float,
                                         0.01f, 16.0f, 0.5f,
                                         "normal stencil size, in pixel footprints at the hit"));
    add_effect_params(scene);
    add_brute_force_params(scene);
}

}  // namespace fgr
