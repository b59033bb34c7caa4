// SPDX-License-Identifier: Apache-2.0
// The device math self-test: it passes where the built-ins are right, it catches a built-in that
// corrupts one lane, its verdict is cached on disk, and a broken (precision, width) pair is
// replaced by a narrower width that passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device/math_check.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"

namespace fgr {
namespace {

class MathCheckTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { device_ = new ComputeDevice(open_device(-1)); }
    static void TearDownTestSuite() { delete device_; }

    std::vector<bool> precisions() const {
        std::vector<bool> list{false};
        if (device_->info.has_fp64) list.push_back(true);
        return list;
    }

    static ComputeDevice* device_;
    ProgramCache cache_{std::filesystem::path()};
};
ComputeDevice* MathCheckTest::device_ = nullptr;

// Width 1 and float lanes are the reference every other width is trusted against: a device whose
// scalar built-ins were wrong would need a fix in fgr, not a narrower packet.
TEST_F(MathCheckTest, ScalarAndFloatBuiltinsPass) {
    for (int width : {1, 4, 8, 16}) {
        const MathCheckReport report = run_math_check(*device_, cache_, false, width);
        EXPECT_TRUE(report.passed()) << "float" << width << ": " << report.failures.front();
        // 13 built-ins, each with ordinary cases and one case per edge value per lane.
        EXPECT_GT(report.lanes_checked, 13 * 7 * width * width);
    }
}

// A built-in that swaps two lanes' results on one function is caught, and named.
TEST_F(MathCheckTest, CatchesABuiltinThatCorruptsALane) {
    for (bool double_precision : precisions()) {
        for (int width : {4, 16}) {
            const MathCheckReport report = run_math_check(*device_, cache_, double_precision, width,
                                                          "-DFGR_CHECK_SWAP_EXP_LANES");
            ASSERT_FALSE(report.passed());
            ASSERT_EQ(report.failures.size(), 1u) << report.failures.front();
            EXPECT_EQ(report.failures.front().rfind("exp: lane 0 of", 0), 0u)
                << report.failures.front();
        }
    }
}

// Whatever the device, the width a render gets is one whose built-ins passed, and never wider
// than asked.
TEST_F(MathCheckTest, TrustedWidthPassesTheCheck) {
    for (bool double_precision : precisions()) {
        for (int requested : {4, 8, 16}) {
            std::vector<std::string> warnings;
            const int width =
                trusted_packet_width(*device_, cache_, double_precision, requested,
                                     [&](const std::string& line) { warnings.push_back(line); });
            EXPECT_LE(width, requested);
            const MathCheckReport report =
                run_math_check(*device_, cache_, double_precision, width);
            EXPECT_TRUE(report.passed()) << report.failures.front();
            EXPECT_EQ(warnings.size(), width == requested ? 0u : 1u);
            if (width != requested) {
                EXPECT_NE(warnings.front().find("math self-test"), std::string::npos);
            }
        }
    }
}

// The verdict is stored beside the program cache, and a cache directory that holds one is
// believed instead of re-running the check: a planted "fail" verdict reaches the caller.
TEST_F(MathCheckTest, VerdictIsCachedOnDisk) {
    test::TempDir first("fgr-math-check");
    ProgramCache first_cache(first.path());
    EXPECT_EQ(math_check_verdict(*device_, first_cache, false, 4), "");
    std::vector<std::filesystem::path> verdicts;
    for (const auto& entry : std::filesystem::directory_iterator(first.path())) {
        if (entry.path().extension() == ".txt") verdicts.push_back(entry.path());
    }
    ASSERT_EQ(verdicts.size(), 1u);
    EXPECT_EQ(test::read_file(verdicts.front()), "pass\n");

    test::TempDir second("fgr-math-check");
    std::ofstream(second.path() / verdicts.front().filename()) << "fail: exp: planted\n";
    ProgramCache second_cache(second.path());
    EXPECT_EQ(math_check_verdict(*device_, second_cache, false, 4), "exp: planted");
    std::vector<std::string> warnings;
    EXPECT_EQ(trusted_packet_width(*device_, second_cache, false, 4,
                                   [&](const std::string& line) { warnings.push_back(line); }),
              1);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings.front().rfind("float4 built-ins", 0), 0u) << warnings.front();
    EXPECT_NE(warnings.front().find("using 1-ray packets"), std::string::npos) << warnings.front();
}

}  // namespace
}  // namespace fgr
