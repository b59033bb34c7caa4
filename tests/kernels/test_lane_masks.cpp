// SPDX-License-Identifier: Apache-2.0
// fgr_any and fgr_all (kernels/core/fgr_types.cl), which every march loop tests once per step, at
// every packet width and precision (double from 4 lanes, as renders use it): a vector lane counts
// as true when its top bit is set (as the built-in any() and all() read it), a scalar when it is
// non-zero. Each case puts one edge value (all ones, the top bit alone, the low bit alone, every
// bit but the top one, zero) in one lane of a packet whose other lanes are all false or all true,
// so a fold that drops or misreads a lane shows.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "device_suite.hpp"
#include "kernel_test_program.hpp"
#include "render/precision.hpp"

namespace fgr {
namespace {

constexpr const char* kMaskTestKernel = R"CL(
typedef FGR_LANES(int, long) mask_scalar;
__kernel void lane_mask_test(__global const mask_scalar* lanes, __global int* out) {
    const int c = get_global_id(0);
#if FGR_WIDTH == 1
    const mask m = lanes[c];
#else
    const mask m = FGR_PASTE(vload, FGR_WIDTH)(c, lanes);
#endif
    out[2 * c] = fgr_any(m) ? 1 : 0;
    out[2 * c + 1] = fgr_all(m) ? 1 : 0;
}
)CL";

class LaneMaskTest : public test::DeviceSuite<> {
protected:
    // Runs the cases (width lanes each) through the kernel; returns any, all for each case.
    template <typename Lane>
    std::vector<cl_int> run(const std::vector<Lane>& lanes, int width, bool double_precision) {
        cl::Program program;
        try {
            program = test::build_library_test_program(*device_, *cache_, kMaskTestKernel, width,
                                                       double_precision);
        } catch (const KernelBuildError& error) {
            ADD_FAILURE() << "width " << width << (double_precision ? " double" : " float") << ": "
                          << error.what() << "\n"
                          << error.build_log();
            throw;
        }
        const size_t cases = lanes.size() / size_t(width);
        cl::Buffer in(device_->context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                      lanes.size() * sizeof(Lane), const_cast<Lane*>(lanes.data()));
        cl::Buffer out(device_->context, CL_MEM_WRITE_ONLY, cases * 2 * sizeof(cl_int));
        cl::Kernel kernel(program, "lane_mask_test");
        kernel.setArg(0, in);
        kernel.setArg(1, out);
        device_->queue.enqueueNDRangeKernel(kernel, cl::NullRange, cl::NDRange(cases));
        std::vector<cl_int> result(cases * 2);
        device_->queue.enqueueReadBuffer(out, CL_TRUE, 0, result.size() * sizeof(cl_int),
                                         result.data());
        return result;
    }

    template <typename Lane>
    void check(int width, bool double_precision) {
        const Lane top = std::numeric_limits<Lane>::min();  // the top bit alone
        const std::vector<Lane> edges{Lane(-1), top, Lane(1), std::numeric_limits<Lane>::max(),
                                      Lane(0)};
        // A lane is true for the vector forms when its top bit is set, for a scalar when non-zero.
        auto is_true = [&](Lane v) { return width == 1 ? v != 0 : v < 0; };
        std::vector<Lane> lanes;
        std::vector<cl_int> expected;
        for (Lane background : {Lane(0), Lane(-1)}) {
            for (Lane edge : edges) {
                for (int at = 0; at < width; ++at) {
                    bool any = false, all = true;
                    for (int lane = 0; lane < width; ++lane) {
                        const Lane v = lane == at ? edge : background;
                        lanes.push_back(v);
                        any = any || is_true(v);
                        all = all && is_true(v);
                    }
                    expected.push_back(any ? 1 : 0);
                    expected.push_back(all ? 1 : 0);
                }
            }
        }
        const std::vector<cl_int> got = run(lanes, width, double_precision);
        ASSERT_EQ(got.size(), expected.size());
        for (size_t i = 0; i < got.size(); ++i) {
            const size_t c = i / 2;
            EXPECT_EQ(got[i], expected[i])
                << (i % 2 ? "fgr_all" : "fgr_any") << " at width " << width
                << (double_precision ? " double" : " float") << ", case " << c << ": lane "
                << c % size_t(width) << " holds " << int64_t(lanes[c * size_t(width) + c % width])
                << " among " << int64_t(lanes[c * size_t(width) + (c + 1) % size_t(width)]);
        }
    }
};

TEST_F(LaneMaskTest, AnyAndAllReadEveryLaneAtEveryWidth) {
    for (int width : {1, 4, 8, 16}) {
        check<cl_int>(width, false);
        // Double runs at least kMinDoublePacketWidth rays per work-item, as renders do.
        if (device_->info.has_fp64 && width >= kMinDoublePacketWidth) check<cl_long>(width, true);
    }
}

}  // namespace
}  // namespace fgr
