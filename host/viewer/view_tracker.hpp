// SPDX-License-Identifier: Apache-2.0
#pragma once
// The views the window thread hands to the render thread. A change of anything that decides the
// image starts a new generation, on which the render thread restarts refinement; a view counts as
// interactive (previews, no refinement) while it keeps changing. Private to fgr_viewer.

#include <cstdint>

#include "viewer/render_worker.hpp"

namespace fgr::viewer {

// How long the view counts as moving after its last change: mouse look arrives in bursts, and
// refining between two bursts would only be cancelled again.
constexpr double kSettleSeconds = 0.15;

class ViewTracker {
public:
    // `state` with its generation and interactivity decided at `now_seconds` (a monotonic
    // clock); `playing`: a camera path is moving the view.
    ViewState track(ViewState state, double now_seconds, bool playing);
    const ViewState& last() const { return last_; }

    // A reload replaced a scene: the view is not refined until the next one is tracked.
    void scene_replaced() { scene_replaced_ = true; }
    // Whether the render thread reports the last view tracked fully refined, and nothing else
    // (a build, a screenshot, a reload) pending.
    bool refined(const WorkerStatus& status) const;

private:
    ViewState last_;
    bool tracked_ = false;
    double last_change_ = -1e9;
    uint64_t generation_ = 0;
    bool scene_replaced_ = false;
};

}  // namespace fgr::viewer
