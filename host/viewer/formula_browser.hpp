// SPDX-License-Identifier: Apache-2.0
#pragma once
// The formula browser (B): a window of the scenes' thumbnails with a search field; clicking one
// shows it. The thumbnails render on a worker of their own while the view is idle. Private to
// fgr_viewer.

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/formulas/formulas.hpp"
#include "scene/scene.hpp"
#include "viewer/gl_handles.hpp"
#include "viewer/replay.hpp"
#include "viewer/scene_set.hpp"
#include "viewer/thumbnails.hpp"

namespace fgr::viewer {

// What the browser asks of the viewer.
struct BrowserHost {
    // The sequence of scene `index` when it is a formula scene, else null.
    std::function<const FormulaScene*(size_t index)> formula_of;
    std::function<void(int index)> switch_scene;
    std::function<void(std::string)> add_message;
};

class FormulaBrowser {
public:
    FormulaBrowser(const SceneSet& scenes, BrowserHost host);

    // Starts the thumbnails' worker on OpenCL device `device_index`; none are asked for before.
    void start_thumbnails(int device_index, int packet_width);
    // Finishes the thumbnail being made and stops the worker.
    void stop_thumbnails() { thumbnails_.reset(); }

    bool shown() const { return shown_; }
    void toggle() { shown_ = !shown_; }
    // The indices of the scenes the search finds, in order.
    std::vector<size_t> matches();

    // Takes the finished thumbnails into textures; the worker makes more only while the view is
    // idle. Whether a new one arrived (the window needs drawing).
    bool receive_thumbnails(bool view_idle);
    // Whether every scene the browser shows has its thumbnail (or failed to get one).
    bool thumbnails_done();

    void draw_window();
    // browser_search and browser_pick; others are not the browser's.
    void apply_replay_event(const ReplayEvent& event);

private:
    const std::string& thumbnail_key_of(size_t index);
    void draw_browser();
    void draw_thumbnail_cell(size_t index);

    const SceneSet& scenes_;
    BrowserHost host_;
    std::unique_ptr<ThumbnailWorker> thumbnails_;
    bool shown_ = false;
    std::string query_;
    std::map<std::string, std::unique_ptr<ImageTexture>> textures_;  // by thumbnail key
    std::map<std::string, std::string> errors_;                      // by thumbnail key
    // Each scene version's thumbnail key; the entry holds its scene.
    std::map<const Scene*, std::pair<std::shared_ptr<const Scene>, std::string>> keys_;
};

}  // namespace fgr::viewer
