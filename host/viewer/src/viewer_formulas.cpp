// The formula browser (a window of thumbnails with a search field; B) and the hybrid editor (the
// panel's "Formula sequence" section). An edit of a sequence makes a new scene that the render
// thread builds as it builds a reloaded one: the old scene and its image stay until the new
// kernel compiles, and a build that fails keeps them.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "fgr/atomic_file.hpp"
#include "fgr/formula_edit.hpp"
#include "fgr/parameters.hpp"
#include "viewer_app.hpp"

namespace fgr::viewer {
namespace {

const ImVec4 kCompilingColour(1, 0.8f, 0.2f, 1);
const ImVec4 kErrorColour(1, 0.4f, 0.4f, 1);
const ImVec4 kSelectedColour(1, 0.8f, 0.2f, 1);

// "mandelbulb x2, amazing_box": the sequence as logs and --stats show it.
std::string sequence_text(const FormulaScene& formula) {
    std::string text;
    for (const FormulaSlot& slot : formula.sequence) {
        if (!text.empty()) text += ", ";
        text += slot.formula->name;
        if (slot.repeat > 1) text += fmt::format(" x{}", slot.repeat);
    }
    return text;
}

}  // namespace

// --- Formula scenes ---------------------------------------------------------------------------

const FormulaScene* ViewerApp::formula_scene_of(size_t index) {
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

// --- The browser ------------------------------------------------------------------------------

std::vector<size_t> ViewerApp::browser_matches() {
    std::vector<SceneSearchEntry> entries;
    for (size_t i = 0; i < scenes_.size(); ++i) {
        entries.push_back(search_entry(*scenes_.at(i), formula_scene_of(i)));
    }
    return matching_scenes(entries, browser_query_);
}

const std::string& ViewerApp::thumbnail_key_of(size_t index) {
    const std::shared_ptr<const Scene>& scene = scenes_.at(index);
    auto found = thumbnail_keys_.find(scene.get());
    if (found == thumbnail_keys_.end()) {
        // The entry holds its scene, so no other scene can take its address while it exists.
        found = thumbnail_keys_.emplace(scene.get(), std::pair(scene, thumbnail_key(*scene))).first;
    }
    return found->second.second;
}

void ViewerApp::receive_thumbnails() {
    if (!thumbnails_) return;
    thumbnails_->set_paused(!view_idle());
    for (Thumbnail& thumbnail : thumbnails_->take_finished()) {
        if (thumbnail.image.rgb.empty()) {
            thumbnail_errors_[thumbnail.key] = thumbnail.error;
            continue;
        }
        auto texture = std::make_unique<ImageTexture>();
        texture->upload(thumbnail.image);
        thumbnail_textures_[thumbnail.key] = std::move(texture);
        redraws_pending_ = std::max(redraws_pending_, 1);
    }
}

// Whether every scene the browser shows has its thumbnail (or failed to get one).
bool ViewerApp::thumbnails_done() {
    if (!thumbnails_ || !show_browser_) return true;
    for (const size_t index : browser_matches()) {
        const std::string& key = thumbnail_key_of(index);
        if (!thumbnail_textures_.count(key) && !thumbnail_errors_.count(key)) return false;
    }
    return true;
}

void ViewerApp::draw_browser_window() {
    if (!show_browser_) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(8, display.y * 0.12f), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(std::min(600.0f, display.x * 0.55f), display.y * 0.8f),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("Formula browser (B)", &show_browser_)) draw_browser();
    ImGui::End();
}

void ViewerApp::draw_browser() {
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##search", "search: name, formula, family, tag", &browser_query_);
    const std::vector<size_t> matches = browser_matches();
    ImGui::TextDisabled("%zu of %zu scenes; click one to view it", matches.size(), scenes_.size());
    const float cell = static_cast<float>(kThumbnailWidth) + ImGui::GetStyle().ItemSpacing.x + 4;
    const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / cell));
    ImGui::BeginChild("thumbnails");
    for (size_t k = 0; k < matches.size(); ++k) {
        if (k % static_cast<size_t>(columns) != 0) ImGui::SameLine();
        draw_thumbnail_cell(matches[k]);
    }
    ImGui::EndChild();
}

