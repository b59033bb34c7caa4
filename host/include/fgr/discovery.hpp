#pragma once
// Finding scenes (plugins and IFS files): the search path and the scan of its directories.

#include <filesystem>
#include <string>
#include <vector>

#include "fgr/scene.hpp"

namespace fgr {

// In order: each directory of $FGR_PLUGIN_PATH (colon-separated, empty entries ignored),
// <exe_dir>/../lib/fgr/plugins (the libdir fgr was built for: built and installed trees match),
// and ~/.local/share/fgr/plugins (when $HOME is set).
std::vector<std::filesystem::path> plugin_search_path(const std::filesystem::path& exe_dir);

// Directory holding the running executable (/proc/self/exe).
std::filesystem::path executable_dir();

struct SkippedPlugin {
    std::filesystem::path file;
    std::string reason;
};

struct Discovery {
    std::vector<Scene> scenes;  // in discovery order; the first of duplicate ids wins
    std::vector<SkippedPlugin> skipped;
};

// Loads every *.so plugin and *.ifs.json IFS file (fgr/ifs.hpp) in each directory, sorted together
// by name within a directory; missing directories are ignored. Each skipped file gets one warning
// log line naming the file and the reason.
Discovery discover_scenes(const std::vector<std::filesystem::path>& directories);

}  // namespace fgr
