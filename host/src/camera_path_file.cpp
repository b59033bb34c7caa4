#include "fgr/camera_path_file.hpp"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "fgr/atomic_file.hpp"
#include "fgr/view_validation.hpp"

namespace fgr {
namespace {

using nlohmann::json;

constexpr const char* kFormat = "fgr-camera-path";
constexpr int kVersion = 1;

json vec3_json(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }
// Positions and targets: JSON numbers are written to round-trip a double exactly.
json vec3_json(glm::dvec3 v) { return json::array({v.x, v.y, v.z}); }

[[noreturn]] void fail(const std::string& reason) { throw std::runtime_error(reason); }

double finite_double(const json& value, const std::string& what) {
    if (!value.is_number()) fail(what + " must be a number");
    const double number = value.get<double>();
    if (!std::isfinite(number) || std::abs(number) > 1e30) {
        fail(what + " must be finite and at most 1e30 in magnitude");
    }
    return number;
}

float finite_number(const json& value, const std::string& what) {
    return static_cast<float>(finite_double(value, what));
}

// Read in full double precision: a deep zoom's keyframes may differ below float's step.
glm::dvec3 dvec3_from(const json& keyframe, const char* key, const std::string& where) {
    const std::string what = where + " \"" + key + "\"";
    if (!keyframe.contains(key)) fail(what + " is missing");
    const json& value = keyframe.at(key);
    if (!value.is_array() || value.size() != 3) fail(what + " must be an array of 3 numbers");
    return {finite_double(value[0], what), finite_double(value[1], what),
            finite_double(value[2], what)};
}

glm::vec3 vec3_from(const json& keyframe, const char* key, const std::string& where) {
    return glm::vec3(dvec3_from(keyframe, key, where));
}

// "version" must be the integer 1: compared as the integer JSON holds, never converted first
// (4294967297 is not 1), and 1.5 or "1" are not integers.
void check_version(const json& document) {
    if (!document.contains("version")) fail("\"version\" is missing (this fgr reads version 1)");
    const json& version = document.at("version");
    const bool is_one = version.is_number_unsigned() ? version.get<std::uint64_t>() == 1
                        : version.is_number_integer() ? version.get<std::int64_t>() == 1
                                                      : false;
    if (!is_one) {
        std::string shown = version.dump();
        if (shown.size() > 40) shown = shown.substr(0, 40) + "...";
        fail("unsupported \"version\" " + shown + " (this fgr reads version 1)");
    }
}

Keyframe keyframe_from(const json& entry, std::size_t index) {
    const std::string where = "keyframe " + std::to_string(index);
    if (!entry.is_object()) fail(where + " must be an object");
    Keyframe keyframe;
    if (!entry.contains("time")) fail(where + " \"time\" is missing");
    keyframe.time = finite_number(entry.at("time"), where + " \"time\"");
    keyframe.view.position = dvec3_from(entry, "position", where);
    keyframe.view.target = dvec3_from(entry, "target", where);
    keyframe.view.up = entry.contains("up") ? vec3_from(entry, "up", where) : glm::vec3(0, 0, 1);
    if (entry.contains("fov")) keyframe.view.fov_degrees = finite_number(entry.at("fov"), where + " \"fov\"");
    // The check plugins' cameras and keyframes get (view_validation.hpp).
    if (const std::string problem = view_problem(keyframe.view); !problem.empty()) {
        fail(where + ": " + problem);
    }
    return keyframe;
}

}  // namespace

std::string camera_path_json(const CameraPathFile& file) {
    json keyframes = json::array();
    for (const Keyframe& keyframe : file.path.keyframes) {
        keyframes.push_back({{"time", keyframe.time},
                             {"position", vec3_json(keyframe.view.position)},
                             {"target", vec3_json(keyframe.view.target)},
                             {"up", vec3_json(keyframe.view.up)},
                             {"fov", keyframe.view.fov_degrees}});
    }
    const json document = {{"format", kFormat},     {"version", kVersion},
                           {"scene", file.scene},   {"name", file.path.name},
                           {"keyframes", keyframes}};
    return document.dump(2) + "\n";
}

CameraPathFile parse_camera_path_json(const std::string& text) {
    const json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (document.is_discarded()) fail("not valid JSON");
    if (!document.is_object()) fail("must be a JSON object");
    if (document.value("format", "") != kFormat) fail("\"format\" must be \"fgr-camera-path\"");
    check_version(document);
    CameraPathFile file;
    if (document.contains("scene") && document.at("scene").is_string()) {
        file.scene = document.at("scene").get<std::string>();
    }
    file.path.name = document.contains("name") && document.at("name").is_string()
                         ? document.at("name").get<std::string>()
                         : "file";
    if (!document.contains("keyframes") || !document.at("keyframes").is_array()) {
        fail("\"keyframes\" must be an array");
    }
    const json& keyframes = document.at("keyframes");
    if (keyframes.size() < 2) fail("a camera path needs at least two keyframes");
    for (std::size_t i = 0; i < keyframes.size(); ++i) {
        file.path.keyframes.push_back(keyframe_from(keyframes[i], i));
        if (i > 0 && !(file.path.keyframes[i].time > file.path.keyframes[i - 1].time)) {
            fail("keyframe " + std::to_string(i) + " \"time\" must be after the previous one");
        }
    }
    return file;
}

CameraPathFile read_camera_path_file(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read camera path '" + file.string() + "'");
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return parse_camera_path_json(text.str());
    } catch (const std::runtime_error& error) {
        throw std::runtime_error("camera path '" + file.string() + "': " + error.what());
    }
}

void write_camera_path_file(const std::filesystem::path& file, const CameraPathFile& contents) {
    write_text_file_atomically(file, camera_path_json(contents));
}

bool looks_like_camera_path_file(const std::string& argument) {
    return argument.size() > 5 && argument.substr(argument.size() - 5) == ".json";
}

}  // namespace fgr
