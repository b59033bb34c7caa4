// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_index.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <sys/stat.h>

#include <exception>
#include <nlohmann/json.hpp>

#include "util/atomic_file.hpp"
#include "util/files.hpp"
#include "util/json_fields.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

constexpr const char* kFormat = "fgr-scene-index";
constexpr int kVersion = 1;
// Far above any real search path's files (about 100 bytes an entry).
constexpr std::size_t kMaxIndexBytes = std::size_t{4} << 20;

fs::path index_key(const fs::path& file) {
    std::error_code error;
    const fs::path absolute = fs::absolute(file, error);
    return (error ? file : absolute).lexically_normal();
}

}  // namespace

std::optional<FileStamp> file_stamp(const fs::path& file) {
    struct stat status {};
    if (::stat(file.c_str(), &status) != 0) return std::nullopt;
    return FileStamp{static_cast<std::uintmax_t>(status.st_size),
                     std::int64_t{status.st_mtim.tv_sec} * 1'000'000'000 + status.st_mtim.tv_nsec,
                     static_cast<std::uintmax_t>(status.st_ino)};
}

SceneIndex SceneIndex::parse(std::string_view text, std::string& problem) {
    problem.clear();
    SceneIndex index;
    try {
        const json document = json_fields::parse_document(text, "not valid JSON");
        if (!document.is_object() || document.value("format", "") != kFormat ||
            document.value("version", 0) != kVersion) {
            problem = fmt::format("not a scene index of version {}", kVersion);
            return SceneIndex{};
        }
        for (const json& entry : document.at("files")) {
            const FileStamp stamp{entry.at("size").get<std::uintmax_t>(),
                                  entry.at("modified_ns").get<std::int64_t>(),
                                  entry.at("inode").get<std::uintmax_t>()};
            index.entries_[fs::path(entry.at("path").get<std::string>())] =
                Entry{stamp, entry.at("id").get<std::string>()};
        }
    } catch (const std::exception& failure) {  // parse_document's, and the JSON library's
        problem = failure.what();
        return SceneIndex{};
    }
    return index;
}

SceneIndex SceneIndex::read(const fs::path& file) {
    std::error_code error;
    if (!fs::exists(file, error)) return {};
    std::string text;
    std::string problem = read_file_bytes(file, text, kMaxIndexBytes);
    SceneIndex index = problem.empty() ? parse(text, problem) : SceneIndex{};
    if (!problem.empty()) {
        spdlog::debug("scene index {} unusable ({}): rebuilt", printable_path(file), problem);
    }
    return index;
}

std::optional<std::string> SceneIndex::id_of(const fs::path& file, const FileStamp& stamp) const {
    const auto entry = entries_.find(index_key(file));
    if (entry == entries_.end() || entry->second.stamp != stamp) return std::nullopt;
    return entry->second.id;
}

void SceneIndex::record(const fs::path& file, const FileStamp& stamp, const std::string& id) {
    Entry& entry = entries_[index_key(file)];
    if (entry.stamp == stamp && entry.id == id) return;
    entry = Entry{stamp, id};
    changed_ = true;
}

void SceneIndex::forget(const fs::path& file) { changed_ |= entries_.erase(index_key(file)) > 0; }

void SceneIndex::keep_only(const fs::path& directory, const std::set<fs::path>& present) {
    std::set<fs::path> kept;
    for (const fs::path& file : present) kept.insert(index_key(file));
    const fs::path folder = index_key(directory);
    for (auto entry = entries_.begin(); entry != entries_.end();) {
        if (entry->first.parent_path() == folder && !kept.contains(entry->first)) {
            entry = entries_.erase(entry);
            changed_ = true;
        } else {
            ++entry;
        }
    }
}

void SceneIndex::write(const fs::path& file) const {
    json files = json::array();
    for (const auto& [path, entry] : entries_) {
        files.push_back({{"path", path.string()},
                         {"size", entry.stamp.size},
                         {"modified_ns", entry.stamp.modified_ns},
                         {"inode", entry.stamp.inode},
                         {"id", entry.id}});
    }
    const json document = {{"format", kFormat}, {"version", kVersion}, {"files", files}};
    try {
        std::error_code ignored;
        fs::create_directories(file.parent_path(), ignored);
        write_text_file_atomically(file, document.dump(1) + "\n");
    } catch (const std::exception& failure) {
        spdlog::debug("could not write the scene index {}: {}", printable_path(file),
                      failure.what());
    }
}

}  // namespace fgr
