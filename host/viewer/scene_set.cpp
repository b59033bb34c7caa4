// SPDX-License-Identifier: Apache-2.0
#include "viewer/scene_set.hpp"

#include <algorithm>
#include <utility>

#include "scene/parameters.hpp"

namespace fgr::viewer {

SceneSession default_session(const Scene& scene) {
    SceneSession session;
    session.camera = FlyCamera::from_view(scene.cameras.front().view);
    session.params = default_param_values(scene);
    session.effects = scene.effects;
    return session;
}

SceneSet::SceneSet(std::vector<Scene> scenes) {
    for (Scene& scene : scenes) scenes_.push_back(std::make_shared<const Scene>(std::move(scene)));
}

std::optional<size_t> SceneSet::find(const std::string& id) const {
    const auto found = std::find_if(scenes_.begin(), scenes_.end(),
                                    [&](const auto& scene) { return scene->id == id; });
    if (found == scenes_.end()) return std::nullopt;
    return static_cast<size_t>(found - scenes_.begin());
}

std::optional<size_t> SceneSet::index_of(const std::shared_ptr<const Scene>& version) const {
    const auto found = std::find(scenes_.begin(), scenes_.end(), version);
    if (found == scenes_.end()) return std::nullopt;
    return static_cast<size_t>(found - scenes_.begin());
}

SceneSession* SceneSet::session_of(size_t index) {
    const auto found = sessions_.find(static_cast<int>(index));
    return found == sessions_.end() ? nullptr : &found->second;
}

const SceneSession* SceneSet::session_of(size_t index) const {
    const auto found = sessions_.find(static_cast<int>(index));
    return found == sessions_.end() ? nullptr : &found->second;
}

void SceneSet::select(int index) {
    current_ = index;
    if (!sessions_.count(index)) sessions_[index] = default_session(current());
}

void SceneSet::select(int index, SceneSession session) {
    current_ = index;
    sessions_[index] = std::move(session);
}

void SceneSet::add(std::shared_ptr<const Scene> scene) { scenes_.push_back(std::move(scene)); }

void SceneSet::replace(size_t index, std::shared_ptr<const Scene> scene) {
    const std::shared_ptr<const Scene> old = std::exchange(scenes_.at(index), scene);
    SceneSession* session = session_of(index);
    if (session == nullptr) return;
    session->params = carry_param_values(*old, session->params, *scene);
    if (session->effects == old->effects) session->effects = scene->effects;
    const int cameras = static_cast<int>(scene->cameras.size());
    session->camera_index = std::min(session->camera_index, cameras - 1);
}

}  // namespace fgr::viewer
