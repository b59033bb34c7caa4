// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_argument.hpp"

#include <fmt/format.h>

#include <array>
#include <fstream>
#include <system_error>

#include "scene/discovery.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/text_scene.hpp"
#include "util/strings.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

SceneArgumentKind argument_kind_of(SceneFileKind kind) {
    switch (kind) {
        case SceneFileKind::Plugin:
            return SceneArgumentKind::PluginFile;
        case SceneFileKind::Ifs:
            return SceneArgumentKind::IfsFile;
        case SceneFileKind::Formula:
            return SceneArgumentKind::FormulaFile;
        case SceneFileKind::Text:
            return SceneArgumentKind::TextFile;
    }
    return SceneArgumentKind::PluginFile;
}

bool is_elf_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::array<char, 4> magic{};
    in.read(magic.data(), magic.size());
    return in.gcount() == 4 && magic == std::array<char, 4>{'\x7f', 'E', 'L', 'F'};
}

}  // namespace

SceneArgumentKind scene_argument_kind(const std::string& argument) {
    const fs::path path = argument;
    std::error_code error;
    const bool is_file = !argument.empty() && fs::is_regular_file(path, error);
    if (const std::optional<SceneFileKind> kind = scene_file_kind(path)) {
        // "mandelbulb.cl" without the file is still a path: ids have no dots.
        return argument_kind_of(*kind);
    }
    if (!is_file && argument.find('/') == std::string::npos) return SceneArgumentKind::Id;
    if (is_file && is_elf_file(path)) return SceneArgumentKind::PluginFile;
    if (is_file && file_has_text_scene_header(path)) return SceneArgumentKind::TextFile;
    throw UsageError(
        fmt::format("{}: {}: fgr opens scene plugins (*.so), IFS files (*.ifs.json), formula files "
                    "(*.formula.json) and text scenes (*.cl), or a scene id (`fgr list`)",
                    printable_text(argument), is_file ? "not a scene file" : "no such file"));
}

Scene load_scene_argument_file(const fs::path& file, SceneArgumentKind kind) {
    LoadResult loaded;
    switch (kind) {
        case SceneArgumentKind::Id:
            throw UsageError(fmt::format("{} is a scene id, not a file", quoted(file)));
        case SceneArgumentKind::PluginFile:
            // dlopen searches the library path for a name without a '/'.
            loaded = load_scene_plugin(file.has_parent_path() ? file : fs::path(".") / file);
            if (loaded.scene) loaded.scene->plugin_file = file;
            break;
        case SceneArgumentKind::IfsFile:
            loaded = load_ifs_scene(file);
            break;
        case SceneArgumentKind::FormulaFile:
            loaded = load_formula_scene(file);
            break;
        case SceneArgumentKind::TextFile:
            loaded = load_text_scene(file);
            break;
    }
    if (!loaded.scene) {
        throw UsageError(fmt::format("{}: {}", printable_path(file), printable_text(loaded.error)));
    }
    return std::move(*loaded.scene);
}

Scene find_scene_argument(const std::string& argument, const std::vector<fs::path>& directories,
                          const fs::path& index_file) {
    const SceneArgumentKind kind = scene_argument_kind(argument);
    if (kind != SceneArgumentKind::Id) return load_scene_argument_file(argument, kind);
    Discovery found = discover_scene(directories, argument, index_file);
    for (Scene& scene : found.scenes) {
        if (scene.id == argument) return std::move(scene);
    }
    throw UsageError(unknown_scene_message(found, argument));
}

}  // namespace fgr
