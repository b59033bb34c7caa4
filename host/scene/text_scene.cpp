// SPDX-License-Identifier: Apache-2.0
#include "scene/text_scene.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "fgr/scene_helpers.h"
#include "scene/effects.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_limits.hpp"
#include "util/files.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

// The reader's pieces live in a namespace of their own: this file is compiled in one unity
// translation unit with the other JSON readers, whose helpers have the same plain names.
namespace fgr::text_header {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// --- Failure reporting ---------------------------------------------------------------------------

// Reading stops at the first problem; parse_text_scene turns this into the LoadResult's reason.
struct HeaderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// How a reason names the key at `path` ("parameters[2].max"): `header "parameters[2].max":`.
std::string at(const std::string& path) {
    return path.empty() ? "header:" : fmt::format("header \"{}\":", path);
}

[[noreturn]] void refuse_at(const std::string& path, const std::string& reason) {
    throw HeaderError(fmt::format("{} {}", at(path), reason));
}

std::string key_path(const std::string& parent, std::string_view key) {
    return parent.empty() ? std::string(key) : fmt::format("{}.{}", parent, key);
}

std::string index_path(const std::string& parent, std::size_t index) {
    return fmt::format("{}[{}]", parent, index);
}

LoadResult failure(std::string reason, std::string declared_id = {}) {
    // Every reason is one line already; this keeps it so whatever a library put in it.
    for (char& c : reason) {
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    }
    return LoadResult{std::nullopt, std::move(reason), std::move(declared_id)};
}

// --- Finding the header --------------------------------------------------------------------------

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v';
}

std::size_t skip_blank(std::string_view text, std::size_t at) {
    while (at < text.size() && is_blank(text[at])) ++at;
    return at;
}

// Where the header's JSON begins (just after the word fgr-scene), or nothing when `text` does not
// start with a header.
std::optional<std::size_t> after_tag(std::string_view text) {
    std::size_t at = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    at = skip_blank(text, at);
    if (text.substr(at, 2) != "/*") return std::nullopt;
    at = skip_blank(text, at + 2);
    if (text.substr(at, kTextSceneTag.size()) != kTextSceneTag) return std::nullopt;
    at += kTextSceneTag.size();
    // The word on its own: "fgr-scenes" is some other comment.
    if (at < text.size() && !is_blank(text[at]) && text.substr(at, 2) != "*/") return std::nullopt;
    return at;
}

// The header's JSON, text[begin, end), parsed where it stands: everything before it is blanked
// but its line breaks, so the parser's "line 3, column 5" is the file's.
json parse_header(std::string_view text, std::size_t begin, std::size_t end) {
    const std::string_view body = text.substr(begin, end - begin);
    if (skip_blank(body, 0) == body.size()) {
        refuse_at("", fmt::format("no JSON object after {}", kTextSceneTag));
    }
    if (json_fields::nests_deeper_than(body, kTextSceneMaxDepth)) {
        refuse_at("", fmt::format("nested deeper than {} levels", kTextSceneMaxDepth));
    }
    std::string padded(begin, ' ');
    for (std::size_t i = 0; i < begin; ++i) {
        if (text[i] == '\n') padded[i] = '\n';
    }
    padded.append(body);
    try {
        return scene_json::parse_object(padded);
    } catch (const std::runtime_error& error) {
        refuse_at("", error.what());
    }
}

// --- Reading values ------------------------------------------------------------------------------

const json* member(const json& object, std::string_view key) {
    const auto found = object.find(std::string(key));
    return found == object.end() ? nullptr : &*found;
}

const json& required(const json& object, const std::string& parent, std::string_view key) {
    const json* value = member(object, key);
    if (value == nullptr) refuse_at(key_path(parent, key), "is missing");
    return *value;
}

void require_object(const json& value, const std::string& path) {
    if (!value.is_object()) refuse_at(path, "must be an object");
}

const json& require_array(const json& value, const std::string& path) {
    if (!value.is_array()) refuse_at(path, "must be an array");
    return value;
}

void check_keys(const json& object, const std::string& path,
                std::initializer_list<std::string_view> known) {
    json_fields::check_keys(object, known,
                            path.empty() ? "header" : fmt::format("header \"{}\"", path));
}

// Numbers are read as doubles and limited well inside float's range, so the description's floats
// are exact conversions (a double beyond float's range would be undefined to convert).
float number(const json& value, const std::string& path) {
    return static_cast<float>(json_fields::finite_double(value, at(path), 1e30));
}

