// SPDX-License-Identifier: Apache-2.0
// Formula scene files (`NAME.formula.json`): reading and checking. The format is in
// docs/sdk/formulas.md; what it shares with IFS files (header, cameras, paths, lights)
// is read by scene_json.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>

#include "camera/view_validation.hpp"
#include "scene/description_validation.hpp"
#include "scene/formulas/formulas.hpp"
#include "scene/scene_json.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

using json_fields::check_keys;
using json_fields::fail;
using json_fields::finite_double;
using json_fields::shown;
using nlohmann::json;

constexpr const char* kFormulaFormat = "fgr-formula";
constexpr std::string_view kFormulaSuffix = ".formula.json";
constexpr std::size_t kMaxTags = 16;

bool is_tag(std::string_view tag) {
    return !tag.empty() && tag.size() <= 32 && std::all_of(tag.begin(), tag.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    });
}

std::string known_formulas() {
    std::string names;
    for (const Formula& formula : formula_library()) {
        if (!names.empty()) names += ", ";
        names += formula.name;
    }
    return names;
}

int integer_from(const json& object, const char* key, int low, int high, const std::string& where) {
    std::int64_t value = 0;
    if (!json_fields::integer_in(object.at(key), low, high, value)) {
        fail("{} \"{}\" {} must be an integer in [{}, {}]", where, key, shown(object.at(key)), low,
             high);
    }
    return static_cast<int>(value);
}

double number_in(const json& value, double low, double high, const std::string& what) {
    const double number = finite_double(value, what);
    if (number < low || number > high) fail("{} {} outside [{}, {}]", what, number, low, high);
    return number;
}

std::array<float, 3> param_value(const json& value, const FormulaParam& param,
                                 const std::string& where) {
    const std::string what = fmt::format("{} parameter \"{}\"", where, param.id);
    if (param.type == ParamType::Float) {
        const double number = number_in(value, param.min_value, param.max_value, what);
        const float f = static_cast<float>(number);
        return {f, f, f};
    }
    if (!value.is_array() || value.size() != 3) fail("{} must be an array of three numbers", what);
    std::array<float, 3> result{};
    for (std::size_t i = 0; i < 3; ++i) {
        result[i] = static_cast<float>(
            number_in(value[i], param.min_value, param.max_value, fmt::format("{}[{}]", what, i)));
    }
    return result;
}

FormulaSlot slot_from(const json& entry, std::size_t index) {
    const std::string where = fmt::format("sequence entry {}", index);
    scene_json::require_object(entry, where);
    check_keys(entry, {"formula", "repeat", "parameters"}, where);
    const std::string name = scene_json::text_from(entry, "formula", where, true);
    FormulaSlot slot;
    slot.formula = find_formula(name);
    if (slot.formula == nullptr) {
        fail("{}: unknown formula '{}' (known: {})", where, printable_excerpt(name),
             known_formulas());
    }
    if (entry.contains("repeat")) {
        slot.repeat = integer_from(entry, "repeat", 1, kFormulaMaxRepeat, where);
    }
    for (const FormulaParam& param : slot.formula->params)
        slot.values.push_back(param.default_value);
    if (entry.contains("parameters")) {
        const json& given = entry.at("parameters");
        const std::string params_where = fmt::format("{} ({})", where, slot.formula->name);
        if (!given.is_object()) fail("{} \"parameters\" must be an object", params_where);
        for (const auto& [key, value] : given.items()) {
            const auto& params = slot.formula->params;
            const auto found = std::find_if(params.begin(), params.end(),
                                            [&](const FormulaParam& p) { return p.id == key; });
            if (found == params.end()) {
                std::string ids;
                for (const FormulaParam& p : params) ids += (ids.empty() ? "" : ", ") + p.id;
                fail("{}: {} has no parameter '{}' ({})", params_where, slot.formula->name,
                     printable_excerpt(key), ids.empty() ? "it has none" : "its: " + ids);
            }
            slot.values[static_cast<std::size_t>(found - params.begin())] =
                param_value(value, *found, params_where);
        }
    }
    return slot;
}

