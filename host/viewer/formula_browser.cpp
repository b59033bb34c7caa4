// SPDX-License-Identifier: Apache-2.0
#include "viewer/formula_browser.hpp"

#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "viewer/scene_search.hpp"
#include "viewer/viewer_util.hpp"

namespace fgr::viewer {
namespace {

const ImVec4 kSelectedColour(1, 0.8f, 0.2f, 1);

}  // namespace

FormulaBrowser::FormulaBrowser(const SceneSet& scenes, BrowserHost host)
    : scenes_(scenes), host_(std::move(host)) {}

void FormulaBrowser::start_thumbnails(int device_index, int packet_width) {
    thumbnails_ = std::make_unique<ThumbnailWorker>(device_index, packet_width,
                                                    default_thumbnail_directory());
}

std::vector<size_t> FormulaBrowser::matches() {
    std::vector<SceneSearchEntry> entries;
    for (size_t i = 0; i < scenes_.size(); ++i) {
        entries.push_back(search_entry(*scenes_.at(i), host_.formula_of(i)));
    }
    return matching_scenes(entries, query_);
}

const std::string& FormulaBrowser::thumbnail_key_of(size_t index) {
    const std::shared_ptr<const Scene>& scene = scenes_.at(index);
    auto found = keys_.find(scene.get());
    if (found == keys_.end()) {
        // The entry holds its scene, so no other scene can take its address while it exists.
        found = keys_.emplace(scene.get(), std::pair(scene, thumbnail_key(*scene))).first;
    }
    return found->second.second;
}

bool FormulaBrowser::receive_thumbnails(bool view_idle) {
    if (!thumbnails_) return false;
    thumbnails_->set_paused(!view_idle);
    bool arrived = false;
    for (Thumbnail& thumbnail : thumbnails_->take_finished()) {
        if (thumbnail.image.rgb.empty()) {
            errors_[thumbnail.key] = thumbnail.error;
            continue;
        }
        auto texture = std::make_unique<ImageTexture>();
        texture->upload(thumbnail.image);
        textures_[thumbnail.key] = std::move(texture);
        arrived = true;
    }
    return arrived;
}

bool FormulaBrowser::thumbnails_done() {
    if (!thumbnails_ || !shown_) return true;
    for (const size_t index : matches()) {
        const std::string& key = thumbnail_key_of(index);
        if (!textures_.count(key) && !errors_.count(key)) return false;
    }
    return true;
}

void FormulaBrowser::draw_window() {
    if (!shown_) return;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(8, display.y * 0.12f), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(ImVec2(std::min(600.0f, display.x * 0.55f), display.y * 0.8f),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowBgAlpha(0.9f);
    if (ImGui::Begin("Formula browser (B)", &shown_)) draw_browser();
    ImGui::End();
}

void FormulaBrowser::draw_browser() {
    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##search", "search: name, formula, family, tag", &query_);
    const std::vector<size_t> found = matches();
    ImGui::TextDisabled("%zu of %zu scenes; click one to view it", found.size(), scenes_.size());
    const float cell = static_cast<float>(kThumbnailWidth) + ImGui::GetStyle().ItemSpacing.x + 4;
    const int columns = std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / cell));
    ImGui::BeginChild("thumbnails");
    for (size_t k = 0; k < found.size(); ++k) {
        if (k % static_cast<size_t>(columns) != 0) ImGui::SameLine();
        draw_thumbnail_cell(found[k]);
    }
    ImGui::EndChild();
}

void FormulaBrowser::draw_thumbnail_cell(size_t index) {
    const Scene& cell_scene = *scenes_.at(index);
    const std::string key = thumbnail_key_of(index);
    const auto texture = textures_.find(key);
    const auto error = errors_.find(key);
    // Asked for when first shown: the worker renders those in view first, one at a time.
    if (texture == textures_.end() && error == errors_.end() && thumbnails_) {
        thumbnails_->request(scenes_.at(index), key);
    }
    const ImVec2 size(kThumbnailWidth, kThumbnailHeight);
    ImGui::PushID(static_cast<int>(index));
    ImGui::BeginGroup();
    bool clicked = false;
    if (texture != textures_.end()) {
        clicked = ImGui::ImageButton(texture->second->id(), size, ImVec2(0, 0), ImVec2(1, 1), 2);
    } else {
        const char* label = error != errors_.end() ? "no image" : "rendering...";
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
        const FormulaScene* formula = host_.formula_of(index);
        ImGui::SetTooltip("%s (%s)\n%s%s%s%s%s", cell_scene.name.c_str(), cell_scene.id.c_str(),
                          cell_scene.description.c_str(),
                          tags.empty() ? "" : "\ntags: ", tags.c_str(),
                          formula ? ("\nsequence: " + sequence_text(*formula)).c_str() : "",
                          error != errors_.end() ? ("\n" + error->second).c_str() : "");
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x + 4);
    ImGui::TextUnformatted(cell_scene.name.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::PopID();
    if (clicked && !current) host_.switch_scene(static_cast<int>(index));
}

void FormulaBrowser::apply_replay_event(const ReplayEvent& event) {
    switch (event.action) {
        case ReplayAction::BrowserSearch:
            shown_ = true;
            query_ = event.text;
            break;
        case ReplayAction::BrowserPick: {
            const std::vector<size_t> found = matches();
            if (static_cast<size_t>(event.count) >= found.size()) {
                const std::string message =
                    fmt::format("browser_pick {}: the search finds {} scene{}", event.count + 1,
                                found.size(), found.size() == 1 ? "" : "s");
                spdlog::error("replay line {}: {}", event.line, message);
                host_.add_message(message);
                break;
            }
            host_.switch_scene(static_cast<int>(found[static_cast<size_t>(event.count)]));
            break;
        }
        default:
            break;
    }
}

}  // namespace fgr::viewer
