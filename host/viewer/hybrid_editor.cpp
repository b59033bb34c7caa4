// SPDX-License-Identifier: Apache-2.0
#include "viewer/hybrid_editor.hpp"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>
#include <utility>
#include <vector>

#include "scene/formulas/formula_edit.hpp"
#include "scene/parameters.hpp"
#include "util/atomic_file.hpp"
#include "viewer/viewer_util.hpp"

namespace fgr::viewer {
namespace {

const ImVec4 kCompilingColour(1, 0.8f, 0.2f, 1);
const ImVec4 kErrorColour(1, 0.4f, 0.4f, 1);

}  // namespace

HybridEditor::HybridEditor(SceneSet& scenes, std::filesystem::path output_dir, HybridHost host)
    : scenes_(scenes), output_dir_(std::move(output_dir)), host_(std::move(host)) {}

const FormulaScene* HybridEditor::formula_of(size_t index) {
    const std::shared_ptr<const Scene>& scene = scenes_.at(index);
    auto found = formula_sources_.find(index);
    if (found == formula_sources_.end() || found->second.scene != scene) {
        FormulaSource source{scene, std::nullopt};
        if (!scene->ifs && is_formula_file_name(scene->plugin_file)) {
            try {
                source.formula = read_formula_file(scene->plugin_file);
                // A file changed since the scene was loaded (its reload still to come) is not
                // this scene's sequence.
                if (formula_kernel_source(*source.formula) != scene->source) source.formula.reset();
            } catch (const std::exception& error) {
                spdlog::warn("{}", error.what());
            }
        }
        found = formula_sources_.insert_or_assign(index, std::move(source)).first;
    }
    return found->second.formula ? &*found->second.formula : nullptr;
}

void HybridEditor::draw_section() {
    const FormulaScene* current = formula_of(static_cast<size_t>(scenes_.current_index()));
    if (current == nullptr) return;
    if (!ImGui::CollapsingHeader("Formula sequence", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const FormulaScene formula = *current;  // an edit below replaces what `current` points to
    ImGui::BeginDisabled(pending_.has_value());
    for (size_t slot = 0; slot < formula.sequence.size(); ++slot) draw_slot(formula, slot);
    const bool full = formula.sequence.size() >= kFormulaMaxSlots;
    ImGui::BeginDisabled(full);
    if (ImGui::BeginCombo("add formula", full ? "sequence full" : "choose...")) {
        for (const Formula& candidate : formula_library()) {
            const std::string label = fmt::format("{}  ({})", candidate.title, candidate.family);
            if (ImGui::Selectable(label.c_str())) {
                edit([&](FormulaScene f) { return with_formula_added(std::move(f), candidate); });
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", candidate.summary.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    if (pending_) {
        ImGui::TextColored(kCompilingColour, "compiling the new sequence... (the old image stays)");
    }
    if (!error_.empty()) ImGui::TextColored(kErrorColour, "%s", error_.c_str());
    if (save_id_.empty()) save_id_ = scenes_.current().id + "-edited";
    ImGui::InputText("##save id", &save_id_);
    ImGui::SameLine();
    if (ImGui::Button("Save as")) save(save_id_);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "writes %s.formula.json to the output folder (--output-dir); copy it "
            "into a plugin folder to load it",
            save_id_.c_str());
    }
}

void HybridEditor::save(const std::string& id) {
    const FormulaScene* current = formula_of(static_cast<size_t>(scenes_.current_index()));
    if (current == nullptr) {
        host_.add_message(
            fmt::format("'{}' is not a formula scene: nothing to save", scenes_.current().id));
        return;
    }
    FormulaScene formula = *current;
    take_slot_values(formula, scenes_.current(), scenes_.session().params);
    formula.id = id;
    // The panel's bailout and march settings, within what a file may say.
    const auto value = [&](const char* param) {
        return param_value(scenes_.current(), scenes_.session().params, param);
    };
    formula.bailout = value("bailout");
    formula.iterations =
        std::clamp(static_cast<int>(value("iterations")), 1, kFormulaMaxIterations);
    formula.march.step_factor = std::clamp(value("step_factor"), float(kFormulaMinStepFactor),
                                           float(kFormulaMaxStepFactor));
    formula.march.max_distance = std::clamp(value("max_distance"), float(kFormulaMinMaxDistance),
                                            float(kFormulaMaxMaxDistance));
    const std::filesystem::path file = output_dir_ / (id + ".formula.json");
    try {
        const std::string text = formula_scene_json(formula);
        parse_formula_json(text, file.string());  // an id the format refuses is said here
        write_text_file_atomically(file, text);
    } catch (const std::exception& error) {
        spdlog::error("{}", error.what());
        host_.add_message(error.what());
        return;
    }
    spdlog::info("saved '{}' ({}) as {}", id, sequence_text(formula), file.string());
    host_.add_message(fmt::format("saved {}", file.string()));
}

void HybridEditor::draw_slot(const FormulaScene& formula, size_t slot) {
    const size_t slots = formula.sequence.size();
    ImGui::PushID(static_cast<int>(slot));
    ImGui::Text("%zu. %s", slot + 1, formula.sequence[slot].formula->title.c_str());
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("%s: %s", formula.sequence[slot].formula->name.c_str(),
                          formula.sequence[slot].formula->summary.c_str());
    }
    int repeat = formula.sequence[slot].repeat;
    ImGui::SetNextItemWidth(90);
    if (ImGui::InputInt("x", &repeat, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue)) {
        repeat = std::clamp(repeat, 1, kFormulaMaxRepeat);
        if (repeat != formula.sequence[slot].repeat) {
            edit([&](FormulaScene f) { return with_repeat(std::move(f), slot, repeat); });
        }
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(slot == 0);
    if (ImGui::ArrowButton("up", ImGuiDir_Up)) {
        edit([&](FormulaScene f) { return with_slot_moved(std::move(f), slot, -1); });
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(slot + 1 == slots);
    if (ImGui::ArrowButton("down", ImGuiDir_Down)) {
        edit([&](FormulaScene f) { return with_slot_moved(std::move(f), slot, 1); });
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(slots == 1);
    if (ImGui::SmallButton("remove")) {
        edit([&](FormulaScene f) { return with_slot_removed(std::move(f), slot); });
    }
    ImGui::EndDisabled();
    ImGui::PopID();
}

void HybridEditor::edit(const std::function<FormulaScene(FormulaScene)>& change) {
    const auto index = static_cast<size_t>(scenes_.current_index());
    if (pending_) {
        host_.add_message(
            "the last edit of the sequence is still compiling; try again when it is done");
        return;
    }
    const FormulaScene* current = formula_of(index);
    if (current == nullptr) {
        host_.add_message(fmt::format("'{}' is not a formula scene: it has no sequence to edit",
                                      scenes_.current().id));
        return;
    }
    FormulaScene formula = *current;
    take_slot_values(formula, scenes_.current(), scenes_.session().params);
    std::shared_ptr<const Scene> candidate;
    try {
        formula = change(std::move(formula));
        candidate = std::make_shared<const Scene>(
            formula_scene_to_scene(formula, scenes_.current().plugin_file));
    } catch (const std::exception& error) {
        error_ = fmt::format("edit of '{}' refused: {}", scenes_.current().id, error.what());
        spdlog::error("{}", error_);
        host_.add_message(error_);
        return;
    }
    spdlog::info("building the edited '{}': {}", candidate->id, sequence_text(formula));
    error_.clear();
    pending_ = PendingEdit{candidate, std::move(formula)};
    host_.build({candidate, scenes_.at(index), scenes_.session().effects});
}

bool HybridEditor::adopt_edit(const ReloadResult& result) {
    if (!pending_ || result.request.candidate != pending_->scene) return false;
    PendingEdit built = std::move(*pending_);
    pending_.reset();
    const std::optional<size_t> index = scenes_.index_of(result.request.replaces);
    if (!index) {
        error_ =
            fmt::format("edit of '{}' dropped: the scene was reloaded meanwhile", built.scene->id);
        host_.add_message(error_);
        return true;
    }
    if (!result.ok) {
        error_ = fmt::format("edit of '{}' refused, keeping the previous sequence: {}",
                             built.scene->id, result.error);
        spdlog::error("{}", error_);
        host_.add_message(error_);
        host_.show_refused(error_, result.error_log);
        return true;
    }
    const std::shared_ptr<const Scene> before = scenes_.at(*index);
    const SceneSession* session = scenes_.session_of(*index);
    const std::vector<float> values = session ? session->params : default_param_values(*before);
    host_.adopt_scene(*index, built.scene);
    if (SceneSession* adopted = scenes_.session_of(*index)) {
        adopted->params = values_after_edit(*before, values, *built.scene, built.formula);
    }
    spdlog::info("'{}' now iterates {}", built.scene->id, sequence_text(built.formula));
    host_.add_message(fmt::format("sequence: {}", sequence_text(built.formula)));
    formula_sources_.insert_or_assign(*index, FormulaSource{built.scene, std::move(built.formula)});
    ++edits_adopted_;
    return true;
}

void HybridEditor::apply_replay_event(const ReplayEvent& event) {
    switch (event.action) {
        case ReplayAction::HybridAdd: {
            const Formula* formula = find_formula(event.text);
            if (formula == nullptr) {
                const std::string message =
                    fmt::format("hybrid_add: unknown formula '{}'", event.text);
                spdlog::error("replay line {}: {}", event.line, message);
                host_.add_message(message);
                break;
            }
            edit([&](FormulaScene f) { return with_formula_added(std::move(f), *formula); });
            break;
        }
        case ReplayAction::HybridRemove:
            edit([&](FormulaScene f) {
                return with_slot_removed(std::move(f), size_t(event.slot));
            });
            break;
        case ReplayAction::HybridMove:
            edit([&](FormulaScene f) {
                return with_slot_moved(std::move(f), size_t(event.slot), event.count);
            });
            break;
        case ReplayAction::HybridRepeat:
            edit([&](FormulaScene f) {
                return with_repeat(std::move(f), size_t(event.slot), event.count);
            });
            break;
        case ReplayAction::HybridSave:
            save(event.text);
            break;
        default:
            break;
    }
}

}  // namespace fgr::viewer
