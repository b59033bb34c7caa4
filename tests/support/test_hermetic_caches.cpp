// SPDX-License-Identifier: Apache-2.0
// The cases of a group share a process, never a kernel cache: each finds its own empty, whichever
// ran before it (the two cases below are one suite, so one group: one process, in this order).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "hermetic_caches.hpp"

namespace fgr::test {
namespace {

// Checks the running case's kernel cache is FGR_CACHE_DIR and empty, then leaves a file in it.
void expect_an_empty_kernel_cache_and_leave_a_file() {
    const std::filesystem::path cache = test_kernel_cache();
    const char* variable = std::getenv("FGR_CACHE_DIR");
    ASSERT_NE(variable, nullptr);
    EXPECT_EQ(std::filesystem::path(variable), cache);
    EXPECT_TRUE(!std::filesystem::exists(cache) || std::filesystem::is_empty(cache)) << cache;
    std::filesystem::create_directories(cache);
    std::ofstream(cache / "left_behind") << "a previous case's entry";
}

TEST(HermeticCaches, EachCaseStartsWithAnEmptyKernelCache) {
    expect_an_empty_kernel_cache_and_leave_a_file();
}

TEST(HermeticCaches, TheNextCaseInTheSameProcessStartsEmptyToo) {
    expect_an_empty_kernel_cache_and_leave_a_file();
}

}  // namespace
}  // namespace fgr::test
