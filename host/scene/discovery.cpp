// SPDX-License-Identifier: Apache-2.0
#include "scene/discovery.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>

#include "scene/scene_file.hpp"
#include "scene/scene_index.hpp"
#include "util/strings.hpp"
#include "util/suggest.hpp"

namespace fgr {
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> split_path_list(std::string_view list) {
    std::vector<fs::path> directories;
    std::size_t start = 0;
    while (start <= list.size()) {
        const std::size_t end = std::min(list.find(':', start), list.size());
        if (end > start) directories.emplace_back(list.substr(start, end - start));
        start = end + 1;
    }
    return directories;
}

// What a directory entry named like a scene file is when it is not a regular file (or a link to
// one): "" for a regular file, else why it cannot be a scene ("a FIFO", "a symbolic link that
// cannot be followed (Too many levels of symbolic links)"). Only the entry's status is read: a
// FIFO is never opened.
std::string not_a_scene_file(const fs::directory_entry& entry) {
    std::error_code error;
    const fs::file_status status = entry.status(error);
    if (error || !fs::exists(status)) {
        std::error_code link_error;
        if (entry.is_symlink(link_error)) {
            return "a symbolic link that cannot be followed (" +
                   (error ? error.message() : std::string("its target does not exist")) + ")";
        }
        return "its status cannot be read (" + error.message() + ")";
    }
    switch (status.type()) {
        case fs::file_type::regular:
            return "";
        case fs::file_type::directory:
            return "a directory";
        case fs::file_type::fifo:
            return "a FIFO";
        case fs::file_type::socket:
            return "a socket";
        case fs::file_type::block:
            return "a block device";
        case fs::file_type::character:
            return "a character device";
        default:
            return "not a regular file";
    }
}

// The entries of a plugin directory named like scene files, sorted by file name so the load
// order, and thus which of two duplicate ids wins, does not depend on the filesystem's directory
// order: regular files (or links to them) named *.so, *.ifs.json or *.formula.json, and *.cl
// files that start with a text scene's header; and the entries so named that are no file to read
// (a directory, a FIFO, a socket, a device, a dangling link or a loop of links), each with why.
struct PluginEntry {
    fs::path file;
    std::string unreadable;  // why it is no file to read; empty for a file
};

std::vector<PluginEntry> plugin_entries_in(const fs::path& directory) {
    std::vector<PluginEntry> entries;
    std::error_code error;
    // Explicit increment(error): the range-for form would throw on a read error mid-directory.
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        if (!is_scene_file_name(it->path())) continue;
        if (std::string why = not_a_scene_file(*it); !why.empty()) {
            entries.push_back({it->path(), "not a regular file: " + why});
        } else if (is_scene_file(it->path())) {
            entries.push_back({it->path(), {}});
        }
    }
    if (error) {
        spdlog::debug("plugin directory {} not scanned fully: {}", printable_path(directory),
                      error.message());
    }
    std::sort(entries.begin(), entries.end(), [](const PluginEntry& a, const PluginEntry& b) {
        return a.file.filename() < b.file.filename();
    });
    return entries;
}

// The same directory can appear twice (e.g. $FGR_PLUGIN_PATH naming the default folder); scanning
// it again would report every plugin in it as a duplicate.
fs::path canonical_or_self(const fs::path& directory) {
    std::error_code error;
    fs::path canonical = fs::canonical(directory, error);
    return error ? directory : canonical;
}

// The directories of the search path in order, each once.
class DirectoryWalk {
public:
    bool first_visit(const fs::path& directory) {
        if (scanned_directories_.insert(canonical_or_self(directory)).second) return true;
        spdlog::debug("plugin directory {} already scanned", printable_path(directory));
        return false;
    }

private:
    std::set<fs::path> scanned_directories_;
};

void warn_skipped(const SkippedPlugin& skipped) {
    spdlog::warn(
        "skipping plugin {}: {}{}", printable_path(skipped.file),
        skipped.declared_id.empty() ? "" : fmt::format("scene '{}': ", skipped.declared_id),
        printable_text(skipped.reason));
}