uint32_t whole(const json& value, const std::string& path) {
    std::int64_t out = 0;
    constexpr std::int64_t kMax = std::numeric_limits<uint32_t>::max();
    if (!json_fields::integer_in(value, 0, kMax, out)) {
        refuse_at(path, fmt::format("must be a whole number from 0 to {}", kMax));
    }
    return static_cast<uint32_t>(out);
}

// Texts go into one-line messages and listings: no control characters (a NUL would also end the
// C string the description hands over).
std::string text(const json& value, const std::string& path) {
    if (!value.is_string()) refuse_at(path, "must be a string");
    std::string out = value.get<std::string>();
    if (out.size() > scene_limits::kMaxTextLength) {
        refuse_at(path, fmt::format("longer than {} bytes", scene_limits::kMaxTextLength));
    }
    for (const char c : out) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) refuse_at(path, "must not hold control characters");
    }
    return out;
}

std::array<float, 3> vec3(const json& value, const std::string& path) {
    if (!value.is_array() || value.size() != 3) refuse_at(path, "must be an array of 3 numbers");
    return {number(value[0], path), number(value[1], path), number(value[2], path)};
}

void set3(float (&out)[3], const std::array<float, 3>& value) {
    for (int i = 0; i < 3; ++i) out[i] = value[static_cast<std::size_t>(i)];
}

std::array<float, 3> vec3_or(const json& object, const std::string& parent, std::string_view key,
                             const std::array<float, 3>& fallback) {
    const json* value = member(object, key);
    return value ? vec3(*value, key_path(parent, key)) : fallback;
}

float number_or(const json& object, const std::string& parent, std::string_view key,
                float fallback) {
    const json* value = member(object, key);
    return value ? number(*value, key_path(parent, key)) : fallback;
}

// The index of `name` among `names`, or a refusal naming them.
std::size_t index_of(const json& value, const std::string& path,
                     const std::vector<std::string>& names, std::string_view what) {
    const std::string name = text(value, path);
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i] == name) return i;
    }
    std::string known;
    for (const std::string& each : names) known += (known.empty() ? "" : ", ") + each;
    refuse_at(path,
              fmt::format("unknown {} {} (known: {})", what, json_fields::shown(value), known));
}

std::vector<std::string> split_choices(const char* choices) {
    std::vector<std::string> names;
    std::string_view rest = choices;
    while (true) {
        const std::size_t bar = rest.find('|');
        names.emplace_back(rest.substr(0, bar));
        if (bar == std::string_view::npos) return names;
        rest.remove_prefix(bar + 1);
    }
}

// --- The description the header becomes ----------------------------------------------------------

// An fgr_scene_desc and everything it points to, kept alive while copy_scene_description reads
// it. Pointers are set by finish(), once the arrays no longer grow.
struct Description {
    std::deque<std::string> strings;  // a deque: its strings never move
    std::vector<fgr_param_desc> params;
    std::vector<fgr_camera> cameras;
    std::vector<std::vector<fgr_keyframe>> keyframes;  // per camera path
    std::vector<fgr_camera_path> paths;
    std::vector<fgr_light> lights;
    std::vector<fgr_builtin_default> builtin_defaults;
    fgr_scene_desc desc{};

    const char* keep(std::string text) {
        strings.push_back(std::move(text));
        return strings.back().c_str();
    }

    void finish() {
        desc.params = params.data();
        desc.param_count = static_cast<uint32_t>(params.size());
        desc.cameras = cameras.data();
        desc.camera_count = static_cast<uint32_t>(cameras.size());
        for (std::size_t i = 0; i < paths.size(); ++i) {
            paths[i].keyframes = keyframes[i].data();
            paths[i].keyframe_count = static_cast<uint32_t>(keyframes[i].size());
        }
        desc.camera_paths = paths.data();
        desc.camera_path_count = static_cast<uint32_t>(paths.size());
        desc.lights = lights.data();
        desc.light_count = static_cast<uint32_t>(lights.size());
        desc.builtin_defaults = builtin_defaults.data();
        desc.builtin_default_count = static_cast<uint32_t>(builtin_defaults.size());
    }
};

// --- Parameters ----------------------------------------------------------------------------------

