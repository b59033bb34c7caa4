// SPDX-License-Identifier: Apache-2.0
#include "view_file/view_file.hpp"

#include <fmt/format.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "camera/view_validation.hpp"
#include "render/renderer.hpp"
#include "render/sample_budget.hpp"
#include "scene/effects.hpp"
#include "scene/parameters.hpp"
#include "scene/scene_json.hpp"
#include "scene/scene_limits.hpp"
#include "util/atomic_file.hpp"
#include "util/content_hash.hpp"
#include "util/files.hpp"
#include "util/installed_files.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

using json_fields::fail;
using nlohmann::json;

// Nesting deeper than this is no view file; refusing it before parsing keeps a hostile file from
// recursing through the JSON library.
constexpr int kMaxViewDepth = 16;
constexpr std::size_t kMaxViewParameters = 1024;

// A parameter's id or an enum choice's name: [a-z][a-z0-9_]*, as a plugin's are.
bool is_parameter_word(std::string_view word) {
    if (word.empty() || word.size() > scene_limits::kMaxIdLength || word[0] < 'a' || word[0] > 'z')
        return false;
    for (const char c : word) {
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
    }
    return true;
}

// The double a decimal reads as (strtod: subnormals too, where std::stod throws).
double decimal(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

// A float written as the shortest decimal that reads back to it, held as the double of that
// decimal: the file shows 0.1, not 0.100000001490116.
json float_json(float value) { return decimal(fmt::format("{}", value)); }

std::string number_text(double value) { return fmt::format("{}", value); }

json vector_json(const glm::vec3& v) { return {float_json(v.x), float_json(v.y), float_json(v.z)}; }

std::string key_path(const std::string& where, const char* key) {
    return where.empty() ? key : where + "." + key;
}

// --- Reading -----------------------------------------------------------------------------------

const json* optional_member(const json& object, const char* key) {
    const auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
}

// object[key], an object; an empty one when it is absent and not required.
const json& object_member(const json& object, const char* key, const std::string& where,
                          bool required) {
    static const json empty = json::object();
    const json* member = optional_member(object, key);
    if (member == nullptr) {
        if (required) fail("\"{}\" is missing", key_path(where, key));
        return empty;
    }
    if (!member->is_object()) fail("\"{}\": must be an object", key_path(where, key));
    return *member;
}

double number_in(const json& object, const char* key, const std::string& where, double low,
                 double high, bool low_open, bool high_open, double fallback) {
    const json* member = optional_member(object, key);
    if (member == nullptr) return fallback;
    const std::string name = key_path(where, key);
    if (!member->is_number()) fail("\"{}\": must be a number", name);
    const double value = member->get<double>();
    const bool above = low_open ? value > low : value >= low;
    const bool below = high_open ? value < high : value <= high;
    if (!std::isfinite(value) || !above || !below) {
        fail("\"{}\": must be a number in {}{:g}, {:g}{} (not {})", name, low_open ? "(" : "[", low,
             high, high_open ? ")" : "]", json_fields::shown(*member));
    }
    return value;
}

float float_in(const json& object, const char* key, const std::string& where, double low,
               double high, float fallback) {
    return static_cast<float>(number_in(object, key, where, low, high, false, false, fallback));
}

int64_t integer_in(const json& object, const char* key, const std::string& where, int64_t low,
                   int64_t high, int64_t fallback) {
    const json* member = optional_member(object, key);
    if (member == nullptr) return fallback;
    int64_t value = 0;
    if (!json_fields::integer_in(*member, low, high, value)) {
        fail("\"{}\": must be an integer in [{}, {}] (not {})", key_path(where, key), low, high,
             json_fields::shown(*member));
    }
    return value;
}

bool bool_from(const json& object, const char* key, const std::string& where, bool fallback) {
    const json* member = optional_member(object, key);
    if (member == nullptr) return fallback;
    if (!member->is_boolean()) fail("\"{}\": must be true or false", key_path(where, key));
    return member->get<bool>();
}

std::string string_from(const json& object, const char* key, const std::string& where,
                        bool required, const std::string& fallback) {
    const json* member = optional_member(object, key);
    if (member == nullptr) {
        if (required) fail("\"{}\" is missing", key_path(where, key));
        return fallback;
    }
    if (!member->is_string()) fail("\"{}\": must be a string", key_path(where, key));
    std::string text = member->get<std::string>();
    if (text.size() > 4096) fail("\"{}\": longer than 4096 bytes", key_path(where, key));
    for (const char c : text) {
        if (static_cast<unsigned char>(c) < 0x20) {
            fail("\"{}\": holds a control character", key_path(where, key));
        }
    }
    return text;
}

template <typename Parse>
auto parsed_value(const json& object, const char* key, const std::string& where,
                  const std::string& fallback, Parse parse) {
    const std::string text = string_from(object, key, where, false, fallback);
    // Every name these take is a word: a longer text is refused without quoting all of it.
    constexpr std::size_t kLongestName = 40;
    if (text.size() > kLongestName) {
        fail("\"{}\": '{}' is no name it takes", key_path(where, key), printable_excerpt(text));
    }
    try {
        return parse(text);
    } catch (const std::exception& error) {
        fail("\"{}\": {}", key_path(where, key), error.what());
    }
}

glm::dvec3 dvec3_in(const json& object, const char* key, const std::string& where) {
    const std::string what = fmt::format("\"{}\":", key_path(where, key));
    if (!object.contains(key)) fail("{} is missing", what);
    const json& value = object.at(key);
    if (!value.is_array() || value.size() != 3) fail("{} must be an array of 3 numbers", what);
    return {json_fields::finite_double(value[0], what, 1e30),
            json_fields::finite_double(value[1], what, 1e30),
            json_fields::finite_double(value[2], what, 1e30)};
}

void read_scene(const json& document, ViewFile& view) {
    const json& scene = object_member(document, "scene", "", true);
    json_fields::check_keys(scene, {"id", "fingerprint", "file"}, "\"scene\"");
    view.scene_id = string_from(scene, "id", "scene", true, "");
    if (!is_scene_id(view.scene_id)) {
        fail("\"scene.id\": {} is not a scene id ([a-z][a-z0-9_-]*, at most {} characters)",
             json_fields::shown(view.scene_id), scene_limits::kMaxIdLength);
    }
    view.scene_fingerprint = string_from(scene, "fingerprint", "scene", false, "");
    if (!view.scene_fingerprint.empty() &&
        (view.scene_fingerprint.size() != 16 ||
         view.scene_fingerprint.find_first_not_of("0123456789abcdef") != std::string::npos)) {
        fail("\"scene.fingerprint\": must be 16 lower-case hex digits");
    }
    view.scene_file = string_from(scene, "file", "scene", false, "");
}

void read_image(const json& document, ViewFile& view) {
    const json& image = object_member(document, "image", "", false);
    json_fields::check_keys(image, {"width", "height", "bit_depth", "alpha", "layers"},
                            "\"image\"");
    view.width = static_cast<int>(integer_in(image, "width", "image", 1, kMaxTiledImageSide, 640));
    view.height =
        static_cast<int>(integer_in(image, "height", "image", 1, kMaxTiledImageSide, 480));
    view.bit_depth = static_cast<int>(integer_in(image, "bit_depth", "image", 8, 16, 8));
    if (view.bit_depth != 8 && view.bit_depth != 16) fail("\"image.bit_depth\": must be 8 or 16");
    view.alpha = bool_from(image, "alpha", "image", false);
    view.layers = string_from(image, "layers", "image", false, "");
}

void read_camera(const json& document, ViewFile& view) {
    const json& camera = object_member(document, "camera", "", true);
    json_fields::check_keys(camera,
                            {"eye", "target", "up", "fov", "projection", "fisheye_fov",
                             "eye_separation", "convergence"},
                            "\"camera\"");
    view.camera.position = dvec3_in(camera, "eye", "camera");
    view.camera.target = dvec3_in(camera, "target", "camera");
    if (camera.contains("up")) view.camera.up = glm::vec3(dvec3_in(camera, "up", "camera"));
    view.camera.fov_degrees =
        static_cast<float>(number_in(camera, "fov", "camera", 0.0, 180.0, true, true, 60.0));
    if (const std::string problem = view_problem(view.camera); !problem.empty()) {
        fail("\"camera\": {}", problem);
    }
    view.projection.kind =
        parsed_value(camera, "projection", "camera", "pinhole",
                     [](const std::string& text) { return parse_projection_kind(text); });
    view.projection.fisheye_fov_degrees = static_cast<float>(number_in(
        camera, "fisheye_fov", "camera", 0.0, 360.0, true, false, kDefaultFisheyeFovDegrees));
    if (camera.contains("eye_separation")) {
        view.projection.eye_separation =
            number_in(camera, "eye_separation", "camera", 0.0, 1e30, false, false, 0.0);
    }
    if (camera.contains("convergence")) {
        view.projection.convergence =
            number_in(camera, "convergence", "camera", 0.0, 1e30, true, false, 1.0);
    }
}

ViewParameter parameter_from(const std::string& id, const json& value) {
    const std::string where = "\"parameters." + id + "\"";
    if (!is_parameter_word(id))
        fail("\"parameters\": {} is not a parameter id", json_fields::shown(id));
    const auto finite = [&](const json& number) {
        return number_text(json_fields::finite_double(number, where, 1e30));
    };
    if (value.is_boolean()) {
        return {id, ViewParameter::Kind::Bool, value.get<bool>() ? "true" : "false"};
    }
    if (value.is_number()) return {id, ViewParameter::Kind::Number, finite(value)};
    if (value.is_string()) {
        const std::string name = value.get<std::string>();
        if (!is_parameter_word(name))
            fail("{}: {} is not a choice name", where, json_fields::shown(value));
        return {id, ViewParameter::Kind::Choice, name};
    }
    if (value.is_array() && value.size() == 3) {
        return {id, ViewParameter::Kind::Vector,
                finite(value[0]) + "," + finite(value[1]) + "," + finite(value[2])};
    }
    fail("{}: must be a number, true or false, a choice's name or an array of 3 numbers", where);
}

void read_parameters(const json& document, ViewFile& view) {
    const json& parameters = object_member(document, "parameters", "", false);
    if (parameters.size() > kMaxViewParameters)
        fail("\"parameters\": more than {}", kMaxViewParameters);
    for (const auto& item : parameters.items()) {
        view.parameters.push_back(parameter_from(item.key(), item.value()));
    }
}

void read_render(const json& document, ViewFile& view) {
    const json& render = object_member(document, "render", "", false);
    json_fields::check_keys(render, {"mode", "samples", "effects", "precision", "prepass"},
                            "\"render\"");
    view.mode = parsed_value(render, "mode", "render", "shaded",
                             [](const std::string& text) { return parse_render_mode(text); });
    view.samples = static_cast<int>(integer_in(render, "samples", "render", 1, kMaxSamples, 1));
    if (const json* effects = optional_member(render, "effects")) {
        if (!effects->is_array() || effects->size() > 64) {
            fail("\"render.effects\": must be an array of effect names");
        }
        for (const json& name : *effects) {
            if (!name.is_string()) fail("\"render.effects\": must be an array of effect names");
            const std::string text = name.get<std::string>();
            if (!is_parameter_word(text)) {
                fail("\"render.effects\": {} is not an effect's name", json_fields::shown(name));
            }
            try {
                apply_effect_changes(0, "+" + text);
            } catch (const std::exception& error) {
                fail("\"render.effects\": {}", error.what());
            }
            view.effects.push_back(text);
        }
    }
    view.precision = parsed_value(render, "precision", "render", "auto",
                                  [](const std::string& text) { return parse_precision(text); });
    view.prepass = bool_from(render, "prepass", "render", true);
}

void read_path(const json& document, ViewFile& view) {
    const json* member = optional_member(document, "path");
    if (member == nullptr) return;
    const json& path = object_member(document, "path", "", true);
    json_fields::check_keys(
        path,
        {"seed", "bounces", "roulette_depth", "radiance_clamp", "light_sampling", "mis",
         "scene_lights", "environment", "environment_rotation", "environment_intensity",
         "turbidity", "sun_elevation", "sun_azimuth", "denoise"},
        "\"path\"");
    ViewPathChoices choices;
    choices.seed = static_cast<uint32_t>(integer_in(path, "seed", "path", 0, UINT32_MAX, 0));
    choices.bounces = static_cast<int>(integer_in(path, "bounces", "path", 0, 1024, 8));
    choices.roulette_depth =
        static_cast<int>(integer_in(path, "roulette_depth", "path", 0, 1024, 3));
    choices.radiance_clamp = float_in(path, "radiance_clamp", "path", 0.0, 1e30, 0.0f);
    choices.light_sampling = bool_from(path, "light_sampling", "path", true);
    choices.mis = bool_from(path, "mis", "path", true);
    choices.scene_lights = bool_from(path, "scene_lights", "path", true);
    choices.denoise = bool_from(path, "denoise", "path", false);
    choices.environment = string_from(path, "environment", "path", false, "sky");
    if (choices.environment.empty()) fail("\"path.environment\": must not be empty");
    choices.environment_rotation = float_in(path, "environment_rotation", "path", -1e6, 1e6, 0.0f);
    choices.environment_intensity =
        float_in(path, "environment_intensity", "path", 0.0, 1e30, 1.0f);
    if (path.contains("turbidity")) {
        choices.turbidity = float_in(path, "turbidity", "path", 1.7, 10.0, 3.0f);
    }
    if (path.contains("sun_elevation")) {
        choices.sun_elevation = float_in(path, "sun_elevation", "path", -10.0, 90.0, 0.0f);
    }
    if (path.contains("sun_azimuth")) {
        choices.sun_azimuth = float_in(path, "sun_azimuth", "path", -1e6, 1e6, 0.0f);
    }
    view.path = choices;
}

// --- Writing -----------------------------------------------------------------------------------

json parameter_json(const ViewParameter& parameter) {
    switch (parameter.kind) {
        case ViewParameter::Kind::Bool:
            return parameter.text == "true";
        case ViewParameter::Kind::Choice:
            return parameter.text;
        case ViewParameter::Kind::Vector: {
            json numbers = json::array();
            std::string_view rest = parameter.text;
            while (!rest.empty()) {
                const std::size_t comma = rest.find(',');
                numbers.push_back(decimal(std::string(rest.substr(0, comma))));
                rest = comma == std::string_view::npos ? "" : rest.substr(comma + 1);
            }
            return numbers;
        }
        case ViewParameter::Kind::Number:
            break;
    }
    return decimal(parameter.text);
}

json path_json(const ViewPathChoices& path) {
    json object = json::object();
    object["seed"] = path.seed;
    object["bounces"] = path.bounces;
    object["roulette_depth"] = path.roulette_depth;
    object["radiance_clamp"] = float_json(path.radiance_clamp);
    object["light_sampling"] = path.light_sampling;
    object["mis"] = path.mis;
    object["scene_lights"] = path.scene_lights;
    object["environment"] = path.environment;
    object["environment_rotation"] = float_json(path.environment_rotation);
    object["environment_intensity"] = float_json(path.environment_intensity);
    if (path.turbidity) object["turbidity"] = float_json(*path.turbidity);
    if (path.sun_elevation) object["sun_elevation"] = float_json(*path.sun_elevation);
    if (path.sun_azimuth) object["sun_azimuth"] = float_json(*path.sun_azimuth);
    if (path.denoise) object["denoise"] = true;
    return object;
}

// Keys in the order written, so that a file reads top-down: what, where from, how.
using ordered = nlohmann::ordered_json;

ordered view_json(const ViewFile& view) {
    ordered document;
    document["$schema"] = schema_reference("view.schema.json");
    document["format"] = kViewFormat;
    document["version"] = kViewVersion;
    if (!view.fgr_version.empty()) document["fgr_version"] = view.fgr_version;
    ordered scene;
    scene["id"] = view.scene_id;
    if (!view.scene_fingerprint.empty()) scene["fingerprint"] = view.scene_fingerprint;
    if (!view.scene_file.empty()) scene["file"] = view.scene_file;
    document["scene"] = scene;
    ordered image;
    image["width"] = view.width;
    image["height"] = view.height;
    image["bit_depth"] = view.bit_depth;
    image["alpha"] = view.alpha;
    image["layers"] = view.layers;
    document["image"] = image;
    ordered camera;
    camera["eye"] = json_fields::vec3_json(view.camera.position);
    camera["target"] = json_fields::vec3_json(view.camera.target);
    camera["up"] = vector_json(view.camera.up);
    camera["fov"] = float_json(view.camera.fov_degrees);
    camera["projection"] = projection_name(view.projection.kind);
    camera["fisheye_fov"] = float_json(view.projection.fisheye_fov_degrees);
    if (view.projection.eye_separation) camera["eye_separation"] = *view.projection.eye_separation;
    if (view.projection.convergence) camera["convergence"] = *view.projection.convergence;
    document["camera"] = camera;
    ordered parameters = ordered::object();
    for (const ViewParameter& parameter : view.parameters) {
        parameters[parameter.id] = ordered(parameter_json(parameter));
    }
    document["parameters"] = parameters;
    ordered render;
    render["mode"] = std::string(render_mode_name(view.mode));
    render["samples"] = view.samples;
    render["effects"] = view.effects;
    render["precision"] = std::string(precision_name(view.precision));
    render["prepass"] = view.prepass;
    document["render"] = render;
    if (view.path) document["path"] = ordered(path_json(*view.path));
    return document;
}

}  // namespace

