// SPDX-License-Identifier: Apache-2.0
#pragma once
// The scene index: which scene id each scene file held when it was last loaded, so that finding
// one scene by id (`fgr render ID`, `fgr check ID`, ...) loads that scene's file and not every
// plugin and scene file on the search path. A file counts as unchanged while its size,
// modification time and inode are; any other file is loaded as discovery would load it. The
// index is only a shortcut: lost, stale or damaged, it costs a full scan, never a wrong scene.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace fgr {

// What the index compares to tell whether a file changed since it was indexed.
struct FileStamp {
    std::uintmax_t size = 0;
    std::int64_t modified_ns = 0;
    std::uintmax_t inode = 0;
    bool operator==(const FileStamp&) const = default;
};

// The file's stamp, or nothing when it cannot be stat'ed.
std::optional<FileStamp> file_stamp(const std::filesystem::path& file);

// The index's file name in the kernel cache directory (device/cache_directory.hpp counts it as an
// entry: `fgr cache clear` removes it, and it is rebuilt on the next search).
constexpr const char* kSceneIndexName = "scene-index.json";

class SceneIndex {
public:
    // The index in `file`; empty when the file is missing, unreadable, too large or not a scene
    // index (logged at debug level: it is rebuilt).
    static SceneIndex read(const std::filesystem::path& file);
    // The index `text` holds (json_fields::parse_document's rules); empty, with `problem` set to
    // why, when it is not a scene index this fgr reads. Never throws.
    static SceneIndex parse(std::string_view text, std::string& problem);

    // The id `file` held when indexed with this stamp; nothing when it is not indexed or has
    // changed since.
    std::optional<std::string> id_of(const std::filesystem::path& file,
                                     const FileStamp& stamp) const;
    void record(const std::filesystem::path& file, const FileStamp& stamp, const std::string& id);
    void forget(const std::filesystem::path& file);
    // Forgets the files of `directory` that are not in `present` (files since removed).
    void keep_only(const std::filesystem::path& directory,
                   const std::set<std::filesystem::path>& present);

    bool changed() const { return changed_; }
    std::size_t size() const { return entries_.size(); }
    // Writes the index to `file` atomically; a failure is logged at debug level, never thrown
    // (the index only saves time).
    void write(const std::filesystem::path& file) const;

private:
    struct Entry {
        FileStamp stamp;
        std::string id;
    };
    std::map<std::filesystem::path, Entry> entries_;  // by absolute, normalised path
    bool changed_ = false;
};

}  // namespace fgr
