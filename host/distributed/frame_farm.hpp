// SPDX-License-Identifier: Apache-2.0
#pragma once
// A FrameDispatch over the ranks of a Cluster: the frames are the farm's tasks
// (distributed/task_farm.hpp), cross between ranks as bytes (distributed/frame_wire.hpp) and reach
// rank 0's sink in task order, whichever rank finished first. A cluster of one process renders
// them one after another.

#include <cstdint>
#include <functional>
#include <vector>

#include "distributed/cluster.hpp"
#include "distributed/task_farm.hpp"
#include "output/frame_dispatch.hpp"

namespace fgr {

class FarmFrameDispatch final : public FrameDispatch {
public:
    // Keeps a reference to `cluster`.
    explicit FarmFrameDispatch(Cluster& cluster, FarmSettings settings = {});

    bool receives() const override { return cluster_.coordinator(); }
    bool run(const std::vector<int64_t>& tasks, const FrameWork& work, const FrameSink& sink,
             const std::function<bool()>& interrupted) override;

    // What the last run's farm did (rank 0): the tasks each rank rendered, for the figures.
    const FarmOutcome& outcome() const { return outcome_; }
    // The rank the last run lost (RankLost's message), "" when none: the video reports it
    // rather than the interruption that followed.
    const std::string& lost() const { return lost_; }

private:
    Cluster& cluster_;
    FarmSettings settings_;
    FarmOutcome outcome_;
    std::string lost_;
};

}  // namespace fgr