std::string scene_fingerprint(const Scene& scene) {
    ContentHash hash;
    hash.add(scene.id).add(scene.source);
    for (const ParamInfo& param : scene.params) {
        hash.add(param.id).add_bytes_of(param.type).add_bytes_of(param.min_value);
        hash.add_bytes_of(param.max_value).add_bytes_of(param.default_value);
        for (const std::string& choice : param.choices) hash.add(choice);
    }
    for (const Light& light : scene.lights) {
        hash.add_bytes_of(light.type).add_bytes_of(light.vector).add_bytes_of(light.colour);
        hash.add_bytes_of(light.intensity).add_bytes_of(light.angular_radius);
    }
    hash.add_bytes_of(scene.effects).add_bytes_of(scene.march.max_steps);
    hash.add_bytes_of(scene.march.max_distance).add_bytes_of(scene.march.hit_threshold);
    hash.add_bytes_of(scene.march.de_iterations).add_bytes_of(scene.march.step_factor);
    hash.add_bytes_of(scene.default_mode).add_bytes_of(scene.scale);
    return hash.hex();
}

std::vector<ViewParameter> changed_parameters(const Scene& scene,
                                              const std::vector<float>& values) {
    const std::vector<float> defaults = default_param_values(scene);
    const std::vector<int> offsets = param_offsets(scene);
    std::vector<ViewParameter> changed;
    for (std::size_t i = 0; i < scene.params.size(); ++i) {
        const ParamInfo& param = scene.params[i];
        const auto first = static_cast<std::size_t>(offsets[i]);
        const auto count = static_cast<std::size_t>(param_components(param.type));
        if (first + count > values.size()) break;
        bool differs = false;
        for (std::size_t c = 0; c < count; ++c) differs |= values[first + c] != defaults[first + c];
        if (!differs) continue;
        const float value = values[first];
        switch (param.type) {
            case ParamType::Bool:
                changed.push_back(
                    {param.id, ViewParameter::Kind::Bool, value != 0.0f ? "true" : "false"});
                break;
            case ParamType::Int: {
                const auto index = static_cast<std::size_t>(value - param.min_value);
                if (!param.choices.empty() && index < param.choices.size()) {
                    changed.push_back(
                        {param.id, ViewParameter::Kind::Choice, param.choices[index]});
                } else {
                    changed.push_back(
                        {param.id, ViewParameter::Kind::Number, fmt::format("{}", value)});
                }
                break;
            }
            case ParamType::Vec3:
            case ParamType::Colour:
                changed.push_back(
                    {param.id, ViewParameter::Kind::Vector,
                     fmt::format("{},{},{}", values[first], values[first + 1], values[first + 2])});
                break;
            case ParamType::Float:
                changed.push_back(
                    {param.id, ViewParameter::Kind::Number, fmt::format("{}", value)});
                break;
        }
    }
    // Sorted by id, as the file reads back.
    std::sort(changed.begin(), changed.end(),
              [](const ViewParameter& a, const ViewParameter& b) { return a.id < b.id; });
    return changed;
}

