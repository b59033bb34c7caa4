// SPDX-License-Identifier: Apache-2.0
// A plugin's embedded scene source against its recorded .cl file (scene/scene_source.hpp).
#include "scene/scene_source.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <system_error>

#include "scene/scene_limits.hpp"
#include "util/files.hpp"
#include "util/strings.hpp"

namespace fgr {

std::optional<std::filesystem::path> recorded_source_file(const Scene& scene) {
    if (scene.ifs) return std::nullopt;  // an IFS scene's source is generated
    const std::filesystem::path file = scene.source_name;
    std::error_code error;
    // A text scene's source is its own file, by the path it was opened by.
    const bool own_file = !scene.plugin_file.empty() && file == scene.plugin_file;
    if (!(file.is_absolute() || own_file) || !std::filesystem::is_regular_file(file, error)) {
        return std::nullopt;
    }
    return file;
}

std::string read_source_file(const std::filesystem::path& file) {
    std::string text;
    if (const std::string failure = read_file_bytes(file, text, scene_limits::kMaxSourceBytes);
        !failure.empty()) {
        throw std::runtime_error(fmt::format("cannot read {}: {}", printable_path(file), failure));
    }
    return text;
}

std::string stale_source_warning(const Scene& scene) {
    const auto file = recorded_source_file(scene);
    if (!file || scene.plugin_file.empty()) return "";
    std::error_code error;
    const auto source_time = std::filesystem::last_write_time(*file, error);
    if (error) return "";
    const auto plugin_time = std::filesystem::last_write_time(scene.plugin_file, error);
    // Only a file edited after the build counts: an older one that differs is what a checkout of
    // another version gives, and the plugin may well be right.
    if (error || source_time <= plugin_time) return "";
    std::string on_disk;
    try {
        on_disk = read_source_file(*file);
    } catch (const std::runtime_error&) {
        return "";
    }
    if (on_disk == scene.source) return "";  // saved again unchanged
    return fmt::format(
        "{} changed after {} was built: rebuild the plugin (and copy it again if "
        "you copied it), or use --dev to read {} from disk",
        file->filename().string(), scene.plugin_file.filename().string(),
        file->filename().string());
}

Scene with_source_from_disk(const Scene& scene) {
    const auto file = recorded_source_file(scene);
    if (!file) {
        throw std::runtime_error(fmt::format(
            "--dev: scene '{}' records no .cl file to read (its source name is '{}'; plugins "
            "built with fgr_add_scene_plugin record their .cl file's absolute path)",
            scene.id, scene.source_name));
    }
    return with_source_file(scene, *file);
}

Scene with_source_file(const Scene& scene, const std::filesystem::path& file) {
    Scene edited = scene;
    edited.source = read_source_file(file);
    edited.source_name = file.string();
    return edited;
}

}  // namespace fgr
