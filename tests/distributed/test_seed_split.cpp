// SPDX-License-Identifier: Apache-2.0
// A still shared out by seed (distributed/seed_split.hpp), as `fgr render --mode path` under
// mpirun shares it, with a stand-in renderer so it runs without a device or MPI: task t renders
// with seed + t and the job's samples, the frames are added in task order weighted by their
// samples, and only a mode whose samples differ with the seed may be split so.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "distributed/cluster.hpp"
#include "distributed/frame_farm.hpp"
#include "distributed/seed_split.hpp"

namespace fgr {
namespace {

FrameRequest path_request(uint32_t seed, int samples) {
    FrameRequest request;
    request.width = 4;
    request.height = 3;
    request.samples = samples;
    request.path.seed = seed;
    return request;
}

TEST(SeedSplit, TaskTTakesTheJobsSeedPlusTAndItsSamples) {
    const SeedSplit split = split_by_seed(path_request(10, 4), RenderMode::Path, 3);
    EXPECT_EQ(split.first_seed, 10u);
    EXPECT_EQ(split.tasks, 3);
    EXPECT_EQ(split.samples_each, 4);
    EXPECT_EQ(split.samples(), 12) << "three ranks give three times the samples";
    EXPECT_EQ(split.task_list(), (std::vector<int64_t>{0, 1, 2}));
    EXPECT_EQ(split.seed(0), 10u);
    EXPECT_EQ(split.seed(2), 12u);
    EXPECT_EQ(split.last_seed(), 12u);
    const FrameRequest task = split.task_request(path_request(10, 4), 1);
    EXPECT_EQ(task.path.seed, 11u);
    EXPECT_EQ(task.samples, 4);
    // Seeds wrap around as the kernel's 32-bit seed does.
    EXPECT_EQ(split_by_seed(path_request(0xffffffffu, 1), RenderMode::Path, 2).last_seed(), 0u);
    // One process alone is one task: the render as it is.
    const SeedSplit alone = split_by_seed(path_request(7, 64), RenderMode::Path, 1);
    EXPECT_EQ(alone.samples(), 64);
    EXPECT_EQ(alone.last_seed(), 7u);
}

TEST(SeedSplit, RefusesModesWhoseSamplesRepeatWhateverTheSeed) {
    EXPECT_THROW(split_by_seed(path_request(0, 1), RenderMode::Shaded, 2), std::invalid_argument);
    EXPECT_THROW(split_by_seed(path_request(0, 16), RenderMode::Brute, 2), std::invalid_argument);
    EXPECT_THROW(split_by_seed(path_request(0, 1), RenderMode::Path, 0), std::invalid_argument);
}

// A frame of `request`'s size whose every linear value is its seed.
Frame seed_frame(const FrameRequest& request) {
    Frame frame;
    frame.image.width = request.width;
    frame.image.height = request.height;
    frame.linear.assign(size_t(request.width) * size_t(request.height) * 3,
                        float(request.path.seed));
    frame.depth.assign(size_t(request.width) * size_t(request.height), 1.0f);
    frame.samples = request.samples;
    frame.hits = 1;
    return frame;
}

TEST(SeedSplit, FramesAreAddedInTaskOrderWeightedByTheirSamples) {
    const FrameRequest request = path_request(10, 4);
    const SeedSplit split = split_by_seed(request, RenderMode::Path, 3);
    std::vector<uint32_t> seeds;
    FarmFrameDispatch dispatch(Cluster::current());
    const std::optional<Frame> sum = render_by_seed(
        split, request,
        [&](const FrameRequest& task) {
            seeds.push_back(task.path.seed);
            EXPECT_EQ(task.samples, 4);
            return seed_frame(task);
        },
        dispatch);
    ASSERT_TRUE(sum);
    EXPECT_EQ(seeds, (std::vector<uint32_t>{10, 11, 12}));
    EXPECT_EQ(sum->samples, 12);
    ASSERT_EQ(sum->linear.size(), size_t(4 * 3 * 3));
    for (float value : sum->linear) EXPECT_FLOAT_EQ(value, 11.0f);  // (10 + 11 + 12) / 3
    EXPECT_EQ(dispatch.outcome().tasks_by_rank, (std::vector<long>{3}));
}

// What a worker rank does: renders what it is handed and returns no frame.
class WorkerDispatch final : public FrameDispatch {
public:
    bool receives() const override { return false; }
    bool run(const std::vector<int64_t>& tasks, const FrameWork& work, const FrameSink&,
             const std::function<bool()>&) override {
        for (int64_t task : tasks) work(task);
        return true;
    }
};

TEST(SeedSplit, AProcessThatOnlyRendersGetsNoSum) {
    const FrameRequest request = path_request(3, 2);
    const SeedSplit split = split_by_seed(request, RenderMode::Path, 2);
    WorkerDispatch worker;
    int rendered = 0;
    const std::optional<Frame> sum = render_by_seed(
        split, request,
        [&](const FrameRequest& task) {
            ++rendered;
            return seed_frame(task);
        },
        worker);
    EXPECT_FALSE(sum);
    EXPECT_EQ(rendered, 2);
}

}  // namespace
}  // namespace fgr
