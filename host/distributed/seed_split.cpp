// SPDX-License-Identifier: Apache-2.0
#include "distributed/seed_split.hpp"

#include <fmt/format.h>

#include <numeric>
#include <stdexcept>

#include "output/parts/frame_merge.hpp"
#include "render/sample_budget.hpp"

namespace fgr {

std::vector<int64_t> SeedSplit::task_list() const {
    std::vector<int64_t> list(static_cast<size_t>(tasks));
    std::iota(list.begin(), list.end(), int64_t{0});
    return list;
}

FrameRequest SeedSplit::task_request(const FrameRequest& request, int64_t task) const {
    FrameRequest part = request;
    part.samples = samples_each;
    part.path.seed = seed(task);
    return part;
}

SeedSplit split_by_seed(const FrameRequest& request, RenderMode mode, int tasks) {
    if (tasks < 1) {
        throw std::invalid_argument(fmt::format("cannot split a render into {} tasks", tasks));
    }
    if (!sample_budget(mode).seeded) {
        throw std::invalid_argument(
            fmt::format("the {} mode takes the same samples whatever the seed: its renders cannot "
                        "be split by seed",
                        render_mode_name(mode)));
    }
    return SeedSplit{request.path.seed, tasks, request.samples};
}

std::optional<Frame> render_by_seed(const SeedSplit& split, const FrameRequest& request,
                                    const std::function<Frame(const FrameRequest&)>& render,
                                    FrameDispatch& dispatch) {
    const FrameWork work = [&](int64_t task) { return render(split.task_request(request, task)); };
    Frame sum;
    const FrameSink add = [&](int64_t, Frame&& frame) { add_samples(sum, frame); };
    const bool finished = dispatch.run(split.task_list(), work, add, {});
    if (!dispatch.receives()) return std::nullopt;
    if (!finished) throw std::runtime_error("interrupted before every seed was rendered");
    return sum;
}

}  // namespace fgr
