#pragma once
// Scene files of either kind, by name: a plugin (`*.so`, plugin_loader.hpp) or an IFS file
// (`*.ifs.json`, ifs.hpp). Discovery and the viewer's hot reload load through here.

#include <filesystem>

#include "scene/description_validation.hpp"

namespace fgr {

// Whether discovery loads `file` as a scene: a *.so plugin, a *.ifs.json IFS file or a
// *.formula.json formula scene (scene/formulas/formulas.hpp).
bool is_scene_file_name(const std::filesystem::path& file);

// An IFS file read and turned into a Scene (ifs_scene_to_scene), or the IfsError's reason without
// the file's name in front (LoadResult's convention: callers add it).
LoadResult load_ifs_scene(const std::filesystem::path& file);

// The same for a formula scene file (scene/formulas/formulas.hpp).
LoadResult load_formula_scene(const std::filesystem::path& file);

// An IFS file's or a formula file's scene, else a plugin's (load_scene_plugin).
LoadResult load_scene_file(const std::filesystem::path& file);

// load_scene_file for IFS and formula files (read afresh each time anyway), reload_scene_plugin
// for plugins: the viewer's hot reload of a changed file.
LoadResult reload_scene_file(const std::filesystem::path& file);

}  // namespace fgr
