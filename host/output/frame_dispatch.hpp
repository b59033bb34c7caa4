// SPDX-License-Identifier: Apache-2.0
#pragma once
// Frames of one job rendered somewhere and handed back in order: the frames of a video, the seeds
// of a still. Where they are rendered is the dispatch's business: this process, or the ranks of an
// MPI job (distributed/frame_farm.hpp), so a job's loop is written once for both.

#include <cstdint>
#include <functional>
#include <vector>

#include "render/renderer.hpp"

namespace fgr {

// Renders task `task` (a frame's index, a seed's number) on whichever process is given it; may
// throw, which ends the job.
using FrameWork = std::function<Frame(int64_t task)>;
// Takes task `task`'s frame, in the order the tasks were listed.
using FrameSink = std::function<void(int64_t task, Frame&& frame)>;

class FrameDispatch {
public:
    virtual ~FrameDispatch() = default;

    // Whether this process is handed the frames: false on an MPI job's workers, which render what
    // they are given and write nothing.
    virtual bool receives() const = 0;

    // Renders `tasks` (consecutive numbers, in order) with `work` and hands each frame to `sink`
    // in that order. Returns false when `interrupted` (polled, when set) stopped it before every
    // frame was handed over. On a process that does not receive, it renders what it is given and
    // returns true without calling `sink`. Throws what `work` or `sink` throw.
    virtual bool run(const std::vector<int64_t>& tasks, const FrameWork& work,
                     const FrameSink& sink, const std::function<bool()>& interrupted) = 0;
};

}  // namespace fgr