struct NamedType {
    const char* name;
    fgr_param_type type;
};
constexpr NamedType kParamTypes[] = {{"float", FGR_PARAM_FLOAT},
                                     {"int", FGR_PARAM_INT},
                                     {"bool", FGR_PARAM_BOOL},
                                     {"vec3", FGR_PARAM_VEC3},
                                     {"colour", FGR_PARAM_COLOUR}};

fgr_param_type param_type(const json* value, const std::string& path) {
    if (value == nullptr) return FGR_PARAM_FLOAT;
    const std::string name = text(*value, path);
    for (const NamedType& type : kParamTypes) {
        if (name == type.name) return type.type;
    }
    refuse_at(path, fmt::format("unknown type {} (known: float, int, bool, vec3, colour)",
                                json_fields::shown(*value)));
}

// "choices": names of the values min..max, joined as the ABI's "a|b|c".
std::vector<std::string> param_choices(const json& value, const std::string& path) {
    require_array(value, path);
    if (value.empty()) refuse_at(path, "must name at least one choice");
    std::vector<std::string> names;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = index_path(path, i);
        std::string name = text(value[i], where);
        if (name.empty()) refuse_at(where, "must not be empty");
        if (name.find('|') != std::string::npos) refuse_at(where, "must not hold '|'");
        names.push_back(std::move(name));
    }
    return names;
}

// A parameter's default: a number, three for vec3 and colour, true or false for bool, a choice's
// name for an enumeration.
void param_default(const json* value, const std::string& path,
                   const std::vector<std::string>& choices, fgr_param_desc& param) {
    const bool three = param.type == FGR_PARAM_VEC3 || param.type == FGR_PARAM_COLOUR;
    if (value == nullptr) {
        if (param.type != FGR_PARAM_BOOL) refuse_at(path, "is missing");
        return;  // false
    }
    if (three) {
        set3(param.default_value, vec3(*value, path));
    } else if (param.type == FGR_PARAM_BOOL && value->is_boolean()) {
        param.default_value[0] = value->get<bool>() ? 1.0f : 0.0f;
    } else if (!choices.empty() && value->is_string()) {
        param.default_value[0] =
            param.min_value + static_cast<float>(index_of(*value, path, choices, "choice"));
    } else {
        param.default_value[0] = number(*value, path);
    }
}

void read_parameter(const json& entry, const std::string& path, Description& out) {
    require_object(entry, path);
    check_keys(entry, path,
               {"id", "type", "label", "group", "description", "min", "max", "default", "choices"});
    fgr_param_desc param{};
    param.header = FGR_HEADER(fgr_param_desc);
    param.id = out.keep(text(required(entry, path, "id"), key_path(path, "id")));
    param.type = param_type(member(entry, "type"), key_path(path, "type"));
    const auto optional_text = [&](const char* key) -> const char* {
        const json* value = member(entry, key);
        return value ? out.keep(text(*value, key_path(path, key))) : nullptr;
    };
    param.label = optional_text("label");
    param.group = optional_text("group");
    param.description = optional_text("description");
    std::vector<std::string> choices;
    if (const json* value = member(entry, "choices")) {
        choices = param_choices(*value, key_path(path, "choices"));
        std::string joined;
        for (const std::string& name : choices) joined += (joined.empty() ? "" : "|") + name;
        param.choices = out.keep(std::move(joined));
    }
    // Ranges a plugin must spell out that the type or the choices already say: bool and colour
    // are 0 to 1, an enumeration's values run from min (0) one per choice.
    const bool unit_range = param.type == FGR_PARAM_BOOL || param.type == FGR_PARAM_COLOUR;
    const bool implied = unit_range || !choices.empty();
    const json* min = member(entry, "min");
    const json* max = member(entry, "max");
    if (!implied && min == nullptr) refuse_at(key_path(path, "min"), "is missing");
    if (!implied && max == nullptr) refuse_at(key_path(path, "max"), "is missing");
    param.min_value = min ? number(*min, key_path(path, "min")) : 0.0f;
    if (max != nullptr) {
        param.max_value = number(*max, key_path(path, "max"));
    } else {
        param.max_value =
            unit_range ? 1.0f : param.min_value + static_cast<float>(choices.size() - 1);
    }
    param_default(member(entry, "default"), key_path(path, "default"), choices, param);
    out.params.push_back(param);
}