void ViewerApp::draw_thumbnail_cell(size_t index) {
    const Scene& cell_scene = *scenes_.at(index);
    const std::string key = thumbnail_key_of(index);
    const auto texture = thumbnail_textures_.find(key);
    const auto error = thumbnail_errors_.find(key);
    // Asked for when first shown: the worker renders those in view first, one at a time.
    if (texture == thumbnail_textures_.end() && error == thumbnail_errors_.end() && thumbnails_) {
        thumbnails_->request(scenes_.at(index), key);
    }
    const ImVec2 size(kThumbnailWidth, kThumbnailHeight);
    ImGui::PushID(static_cast<int>(index));
    ImGui::BeginGroup();
    bool clicked = false;
    if (texture != thumbnail_textures_.end()) {
        clicked = ImGui::ImageButton(texture->second->id(), size, ImVec2(0, 0), ImVec2(1, 1), 2);
    } else {
        const char* label = error != thumbnail_errors_.end() ? "no image" : "rendering...";
        clicked = ImGui::Button(label, ImVec2(size.x + 4, size.y + 4));
    }
    const bool current = static_cast<int>(index) == scenes_.current_index();
    if (current) {
        ImGui::GetWindowDrawList()->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(),
                                            ImGui::GetColorU32(kSelectedColour), 0.0f, 0, 2.0f);
    }
    if (ImGui::IsItemHovered()) {
        std::string tags;
        for (const std::string& tag : cell_scene.tags) tags += (tags.empty() ? "" : ", ") + tag;
        const FormulaScene* formula = formula_scene_of(index);
        ImGui::SetTooltip("%s (%s)\n%s%s%s%s%s", cell_scene.name.c_str(), cell_scene.id.c_str(),
                          cell_scene.description.c_str(),
                          tags.empty() ? "" : "\ntags: ", tags.c_str(),
                          formula ? ("\nsequence: " + sequence_text(*formula)).c_str() : "",
                          error != thumbnail_errors_.end() ? ("\n" + error->second).c_str() : "");
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x + 4);
    ImGui::TextUnformatted(cell_scene.name.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::PopID();
    if (clicked && !current) switch_scene(static_cast<int>(index));
}

// --- The hybrid editor ------------------------------------------------------------------------

