// SPDX-License-Identifier: Apache-2.0
#include "distributed/frame_farm.hpp"

#include <utility>

#include "distributed/frame_wire.hpp"

namespace fgr {

FarmFrameDispatch::FarmFrameDispatch(Cluster& cluster, FarmSettings settings)
    : cluster_(cluster), settings_(std::move(settings)) {}

bool FarmFrameDispatch::run(const std::vector<int64_t>& tasks, const FrameWork& work,
                            const FrameSink& sink, const std::function<bool()>& interrupted) {
    const TaskWork bytes_of = [&](int64_t task) { return frame_to_bytes(work(task)); };
    if (!cluster_.coordinator()) {
        outcome_ = run_farm(cluster_, {}, bytes_of, {});
        return true;
    }
    InTaskOrder in_order(
        [&](int64_t task, std::vector<uint8_t>&& bytes) { sink(task, frame_from_bytes(bytes)); },
        tasks.empty() ? 0 : tasks.front());
    const ResultSink collect = [&](int64_t task, std::vector<uint8_t>&& bytes) {
        in_order.add(task, std::move(bytes));
    };
    FarmSettings settings = settings_;
    if (interrupted) settings.interrupted = interrupted;
    try {
        outcome_ = run_farm(cluster_, tasks, bytes_of, collect, settings);
    } catch (const RankLost& error) {
        lost_ = error.what();
        throw;
    }
    return outcome_.finished;
}

}  // namespace fgr