// "colour_parameters": the orbit-trap colour's three parameters (colour_mode, palette,
// base_colour), as FGR_COLOUR_PARAMS declares them for a plugin: true, or an object choosing their
// defaults by name.
void read_colour_parameters(const json& value, const std::string& path, Description& out) {
    if (value.is_boolean()) {
        if (!value.get<bool>()) return;
    } else {
        require_object(value, path);
        check_keys(value, path, {"mode", "palette", "base_colour"});
    }
    const fgr_param_desc names[] = {FGR_COLOUR_PARAMS(0, 0, 1.0f, 1.0f, 1.0f)};
    std::size_t mode = 0, palette = 0;
    std::array<float, 3> base{1.0f, 1.0f, 1.0f};
    if (value.is_object()) {
        if (const json* given = member(value, "mode")) {
            mode = index_of(*given, key_path(path, "mode"), split_choices(names[0].choices),
                            "colour mode");
        }
        if (const json* given = member(value, "palette")) {
            palette = index_of(*given, key_path(path, "palette"), split_choices(names[1].choices),
                               "palette");
        }
        base = vec3_or(value, path, "base_colour", base);
    }
    const fgr_param_desc params[] = {FGR_COLOUR_PARAMS(mode, palette, base[0], base[1], base[2])};
    out.params.insert(out.params.end(), std::begin(params), std::end(params));
}

// --- Cameras, camera paths and lights ------------------------------------------------------------

constexpr std::array<float, 3> kUpZ{0.0f, 0.0f, 1.0f};
constexpr float kDefaultFov = 60.0f;

// The fields a camera and a keyframe share: "position" and "target" (required), "up" (+z) and
// "fov" (horizontal degrees, 60), as in IFS and formula files.
template <typename View>
void read_view(const json& entry, const std::string& path, View& view) {
    set3(view.position, vec3(required(entry, path, "position"), key_path(path, "position")));
    set3(view.target, vec3(required(entry, path, "target"), key_path(path, "target")));
    set3(view.up, vec3_or(entry, path, "up", kUpZ));
    view.fov_degrees = number_or(entry, path, "fov", kDefaultFov);
}

void read_cameras(const json& value, const std::string& path, Description& out) {
    require_array(value, path);
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = index_path(path, i);
        require_object(value[i], where);
        check_keys(value[i], where, {"name", "position", "target", "up", "fov"});
        fgr_camera camera{};
        camera.header = FGR_HEADER(fgr_camera);
        camera.name = out.keep(text(required(value[i], where, "name"), key_path(where, "name")));
        read_view(value[i], where, camera);
        out.cameras.push_back(camera);
    }
}

void read_camera_paths(const json& value, const std::string& path, Description& out) {
    require_array(value, path);
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = index_path(path, i);
        require_object(value[i], where);
        check_keys(value[i], where, {"name", "keyframes"});
        fgr_camera_path camera_path{};
        camera_path.header = FGR_HEADER(fgr_camera_path);
        camera_path.name =
            out.keep(text(required(value[i], where, "name"), key_path(where, "name")));
        const std::string keys_path = key_path(where, "keyframes");
        const json& keys = require_array(required(value[i], where, "keyframes"), keys_path);
        std::vector<fgr_keyframe> keyframes;
        for (std::size_t k = 0; k < keys.size(); ++k) {
            const std::string key_where = index_path(keys_path, k);
            require_object(keys[k], key_where);
            check_keys(keys[k], key_where, {"time", "position", "target", "up", "fov"});
            fgr_keyframe keyframe{};
            keyframe.header = FGR_HEADER(fgr_keyframe);
            keyframe.time =
                number(required(keys[k], key_where, "time"), key_path(key_where, "time"));
            read_view(keys[k], key_where, keyframe);
            keyframes.push_back(keyframe);
        }
        out.keyframes.push_back(std::move(keyframes));
        out.paths.push_back(camera_path);
    }
}

