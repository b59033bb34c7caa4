// SPDX-License-Identifier: Apache-2.0
#pragma once
// Finding scenes (plugins and scene files): the search path and the scan of its directories.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"
#include "util/installed_files.hpp"  // executable_dir(), which plugin_search_path takes

namespace fgr {

// In order: each directory of $FGR_PLUGIN_PATH (colon-separated, empty entries ignored),
// <exe_dir>/../lib/fgr/plugins (the libdir fgr was built for: built and installed trees match),
// and ~/.local/share/fgr/plugins (when $HOME is set).
std::vector<std::filesystem::path> plugin_search_path(const std::filesystem::path& exe_dir);

struct SkippedPlugin {
    std::filesystem::path file;
    std::string reason;
    std::string declared_id = {};  // the scene id its description declared, if it got that far
};

struct Discovery {
    std::vector<Scene> scenes;  // in discovery order; the first of duplicate ids wins
    std::vector<SkippedPlugin> skipped;
};

// Loads every scene file (scene/scene_file.hpp: *.so plugins, *.ifs.json IFS files,
// *.formula.json formula files and *.cl text scenes) in each directory, sorted together by name
// within a directory; missing directories, and .cl files without a text scene's header, are
// ignored. Each skipped file gets one warning log line naming the file and the reason, and so does
// each entry named like a scene file that is no regular file (a directory, a FIFO, a socket, a
// dangling link or a loop of links), which is never opened.
Discovery discover_scenes(const std::vector<std::filesystem::path>& directories);

// Scene `id` alone, as discover_scenes(directories) would find it (the first file in search
// order that holds it), without loading the other scenes' files that the scene index in
// `index_file` (scene/scene_index.hpp) knows to hold other ids; the index is brought up to date
// with what was loaded. When no file holds `id`, it is discover_scenes(directories) in full, for
// unknown_scene_message. An empty `index_file` means no index: files are loaded in order up to
// the scene's.
Discovery discover_scene(const std::vector<std::filesystem::path>& directories,
                         const std::string& id, const std::filesystem::path& index_file);

// The one-line error for a scene id that `found` lacks. When a refused file is that scene (its
// description declared the id, or, refused before the id could be read, its file name is the id,
// e.g. liboops.so or oops.ifs.json for 'oops'), the message names the file and why it was refused;
// otherwise it offers the nearest scene id (or points to `fgr list`) and names the files that were
// refused.
std::string unknown_scene_message(const Discovery& found, std::string_view id);

}  // namespace fgr
