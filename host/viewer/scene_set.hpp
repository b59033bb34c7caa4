// SPDX-License-Identifier: Apache-2.0
#pragma once
// The scenes the viewer can show, the one it shows, and what the user made of each scene shown so
// far: its session. Hot reload and the hybrid editor replace a scene by a new version of it; the
// session then carries over. Private to fgr_viewer.

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "viewer/fly_camera.hpp"

namespace fgr::viewer {

// Per-scene state, remembered while the viewer runs.
struct SceneSession {
    FlyCamera camera;
    std::vector<float> params;
    uint64_t effects = 0;
    int camera_index = 0;
    int path_index = 0;  // into CameraPaths::playable()
    CameraPath recorded{"recorded", {}};
};

// The scene's default camera, parameters and effects.
SceneSession default_session(const Scene& scene);

class SceneSet {
public:
    explicit SceneSet(std::vector<Scene> scenes);

    size_t size() const { return scenes_.size(); }
    const std::shared_ptr<const Scene>& at(size_t index) const { return scenes_.at(index); }
    // The index of the scene `id`.
    std::optional<size_t> find(const std::string& id) const;
    // The index of the scene whose running version is `version`; none once it was replaced.
    std::optional<size_t> index_of(const std::shared_ptr<const Scene>& version) const;

    int current_index() const { return current_; }
    const std::shared_ptr<const Scene>& current_ptr() const { return at(size_t(current_)); }
    const Scene& current() const { return *current_ptr(); }
    SceneSession& session() { return sessions_.at(current_); }
    const SceneSession& session() const { return sessions_.at(current_); }
    // The session of scene `index`; null while the scene was never shown.
    SceneSession* session_of(size_t index);
    const SceneSession* session_of(size_t index) const;

    // Shows scene `index`, its session starting from the scene's defaults the first time.
    void select(int index);
    // Shows scene `index` with `session` (the first scene, as the command line sets it up).
    void select(int index, SceneSession session);

    void add(std::shared_ptr<const Scene> scene);
    // The new version takes the old one's place; its session keeps the camera and every parameter
    // that still exists, and follows the scene's effects unless the user had changed them.
    void replace(size_t index, std::shared_ptr<const Scene> scene);

private:
    std::vector<std::shared_ptr<const Scene>> scenes_;
    int current_ = 0;
    std::map<int, SceneSession> sessions_;
};

}  // namespace fgr::viewer
