// SPDX-License-Identifier: Apache-2.0
// The buffer a renderer keeps for its frames' planes (render/frame_planes.hpp): both ways of
// reading it back give the host what the device wrote last, as the buffer grows, and when a
// smaller frame reuses a larger one's buffer.

#include <gtest/gtest.h>

#include <numeric>
#include <span>
#include <vector>

#include "render/frame_planes.hpp"
#include "support/device_suite.hpp"

namespace fgr {
namespace {

class FramePlanesTest : public test::DeviceSuite<::testing::TestWithParam<HostView>> {
protected:
    // Writes `count` values from `first` upwards into the reserved buffer, as a kernel would.
    static std::vector<float> write_ramp(const cl::Buffer& buffer, size_t count, float first) {
        std::vector<float> values(count);
        std::iota(values.begin(), values.end(), first);
        device_->queue.enqueueWriteBuffer(buffer, CL_TRUE, 0, sizeof(float) * count, values.data());
        return values;
    }
    static std::vector<float> copied(std::span<const float> values) {
        return {values.begin(), values.end()};
    }
};

TEST_P(FramePlanesTest, TheHostReadsWhatTheDeviceWroteLastAsTheBufferGrowsAndIsReused) {
    FramePlanes planes(*device_, GetParam());
    const size_t small = 1000, large = 300000;  // the large one past any first allocation
    std::vector<float> expected = write_ramp(planes.reserve(small), small, 1.0f);
    EXPECT_EQ(copied(planes.read(small)), expected);

    expected = write_ramp(planes.reserve(large), large, 5.0f);
    EXPECT_EQ(copied(planes.read(large)), expected) << "after growing";

    // A smaller frame in the large buffer, then a part of it: each read sees the latest writes.
    expected = write_ramp(planes.reserve(small), small, -7.0f);
    EXPECT_EQ(copied(planes.read(small)), expected) << "reusing the larger buffer";
    expected = write_ramp(planes.reserve(small / 2), small / 2, 100.0f);
    EXPECT_EQ(copied(planes.read(small / 2)), expected) << "a read after a read";
}

TEST_P(FramePlanesTest, ReservingAgainKeepsTheBufferWhileTheFrameFits) {
    FramePlanes planes(*device_, GetParam());
    const cl::Buffer first = planes.reserve(4096);
    EXPECT_EQ(planes.reserve(4096)(), first());
    EXPECT_EQ(planes.reserve(100)(), first());
    EXPECT_NE(planes.reserve(4097)(), first());
}

TEST(FramePlanes, CpusMapTheBufferAndOtherDevicesStageIt) {
    DeviceInfo cpu;
    cpu.is_cpu = true;
    DeviceInfo gpu;
    gpu.is_gpu = true;
    EXPECT_EQ(FramePlanes::preferred_view(cpu), HostView::Mapped);
    EXPECT_EQ(FramePlanes::preferred_view(gpu), HostView::Staged);
}

INSTANTIATE_TEST_SUITE_P(Views, FramePlanesTest,
                         ::testing::Values(HostView::Mapped, HostView::Staged),
                         [](const auto& instance) {
                             return instance.param == HostView::Mapped ? "Mapped" : "Staged";
                         });

}  // namespace
}  // namespace fgr
