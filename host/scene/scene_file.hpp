// SPDX-License-Identifier: Apache-2.0
#pragma once
// Scene files of every kind, by name: a plugin (`*.so`, plugin_loader.hpp), an IFS file
// (`*.ifs.json`, ifs.hpp), a formula file (`*.formula.json`, formulas.hpp) or a text scene (`*.cl`
// that starts with an fgr-scene header, text_scene.hpp). Discovery, opening a scene by path and
// the viewer's hot reload load through here.

#include <filesystem>
#include <optional>

#include "scene/description_validation.hpp"

namespace fgr {

enum class SceneFileKind { Plugin, Ifs, Formula, Text };

// The kind of scene file `file` is named as: *.so, *.ifs.json, *.formula.json or *.cl; nothing
// for any other name.
std::optional<SceneFileKind> scene_file_kind(const std::filesystem::path& file);

// Whether `file` is named like a scene file (scene_file_kind): the names the viewer watches.
bool is_scene_file_name(const std::filesystem::path& file);

// Whether discovery loads `file` as a scene: a file named like one, and for a *.cl file only when
// it starts with a text scene's header (is_text_scene_file); other .cl files in a plugin folder
// are sources that scenes include, and are not scenes.
bool is_scene_file(const std::filesystem::path& file);

// An IFS file read and turned into a Scene (ifs_scene_to_scene), or the IfsError's reason without
// the file's name in front (LoadResult's convention: callers add it).
LoadResult load_ifs_scene(const std::filesystem::path& file);

// The same for a formula scene file (scene/formulas/formulas.hpp).
LoadResult load_formula_scene(const std::filesystem::path& file);

// An IFS file's, a formula file's or a text scene's scene, else a plugin's (load_scene_plugin).
LoadResult load_scene_file(const std::filesystem::path& file);

// load_scene_file for IFS, formula and text files (read afresh each time anyway),
// reload_scene_plugin for plugins: the viewer's hot reload of a changed file.
LoadResult reload_scene_file(const std::filesystem::path& file);

}  // namespace fgr
