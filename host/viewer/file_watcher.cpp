// SPDX-License-Identifier: Apache-2.0
#include "viewer/file_watcher.hpp"

#include <algorithm>
#include <system_error>

#include "scene/scene_file.hpp"

namespace fgr::viewer {

namespace fs = std::filesystem;

void FileWatcher::watch_directory(const fs::path& directory) {
    if (std::find(directories_.begin(), directories_.end(), directory) == directories_.end()) {
        directories_.push_back(directory);
    }
}

void FileWatcher::watch_file(const fs::path& file) {
    if (std::find(files_.begin(), files_.end(), file) == files_.end()) files_.push_back(file);
}

std::map<fs::path, FileWatcher::Stamp> FileWatcher::current_files() const {
    std::map<fs::path, Stamp> found;
    const auto record = [&](const fs::path& file) {
        std::error_code error;
        if (!fs::is_regular_file(file, error)) return;
        Stamp stamp{fs::last_write_time(file, error), 0};
        if (error) return;
        stamp.size = fs::file_size(file, error);
        if (!error) found[file] = stamp;
    };
    for (const fs::path& directory : directories_) {
        std::error_code error;
        for (fs::directory_iterator it(directory, error), end; !error && it != end;
             it.increment(error)) {
            if (is_scene_file_name(it->path())) record(it->path());
        }
    }
    for (const fs::path& file : files_) record(file);
    return found;
}

std::vector<fs::path> FileWatcher::poll() {
    const std::map<fs::path, Stamp> now = current_files();
    std::vector<fs::path> changed;
    for (const auto& [file, stamp] : now) {
        auto seen = seen_.find(file);
        if (seen == seen_.end()) {
            // New: report once it has held still for a poll (at once counts as "before").
            seen_[file] = {stamp, first_poll_};
        } else if (!(seen->second.stamp == stamp)) {
            seen->second = {stamp, false};
        } else if (!seen->second.reported) {
            seen->second.reported = true;
            changed.push_back(file);
        }
    }
    std::erase_if(seen_, [&](const auto& entry) { return !now.count(entry.first); });
    first_poll_ = false;
    return changed;
}

}  // namespace fgr::viewer
