// The viewer's hot reload: watching plugin folders and scene sources, and swapping in a new
// version of a scene once the render thread has built it.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "fgr/discovery.hpp"
#include "fgr/parameters.hpp"
#include "fgr/scene_file.hpp"
#include "fgr/scene_source.hpp"
#include "viewer_app.hpp"

namespace fgr::viewer {
namespace {

// How often plugin folders (and in --dev mode scene sources) are checked for changes.
constexpr double kWatchSeconds = 0.5;

}  // namespace

// --- Hot reload --------------------------------------------------------------------------------

void ViewerApp::watch_sources() {
    for (const auto& directory : plugin_search_path(executable_dir())) {
        watcher_.watch_directory(directory);
    }
    if (options_.dev) {
        // A scene built with fgr_add_scene_plugin names its .cl file by absolute path.
        for (size_t i = 0; i < scenes_.size(); ++i) {
            const Scene& scene = *scenes_.at(i);
            const std::filesystem::path source = scene.source_name;
            if (source.is_absolute() && std::filesystem::exists(source)) {
                watcher_.watch_file(source);
                spdlog::info("watching {} for '{}'", source.string(), scene.id);
            }
        }
    }
    watcher_.poll();  // what is there now is what was loaded
}

void ViewerApp::poll_sources() {
    const double now = seconds_since(start_);
    if (now < next_watch_) return;
    next_watch_ = now + kWatchSeconds;
    for (const std::filesystem::path& file : watcher_.poll()) {
        if (is_scene_file_name(file)) {
            reload_plugin(file);
        } else {
            reload_source(file);
        }
    }
}

void ViewerApp::reload_plugin(const std::filesystem::path& file) {
    // A plugin from a fresh copy (a library still loaded under this path would come back as it
    // was), an IFS file read again.
    LoadResult loaded = reload_scene_file(file);
    if (!loaded.scene) {
        const std::string message =
            fmt::format("{}: {} (keeping the version loaded before)", file.string(), loaded.error);
        spdlog::error("{}", message);
        add_message(message);
        reload_error_ = {message, ""};
        ++watched_changes_handled_;
        return;
    }
    auto candidate = std::make_shared<const Scene>(std::move(*loaded.scene));
    const std::optional<size_t> same_id = scenes_.find(candidate->id);
    if (!same_id) {
        spdlog::info("new scene '{}' from {}", candidate->id, file.string());
        add_message(fmt::format("new scene '{}'", candidate->id));
        scenes_.add(candidate);
        // An IFS scene's source is generated, not a file to watch.
        if (options_.dev && !candidate->ifs) watcher_.watch_file(candidate->source_name);
        ++watched_changes_handled_;
        return;
    }
    const std::shared_ptr<const Scene>& running = scenes_.at(*same_id);
    if (running->plugin_file != candidate->plugin_file) {
        spdlog::warn("{}: scene '{}' is already loaded from {}; ignored", file.string(),
                     candidate->id, running->plugin_file.string());
        ++watched_changes_handled_;
        return;
    }
    const SceneSession* session = scenes_.session_of(*same_id);
    const uint64_t effects = session ? session->effects : candidate->effects;
    spdlog::info("{} changed: building the new '{}'", file.string(), candidate->id);
    worker_->request_reload({candidate, running, effects});
}

void ViewerApp::reload_source(const std::filesystem::path& file) {
    std::string text;
    try {
        text = read_source_file(file);
    } catch (const std::runtime_error& error) {
        add_message(error.what());
        ++watched_changes_handled_;
        return;
    }
    for (size_t i = 0; i < scenes_.size(); ++i) {
        if (scenes_.at(i)->source_name != file.string()) continue;
        Scene edited = *scenes_.at(i);
        edited.source = text;
        const SceneSession* session = scenes_.session_of(i);
        const uint64_t effects = session ? session->effects : edited.effects;
        spdlog::info("{} changed: building the new '{}'", file.string(), edited.id);
        worker_->request_reload(
            {std::make_shared<const Scene>(std::move(edited)), scenes_.at(i), effects});
    }
}

void ViewerApp::apply_reloads() {
    for (const ReloadResult& result : worker_->take_reloads()) {
        ++watched_changes_handled_;
        if (adopt_hybrid_edit(result)) continue;
        const std::optional<size_t> running = scenes_.index_of(result.request.replaces);
        if (!running) continue;  // replaced again meanwhile
        const std::string& id = result.request.candidate->id;
        if (!result.ok) {
            const std::string message = fmt::format(
                "update of '{}' refused, keeping the previous version: {}", id, result.error);
            spdlog::error("{}", message);
            add_message(message);
            reload_error_ = {message, result.error_log};
            continue;
        }
        adopt_scene(*running, result.request.candidate);
        reload_error_ = {};
        spdlog::info("reloaded '{}'", id);
        add_message(fmt::format("reloaded '{}'", id));
    }
}

void ViewerApp::adopt_scene(size_t index, const std::shared_ptr<const Scene>& scene) {
    scenes_.replace(index, scene);
    view_.scene_replaced();
}

}  // namespace fgr::viewer
