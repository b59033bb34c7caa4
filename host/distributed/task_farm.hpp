// SPDX-License-Identifier: Apache-2.0
#pragma once
// Work shared out over the ranks of a Cluster, as a farm: rank 0 hands tasks out in order to
// whichever rank asks next (so a slow rank or a slow task holds no one else up) and gathers the
// results; every other rank pulls a task, renders it, sends the result and pulls the next. Rank 0
// renders too, on a second thread, while its main thread schedules and writes.

#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "distributed/cluster.hpp"

namespace fgr {

// Renders task `task` into bytes (on any rank); may throw, which ends the job.
using TaskWork = std::function<std::vector<uint8_t>(int64_t task)>;
// Rank 0: takes the result of `task`, in the order results arrive (not task order).
using ResultSink = std::function<void(int64_t task, std::vector<uint8_t>&& result)>;

struct FarmSettings {
    // At most this many tasks handed out beyond the oldest unfinished one: bounds what rank 0
    // keeps while it waits for a slow task (0: four per rank).
    int window = 0;
    // Rank 0: polled; true stops handing out tasks (the farm then returns interrupted).
    std::function<bool()> interrupted{};
    // Rank 0 renders tasks too, besides scheduling and writing. The environment variable
    // FGR_MPI_RANK0_RENDERS=0 turns that off: for a rank 0 on a node of its own, or to see that
    // the workers alone give the same result (the tests).
    bool coordinator_renders = coordinator_renders_by_default();

    static bool coordinator_renders_by_default();
};

// What a farm did (rank 0's view).
struct FarmOutcome {
    bool finished = false;            // every result went to the sink (not interrupted)
    std::vector<long> tasks_by_rank;  // results each rank delivered
};

// Results that arrive in any order handed on in task order (first, first + 1, ...): frames into
// a video, seeds into a sum that must come out the same run to run. Holds the early ones.
class InTaskOrder {
public:
    explicit InTaskOrder(ResultSink next, int64_t first = 0)
        : next_(std::move(next)), expected_(first) {}
    void add(int64_t task, std::vector<uint8_t>&& result);
    int64_t delivered_up_to() const { return expected_; }  // the next task to hand on
    size_t held() const { return early_.size(); }

private:
    ResultSink next_;
    std::map<int64_t, std::vector<uint8_t>> early_;
    int64_t expected_;
};

// "0:7 1:6 2:7": the tasks each rank rendered, for the figures a command prints.
std::string tasks_by_rank_text(const FarmOutcome& outcome);

// Thrown on rank 0 when a worker failed; the message names the rank and its host.
struct RankFailure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Thrown on rank 0 when a worker on its node ended without a word (killed, crashed:
// Cluster::vanished_worker), also when rank 0 was stopped meanwhile (mpirun ends the job when a
// rank dies): the rank's death, not the stop, is what to report.
struct RankLost : RankFailure {
    using RankFailure::RankFailure;
};

// Runs `tasks` (ids, handed out in this order) over every rank of `cluster`. Rank 0 returns when
// every result went to `sink` (finished) or `interrupted` stopped it; workers return when rank 0
// has no more tasks for them. Throws RankFailure (rank 0) for a failed worker, RankLost for one
// whose process is gone; whatever
// `work` or `sink` throws propagates on the rank it was thrown on.
FarmOutcome run_farm(Cluster& cluster, const std::vector<int64_t>& tasks, const TaskWork& work,
                     const ResultSink& sink, const FarmSettings& settings = {});

}  // namespace fgr
