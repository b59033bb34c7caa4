// SPDX-License-Identifier: Apache-2.0
#pragma once
// Plays a replay script (`fgr view --replay FILE`, replay.hpp) into the viewer: input events go
// to SDL's queue as if the user made them, the browser's and the hybrid editor's events to those
// parts, and a wait holds the script until what it waits for has happened. Private to
// fgr_viewer.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "viewer/replay.hpp"

namespace fgr::viewer {

// What a replayed script asks of the viewer.
struct ReplayHost {
    std::function<std::pair<int, int>()> window_size;  // in screen coordinates
    std::function<uint32_t()> window_id;               // SDL's, for the events pushed
    std::function<void(int width, int height)> resize_window;
    std::function<bool()> view_idle;        // wait_idle
    std::function<bool()> thumbnails_done;  // wait_thumbnails
    // wait_samples: the samples (passes) of the frame on screen if it is full size, else 0.
    std::function<int()> full_size_samples;
    // wait_frames: the frames shown so far, previews included.
    std::function<long()> frames_shown;
    // wait_reload: the count of changes to watched files dealt with so far.
    std::function<uint64_t()> changes_handled;
    std::function<void()> quit;
    std::function<void(const ReplayEvent&)> browser_event;  // browser_search, browser_pick
    std::function<void(const ReplayEvent&)> editor_event;   // hybrid_*
    std::function<void(const std::string& assignment)> set_parameter;  // set ID=VALUE
};

class ReplayDriver {
public:
    // Reads the script and checks its keys and formulas, so that a typo fails before a window
    // opens (UsageError, "FILE:LINE: reason").
    static std::vector<ReplayEvent> load(const std::filesystem::path& file);

    ReplayDriver(std::vector<ReplayEvent> events, ReplayHost host);

    // Pushes the events due at `now_seconds` (a monotonic clock; the first call starts the
    // script), unless a wait holds them.
    void feed(double now_seconds);
    // A replayed resize asked for a size the window does not have yet: the view is not idle.
    bool window_size_pending() const;

private:
    // Whether what the wait the script is held at names has not happened yet.
    bool still_waiting() const;
    void push(const ReplayEvent& event);
    void push_key(const ReplayEvent& event);
    void push_mouse(const ReplayEvent& event);

    ReplayClock clock_;
    ReplayHost host_;
    bool thumbnails_awaited_ = false;  // wait_thumbnails is holding the script
    // The count of changes dealt with when wait_reload began: the script goes on once it grows.
    std::optional<uint64_t> awaited_changes_;
    // The samples wait_samples holds the script for, until the frame on screen has them.
    std::optional<int> awaited_samples_;
    // The count of frames shown that wait_frames holds the script for.
    std::optional<long> awaited_frames_;
    // The window size the last resize asked for, until the next wait is over.
    std::optional<std::pair<int, int>> window_size_;
};

}  // namespace fgr::viewer
