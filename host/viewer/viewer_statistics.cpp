// SPDX-License-Identifier: Apache-2.0
#include "viewer/viewer_statistics.hpp"

#include <fmt/format.h>

namespace fgr::viewer {

void ViewerStatistics::add_shown_frame(const DisplayFrame& frame) {
    render_times_.add(frame.render_ms);
    if (frame.scale < 1.0f) {
        ++preview_frames_;
        preview_scale_sum_ += frame.scale;
    }
    ++frames_shown_;
}

void ViewerStatistics::print() const {
    fmt::print("frames_shown {}\n", frames_shown_);
    fmt::print("{}\n", format_summary("render_ms", render_times_.summary()));
    fmt::print("{}\n", format_summary("ui_frame_ms", window_frames_.summary()));
    fmt::print("preview_frames {} mean_scale {:.3f}\n", preview_frames_,
               preview_frames_ ? preview_scale_sum_ / preview_frames_ : 1.0);
}

}  // namespace fgr::viewer
