// SPDX-License-Identifier: Apache-2.0
#pragma once
// Camera paths in the viewer: the current scene's own, the one recorded with K and the file given
// with --camera-path; playing the selected one (P) and recording keyframes. Private to fgr_viewer.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "scene/scene.hpp"
#include "viewer/scene_set.hpp"

namespace fgr::viewer {

class CameraPaths {
public:
    // Reads `file` when there is one (a UsageError when it cannot). Saved paths go to
    // `output_dir`; what the user should know goes to `add_message`.
    CameraPaths(SceneSet& scenes, const std::optional<std::filesystem::path>& file,
                std::filesystem::path output_dir, std::function<void(std::string)> add_message);

    // The current scene's paths, its own first, then the recorded one (from two keyframes) and
    // the file's.
    std::vector<CameraPath> playable() const;
    // Selects the current scene's path `name` for P (UsageError naming the paths).
    void select(const std::string& name);

    bool playing() const { return playing_; }
    double playback_time() const { return playback_time_; }  // seconds into the playing path
    void toggle_playback();
    // The user took the camera (or chose another scene, camera or path).
    void stop() { playing_ = false; }
    // Moves the current scene's camera `dt` seconds along the selected path while playing.
    void advance(double dt);
    bool loop() const { return loop_; }
    void set_loop(bool loop) { loop_ = loop; }

    // Appends the current view to the recorded path, keyframe_interval() after the last one.
    void record_keyframe();
    float keyframe_interval() const { return keyframe_interval_; }
    void set_keyframe_interval(float seconds) { keyframe_interval_ = seconds; }
    // Writes the recorded path as <output dir>/fgr-path-<scene>-<time>.json.
    void save_recorded();

private:
    SceneSet& scenes_;
    std::optional<CameraPathFile> loaded_path_;  // --camera-path's
    std::filesystem::path output_dir_;
    std::function<void(std::string)> add_message_;
    bool playing_ = false;
    bool loop_ = true;
    double playback_time_ = 0.0;
    float keyframe_interval_ = 2.0f;
};

}  // namespace fgr::viewer
