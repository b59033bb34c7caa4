// SPDX-License-Identifier: Apache-2.0
#pragma once
// The scene a command names: `fgr render|view|check|video|bench SCENE` take a scene id or a scene
// file by path. Which of the two an argument is, and what kind of file, is decided in one place
// (scene_argument_kind); the scene it names is found in one place (find_scene_argument).

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_file.hpp"

namespace fgr {

enum class SceneArgumentKind {
    Id,           // a scene id, found along the plugin search path
    PluginFile,   // *.so
    IfsFile,      // *.ifs.json
    FormulaFile,  // *.formula.json
    TextFile,     // *.cl that starts with an fgr-scene header (scene/text_scene.hpp)
};

// What `argument` names. A path when it names an existing file, holds a '/', or ends with a scene
// file's suffix (.so, .ifs.json, .formula.json, .cl); its kind is then its suffix's, or, for an
// existing file with none of them, what its first bytes say (an ELF library, a text scene's
// header). Anything else is an id. Throws UsageError, naming the file, for a path that is of none
// of the kinds.
SceneArgumentKind scene_argument_kind(const std::string& argument);

// The scene in `file`, a path of `kind` (not Id), loaded alone; UsageError "<file>: <reason>",
// one line, when it is refused.
Scene load_scene_argument_file(const std::filesystem::path& file, SceneArgumentKind kind);

// The scene `argument` names: a file by path, loaded alone (no plugin folder is scanned), or a
// scene id: the first file in `directories` that holds it (discover_scene, through the scene index
// in `index_file`; empty: none). UsageError, one line, naming the refused file or, for an unknown
// id, the scenes there are (unknown_scene_message).
Scene find_scene_argument(const std::string& argument,
                          const std::vector<std::filesystem::path>& directories,
                          const std::filesystem::path& index_file);

}  // namespace fgr
