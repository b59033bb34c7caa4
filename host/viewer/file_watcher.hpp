// SPDX-License-Identifier: Apache-2.0
#pragma once
// Notices new and changed files by polling their modification time and size: the plugin folders
// (every file named like a scene file in them: *.so plugins, *.ifs.json and *.formula.json files
// and *.cl files, which may be text scenes) and single files (a scene file opened by path, a
// scene's .cl source in `fgr view --dev`). Polling is portable and cheap at the viewer's rate (a
// stat per file, twice a second).

#include <cstdint>
#include <filesystem>
#include <map>
#include <vector>

namespace fgr::viewer {

class FileWatcher {
public:
    // Every file in `directory` (which need not exist yet) named like a scene file
    // (is_scene_file_name).
    void watch_directory(const std::filesystem::path& directory);
    // One file (which need not exist yet).
    void watch_file(const std::filesystem::path& file);

    // Files that appeared or changed since they were last reported, once they have kept the same
    // time and size for one poll, so a file still being copied is not read half-written. The
    // first poll only records what is there: nothing that existed before watching is reported.
    std::vector<std::filesystem::path> poll();

private:
    struct Stamp {
        std::filesystem::file_time_type time;
        std::uintmax_t size = 0;
        bool operator==(const Stamp&) const = default;
    };
    struct Seen {
        Stamp stamp;
        bool reported = false;
    };

    std::map<std::filesystem::path, Stamp> current_files() const;

    std::vector<std::filesystem::path> directories_;
    std::vector<std::filesystem::path> files_;
    std::map<std::filesystem::path, Seen> seen_;
    bool first_poll_ = true;
};

}  // namespace fgr::viewer
