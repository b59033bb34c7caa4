// SPDX-License-Identifier: Apache-2.0
#pragma once
// The frame counts and times `fgr view --stats` prints on exit. Private to fgr_viewer.

#include "viewer/frame_stats.hpp"
#include "viewer/render_worker.hpp"

namespace fgr::viewer {

class ViewerStatistics {
public:
    // One pass of the window thread's loop took `ms`.
    void add_window_frame(double ms) { window_frames_.add(ms); }
    void add_shown_frame(const DisplayFrame& frame);
    long frames_shown() const { return frames_shown_; }
    // The lines frames_shown, render_ms, ui_frame_ms and preview_frames on stdout.
    void print() const;

private:
    FrameStats render_times_;
    FrameStats window_frames_;
    long frames_shown_ = 0;
    int preview_frames_ = 0;  // shown at reduced resolution
    double preview_scale_sum_ = 0.0;
};

}  // namespace fgr::viewer
