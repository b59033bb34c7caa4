// SPDX-License-Identifier: Apache-2.0
#include "cli/scaffold.hpp"

#include <fmt/format.h>

#include <cctype>
#include <system_error>

#include "scene/parameters.hpp"
#include "scene/scene_limits.hpp"
#include "template_CMakeLists_txt.h"
#include "template_README_md.h"
#include "template_scene_c.h"
#include "template_scene_cl.h"
#include "template_text_scene_cl.h"
#include "util/atomic_file.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

struct TemplateFile {
    const char* text;
    std::string name;  // in the new project, placeholders filled
};

// An empty directory may be replaced; anything else in the way is refused.
void check_target(const fs::path& directory) {
    std::error_code error;
    if (!fs::exists(directory, error)) return;
    if (!fs::is_directory(directory, error) || !fs::is_empty(directory, error)) {
        throw UsageError(
            fmt::format("'{}' already exists and is not an empty directory", directory.string()));
    }
}

// Removes the temporary directory unless the project was moved into place.
struct TemporaryDirectory {
    fs::path path;
    bool committed = false;
    ~TemporaryDirectory() {
        std::error_code ignored;
        if (!committed) fs::remove_all(path, ignored);
    }
};

}  // namespace

ScaffoldNames scaffold_names(const std::string& id) {
    if (!is_scene_id(id)) {
        throw UsageError(fmt::format(
            "scene name '{}' must be a scene id: a lowercase letter, then lowercase letters, "
            "digits, '-' or '_' (at most {})",
            id, scene_limits::kMaxIdLength));
    }
    ScaffoldNames names{id, id, ""};
    for (char& c : names.symbol) c = c == '-' ? '_' : c;
    bool word_start = true;
    for (const char c : id) {
        if (c == '-' || c == '_') {
            names.display_name += ' ';
            word_start = true;
        } else {
            names.display_name += word_start ? static_cast<char>(std::toupper(c)) : c;
            word_start = false;
        }
    }
    return names;
}

std::string fill_template(const std::string& text,
                          const std::vector<std::pair<std::string, std::string>>& values) {
    std::string out = text;
    for (const auto& [key, value] : values) {
        const std::string placeholder = "@" + key + "@";
        for (std::size_t at = out.find(placeholder); at != std::string::npos;
             at = out.find(placeholder, at + value.size())) {
            out.replace(at, placeholder.size(), value);
        }
    }
    return out;
}

fs::path scaffold_text_scene(const std::string& id, const fs::path& directory) {
    const ScaffoldNames names = scaffold_names(id);
    std::error_code error;
    if (!fs::is_directory(directory, error)) {
        throw UsageError(fmt::format("'{}' is not a directory", directory.string()));
    }
    const fs::path file = directory / (names.id + ".cl");
    if (fs::exists(fs::symlink_status(file, error))) {
        throw UsageError(fmt::format("'{}' already exists", file.string()));
    }
    write_text_file_atomically(
        file, fill_template(template_text_scene_cl,
                            {{"SCENE_ID", names.id}, {"SCENE_NAME", names.display_name}}));
    return file;
}

std::vector<fs::path> scaffold_scene(const std::string& id, const fs::path& directory,
                                     const fs::path& fgr_prefix) {
    const ScaffoldNames names = scaffold_names(id);
    check_target(directory);
    const std::vector<std::pair<std::string, std::string>> values = {
        {"SCENE_ID", names.id},
        {"SCENE_SYMBOL", names.symbol},
        {"SCENE_NAME", names.display_name},
        {"FGR_PREFIX", fgr_prefix.string()}};
    const std::vector<TemplateFile> files = {{template_CMakeLists_txt, "CMakeLists.txt"},
                                             {template_scene_c, names.symbol + ".c"},
                                             {template_scene_cl, names.symbol + ".cl"},
                                             {template_README_md, "README.md"}};

    const fs::path parent = directory.has_parent_path() ? directory.parent_path() : ".";
    std::error_code error;
    fs::create_directories(parent, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot create '{}': {}", parent.string(), error.message()));
    }
    TemporaryDirectory staging{parent / (directory.filename().string() + ".tmp-new-scene")};
    fs::remove_all(staging.path, error);
    fs::create_directory(staging.path, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot create '{}': {}", staging.path.string(), error.message()));
    }
    std::vector<fs::path> written;
    for (const TemplateFile& file : files) {
        write_text_file_atomically(staging.path / file.name, fill_template(file.text, values));
        written.push_back(directory / file.name);
    }
    if (fs::exists(directory)) fs::remove(directory, error);  // checked empty above
    fs::rename(staging.path, directory, error);
    if (error) {
        throw std::runtime_error(
            fmt::format("cannot create '{}': {}", directory.string(), error.message()));
    }
    staging.committed = true;
    return written;
}

}  // namespace fgr
