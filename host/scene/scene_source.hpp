// SPDX-License-Identifier: Apache-2.0
#pragma once
// A plugin's scene source against its .cl file on disk. Plugins built with fgr_add_scene_plugin
// embed their .cl file and record its absolute path as the source name: `--dev` (fgr render,
// fgr check, fgr view) reads that file instead of the embedded copy, and without --dev fgr warns
// when the file was changed after the plugin was built (a rebuild or a re-copy forgotten).
#include <filesystem>
#include <optional>
#include <string>

#include "scene/scene.hpp"

namespace fgr {

// The .cl file the scene's plugin recorded, when its source name is an absolute path to a file
// that exists, or a text scene's own file (IFS scenes and scenes built by hand have none).
std::optional<std::filesystem::path> recorded_source_file(const Scene& scene);

// One line when the recorded .cl file is newer than the plugin and differs from the source the
// plugin embeds, e.g. "scene.cl changed after libscene.so was built: rebuild the plugin, or use
// --dev"; "" when they agree, or there is no file to compare with.
std::string stale_source_warning(const Scene& scene);

// The whole of a source file; throws std::runtime_error naming it when it cannot be read.
std::string read_source_file(const std::filesystem::path& file);

// The scene with its source read from `file`, which becomes its source name (so build messages
// name it); throws std::runtime_error naming the file when it cannot be read.
Scene with_source_file(const Scene& scene, const std::filesystem::path& file);

// The scene with its source read afresh from its recorded .cl file (--dev); throws
// std::runtime_error when the scene records no file that exists, naming what it records.
Scene with_source_from_disk(const Scene& scene);

}  // namespace fgr
