// SPDX-License-Identifier: Apache-2.0
#include "scene/scene_file.hpp"

#include <exception>
#include <string>

#include "scene/formulas/formulas.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/text_scene.hpp"
#include "util/strings.hpp"

namespace fgr {

std::optional<SceneFileKind> scene_file_kind(const std::filesystem::path& file) {
    if (file.extension() == ".so") return SceneFileKind::Plugin;
    if (is_ifs_file_name(file)) return SceneFileKind::Ifs;
    if (is_formula_file_name(file)) return SceneFileKind::Formula;
    if (is_text_scene_file_name(file)) return SceneFileKind::Text;
    return std::nullopt;
}

bool is_scene_file_name(const std::filesystem::path& file) {
    return scene_file_kind(file).has_value();
}

bool is_scene_file(const std::filesystem::path& file) {
    const std::optional<SceneFileKind> kind = scene_file_kind(file);
    return kind && (kind != SceneFileKind::Text || is_text_scene_file(file));
}

namespace {

// A scene read from a data file by `load` (which throws FileError, "<file>: reason", for a bad
// file): the reason without the file's name in front (LoadResult's convention: callers add it).
template <typename FileError, typename Load>
LoadResult load_data_scene(const std::filesystem::path& file, Load load) {
    try {
        return LoadResult{load(), {}};
    } catch (const FileError& error) {
        std::string reason = error.what();
        const std::string prefix = printable_path(file) + ": ";
        if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
        return LoadResult{std::nullopt, reason};
    } catch (const std::exception& error) {
        return LoadResult{std::nullopt, std::string("loading failed: ") + error.what()};
    }
}

}  // namespace

LoadResult load_ifs_scene(const std::filesystem::path& file) {
    return load_data_scene<IfsError>(file,
                                     [&] { return ifs_scene_to_scene(read_ifs_file(file), file); });
}

LoadResult load_formula_scene(const std::filesystem::path& file) {
    return load_data_scene<FormulaError>(
        file, [&] { return formula_scene_to_scene(read_formula_file(file), file); });
}

namespace {

// The data files' scenes (read afresh every time); nothing for a plugin.
std::optional<LoadResult> load_data_file(const std::filesystem::path& file) {
    switch (scene_file_kind(file).value_or(SceneFileKind::Plugin)) {
        case SceneFileKind::Ifs:
            return load_ifs_scene(file);
        case SceneFileKind::Formula:
            return load_formula_scene(file);
        case SceneFileKind::Text:
            return load_text_scene(file);
        case SceneFileKind::Plugin:
            break;
    }
    return std::nullopt;
}

}  // namespace

LoadResult load_scene_file(const std::filesystem::path& file) {
    if (std::optional<LoadResult> data = load_data_file(file)) return std::move(*data);
    return load_scene_plugin(file);
}

LoadResult reload_scene_file(const std::filesystem::path& file) {
    if (std::optional<LoadResult> data = load_data_file(file)) return std::move(*data);
    return reload_scene_plugin(file);
}

}  // namespace fgr
