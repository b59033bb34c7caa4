// SPDX-License-Identifier: Apache-2.0
#pragma once
// The viewer's hot reload: watching the plugin folders and the scenes' files (and with --dev the
// scenes' .cl sources), having the render thread build a new version of a scene that changed, and
// swapping it in once it has built; a version that fails to build is refused and the running one
// stays. Private to fgr_viewer.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "viewer/file_watcher.hpp"
#include "viewer/render_worker.hpp"
#include "viewer/scene_set.hpp"

namespace fgr::viewer {

// What hot reload asks of the viewer.
struct ReloadHost {
    std::function<void(ReloadRequest)> build;  // on the render thread, before it replaces anything
    // The hybrid editor's builds come back with the reloads: true when it took `result` as its own.
    std::function<bool(const ReloadResult& result)> claim_edit;
    // The built version takes the place of scene `index`.
    std::function<void(size_t index, std::shared_ptr<const Scene> scene)> adopt_scene;
    // Shows why an update was refused (summary, compiler log) until one is adopted.
    std::function<void(std::string summary, std::string log)> show_refused;
    std::function<void()> clear_refused;
    std::function<void(std::string)> add_message;
};

class HotReloader {
public:
    HotReloader(SceneSet& scenes, bool dev, ReloadHost host);

    // Starts watching; what is there now is what was loaded.
    void watch();
    // Looks for changed files twice a second (`now_seconds`: a monotonic clock) and asks for a
    // build of each scene that changed.
    void poll(double now_seconds);
    // Adopts what the render thread built, or says why it refused.
    void apply(const std::vector<ReloadResult>& results);
    // Changes to watched files dealt with so far: reloaded, refused, added, failed to load.
    uint64_t changes_handled() const { return changes_handled_; }

private:
    // Whether `file` is the scene file of a scene in the set.
    bool holds_a_scene(const std::filesystem::path& file) const;
    void reload_plugin(const std::filesystem::path& file);
    void reload_source(const std::filesystem::path& file);

    SceneSet& scenes_;
    bool dev_;
    ReloadHost host_;
    FileWatcher watcher_;
    double next_poll_ = 0.0;
    uint64_t changes_handled_ = 0;
};

}  // namespace fgr::viewer