std::string parameter_assignment(const ViewParameter& parameter) {
    return parameter.id + "=" + parameter.text;
}

std::string view_file_text(const ViewFile& view) { return view_json(view).dump(2) + "\n"; }

ViewFile parse_view_file(const std::string& text) {
    if (text.size() > kMaxViewBytes) fail("larger than {} bytes: not a view file", kMaxViewBytes);
    if (json_fields::nests_deeper_than(text, kMaxViewDepth)) {
        fail("nested more than {} levels deep: not a view file", kMaxViewDepth);
    }
    const json document = scene_json::parse_object(text);
    json_fields::check_keys(document,
                            {"$schema", "format", "version", "fgr_version", "scene", "image",
                             "camera", "parameters", "render", "path"},
                            "the view");
    json_fields::check_schema_key(document);
    if (string_from(document, "format", "", true, "") != kViewFormat) {
        fail("\"format\": must be \"{}\" (this is not a view file)", kViewFormat);
    }
    json_fields::check_version(document, kViewVersion);
    ViewFile view;
    view.fgr_version = string_from(document, "fgr_version", "", false, "");
    read_scene(document, view);
    read_image(document, view);
    read_camera(document, view);
    read_parameters(document, view);
    read_render(document, view);
    read_path(document, view);
    return view;
}

