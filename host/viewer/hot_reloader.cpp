// SPDX-License-Identifier: Apache-2.0
#include "viewer/hot_reloader.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "scene/discovery.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_source.hpp"
#include "util/strings.hpp"

namespace fgr::viewer {
namespace {

// How often plugin folders (and in --dev mode scene sources) are checked for changes.
constexpr double kWatchSeconds = 0.5;

}  // namespace

HotReloader::HotReloader(SceneSet& scenes, bool dev, ReloadHost host)
    : scenes_(scenes), dev_(dev), host_(std::move(host)) {}

void HotReloader::watch() {
    for (const auto& directory : plugin_search_path(executable_dir())) {
        watcher_.watch_directory(directory);
    }
    for (size_t i = 0; i < scenes_.size(); ++i) {
        const Scene& scene = *scenes_.at(i);
        // A scene file opened by path may be outside the plugin folders. (One inside is reported
        // once: the watcher keys files by path.)
        if (!scene.plugin_file.empty()) watcher_.watch_file(scene.plugin_file);
        // A scene built with fgr_add_scene_plugin names its .cl file by absolute path.
        if (dev_) {
            if (const auto source = recorded_source_file(scene); source) {
                watcher_.watch_file(*source);
                spdlog::info("watching {} for '{}'", source->string(), scene.id);
            }
        }
    }
    watcher_.poll();  // what is there now is what was loaded
}

void HotReloader::poll(double now_seconds) {
    if (now_seconds < next_poll_) return;
    next_poll_ = now_seconds + kWatchSeconds;
    for (const std::filesystem::path& file : watcher_.poll()) {
        if (is_scene_file(file) || holds_a_scene(file)) {
            reload_plugin(file);
        } else if (dev_) {
            reload_source(file);  // other .cl files in plugin folders count only with --dev
        }
    }
}

bool HotReloader::holds_a_scene(const std::filesystem::path& file) const {
    // A text scene whose header was broken is no longer a scene file by its first bytes, but it
    // is still the file of a scene on screen: reloading it says what is wrong.
    for (size_t i = 0; i < scenes_.size(); ++i) {
        if (scenes_.at(i)->plugin_file == file && is_scene_file_name(file)) return true;
    }
    return false;
}

void HotReloader::reload_plugin(const std::filesystem::path& file) {
    // A plugin from a fresh copy (a library still loaded under this path would come back as it
    // was), an IFS, formula or text scene file read again.
    LoadResult loaded = reload_scene_file(file);
    if (!loaded.scene) {
        const std::string message = fmt::format("{}: {} (keeping the version loaded before)",
                                                printable_path(file), printable_text(loaded.error));
        spdlog::error("{}", message);
        host_.add_message(message);
        host_.show_refused(message, "");
        ++changes_handled_;
        return;
    }
    auto candidate = std::make_shared<const Scene>(std::move(*loaded.scene));
    const std::optional<size_t> same_id = scenes_.find(candidate->id);
    if (!same_id) {
        spdlog::info("new scene '{}' from {}", candidate->id, printable_path(file));
        host_.add_message(fmt::format("new scene '{}'", candidate->id));
        scenes_.add(candidate);
        // An IFS scene's source is generated, not a file to watch.
        if (dev_ && !candidate->ifs) {
            if (const auto source = recorded_source_file(*candidate); source) {
                watcher_.watch_file(*source);
            }
        }
        ++changes_handled_;
        return;
    }
    const std::shared_ptr<const Scene>& running = scenes_.at(*same_id);
    if (running->plugin_file != candidate->plugin_file) {
        spdlog::warn("{}: scene '{}' is already loaded from {}; ignored", printable_path(file),
                     candidate->id, printable_path(running->plugin_file));
        ++changes_handled_;
        return;
    }
    const SceneSession* session = scenes_.session_of(*same_id);
    const uint64_t effects = session ? session->effects : candidate->effects;
    spdlog::info("{} changed: building the new '{}'", printable_path(file), candidate->id);
    host_.build({candidate, running, effects});
}

void HotReloader::reload_source(const std::filesystem::path& file) {
    std::string text;
    try {
        text = read_source_file(file);
    } catch (const std::runtime_error& error) {
        host_.add_message(error.what());
        ++changes_handled_;
        return;
    }
    for (size_t i = 0; i < scenes_.size(); ++i) {
        if (scenes_.at(i)->source_name != file.string()) continue;
        Scene edited = *scenes_.at(i);
        edited.source = text;
        const SceneSession* session = scenes_.session_of(i);
        const uint64_t effects = session ? session->effects : edited.effects;
        spdlog::info("{} changed: building the new '{}'", printable_path(file), edited.id);
        host_.build({std::make_shared<const Scene>(std::move(edited)), scenes_.at(i), effects});
    }
}

void HotReloader::apply(const std::vector<ReloadResult>& results) {
    for (const ReloadResult& result : results) {
        ++changes_handled_;
        if (host_.claim_edit(result)) continue;
        const std::optional<size_t> running = scenes_.index_of(result.request.replaces);
        if (!running) continue;  // replaced again meanwhile
        const std::string& id = result.request.candidate->id;
        if (!result.ok) {
            const std::string message = fmt::format(
                "update of '{}' refused, keeping the previous version: {}", id, result.error);
            spdlog::error("{}", message);
            host_.add_message(message);
            host_.show_refused(message, result.error_log);
            continue;
        }
        host_.adopt_scene(*running, result.request.candidate);
        host_.clear_refused();
        spdlog::info("reloaded '{}'", id);
        host_.add_message(fmt::format("reloaded '{}'", id));
    }
}

}  // namespace fgr::viewer