class SceneCollector {
public:
    void scan(const fs::path& directory) {
        if (!walk_.first_visit(directory)) return;
        for (PluginEntry& entry : plugin_entries_in(directory)) {
            if (entry.unreadable.empty()) {
                load(entry.file);
            } else {
                skip(entry.file, std::move(entry.unreadable));
            }
        }
    }

    Discovery take() { return std::move(discovery_); }

private:
    void load(const fs::path& file) {
        LoadResult result = load_scene_file(file);
        if (!result.scene) return skip(file, result.error, result.declared_id);
        const auto [existing, inserted] = loaded_from_.emplace(result.scene->id, file);
        if (!inserted) {
            return skip(file, fmt::format("duplicate scene id '{}' (already loaded from {})",
                                          result.scene->id, printable_path(existing->second)));
        }
        spdlog::debug("loaded scene '{}' from {}", result.scene->id, printable_path(file));
        discovery_.scenes.push_back(std::move(*result.scene));
    }

    void skip(const fs::path& file, std::string reason, std::string declared_id = {}) {
        discovery_.skipped.push_back({file, std::move(reason), std::move(declared_id)});
        warn_skipped(discovery_.skipped.back());
    }

    Discovery discovery_;
    std::map<std::string, fs::path> loaded_from_;  // scene id -> file it came from
    DirectoryWalk walk_;
};

// The first scene with `id` in search order, as discover_scenes would pick it (the first of
// duplicate ids wins), loading only the files the index cannot vouch for and the one that holds
// it. The files refused on the way are added to `refused`.
std::optional<Scene> first_scene_with_id(const std::vector<fs::path>& directories,
                                         const std::string& id, SceneIndex& index,
                                         std::vector<SkippedPlugin>& refused) {
    DirectoryWalk walk;
    for (const fs::path& directory : directories) {
        if (!walk.first_visit(directory)) continue;
        std::vector<fs::path> files;
        for (PluginEntry& entry : plugin_entries_in(directory)) {
            if (entry.unreadable.empty()) {
                files.push_back(entry.file);
            } else {
                refused.push_back({entry.file, std::move(entry.unreadable)});
            }
        }
        index.keep_only(directory, std::set<fs::path>(files.begin(), files.end()));
        for (const fs::path& file : files) {
            const std::optional<FileStamp> stamp = file_stamp(file);
            if (stamp) {
                const std::optional<std::string> indexed = index.id_of(file, *stamp);
                if (indexed && *indexed != id) continue;  // another scene, unchanged
            }
            LoadResult result = load_scene_file(file);
            if (!result.scene) {
                refused.push_back({file, result.error, result.declared_id});
                index.forget(file);
                continue;
            }
            if (stamp) index.record(file, *stamp, result.scene->id);
            if (result.scene->id == id) {
                spdlog::debug("loaded scene '{}' from {}", id, printable_path(file));
                return std::move(result.scene);
            }
        }
    }
    return std::nullopt;
}

std::vector<std::string> scene_ids(const std::vector<Scene>& scenes) {
    std::vector<std::string> ids;
    for (const auto& scene : scenes) ids.push_back(scene.id);
    return ids;
}

// `id` with its underscores read as dashes.
std::string dashed(std::string_view id) {
    std::string text(id);
    std::replace(text.begin(), text.end(), '_', '-');
    return text;
}

// The scene id a file name suggests: oops.so, liboops.so, oops.ifs.json, oops.formula.json and
// oops.cl give "oops"; '_' reads as '-' (a CMake target liboops_scene.so for the scene
// 'oops-scene').
std::string id_from_file_name(const fs::path& file) {
    std::string name = file.filename().string();
    for (const std::string_view suffix : {".ifs.json", ".formula.json", ".so", ".cl"}) {
        if (name.ends_with(suffix)) {
            name.erase(name.size() - suffix.size());
            break;
        }
    }
    if (name.starts_with("lib")) name.erase(0, 3);
    return dashed(name);
}

