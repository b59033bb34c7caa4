// SPDX-License-Identifier: Apache-2.0
#pragma once
// The formula browser's search: which scenes a query finds. A scene is found by its id, name and
// tags, and a formula scene also by its formulas' names, titles and families; every word of the
// query must occur (ignoring case) in one of them, so "box julia" finds the Mandelbox Julia.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/formulas/formulas.hpp"
#include "scene/scene.hpp"

namespace fgr::viewer {

// What a scene is found by.
struct SceneSearchEntry {
    std::vector<std::string> words;  // id, name, tags, formulas' names, titles and families
};

// The entry of a scene; `formula_scene` is its sequence when it is a formula scene (else null).
SceneSearchEntry search_entry(const Scene& scene, const FormulaScene* formula_scene);

// Whether every word of `query` (split at spaces) occurs in one of the entry's words, ignoring
// ASCII case; an empty query finds everything.
bool matches_query(const SceneSearchEntry& entry, std::string_view query);

// The indices of the entries the query finds, in order.
std::vector<std::size_t> matching_scenes(std::span<const SceneSearchEntry> entries,
                                         std::string_view query);

}  // namespace fgr::viewer