std::vector<std::string> tags_from(const json& document) {
    std::vector<std::string> tags;
    if (!document.contains("tags")) return tags;
    const json& array = scene_json::array_from(document, "tags", 0, kMaxTags, "\"tags\"");
    for (std::size_t i = 0; i < array.size(); ++i) {
        if (!array[i].is_string() || !is_tag(array[i].get<std::string>())) {
            fail("\"tags\" entry {} {} must be a string of [a-z0-9-], at most 32 characters", i,
                 shown(array[i]));
        }
        tags.push_back(array[i].get<std::string>());
    }
    return tags;
}

// The distance the sequence calls for (sequence_distance), or the one the file chooses; a hybrid
// with a formula that has a distance of its own must choose.
FormulaDistance distance_from(const json& document, const std::vector<FormulaSlot>& sequence) {
    if (document.contains("distance")) {
        const json& value = document.at("distance");
        if (value == "logarithmic") return FormulaDistance::Logarithmic;
        if (value == "linear") return FormulaDistance::Linear;
        fail("\"distance\" {} must be \"logarithmic\" or \"linear\"", shown(value));
    }
    const auto own = std::find_if(sequence.begin(), sequence.end(), [](const FormulaSlot& s) {
        return s.formula->distance == FormulaDistance::Own;
    });
    if (own != sequence.end() && sequence.size() > 1) {
        fail(
            "a hybrid with {} (a formula with a distance of its own) needs \"distance\": "
            "\"linear\" or \"logarithmic\"",
            own->formula->name);
    }
    return sequence_distance(sequence);
}

// The strongest estimate the sequence allows (strongest_estimate); a file may ask for a weaker one
// (the delta estimate, or an inside test), not a stronger one its formulas do not have.
FormulaEstimate estimate_from(const json& document, const FormulaScene& scene) {
    const FormulaSlot& weakest =
        *std::max_element(scene.sequence.begin(), scene.sequence.end(),
                          [](const FormulaSlot& a, const FormulaSlot& b) {
                              return a.formula->estimate < b.formula->estimate;
                          });
    const FormulaEstimate available = strongest_estimate(scene.sequence);
    if (!document.contains("estimate")) return available;
    const json& value = document.at("estimate");
    FormulaEstimate asked;
    if (value == "analytic") {
        asked = FormulaEstimate::Analytic;
    } else if (value == "delta") {
        asked = FormulaEstimate::Delta;
    } else if (value == "inside") {
        asked = FormulaEstimate::Inside;
    } else {
        fail("\"estimate\" {} must be \"analytic\", \"delta\" or \"inside\"", shown(value));
    }
    if (asked < available) {
        fail("\"estimate\" {}: {} has {} (use {})", shown(value), weakest.formula->name,
             available == FormulaEstimate::Delta ? "no analytic derivative"
                                                 : "no distance estimate, only an inside test",
             available == FormulaEstimate::Delta ? "\"delta\" or \"inside\"" : "\"inside\"");
    }
    if (asked == FormulaEstimate::Delta && scene.distance == FormulaDistance::Own) {
        fail(
            "\"estimate\": \"delta\" needs \"distance\" \"logarithmic\" or \"linear\" ({} "
            "has a distance of its own)",
            scene.sequence[0].formula->name);
    }
    return asked;
}

