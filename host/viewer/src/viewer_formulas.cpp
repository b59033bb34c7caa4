// The formula browser (a window of thumbnails with a search field; B) and the hybrid editor (the
// panel's "Formula sequence" section). An edit of a sequence makes a new scene that the render
// thread builds as it builds a reloaded one: the old scene and its image stay until the new
// kernel compiles, and a build that fails keeps them.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "viewer_app.hpp"
#include "viewer_util.hpp"

namespace fgr::viewer {
namespace {

const ImVec4 kSelectedColour(1, 0.8f, 0.2f, 1);

}  // namespace

// --- The browser ------------------------------------------------------------------------------

std::vector<size_t> ViewerApp::browser_matches() {
    std::vector<SceneSearchEntry> entries;
    for (size_t i = 0; i < scenes_.size(); ++i) {
        entries.push_back(search_entry(*scenes_.at(i), hybrid_.formula_of(i)));
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
        const FormulaScene* formula = hybrid_.formula_of(index);
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
        case ReplayAction::HybridAdd:
        case ReplayAction::HybridRemove:
        case ReplayAction::HybridMove:
        case ReplayAction::HybridRepeat:
        case ReplayAction::HybridSave:
            hybrid_.apply_replay_event(event);
            break;
        default:
            break;
    }
}

}  // namespace fgr::viewer
