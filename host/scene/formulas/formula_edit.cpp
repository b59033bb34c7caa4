// SPDX-License-Identifier: Apache-2.0
// Edits of a formula scene's sequence (scene/formulas/formula_edit.hpp).
#include "scene/formulas/formula_edit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>

#include "camera/view_json.hpp"
#include "scene/parameters.hpp"
#include "util/installed_files.hpp"
#include "util/json_fields.hpp"

namespace fgr {
namespace {

[[noreturn]] void refuse(const std::string& reason) { throw FormulaEditError(reason); }

void check_slot(const FormulaScene& scene, std::size_t slot) {
    if (slot >= scene.sequence.size()) {
        refuse(fmt::format("no formula {} in a sequence of {}", slot + 1, scene.sequence.size()));
    }
}

// What the sequence decides, worked out as a file without "distance" and "estimate" would have
// it (formula_file.cpp), except that a formula with a distance of its own in a hybrid gets the
// linear one (its folds and scales set the growth) where a file must choose. A delta estimate the
// scene asked for stays while the sequence and the distance allow it; an inside test is what a
// sequence gives, and goes with the formula that gave it.
void settle_sequence_settings(FormulaScene& scene) {
    scene.distance = sequence_distance(scene.sequence);
    const FormulaEstimate available = strongest_estimate(scene.sequence);
    const bool keep_delta = scene.estimate == FormulaEstimate::Delta &&
                            available <= FormulaEstimate::Delta &&
                            scene.distance != FormulaDistance::Own;
    scene.estimate = keep_delta ? FormulaEstimate::Delta : available;
    scene.max_bailout = sequence_max_bailout(scene.sequence);
    scene.bailout = std::min(scene.bailout, scene.max_bailout);
}

using nlohmann::json;

json slot_json(const FormulaSlot& slot) {
    json entry = {{"formula", slot.formula->name}, {"repeat", slot.repeat}};
    json parameters = json::object();
    for (std::size_t i = 0; i < slot.formula->params.size(); ++i) {
        const FormulaParam& param = slot.formula->params[i];
        const auto& value = slot.values[i];
        parameters[param.id] = param.type == ParamType::Float
                                   ? json(value[0])
                                   : json::array({value[0], value[1], value[2]});
    }
    entry["parameters"] = parameters;
    return entry;
}

json light_json(const Light& light) {
    json entry = {{"colour", json_fields::vec3_json(light.colour)}, {"intensity", light.intensity}};
    if (light.type == LightType::Point) {
        entry["type"] = "point";
        entry["position"] = json_fields::vec3_json(light.vector);
    } else {
        entry["type"] = "directional";
        entry["direction"] = json_fields::vec3_json(light.vector);
        entry["angular_radius_degrees"] = light.angular_radius * (180.0 / std::numbers::pi);
    }
    return entry;
}

}  // namespace

std::string formula_scene_json(const FormulaScene& scene) {
    json document = {{"$schema", schema_reference("formula.schema.json")},
                     {"format", "fgr-formula"},
                     {"version", kFormulaFormatVersion},
                     {"id", scene.id},
                     {"name", scene.name},
                     {"description", scene.description},
                     {"tags", scene.tags},
                     {"iterations", scene.iterations},
                     {"bailout", scene.bailout},
                     {"step_factor", scene.march.step_factor},
                     {"max_distance", scene.march.max_distance}};
    json sequence = json::array();
    for (const FormulaSlot& slot : scene.sequence) sequence.push_back(slot_json(slot));
    document["sequence"] = sequence;
    // A formula's own distance is what a file without "distance" gets; the others may be written.
    if (scene.distance == FormulaDistance::Logarithmic) document["distance"] = "logarithmic";
    if (scene.distance == FormulaDistance::Linear) document["distance"] = "linear";
    document["estimate"] = formula_estimate_name(scene.estimate);
    json cameras = json::array();
    for (const NamedCamera& camera : scene.cameras) {
        json entry = json_fields::view_json(camera.view);
        entry["name"] = camera.name;
        cameras.push_back(entry);
    }
    document["cameras"] = cameras;
    json paths = json::array();
    for (const CameraPath& path : scene.camera_paths) {
        paths.push_back(
            {{"name", path.name}, {"keyframes", json_fields::keyframes_json(path.keyframes)}});
    }
    document["camera_paths"] = paths;
    json lights = json::array();
    for (const Light& light : scene.lights) lights.push_back(light_json(light));
    document["lights"] = lights;
    if (!scene.environment.empty()) document["environment"] = scene.environment;
    return document.dump(2) + "\n";
}

FormulaScene with_formula_added(FormulaScene scene, const Formula& formula) {
    if (scene.sequence.size() >= kFormulaMaxSlots) {
        refuse(fmt::format("a sequence holds at most {} formulas", kFormulaMaxSlots));
    }
    FormulaSlot slot;
    slot.formula = &formula;
    for (const FormulaParam& param : formula.params) slot.values.push_back(param.default_value);
    scene.sequence.push_back(std::move(slot));
    scene.iterations = std::max(scene.iterations, formula.iterations);
    scene.march.de_iterations = static_cast<uint32_t>(scene.iterations);
    scene.march.step_factor = std::min(scene.march.step_factor, formula.step_factor);
    scene.march.max_distance = std::max(scene.march.max_distance, formula.max_distance);
    scene.bailout = std::max(scene.bailout, formula.bailout);
    settle_sequence_settings(scene);
    return scene;
}

FormulaScene with_slot_removed(FormulaScene scene, std::size_t slot) {
    check_slot(scene, slot);
    if (scene.sequence.size() == 1) refuse("a sequence needs at least one formula");
    scene.sequence.erase(scene.sequence.begin() + static_cast<std::ptrdiff_t>(slot));
    settle_sequence_settings(scene);
    return scene;
}

FormulaScene with_slot_moved(FormulaScene scene, std::size_t slot, int offset) {
    check_slot(scene, slot);
    const auto target = static_cast<std::ptrdiff_t>(slot) + offset;
    if (target < 0 || target >= static_cast<std::ptrdiff_t>(scene.sequence.size())) {
        refuse(fmt::format("formula {} cannot move {} place{} {}", slot + 1, std::abs(offset),
                           std::abs(offset) == 1 ? "" : "s", offset < 0 ? "up" : "down"));
    }
    const auto from = scene.sequence.begin() + static_cast<std::ptrdiff_t>(slot);
    const auto to = scene.sequence.begin() + target;
    if (offset < 0) {
        std::rotate(to, from, from + 1);
    } else {
        std::rotate(from, from + 1, to + 1);
    }
    return scene;
}

FormulaScene with_repeat(FormulaScene scene, std::size_t slot, int repeat) {
    check_slot(scene, slot);
    if (repeat < 1 || repeat > kFormulaMaxRepeat) {
        refuse(fmt::format("repeat {} is outside [1, {}]", repeat, kFormulaMaxRepeat));
    }
    scene.sequence[slot].repeat = repeat;
    return scene;
}

void take_slot_values(FormulaScene& scene, const Scene& running, const std::vector<float>& values) {
    const std::vector<int> offsets = param_offsets(running);
    const std::size_t slots = scene.sequence.size();
    for (std::size_t slot = 0; slot < slots; ++slot) {
        FormulaSlot& entry = scene.sequence[slot];
        for (std::size_t i = 0; i < entry.formula->params.size(); ++i) {
            const std::string id = formula_param_id(slots, slot, entry.formula->params[i].id);
            const ParamInfo* param = running.find_param(id);
            if (param == nullptr) continue;
            const auto index = static_cast<std::size_t>(param - running.params.data());
            const auto offset = static_cast<std::size_t>(offsets[index]);
            for (int c = 0; c < param_components(param->type); ++c) {
                entry.values[i][static_cast<std::size_t>(c)] = values[offset + std::size_t(c)];
            }
            if (param_components(param->type) == 1) entry.values[i].fill(values[offset]);
        }
    }
}

std::vector<float> values_after_edit(const Scene& before, const std::vector<float>& values,
                                     const Scene& after, const FormulaScene& edited) {
    std::set<std::string> slot_ids;
    const std::size_t slots = edited.sequence.size();
    for (std::size_t slot = 0; slot < slots; ++slot) {
        for (const FormulaParam& param : edited.sequence[slot].formula->params) {
            slot_ids.insert(formula_param_id(slots, slot, param.id));
        }
    }
    std::vector<float> result = carry_param_values(before, values, after);
    const std::vector<float> defaults = default_param_values(after);
    const std::vector<int> offsets = param_offsets(after);
    for (std::size_t i = 0; i < after.params.size(); ++i) {
        if (!slot_ids.count(after.params[i].id)) continue;
        const auto offset = static_cast<std::size_t>(offsets[i]);
        const auto components = static_cast<std::size_t>(param_components(after.params[i].type));
        std::copy_n(defaults.begin() + static_cast<std::ptrdiff_t>(offset), components,
                    result.begin() + static_cast<std::ptrdiff_t>(offset));
    }
    return result;
}

}  // namespace fgr