ViewFile read_view_file(const std::filesystem::path& file) {
    try {
        std::error_code error;
        if (!std::filesystem::is_regular_file(file, error)) {
            fail(std::filesystem::exists(file, error) ? "not a regular file" : "no such file");
        }
        std::string text;
        if (const std::string failure = read_file_bytes(file, text, kMaxViewBytes);
            !failure.empty()) {
            fail(failure);
        }
        return parse_view_file(text);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error(fmt::format("{}: {}", printable_path(file), error.what()));
    }
}

void write_view_file(const std::filesystem::path& file, const ViewFile& view) {
    const std::string text = view_file_text(view);
    const std::string failure =
        replace_file_atomically(file, [&](const std::filesystem::path& temporary) {
            std::ofstream out(temporary, std::ios::binary);
            out << text;
            out.close();
            return out ? std::string() : std::string("write failed");
        });
    if (!failure.empty()) {
        throw std::runtime_error(fmt::format("cannot write {}: {}", printable_path(file), failure));
    }
}

bool is_view_file_name(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    const std::string suffix = kViewFileSuffix;
    return name.size() > suffix.size() && name.ends_with(suffix);
}

std::string scene_change_warning(const ViewFile& view, const Scene& scene) {
    if (view.scene_fingerprint.empty()) return "";
    const std::string now = scene_fingerprint(scene);
    if (now == view.scene_fingerprint) return "";
    return fmt::format(
        "scene '{}' changed since this view was saved (fingerprint {}, now {}): the image may "
        "differ from the one the view was saved from",
        scene.id, view.scene_fingerprint, now);
}