// The refused file that was scene `id`: by the id its description declared, else by its name.
const SkippedPlugin* refused_scene(const Discovery& found, std::string_view id) {
    for (const SkippedPlugin& skipped : found.skipped) {
        if (skipped.declared_id == id) return &skipped;
    }
    for (const SkippedPlugin& skipped : found.skipped) {
        if (skipped.declared_id.empty() && id_from_file_name(skipped.file) == dashed(id)) {
            return &skipped;
        }
    }
    return nullptr;
}

}  // namespace

std::string unknown_scene_message(const Discovery& found, std::string_view id) {
    if (const SkippedPlugin* refused = refused_scene(found, id)) {
        return fmt::format("unknown scene '{}': plugin {} was refused: {}", id,
                           printable_path(refused->file), printable_text(refused->reason));
    }
    std::string refused;
    if (!found.skipped.empty()) {
        // One of them may be the scene under another name: say which files were refused and why.
        constexpr std::size_t kShown = 3;
        refused = "refused:";
        for (std::size_t i = 0; i < std::min(found.skipped.size(), kShown); ++i) {
            refused +=
                fmt::format("{} {} ({})", i == 0 ? "" : ",", printable_path(found.skipped[i].file),
                            printable_text(found.skipped[i].reason));
        }
        if (found.skipped.size() > kShown) {
            refused += fmt::format(" and {} more", found.skipped.size() - kShown);
        }
    }
    if (found.scenes.empty()) {
        return fmt::format(
            "unknown scene '{}' (no scenes found: `fgr list` names the folders "
            "searched{}{})",
            id, refused.empty() ? "" : "; ", refused);
    }
    // The nearest id, not every id: there are dozens.
    const std::string suggestion = did_you_mean(id, scene_ids(found.scenes));
    if (suggestion.empty()) {
        return fmt::format("unknown scene '{}' (`fgr list` lists the scenes{}{})", id,
                           refused.empty() ? "" : "; ", refused);
    }
    std::string message = fmt::format("unknown scene '{}'", id);
    if (!refused.empty()) message += " (" + refused + ")";
    return message + suggestion;
}

std::vector<fs::path> plugin_search_path(const fs::path& exe_dir) {
    std::vector<fs::path> directories;
    if (const char* env = std::getenv("FGR_PLUGIN_PATH")) directories = split_path_list(env);
    // An unknown executable directory must not turn into a path relative to the working directory.
    if (!exe_dir.empty()) {
        directories.push_back((exe_dir / FGR_PLUGINS_FROM_BIN).lexically_normal());
    }
    const char* home = std::getenv("HOME");
    if (home != nullptr && *home != '\0') {
        directories.push_back(fs::path(home) / ".local" / "share" / "fgr" / "plugins");
    }
    return directories;
}

Discovery discover_scenes(const std::vector<fs::path>& directories) {
    SceneCollector collector;
    for (const fs::path& directory : directories) collector.scan(directory);
    return collector.take();
}

Discovery discover_scene(const std::vector<fs::path>& directories, const std::string& id,
                         const fs::path& index_file) {
    SceneIndex index = index_file.empty() ? SceneIndex{} : SceneIndex::read(index_file);
    std::vector<SkippedPlugin> refused;
    std::optional<Scene> scene = first_scene_with_id(directories, id, index, refused);
    if (index.changed() && !index_file.empty()) index.write(index_file);
    // Not found: the full scan, for the error's list of scenes and refusals (and its warnings).
    if (!scene) return discover_scenes(directories);
    for (const SkippedPlugin& skipped : refused) warn_skipped(skipped);
    Discovery found;
    found.scenes.push_back(std::move(*scene));
    found.skipped = std::move(refused);
    return found;
}

}  // namespace fgr