fgr_light read_light(const json& entry, const std::string& path) {
    require_object(entry, path);
    fgr_light light{};
    light.header = FGR_HEADER(fgr_light);
    const std::string type_path = key_path(path, "type");
    const json& type = required(entry, path, "type");
    if (type == "directional") {
        check_keys(entry, path,
                   {"type", "direction", "colour", "intensity", "angular_radius_degrees"});
        light.type = FGR_LIGHT_DIRECTIONAL;
        set3(light.vector, vec3(required(entry, path, "direction"), key_path(path, "direction")));
        light.angular_radius_degrees = number_or(entry, path, "angular_radius_degrees", 0.0f);
    } else if (type == "point") {
        check_keys(entry, path, {"type", "position", "colour", "intensity"});
        light.type = FGR_LIGHT_POINT;
        set3(light.vector, vec3(required(entry, path, "position"), key_path(path, "position")));
    } else {
        refuse_at(type_path,
                  fmt::format("{} must be \"directional\" or \"point\"", json_fields::shown(type)));
    }
    set3(light.colour, vec3_or(entry, path, "colour", std::array<float, 3>{1.0f, 1.0f, 1.0f}));
    light.intensity = number_or(entry, path, "intensity", 1.0f);
    return light;
}

// What a scene without cameras gets: the SDK template's front view of a ball of radius `scale`
// at the origin, +z up.
fgr_camera default_camera(float scale) {
    fgr_camera camera{};
    camera.header = FGR_HEADER(fgr_camera);
    camera.name = "default";
    set3(camera.position, {0.0f, -3.6f * scale, 1.4f * scale});
    set3(camera.up, kUpZ);
    camera.fov_degrees = 50.0f;
    return camera;
}

// The orbit IFS and formula files get without camera paths (scene_json::default_orbit), around
// the first camera.
std::vector<fgr_keyframe> default_orbit_keyframes(const fgr_camera& first) {
    NamedCamera camera;
    camera.name = "orbit";
    camera.view.position = {first.position[0], first.position[1], first.position[2]};
    camera.view.target = {first.target[0], first.target[1], first.target[2]};
    camera.view.up = {first.up[0], first.up[1], first.up[2]};
    camera.view.fov_degrees = first.fov_degrees;
    std::vector<fgr_keyframe> keyframes;
    for (const Keyframe& key : scene_json::default_orbit(camera).keyframes) {
        fgr_keyframe keyframe{};
        keyframe.header = FGR_HEADER(fgr_keyframe);
        keyframe.time = key.time;
        set3(keyframe.position,
             {static_cast<float>(key.view.position.x), static_cast<float>(key.view.position.y),
              static_cast<float>(key.view.position.z)});
        set3(keyframe.target,
             {static_cast<float>(key.view.target.x), static_cast<float>(key.view.target.y),
              static_cast<float>(key.view.target.z)});
        set3(keyframe.up, {key.view.up.x, key.view.up.y, key.view.up.z});
        keyframe.fov_degrees = key.view.fov_degrees;
        keyframes.push_back(keyframe);
    }
    return keyframes;
}

fgr_light default_light() {
    const Light usual = scene_json::default_light();
    fgr_light light{};
    light.header = FGR_HEADER(fgr_light);
    light.type = FGR_LIGHT_DIRECTIONAL;
    set3(light.vector, {usual.vector.x, usual.vector.y, usual.vector.z});
    set3(light.colour, {usual.colour.r, usual.colour.g, usual.colour.b});
    light.intensity = usual.intensity;
    return light;
}

// --- Effects, march settings and the scene's tuning ----------------------------------------------

// The template's: hard shadows and step-count occlusion.
constexpr uint64_t kDefaultEffects = FGR_EFFECT_SHADOWS | FGR_EFFECT_AMBIENT_OCCLUSION;

uint64_t read_effects(const json& value, const std::string& path) {
    require_array(value, path);
    uint64_t effects = 0;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string where = index_path(path, i);
        const std::string name = text(value[i], where);
        bool known = false;
        for (const EffectSwitch& effect : effect_switches()) {
            if (name == effect.name) {
                effects |= effect.bit;
                known = true;
            }
        }
        if (!known) {
            refuse_at(where, fmt::format("unknown effect {} (known: {})",
                                         json_fields::shown(value[i]), effect_names(~uint64_t{0})));
        }
    }
    return effects;
}