std::string view_summary(const ViewFile& view) {
    std::string text = fmt::format("scene {}{}\n", view.scene_id,
                                   view.scene_file.empty() ? "" : " (" + view.scene_file + ")");
    text += fmt::format("size {}x{}\n", view.width, view.height);
    const CameraView& camera = view.camera;
    text += fmt::format("camera --eye {},{},{} --target {},{},{} --up {},{},{} --fov {}\n",
                        camera.position.x, camera.position.y, camera.position.z, camera.target.x,
                        camera.target.y, camera.target.z, camera.up.x, camera.up.y, camera.up.z,
                        camera.fov_degrees);
    if (view.projection.kind != ProjectionKind::Pinhole) {
        text += fmt::format("projection {}\n", projection_name(view.projection.kind));
    }
    text += fmt::format("mode {} --spp {} precision {}\n", render_mode_name(view.mode),
                        view.samples, precision_name(view.precision));
    std::string effects;
    for (const std::string& name : view.effects) effects += (effects.empty() ? "" : ",") + name;
    text += fmt::format("effects {}\n", effects.empty() ? "none" : effects);
    for (const ViewParameter& parameter : view.parameters) {
        text += fmt::format("--set {}\n", parameter_assignment(parameter));
    }
    if (view.path) {
        text += fmt::format("path seed {} bounces {} environment {}{}\n", view.path->seed,
                            view.path->bounces, view.path->environment,
                            view.path->denoise ? " denoised" : "");
    }
    return text;
}