void ViewerApp::draw_hybrid_section() {
    const FormulaScene* current = formula_scene_of(static_cast<size_t>(scenes_.current_index()));
    if (current == nullptr) return;
    if (!ImGui::CollapsingHeader("Formula sequence", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const FormulaScene formula = *current;  // an edit below replaces what `current` points to
    ImGui::BeginDisabled(pending_hybrid_.has_value());
    for (size_t slot = 0; slot < formula.sequence.size(); ++slot) draw_hybrid_slot(formula, slot);
    const bool full = formula.sequence.size() >= kFormulaMaxSlots;
    ImGui::BeginDisabled(full);
    if (ImGui::BeginCombo("add formula", full ? "sequence full" : "choose...")) {
        for (const Formula& candidate : formula_library()) {
            const std::string label = fmt::format("{}  ({})", candidate.title, candidate.family);
            if (ImGui::Selectable(label.c_str())) {
                edit_hybrid(
                    [&](FormulaScene f) { return with_formula_added(std::move(f), candidate); });
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", candidate.summary.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    if (pending_hybrid_) {
        ImGui::TextColored(kCompilingColour, "compiling the new sequence... (the old image stays)");
    }
    if (!hybrid_error_.empty()) ImGui::TextColored(kErrorColour, "%s", hybrid_error_.c_str());
    if (save_id_.empty()) save_id_ = scene().id + "-edited";
    ImGui::InputText("##save id", &save_id_);
    ImGui::SameLine();
    if (ImGui::Button("Save as")) save_formula_scene(save_id_);
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "writes %s.formula.json to the output folder (--output-dir); copy it "
            "into a plugin folder to load it",
            save_id_.c_str());
    }
}

void ViewerApp::save_formula_scene(const std::string& id) {
    const FormulaScene* current = formula_scene_of(static_cast<size_t>(scenes_.current_index()));
    if (current == nullptr) {
        add_message(fmt::format("'{}' is not a formula scene: nothing to save", scene().id));
        return;
    }
    FormulaScene formula = *current;
    take_slot_values(formula, scene(), session().params);
    formula.id = id;
    // The panel's bailout and march settings, within what a file may say.
    const auto value = [&](const char* param) {
        return param_value(scene(), session().params, param);
    };
    formula.bailout = value("bailout");
    formula.iterations =
        std::clamp(static_cast<int>(value("iterations")), 1, kFormulaMaxIterations);
    formula.march.step_factor = std::clamp(value("step_factor"), float(kFormulaMinStepFactor),
                                           float(kFormulaMaxStepFactor));
    formula.march.max_distance = std::clamp(value("max_distance"), float(kFormulaMinMaxDistance),
                                            float(kFormulaMaxMaxDistance));
    const std::filesystem::path file = options_.output_dir / (id + ".formula.json");
    try {
        const std::string text = formula_scene_json(formula);
        parse_formula_json(text, file.string());  // an id the format refuses is said here
        write_text_file_atomically(file, text);
    } catch (const std::exception& error) {
        spdlog::error("{}", error.what());
        add_message(error.what());
        return;
    }
    spdlog::info("saved '{}' ({}) as {}", id, sequence_text(formula), file.string());
    add_message(fmt::format("saved {}", file.string()));
}

void ViewerApp::draw_hybrid_slot(const FormulaScene& formula, size_t slot) {
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
            edit_hybrid([&](FormulaScene f) { return with_repeat(std::move(f), slot, repeat); });
        }
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(slot == 0);
    if (ImGui::ArrowButton("up", ImGuiDir_Up)) {
        edit_hybrid([&](FormulaScene f) { return with_slot_moved(std::move(f), slot, -1); });
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(slot + 1 == slots);
    if (ImGui::ArrowButton("down", ImGuiDir_Down)) {
        edit_hybrid([&](FormulaScene f) { return with_slot_moved(std::move(f), slot, 1); });
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(slots == 1);
    if (ImGui::SmallButton("remove")) {
        edit_hybrid([&](FormulaScene f) { return with_slot_removed(std::move(f), slot); });
    }
    ImGui::EndDisabled();
    ImGui::PopID();
}

void ViewerApp::edit_hybrid(const std::function<FormulaScene(FormulaScene)>& edit) {
    const auto index = static_cast<size_t>(scenes_.current_index());
    if (pending_hybrid_) {
        add_message("the last edit of the sequence is still compiling; try again when it is done");
        return;
    }
    const FormulaScene* current = formula_scene_of(index);
    if (current == nullptr) {
        add_message(
            fmt::format("'{}' is not a formula scene: it has no sequence to edit", scene().id));
        return;
    }
    FormulaScene formula = *current;
    take_slot_values(formula, scene(), session().params);
    std::shared_ptr<const Scene> candidate;
    try {
        formula = edit(std::move(formula));
        candidate =
            std::make_shared<const Scene>(formula_scene_to_scene(formula, scene().plugin_file));
    } catch (const std::exception& error) {
        hybrid_error_ = fmt::format("edit of '{}' refused: {}", scene().id, error.what());
        spdlog::error("{}", hybrid_error_);
        add_message(hybrid_error_);
        return;
    }
    spdlog::info("building the edited '{}': {}", candidate->id, sequence_text(formula));
    hybrid_error_.clear();
    pending_hybrid_ = PendingHybrid{candidate, std::move(formula)};
    worker_->request_reload({candidate, scenes_.at(index), session().effects});
}

// Takes the render thread's verdict on the pending edit; false when `result` is not about it.
bool ViewerApp::adopt_hybrid_edit(const ReloadResult& result) {
    if (!pending_hybrid_ || result.request.candidate != pending_hybrid_->scene) return false;
    PendingHybrid edit = std::move(*pending_hybrid_);
    pending_hybrid_.reset();
    const std::optional<size_t> index = scenes_.index_of(result.request.replaces);
    if (!index) {
        hybrid_error_ =
            fmt::format("edit of '{}' dropped: the scene was reloaded meanwhile", edit.scene->id);
        add_message(hybrid_error_);
        return true;
    }
    if (!result.ok) {
        hybrid_error_ = fmt::format("edit of '{}' refused, keeping the previous sequence: {}",
                                    edit.scene->id, result.error);
        spdlog::error("{}", hybrid_error_);
        add_message(hybrid_error_);
        reload_error_ = {hybrid_error_, result.error_log};
        return true;
    }
    const std::shared_ptr<const Scene> before = scenes_.at(*index);
    const SceneSession* session = scenes_.session_of(*index);
    const std::vector<float> values = session ? session->params : default_param_values(*before);
    adopt_scene(*index, edit.scene);
    if (SceneSession* adopted = scenes_.session_of(*index)) {
        adopted->params = values_after_edit(*before, values, *edit.scene, edit.formula);
    }
    spdlog::info("'{}' now iterates {}", edit.scene->id, sequence_text(edit.formula));
    add_message(fmt::format("sequence: {}", sequence_text(edit.formula)));
    formula_sources_.insert_or_assign(*index, FormulaSource{edit.scene, std::move(edit.formula)});
    ++hybrid_edits_;
    return true;
}

// --- Replayed browser and editor events -------------------------------------------------------

void ViewerApp::apply_replay_formula_event(const ReplayEvent& event) {
    const auto replay_error = [&](const std::string& message) {
        spdlog::error("replay line {}: {}", event.line, message);
        add_message(message);
    };
    switch (event.action) {
        case ReplayAction::BrowserSearch:
            show_browser_ = true;
            browser_query_ = event.text;
            break;
        case ReplayAction::BrowserPick: {
            const std::vector<size_t> matches = browser_matches();
            if (static_cast<size_t>(event.count) >= matches.size()) {
                replay_error(fmt::format("browser_pick {}: the search finds {} scene{}",
                                         event.count + 1, matches.size(),
                                         matches.size() == 1 ? "" : "s"));
                break;
            }
            switch_scene(static_cast<int>(matches[static_cast<size_t>(event.count)]));
            break;
        }
        case ReplayAction::WaitThumbnails:
            thumbnails_awaited_ = true;
            break;
        case ReplayAction::HybridAdd: {
            const Formula* formula = find_formula(event.text);
            if (formula == nullptr) {
                replay_error(fmt::format("hybrid_add: unknown formula '{}'", event.text));
                break;
            }
            edit_hybrid([&](FormulaScene f) { return with_formula_added(std::move(f), *formula); });
            break;
        }
        case ReplayAction::HybridRemove:
            edit_hybrid([&](FormulaScene f) {
                return with_slot_removed(std::move(f), size_t(event.slot));
            });
            break;
        case ReplayAction::HybridMove:
            edit_hybrid([&](FormulaScene f) {
                return with_slot_moved(std::move(f), size_t(event.slot), event.count);
            });
            break;
        case ReplayAction::HybridRepeat:
            edit_hybrid([&](FormulaScene f) {
                return with_repeat(std::move(f), size_t(event.slot), event.count);
            });
            break;
        case ReplayAction::HybridSave:
            save_formula_scene(event.text);
            break;
        default:
            break;
    }
}

}  // namespace fgr::viewer
