#include "fgr/scene_file.hpp"

#include <exception>
#include <string>

#include "fgr/ifs.hpp"
#include "fgr/plugin_loader.hpp"

namespace fgr {

bool is_scene_file_name(const std::filesystem::path& file) {
    return file.extension() == ".so" || is_ifs_file_name(file);
}

LoadResult load_ifs_scene(const std::filesystem::path& file) {
    try {
        return LoadResult{ifs_scene_to_scene(read_ifs_file(file), file), {}};
    } catch (const IfsError& error) {
        std::string reason = error.what();
        const std::string prefix = file.string() + ": ";
        if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
        return LoadResult{std::nullopt, reason};
    } catch (const std::exception& error) {
        return LoadResult{std::nullopt, std::string("loading failed: ") + error.what()};
    }
}

LoadResult load_scene_file(const std::filesystem::path& file) {
    return is_ifs_file_name(file) ? load_ifs_scene(file) : load_scene_plugin(file);
}

LoadResult reload_scene_file(const std::filesystem::path& file) {
    return is_ifs_file_name(file) ? load_ifs_scene(file) : reload_scene_plugin(file);
}

}  // namespace fgr
