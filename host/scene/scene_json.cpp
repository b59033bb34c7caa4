// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <numbers>
#include <set>
#include <stdexcept>

#include "camera/view_json.hpp"
#include "scene/description_validation.hpp"
#include "scene/environment_spec.hpp"
#include "scene/scene_limits.hpp"
#include "util/files.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr::scene_json {
namespace {

using json_fields::check_keys;
using json_fields::dvec3_from;
using json_fields::fail;
using json_fields::finite_double;
using json_fields::shown;
using nlohmann::json;
using scene_limits::kMaxAngularRadiusDegrees;
using scene_limits::kMaxCameraPaths;
using scene_limits::kMaxCameras;
using scene_limits::kMaxIdLength;
using scene_limits::kMaxKeyframes;
using scene_limits::kMaxLights;
using scene_limits::kMaxTextLength;
using scene_limits::kMinKeyframes;

std::vector<Keyframe> keyframes_from(const json& path, const std::string& where);
Light light_from(const json& entry, std::size_t index);

}  // namespace

std::string read_bounded(const std::filesystem::path& file, std::size_t max_bytes) {
    std::string text;
    if (const std::string failure = read_file_bytes(file, text, max_bytes); !failure.empty()) {
        fail("{}: {}", printable_path(file), failure);
    }
    return text;
}

json parse_object(std::string_view text) {
    json document = json_fields::parse_document(text, "not valid JSON");
    if (!document.is_object()) fail("must be a JSON object");
    return document;
}

void check_format(const json& document, const char* format, int version) {
    if (!document.contains("format")) fail("\"format\" is missing (must be \"{}\")", format);
    if (document.at("format") != format) {
        fail("\"format\" {} must be \"{}\"", shown(document.at("format")), format);
    }
    json_fields::check_version(document, version);
}

Header header_from(const json& document) {
    Header header;
    header.id = text_from(document, "id", "", true);
    if (!is_scene_id(header.id)) {
        fail("\"id\" '{}' {} (at most {} characters)", printable_excerpt(header.id),
             scene_limits::kSceneIdRule, kMaxIdLength);
    }
    header.name = text_from(document, "name", "", true);
    if (header.name.empty()) fail("\"name\" is empty");
    header.description = text_from(document, "description", "", false);
    return header;
}

// Names and descriptions: at most kMaxTextLength bytes, no control characters (they would break
// `fgr list` and the one-line messages that quote them).
std::string text_from(const json& object, const char* key, const std::string& where,
                      bool required) {
    const std::string what =
        where.empty() ? fmt::format("\"{}\"", key) : fmt::format("{} \"{}\"", where, key);
    if (!object.contains(key)) {
        if (required) fail("{} is missing", what);
        return {};
    }
    const json& value = object.at(key);
    if (!value.is_string()) fail("{} must be a string", what);
    std::string text = value.get<std::string>();
    if (text.size() > kMaxTextLength) fail("{} longer than {} bytes", what, kMaxTextLength);
    if (std::any_of(text.begin(), text.end(),
                    [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; })) {
        fail("{} contains a control character", what);
    }
    return text;
}

const json& array_from(const json& object, const char* key, std::size_t min_size,
                       std::size_t max_size, const std::string& what) {
    const json& value = object.at(key);
    if (!value.is_array()) fail("{} must be an array", what);
    if (value.size() < min_size || value.size() > max_size) {
        fail("{} has {} entries; {} to {} allowed", what, value.size(), min_size, max_size);
    }
    return value;
}

void require_object(const json& value, const std::string& where) {
    if (!value.is_object()) fail("{} must be an object", where);
}

std::string camera_name_from(const json& object, const std::string& where) {
    const std::string name = text_from(object, "name", where, true);
    if (!is_camera_name(name)) {
        fail("{}: name '{}' {} (at most {} characters)", where, printable_excerpt(name),
             scene_limits::kCameraNameRule, kMaxIdLength);
    }
    return name;
}

