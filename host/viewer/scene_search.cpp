// SPDX-License-Identifier: Apache-2.0
#include "viewer/scene_search.hpp"

#include <algorithm>
#include <sstream>

#include "util/lower_case.hpp"

namespace fgr::viewer {

SceneSearchEntry search_entry(const Scene& scene, const FormulaScene* formula_scene) {
    SceneSearchEntry entry;
    entry.words = {lower_case(scene.id), lower_case(scene.name)};
    for (const std::string& tag : scene.tags) entry.words.push_back(lower_case(tag));
    if (formula_scene == nullptr) return entry;
    for (const FormulaSlot& slot : formula_scene->sequence) {
        entry.words.push_back(lower_case(slot.formula->name));
        entry.words.push_back(lower_case(slot.formula->title));
        entry.words.push_back(lower_case(slot.formula->family));
    }
    return entry;
}

bool matches_query(const SceneSearchEntry& entry, std::string_view query) {
    std::istringstream words{lower_case(query)};
    for (std::string word; words >> word;) {
        const bool found = std::any_of(
            entry.words.begin(), entry.words.end(),
            [&](const std::string& text) { return text.find(word) != std::string::npos; });
        if (!found) return false;
    }
    return true;
}

std::vector<std::size_t> matching_scenes(std::span<const SceneSearchEntry> entries,
                                         std::string_view query) {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (matches_query(entries[i], query)) found.push_back(i);
    }
    return found;
}

}  // namespace fgr::viewer