fgr_march_settings read_march(const json* value, const std::string& path, float scale) {
    const MarchSettings defaults;
    fgr_march_settings march =
        FGR_MARCH(defaults.max_steps, defaults.max_distance * scale, defaults.hit_threshold,
                  defaults.de_iterations, defaults.step_factor);
    if (value == nullptr) return march;
    require_object(*value, path);
    check_keys(*value, path,
               {"max_steps", "max_distance", "hit_threshold", "iterations", "step_factor"});
    if (const json* given = member(*value, "max_steps")) {
        march.max_steps = whole(*given, key_path(path, "max_steps"));
    }
    march.max_distance = number_or(*value, path, "max_distance", march.max_distance);
    march.hit_threshold = number_or(*value, path, "hit_threshold", march.hit_threshold);
    if (const json* given = member(*value, "iterations")) {
        march.de_iterations = whole(*given, key_path(path, "iterations"));
    }
    march.step_factor = number_or(*value, path, "step_factor", march.step_factor);
    // The ABI reads 0 as "full steps"; written out, it is a mistake.
    if (!(march.step_factor > 0.0f)) refuse_at(key_path(path, "step_factor"), "must be above 0");
    return march;
}

// "builtin_defaults": {"ao_radius": 0.2, "fog_colour": [0.1, 0.1, 0.2]}, a number for each
// scalar built-in and three for a colour.
void read_builtin_defaults(const json& value, const std::string& path, Description& out) {
    require_object(value, path);
    Scene probe;
    add_builtin_params(probe);
    for (const auto& item : value.items()) {
        const std::string where = key_path(path, item.key());
        const ParamInfo* builtin = probe.find_param(item.key());
        const bool three = builtin ? param_components(builtin->type) == 3 : item.value().is_array();
        fgr_builtin_default entry{};
        entry.header = FGR_HEADER(fgr_builtin_default);
        entry.id = out.keep(text(json(item.key()), where));
        if (three) {
            set3(entry.value, vec3(item.value(), where));
        } else {
            entry.value[0] = number(item.value(), where);
        }
        out.builtin_defaults.push_back(entry);
    }
}

// "colour_modes": the colour_mode values the scene offers, by name.
uint32_t read_colour_modes(const json& value, const std::string& path) {
    require_array(value, path);
    if (value.empty()) refuse_at(path, "must name at least one colour mode (leave it out for all)");
    const fgr_param_desc colour[] = {FGR_COLOUR_PARAMS(0, 0, 1.0f, 1.0f, 1.0f)};
    const std::vector<std::string> names = split_choices(colour[0].choices);
    uint32_t modes = 0;
    for (std::size_t i = 0; i < value.size(); ++i) {
        modes |= 1u << index_of(value[i], index_path(path, i), names, "colour mode");
    }
    return modes;
}

// --- The header ----------------------------------------------------------------------------------

void read_header(const json& document, Description& out) {
    check_keys(document, "",
               {"$schema", "id", "name", "description", "parameters", "colour_parameters",
                "cameras", "camera_paths", "lights", "effects", "march", "default_mode",
                "builtin_defaults", "colour_modes", "scale", "environment"});
    if (const json* schema = member(document, "$schema")) text(*schema, "$schema");
    fgr_scene_desc& desc = out.desc;
    desc.header = FGR_HEADER(fgr_scene_desc);
    desc.id = out.keep(text(required(document, "", "id"), "id"));
    desc.name = out.keep(text(required(document, "", "name"), "name"));
    const json* description = member(document, "description");
    desc.description = out.keep(description ? text(*description, "description") : "");

    float scale = 1.0f;
    if (const json* given = member(document, "scale")) {
        scale = number(*given, "scale");
        if (!(scale > 0.0f)) refuse_at("scale", "must be above 0");
        desc.scale = scale;
    }
    if (const json* params = member(document, "parameters")) {
        require_array(*params, "parameters");
        for (std::size_t i = 0; i < params->size(); ++i) {
            read_parameter((*params)[i], index_path("parameters", i), out);
        }
    }
    if (const json* colour = member(document, "colour_parameters")) {
        read_colour_parameters(*colour, "colour_parameters", out);
    }
    if (const json* cameras = member(document, "cameras")) {
        read_cameras(*cameras, "cameras", out);
    } else {
        out.cameras.push_back(default_camera(scale));
    }
    if (const json* paths = member(document, "camera_paths")) {
        read_camera_paths(*paths, "camera_paths", out);
    } else if (!out.cameras.empty()) {
        out.keyframes.push_back(default_orbit_keyframes(out.cameras.front()));
        fgr_camera_path orbit{};
        orbit.header = FGR_HEADER(fgr_camera_path);
        orbit.name = "orbit";
        out.paths.push_back(orbit);
    }
    if (const json* lights = member(document, "lights")) {
        require_array(*lights, "lights");
        for (std::size_t i = 0; i < lights->size(); ++i) {
            out.lights.push_back(read_light((*lights)[i], index_path("lights", i)));
        }
    } else {
        out.lights.push_back(default_light());
    }
    const json* effects = member(document, "effects");
    desc.effects = effects ? read_effects(*effects, "effects") : kDefaultEffects;
    desc.march = read_march(member(document, "march"), "march", scale);
    if (const json* mode = member(document, "default_mode")) {
        desc.default_mode = out.keep(text(*mode, "default_mode"));
    }
    if (const json* defaults = member(document, "builtin_defaults")) {
        read_builtin_defaults(*defaults, "builtin_defaults", out);
    }
    if (const json* modes = member(document, "colour_modes")) {
        desc.colour_modes = read_colour_modes(*modes, "colour_modes");
    }
    // Checked with the rest of the description (copy_scene_description), as a plugin's is.
    if (const json* environment = member(document, "environment")) {
        desc.environment = out.keep(text(*environment, "environment"));
    }
    out.finish();
}

