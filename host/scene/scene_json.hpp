// SPDX-License-Identifier: Apache-2.0
#pragma once
// What fgr's JSON scene files (IFS scenes `NAME.ifs.json`, formula scenes `NAME.formula.json`)
// read the same way: the file itself (bounded in size), the header (format, version, id, name,
// description), names and texts, cameras, camera paths and lights, and the defaults a file may
// leave out. Each reader throws std::runtime_error with a one-line reason; the caller puts the
// file's name in front. The limits a plugin has (scene_limits.hpp) bound them.

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace fgr::scene_json {

// The Scene of a scene file's data (an IfsScene, a FormulaScene): its id, name and description,
// cameras, camera paths and lights, the OpenCL source written from it and the file. The source's
// name is the id and `suffix` (".ifs.cl"), not the file's path: `fgr view --dev` watches a
// scene's source_name as OpenCL source.
template <typename FileData>
Scene scene_of_file(const FileData& data, std::string source, const char* suffix,
                    const std::filesystem::path& file) {
    Scene scene;
    scene.id = data.id;
    scene.name = data.name;
    scene.description = data.description;
    scene.source = std::move(source);
    scene.source_name = data.id + suffix;
    scene.plugin_file = file;
    scene.cameras = data.cameras;
    scene.camera_paths = data.camera_paths;
    scene.lights = data.lights;
    scene.environment = data.environment;
    return scene;
}

// The file's bytes (util/files.hpp read_file_bytes: a regular file of at most max_bytes, checked
// before anything is read), else std::runtime_error "<file>: <why>", the file's name as
// printable_path shows it.
std::string read_bounded(const std::filesystem::path& file, std::size_t max_bytes);

// The document `text` parses to through json_fields::parse_document (no NUL byte, nesting at most
// 64 deep, no key twice, nothing after the value): a JSON object, else "not valid JSON: <why>" or
// "must be a JSON object".
nlohmann::json parse_object(std::string_view text);

// "format" must be `format` and "version" the integer `version`.
void check_format(const nlohmann::json& document, const char* format, int version);

// Names and descriptions: at most kMaxTextLength bytes, no control characters (they would break
// `fgr list` and the one-line messages that quote them). Empty when absent and not required.
std::string text_from(const nlohmann::json& object, const char* key, const std::string& where,
                      bool required);

// object[key]: an array of min_size to max_size entries.
const nlohmann::json& array_from(const nlohmann::json& object, const char* key,
                                 std::size_t min_size, std::size_t max_size,
                                 const std::string& what);

void require_object(const nlohmann::json& value, const std::string& where);

// A scene's "id" (required, [a-z][a-z0-9_-]*), "name" (required, not empty) and "description".
struct Header {
    std::string id;
    std::string name;
    std::string description;
};
Header header_from(const nlohmann::json& document);

// A camera's or path's "name": [a-z0-9_-]+.
std::string camera_name_from(const nlohmann::json& object, const std::string& where);

// The document's "cameras", "camera_paths" and "lights" (each optional: empty when absent).
std::vector<NamedCamera> cameras_from(const nlohmann::json& document);
std::vector<CameraPath> camera_paths_from(const nlohmann::json& document);
std::vector<Light> lights_from(const nlohmann::json& document);

// The document's "environment" (optional: "" when absent), the scene's own for the path mode, as
// check_scene_environment (scene/environment_spec.hpp) takes it: "sky", "studio", "uniform",
// "uniform:V" or "uniform:R,G,B".
std::string environment_from(const nlohmann::json& document);

// A turn around the vertical through the camera's target, at its distance and height: five
// keyframes 90 degrees apart, two seconds each (the last back where it started).
CameraPath default_orbit(const NamedCamera& camera);
// The DE scenes' usual warm key light (sdk/template/scene.c).
Light default_light();

}  // namespace fgr::scene_json