ViewPathChoices path_choices_of(const PathSettings& settings,
                                const EnvironmentChoice& environment) {
    ViewPathChoices path;
    path.seed = settings.seed;
    path.bounces = settings.max_bounces;
    path.roulette_depth = settings.roulette_depth;
    path.radiance_clamp = settings.radiance_clamp;
    path.light_sampling = settings.light_sampling;
    path.mis = settings.mis;
    path.scene_lights = settings.scene_lights;
    path.environment = environment_argument(environment);
    path.environment_rotation = environment.rotation_degrees;
    path.environment_intensity = environment.intensity;
    if (environment.kind == EnvironmentKind::Sky) {
        if (environment.sky.turbidity != SkySettings{}.turbidity) {
            path.turbidity = environment.sky.turbidity;
        }
        if (!environment.sun_from_scene) {
            path.sun_elevation = environment.sky.sun_elevation_degrees;
            path.sun_azimuth = environment.sky.sun_azimuth_degrees;
        }
    }
    return path;
}

PathSettings path_settings_of(const ViewPathChoices& path) {
    PathSettings settings;
    settings.max_bounces = path.bounces;
    settings.roulette_depth = path.roulette_depth;
    settings.radiance_clamp = path.radiance_clamp;
    settings.light_sampling = path.light_sampling;
    settings.mis = path.mis;
    settings.scene_lights = path.scene_lights;
    settings.seed = path.seed;
    check_path_settings(settings);
    return settings;
}

EnvironmentChoice environment_choice_of(const ViewPathChoices& path) {
    EnvironmentChoice choice = parse_environment(path.environment);
    choice.rotation_degrees = path.environment_rotation;
    choice.intensity = path.environment_intensity;
    if (path.turbidity) choice.sky.turbidity = *path.turbidity;
    if (path.sun_elevation || path.sun_azimuth) {
        choice.sun_from_scene = false;
        if (path.sun_elevation) choice.sky.sun_elevation_degrees = *path.sun_elevation;
        if (path.sun_azimuth) choice.sky.sun_azimuth_degrees = *path.sun_azimuth;
    }
    if (choice.kind != EnvironmentKind::Sky &&
        (path.turbidity || path.sun_elevation || path.sun_azimuth)) {
        throw std::invalid_argument(
            "path.turbidity, path.sun_elevation and path.sun_azimuth need the environment sky");
    }
    return choice;
}

}  // namespace fgr