namespace {

std::vector<Keyframe> keyframes_from(const json& path, const std::string& where) {
    if (!path.contains("keyframes")) fail("{} \"keyframes\" is missing", where);
    const json& array =
        array_from(path, "keyframes", kMinKeyframes, kMaxKeyframes, where + " \"keyframes\"");
    std::vector<Keyframe> keyframes;
    for (std::size_t i = 0; i < array.size(); ++i) {
        const json& entry = array[i];
        const std::string keyframe_where = fmt::format("{} keyframe {}", where, i);
        require_object(entry, keyframe_where);
        check_keys(entry, {"time", "position", "target", "up", "fov"}, keyframe_where);
        if (!entry.contains("time")) fail("{} \"time\" is missing", keyframe_where);
        Keyframe keyframe;
        // Times are floats in a Scene: read as the plugins' are, then compared as stored.
        keyframe.time =
            static_cast<float>(finite_double(entry.at("time"), keyframe_where + " \"time\"", 1e30));
        if (!keyframes.empty() && !(keyframe.time > keyframes.back().time)) {
            fail("{}: time {} not after {}", keyframe_where, keyframe.time, keyframes.back().time);
        }
        keyframe.view = json_fields::view_from(entry, keyframe_where);
        keyframes.push_back(keyframe);
    }
    return keyframes;
}

// As a plugin's lights (description_validation.cpp copy_light): finite, colour and intensity not
// negative, a directional light's direction not zero (normalised here), its disc's angular radius
// in [0, 45] degrees.
Light light_from(const json& entry, std::size_t index) {
    const std::string where = fmt::format("light {}", index);
    require_object(entry, where);
    if (!entry.contains("type")) fail("{} \"type\" is missing", where);
    const json& type = entry.at("type");
    Light light;
    if (type == "directional") {
        check_keys(entry, {"type", "direction", "colour", "intensity", "angular_radius_degrees"},
                   where);
        light.type = LightType::Directional;
        const glm::dvec3 direction = dvec3_from(entry, "direction", where);
        const double length = glm::length(direction);
        if (!(length > 0.0) || !std::isfinite(length)) fail("{}: zero direction", where);
        light.vector = glm::vec3(direction / length);
        if (entry.contains("angular_radius_degrees")) {
            const double degrees = finite_double(entry.at("angular_radius_degrees"),
                                                 where + " \"angular_radius_degrees\"");
            if (degrees < 0.0 || degrees > kMaxAngularRadiusDegrees) {
                fail("{}: angular_radius_degrees {} outside [0, {}]", where, degrees,
                     kMaxAngularRadiusDegrees);
            }
            light.angular_radius = static_cast<float>(degrees * (std::numbers::pi / 180.0));
        }
    } else if (type == "point") {
        check_keys(entry, {"type", "position", "colour", "intensity"}, where);
        light.type = LightType::Point;
        light.vector = glm::vec3(dvec3_from(entry, "position", where));
    } else {
        fail("{} \"type\" {} must be \"directional\" or \"point\"", where, shown(type));
    }
    if (entry.contains("colour")) {
        const glm::dvec3 colour = dvec3_from(entry, "colour", where, 1e6);
        if (colour.r < 0.0 || colour.g < 0.0 || colour.b < 0.0) {
            fail("{}: negative colour", where);
        }
        light.colour = glm::vec3(colour);
    }
    if (entry.contains("intensity")) {
        const double intensity =
            finite_double(entry.at("intensity"), where + " \"intensity\"", 1e6);
        if (intensity < 0.0) fail("{}: negative intensity {}", where, intensity);
        light.intensity = static_cast<float>(intensity);
    }
    return light;
}

}  // namespace

std::vector<NamedCamera> cameras_from(const json& document) {
    std::vector<NamedCamera> cameras;
    if (!document.contains("cameras")) return cameras;
    const json& array = array_from(document, "cameras", 1, kMaxCameras, "\"cameras\"");
    std::set<std::string> names;
    for (std::size_t i = 0; i < array.size(); ++i) {
        const json& entry = array[i];
        const std::string where = fmt::format("camera {}", i);
        require_object(entry, where);
        check_keys(entry, {"name", "position", "target", "up", "fov"}, where);
        NamedCamera camera;
        camera.name = camera_name_from(entry, where);
        if (!names.insert(camera.name).second) fail("{}: duplicate name '{}'", where, camera.name);
        camera.view = json_fields::view_from(entry, fmt::format("camera '{}'", camera.name));
        cameras.push_back(std::move(camera));
    }
    return cameras;
}

std::vector<CameraPath> camera_paths_from(const json& document) {
    std::vector<CameraPath> paths;
    if (!document.contains("camera_paths")) return paths;
    const json& array =
        array_from(document, "camera_paths", 0, kMaxCameraPaths, "\"camera_paths\"");
    std::set<std::string> names;
    for (std::size_t i = 0; i < array.size(); ++i) {
        const json& entry = array[i];
        std::string where = fmt::format("camera path {}", i);
        require_object(entry, where);
        check_keys(entry, {"name", "keyframes"}, where);
        CameraPath path;
        path.name = camera_name_from(entry, where);
        if (!names.insert(path.name).second) fail("{}: duplicate name '{}'", where, path.name);
        path.keyframes = keyframes_from(entry, fmt::format("camera path '{}'", path.name));
        paths.push_back(std::move(path));
    }
    return paths;
}

std::vector<Light> lights_from(const json& document) {
    std::vector<Light> lights;
    if (!document.contains("lights")) return lights;
    const json& array = array_from(document, "lights", 1, kMaxLights, "\"lights\"");
    for (std::size_t i = 0; i < array.size(); ++i) lights.push_back(light_from(array[i], i));
    return lights;
}

std::string environment_from(const json& document) {
    const std::string text = text_from(document, "environment", "", false);
    try {
        check_scene_environment(text);
    } catch (const std::invalid_argument& error) {
        fail("\"environment\": {}", error.what());
    }
    return text;
}

CameraPath default_orbit(const NamedCamera& camera) {
    CameraPath path;
    path.name = "orbit";
    const glm::dvec3 target = camera.view.target;
    const glm::dvec3 offset = camera.view.position - target;
    for (int step = 0; step <= 4; ++step) {
        const double angle = glm::radians(90.0 * step);
        const double c = std::cos(angle), s = std::sin(angle);
        Keyframe keyframe;
        keyframe.time = 2.0f * static_cast<float>(step);
        keyframe.view = camera.view;
        keyframe.view.position =
            target + glm::dvec3(c * offset.x - s * offset.y, s * offset.x + c * offset.y, offset.z);
        path.keyframes.push_back(keyframe);
    }
    return path;
}

Light default_light() {
    Light light;
    light.type = LightType::Directional;
    light.vector = glm::vec3(glm::normalize(glm::dvec3(0.6, -0.5, 0.8)));
    light.colour = glm::vec3(1.0f, 0.95f, 0.85f);
    light.intensity = 1.1f;
    return light;
}

}  // namespace fgr::scene_json