// The id the header declares, when it is a valid one: a refused text scene is still found by it
// (unknown_scene_message).
std::string declared_id(const json& document) {
    const json* id = member(document, "id");
    if (id == nullptr || !id->is_string()) return {};
    std::string text = id->get<std::string>();
    return is_scene_id(text) ? text : std::string();
}

}  // namespace
}  // namespace fgr::text_header

namespace fgr {

namespace fs = std::filesystem;

bool is_text_scene_file_name(const fs::path& file) { return file.extension() == ".cl"; }

bool starts_with_text_scene_header(std::string_view text) {
    return text_header::after_tag(text).has_value();
}

bool is_text_scene_file(const fs::path& file) {
    return is_text_scene_file_name(file) && file_has_text_scene_header(file);
}

bool file_has_text_scene_header(const fs::path& file) {
    // Opened only when it is a regular file, checked on the open descriptor: a FIFO named x.cl
    // never blocks the scan.
    std::string reason;
    const FilePointer in = open_regular_file(file, reason);
    if (in == nullptr) return false;
    std::array<char, kTextSceneSniffBytes> start{};
    const std::size_t read = std::fread(start.data(), 1, start.size(), in.get());
    return starts_with_text_scene_header(std::string_view(start.data(), read));
}

LoadResult parse_text_scene(std::string_view text, const fs::path& file) {
    const std::optional<std::size_t> json_begin = text_header::after_tag(text);
    if (!json_begin) {
        return text_header::failure(fmt::format(
            "does not start with a text scene's header, a comment /* {} {{...}} */ (see the "
            "SDK guide, \"A scene in ten lines of text\")",
            kTextSceneTag));
    }
    if (text.find('\0') != std::string_view::npos)
        return text_header::failure("holds a NUL byte: not text");
    std::string id;
    try {
        const std::size_t close = text.find("*/", *json_begin);
        if (close == std::string_view::npos) {
            text_header::refuse_at("", "the comment is not closed (no */)");
        }
        const nlohmann::json document = text_header::parse_header(text, *json_begin, close);
        id = text_header::declared_id(document);
        text_header::Description out;
        text_header::read_header(document, out);
        const std::string source_name = file.string();
        out.desc.source = text.data();
        out.desc.source_length = text.size();
        out.desc.source_name = source_name.c_str();
        LoadResult result = copy_scene_description(&out.desc);
        if (result.scene) {
            result.scene->plugin_file = file;
        } else {
            result.error = text_header::failure(std::move(result.error)).error;
            if (result.declared_id.empty()) result.declared_id = id;
        }
        return result;
    } catch (const std::runtime_error& error) {  // HeaderError, and json_fields' refusals
        return text_header::failure(error.what(), id);
    } catch (const std::exception& error) {
        return text_header::failure(fmt::format("header could not be read: {}", error.what()), id);
    }
}

LoadResult load_text_scene(const fs::path& file) {
    std::string text;
    try {
        text = scene_json::read_bounded(file, scene_limits::kMaxSourceBytes);
    } catch (const std::runtime_error& error) {
        std::string reason = error.what();
        const std::string prefix = printable_path(file) + ": ";
        if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
        return text_header::failure(std::move(reason));
    }
    return parse_text_scene(text, file);
}

}  // namespace fgr