void march_from(const json& document, FormulaScene& scene) {
    int iterations = 0;
    float bailout = 0.0f, step_factor = 1.0f, max_distance = 0.0f;
    const float max_bailout = sequence_max_bailout(scene.sequence);
    for (const FormulaSlot& slot : scene.sequence) {
        iterations = std::max(iterations, slot.formula->iterations);
        bailout = std::max(bailout, slot.formula->bailout);
        step_factor = std::min(step_factor, slot.formula->step_factor);
        max_distance = std::max(max_distance, slot.formula->max_distance);
    }
    if (document.contains("iterations")) {
        iterations = integer_from(document, "iterations", 1, kFormulaMaxIterations, "top level");
    }
    bailout = std::min(bailout, max_bailout);
    if (document.contains("bailout")) {
        bailout =
            static_cast<float>(number_in(document.at("bailout"), 0.5, max_bailout, "\"bailout\""));
    }
    if (document.contains("step_factor")) {
        step_factor =
            static_cast<float>(number_in(document.at("step_factor"), kFormulaMinStepFactor,
                                         kFormulaMaxStepFactor, "\"step_factor\""));
    }
    if (document.contains("max_distance")) {
        max_distance =
            static_cast<float>(number_in(document.at("max_distance"), kFormulaMinMaxDistance,
                                         kFormulaMaxMaxDistance, "\"max_distance\""));
    }
    scene.iterations = iterations;
    scene.bailout = bailout;
    scene.max_bailout = max_bailout;
    scene.march.de_iterations = static_cast<uint32_t>(iterations);
    scene.march.step_factor = step_factor;
    scene.march.max_distance = max_distance;
}

FormulaScene parse_formula_document(const std::string& text) {
    if (text.size() > kFormulaMaxFileBytes) {
        fail("{} bytes, more than the {} a formula file may have", text.size(),
             kFormulaMaxFileBytes);
    }
    const json document = scene_json::parse_object(text);
    check_keys(document,
               {"$schema", "format", "version", "id", "name", "description", "tags", "sequence",
                "iterations", "bailout", "distance", "estimate", "step_factor", "max_distance",
                "cameras", "camera_paths", "lights", "environment"},
               "top level");
    json_fields::check_schema_key(document);
    scene_json::check_format(document, kFormulaFormat, kFormulaFormatVersion);
    FormulaScene scene;
    const scene_json::Header header = scene_json::header_from(document);
    scene.id = header.id;
    scene.name = header.name;
    scene.description = header.description;
    scene.tags = tags_from(document);
    if (!document.contains("sequence")) fail("\"sequence\" is missing");
    const json& sequence =
        scene_json::array_from(document, "sequence", 1, kFormulaMaxSlots, "\"sequence\"");
    for (std::size_t i = 0; i < sequence.size(); ++i) {
        scene.sequence.push_back(slot_from(sequence[i], i));
    }
    scene.distance = distance_from(document, scene.sequence);
    scene.estimate = estimate_from(document, scene);
    march_from(document, scene);
    scene.cameras = scene_json::cameras_from(document);
    if (scene.cameras.empty()) {
        scene.cameras.push_back(NamedCamera{"default", scene.sequence.front().formula->view});
    }
    scene.camera_paths = scene_json::camera_paths_from(document);
    if (scene.camera_paths.empty()) {
        scene.camera_paths.push_back(scene_json::default_orbit(scene.cameras[0]));
    }
    scene.lights = scene_json::lights_from(document);
    if (scene.lights.empty()) scene.lights.push_back(scene_json::default_light());
    scene.environment = scene_json::environment_from(document);
    return scene;
}

}  // namespace

bool is_formula_file_name(const std::filesystem::path& file) {
    const std::string name = file.filename().string();
    return name.size() > kFormulaSuffix.size() &&
           name.compare(name.size() - kFormulaSuffix.size(), kFormulaSuffix.size(),
                        kFormulaSuffix) == 0;
}

FormulaScene parse_formula_json(const std::string& text, const std::string& origin) {
    try {
        return parse_formula_document(text);
    } catch (const std::runtime_error& error) {
        throw FormulaError(origin + ": " + error.what());
    } catch (const json::exception& error) {
        // Not expected (every value's type is checked before it is read); still one line.
        throw FormulaError(origin + ": unexpected JSON content (" + std::string(error.what()) +
                           ")");
    }
}

FormulaScene read_formula_file(const std::filesystem::path& file) {
    std::string text;
    try {
        text = scene_json::read_bounded(file, kFormulaMaxFileBytes);
    } catch (const std::runtime_error& error) {
        throw FormulaError(error.what());
    }
    return parse_formula_json(text, printable_path(file));
}

}  // namespace fgr
