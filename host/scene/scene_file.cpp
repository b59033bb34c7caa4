#include "scene/scene_file.hpp"

#include <exception>
#include <string>

#include "scene/formulas/formulas.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/plugin_loader.hpp"

namespace fgr {

bool is_scene_file_name(const std::filesystem::path& file) {
    return file.extension() == ".so" || is_ifs_file_name(file) || is_formula_file_name(file);
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
        const std::string prefix = file.string() + ": ";
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

LoadResult load_scene_file(const std::filesystem::path& file) {
    if (is_ifs_file_name(file)) return load_ifs_scene(file);
    if (is_formula_file_name(file)) return load_formula_scene(file);
    return load_scene_plugin(file);
}

LoadResult reload_scene_file(const std::filesystem::path& file) {
    if (is_ifs_file_name(file)) return load_ifs_scene(file);
    if (is_formula_file_name(file)) return load_formula_scene(file);
    return reload_scene_plugin(file);
}

}  // namespace fgr
