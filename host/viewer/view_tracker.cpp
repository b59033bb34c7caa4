// SPDX-License-Identifier: Apache-2.0
#include "viewer/view_tracker.hpp"

#include <utility>

namespace fgr::viewer {
namespace {

// Whether `next` renders the image `last` did. Every field counts but the two that this answer
// decides: the generation it gets and whether it is interactive.
bool same_image_inputs(ViewState next, const ViewState& last) {
    next.generation = last.generation;
    next.interactive = last.interactive;
    return next == last;
}

}  // namespace

ViewState ViewTracker::track(ViewState state, double now_seconds, bool playing) {
    if (!tracked_ || !same_image_inputs(state, last_)) {
        ++generation_;
        last_change_ = now_seconds;
    }
    state.generation = generation_;
    state.interactive = playing || now_seconds - last_change_ < kSettleSeconds;
    last_ = state;
    tracked_ = true;
    scene_replaced_ = false;
    return state;
}

bool ViewTracker::refined(const WorkerStatus& status) const {
    return status.idle && status.idle_generation == generation_ && !status.compiling &&
           status.pending_screenshots == 0 && status.pending_reloads == 0 && !last_.interactive &&
           !scene_replaced_;
}

}  // namespace fgr::viewer
