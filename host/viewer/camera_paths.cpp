// SPDX-License-Identifier: Apache-2.0
#include "viewer/camera_paths.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "camera/camera.hpp"
#include "scene/parameters.hpp"
#include "viewer/viewer_util.hpp"

namespace fgr::viewer {

CameraPaths::CameraPaths(SceneSet& scenes, const std::optional<std::filesystem::path>& file,
                         std::filesystem::path output_dir,
                         std::function<void(std::string)> add_message)
    : scenes_(scenes), output_dir_(std::move(output_dir)), add_message_(std::move(add_message)) {
    if (!file) return;
    try {
        loaded_path_ = read_camera_path_file(*file);
    } catch (const std::runtime_error& error) {
        throw UsageError(error.what());
    }
}

std::vector<CameraPath> CameraPaths::playable() const {
    std::vector<CameraPath> paths = scenes_.current().camera_paths;
    const SceneSession& session = scenes_.session();
    if (session.recorded.keyframes.size() >= 2) paths.push_back(session.recorded);
    if (loaded_path_) {
        paths.push_back(loaded_path_->path);
        paths.back().name = "file: " + loaded_path_->path.name;
    }
    return paths;
}

void CameraPaths::select(const std::string& name) {
    const std::vector<CameraPath> paths = playable();
    std::string names;
    for (size_t i = 0; i < paths.size(); ++i) {
        if (paths[i].name == name) {
            scenes_.session().path_index = static_cast<int>(i);
            return;
        }
        names += (names.empty() ? "" : ", ") + paths[i].name;
    }
    throw UsageError(fmt::format("scene '{}' has no camera path '{}' (its paths: {})",
                                 scenes_.current().id, name, names.empty() ? "none" : names));
}

void CameraPaths::toggle_playback() {
    if (playing_) {
        playing_ = false;
        return;
    }
    if (playable().empty()) {
        add_message_("no camera path to play: record one with K");
        return;
    }
    playing_ = true;
    playback_time_ = 0.0;
}

void CameraPaths::advance(double dt) {
    if (!playing_) return;
    const std::vector<CameraPath> paths = playable();
    if (paths.empty()) {
        playing_ = false;
        return;
    }
    SceneSession& session = scenes_.session();
    const CameraPath& path =
        paths[static_cast<size_t>(std::clamp(session.path_index, 0, int(paths.size()) - 1))];
    playback_time_ += dt;
    if (playback_time_ > path.duration()) {
        if (!loop_) playing_ = false;
        playback_time_ =
            loop_ ? std::fmod(playback_time_, double(path.duration())) : double(path.duration());
    }
    const CameraView view =
        evaluate_camera_path(path, path.keyframes.front().time + float(playback_time_));
    session.camera = FlyCamera::from_view(view);
}

void CameraPaths::record_keyframe() {
    SceneSession& session = scenes_.session();
    CameraPath& recorded = session.recorded;
    const float time =
        recorded.keyframes.empty() ? 0.0f : recorded.keyframes.back().time + keyframe_interval_;
    recorded.keyframes.push_back({time, session.camera.to_view()});
    add_message_(fmt::format("keyframe {} at {:.1f} s", recorded.keyframes.size(), time));
}

void CameraPaths::save_recorded() {
    const std::string& scene_id = scenes_.current().id;
    const CameraPath& recorded = scenes_.session().recorded;
    if (recorded.keyframes.size() < 2) {
        add_message_("record at least two keyframes (K) before saving");
        return;
    }
    const auto file = output_dir_ / fmt::format("fgr-path-{}-{}.json", scene_id, file_timestamp());
    try {
        write_camera_path_file(file, {scene_id, recorded});
    } catch (const std::runtime_error& error) {
        spdlog::error("{}", error.what());
        add_message_(error.what());
        return;
    }
    spdlog::info(
        "saved camera path {} ({} keyframes, {:.1f} s); render it with `fgr render {} "
        "--camera-path {} --time T`",
        file.string(), recorded.keyframes.size(), recorded.duration(), scene_id, file.string());
    add_message_(fmt::format("saved {}", file.string()));
}

}  // namespace fgr::viewer
