// SPDX-License-Identifier: Apache-2.0
#include "camera/camera_path_file.hpp"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "camera/view_json.hpp"
#include "util/atomic_file.hpp"
#include "util/files.hpp"
#include "util/installed_files.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "fgr-camera-path";
constexpr int kVersion = 1;
constexpr const char* kSchema = "camera-path.schema.json";
using json_fields::fail;

Keyframe keyframe_from(const json& entry, std::size_t index) {
    const std::string where = "keyframe " + std::to_string(index);
    if (!entry.is_object()) fail(where + " must be an object");
    json_fields::check_keys(entry, {"time", "position", "target", "up", "fov"}, where);
    Keyframe keyframe;
    if (!entry.contains("time")) fail(where + " \"time\" is missing");
    keyframe.time =
        static_cast<float>(json_fields::finite_double(entry.at("time"), where + " \"time\""));
    keyframe.view = json_fields::view_from(entry, where);
    return keyframe;
}

}  // namespace

std::string camera_path_json(const CameraPathFile& file) {
    const json document = {{"$schema", schema_reference(kSchema)},
                           {"format", kFormat},
                           {"version", kVersion},
                           {"scene", file.scene},
                           {"name", file.path.name},
                           {"keyframes", json_fields::keyframes_json(file.path.keyframes)}};
    return document.dump(2) + "\n";
}

CameraPathFile parse_camera_path_json(const std::string& text) {
    const json document = json_fields::parse_document(text, "not valid JSON");
    if (!document.is_object()) fail("must be a JSON object");
    // Compared as JSON: value("format", "") throws a type_error when "format" is not a string.
    if (!document.contains("format") || document.at("format") != kFormat) {
        fail("\"format\" must be \"fgr-camera-path\"");
    }
    json_fields::check_version(document, kVersion);
    json_fields::check_keys(
        document, {"$schema", "format", "version", "scene", "name", "keyframes"}, "top level");
    json_fields::check_schema_key(document);
    const auto string_of = [&](const char* key, const char* absent) {
        if (!document.contains(key)) return std::string(absent);
        if (!document.at(key).is_string()) fail("\"{}\" must be a string", key);
        return document.at(key).get<std::string>();
    };
    CameraPathFile file;
    file.scene = string_of("scene", "");
    file.path.name = string_of("name", "file");
    if (!document.contains("keyframes") || !document.at("keyframes").is_array()) {
        fail("\"keyframes\" must be an array");
    }
    const json& keyframes = document.at("keyframes");
    if (keyframes.size() < 2) fail("a camera path needs at least two keyframes");
    if (keyframes.size() > kMaxPathKeyframes) {
        fail("{} keyframes: a camera path has at most {}", keyframes.size(), kMaxPathKeyframes);
    }
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        file.path.keyframes.push_back(keyframe_from(keyframes[i], i));
        if (i > 0 && !(file.path.keyframes[i].time > file.path.keyframes[i - 1].time)) {
            fail("keyframe " + std::to_string(i) + " \"time\" must be after the previous one");
        }
    }
    return file;
}

CameraPathFile read_camera_path_file(const std::filesystem::path& file) {
    std::string text;
    if (const std::string problem = read_file_bytes(file, text, kMaxCameraPathFileBytes);
        !problem.empty()) {
        throw std::runtime_error("cannot read camera path " + quoted(file) + ": " + problem);
    }
    try {
        return parse_camera_path_json(text);
    } catch (const std::runtime_error& error) {
        throw std::runtime_error("camera path " + quoted(file) + ": " + error.what());
    }
}

void write_camera_path_file(const std::filesystem::path& file, const CameraPathFile& contents) {
    write_text_file_atomically(file, camera_path_json(contents));
}

bool looks_like_camera_path_file(const std::string& argument) {
    return argument.size() > 5 && argument.substr(argument.size() - 5) == ".json";
}

}  // namespace fgr
