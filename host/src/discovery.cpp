#include "fgr/discovery.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <string_view>
#include <system_error>

#include <spdlog/spdlog.h>

#include "fgr/scene_file.hpp"

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

// Regular files (or links to them) named *.so or *.ifs.json, sorted by file name so the load
// order, and thus which of two duplicate ids wins, does not depend on the filesystem's directory
// order.
std::vector<fs::path> plugin_files_in(const fs::path& directory) {
    std::vector<fs::path> files;
    std::error_code error;
    // Explicit increment(error): the range-for form would throw on a read error mid-directory.
    for (fs::directory_iterator it(directory, error), end; !error && it != end;
         it.increment(error)) {
        std::error_code status_error;
        if (is_scene_file_name(it->path()) && it->is_regular_file(status_error)) {
            files.push_back(it->path());
        }
    }
    if (error) {
        spdlog::debug("plugin directory {} not scanned fully: {}", directory.string(),
                      error.message());
    }
    std::sort(files.begin(), files.end(),
              [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
    return files;
}

// The same directory can appear twice (e.g. $FGR_PLUGIN_PATH naming the default folder); scanning
// it again would report every plugin in it as a duplicate.
fs::path canonical_or_self(const fs::path& directory) {
    std::error_code error;
    fs::path canonical = fs::canonical(directory, error);
    return error ? directory : canonical;
}

class SceneCollector {
public:
    void scan(const fs::path& directory) {
        if (!scanned_directories_.insert(canonical_or_self(directory)).second) {
            spdlog::debug("plugin directory {} already scanned", directory.string());
            return;
        }
        for (const fs::path& file : plugin_files_in(directory)) load(file);
    }

    Discovery take() { return std::move(discovery_); }

private:
    void load(const fs::path& file) {
        LoadResult result = load_scene_file(file);
        if (!result.scene) return skip(file, result.error);
        const auto [existing, inserted] = loaded_from_.emplace(result.scene->id, file);
        if (!inserted) {
            return skip(file, fmt::format("duplicate scene id '{}' (already loaded from {})",
                                          result.scene->id, existing->second.string()));
        }
        spdlog::debug("loaded scene '{}' from {}", result.scene->id, file.string());
        discovery_.scenes.push_back(std::move(*result.scene));
    }

    void skip(const fs::path& file, std::string reason) {
        spdlog::warn("skipping plugin {}: {}", file.string(), reason);
        discovery_.skipped.push_back({file, std::move(reason)});
    }

    Discovery discovery_;
    std::map<std::string, fs::path> loaded_from_;  // scene id -> file it came from
    std::set<fs::path> scanned_directories_;
};

}  // namespace

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

fs::path executable_dir() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) {
        spdlog::debug("cannot resolve /proc/self/exe: {}", error.message());
        return {};
    }
    return exe.parent_path();
}

Discovery discover_scenes(const std::vector<fs::path>& directories) {
    SceneCollector collector;
    for (const fs::path& directory : directories) collector.scan(directory);
    return collector.take();
}

}  // namespace fgr
