// SPDX-License-Identifier: Apache-2.0
#pragma once
// One still shared out by seed, for a mode whose samples differ with the seed (the path tracer,
// SampleBudget::seeded): task t renders the whole image with the job's samples per pixel and seed
// `seed + t`, and the frames are added up in task order with their sample counts
// (output/parts/frame_merge.hpp). N tasks give N times the samples, the same estimator as one
// render that took them all, and the same image run to run whichever rank rendered which task.
// Under MPI each rank takes one task.

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "output/frame_dispatch.hpp"
#include "render/renderer.hpp"
#include "scene/render_mode.hpp"

namespace fgr {

struct SeedSplit {
    uint32_t first_seed = 0;  // task 0's: the job's seed
    int tasks = 1;
    int samples_each = 1;  // per pixel, in every task

    uint32_t seed(int64_t task) const { return first_seed + static_cast<uint32_t>(task); }
    uint32_t last_seed() const { return seed(tasks - 1); }
    // Samples per pixel of the sum: every task's.
    int samples() const { return samples_each * tasks; }
    // The tasks' numbers, 0 .. tasks - 1.
    std::vector<int64_t> task_list() const;
    // `request` as task `task` renders it: its seed.
    FrameRequest task_request(const FrameRequest& request, int64_t task) const;
};

// `request` (its samples and seed, in `mode`) split into `tasks`. Throws std::invalid_argument
// when tasks < 1, or when `mode` takes the same samples whatever the seed (the tasks would repeat
// each other's samples: such a still is shared out in tiles instead).
SeedSplit split_by_seed(const FrameRequest& request, RenderMode mode, int tasks);

// Renders each task of `split` through `dispatch` (render(split.task_request(request, t))) and adds
// the frames up in task order: the sum on the process that receives them (no display image, no
// time), nullopt elsewhere. Throws std::runtime_error when the dispatch was interrupted, and what
// rendering or adding throws.
std::optional<Frame> render_by_seed(const SeedSplit& split, const FrameRequest& request,
                                    const std::function<Frame(const FrameRequest&)>& render,
                                    FrameDispatch& dispatch);

}  // namespace fgr
