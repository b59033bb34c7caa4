// SPDX-License-Identifier: Apache-2.0
// Each test case starts with a fresh kernel cache of its own (hermetic_caches.hpp), also when the
// cases of a group share a process (tests/CMakeLists.txt), so that no case sees a binary or a math
// verdict another left behind, in whatever order or company it runs.
#include <gtest/gtest.h>

#include "hermetic_caches.hpp"

namespace fgr::test {
namespace {

class FreshKernelCachePerCase : public ::testing::EmptyTestEventListener {
    void OnTestStart(const ::testing::TestInfo&) override { start_fresh_kernel_cache(); }
};

// Before main(): gtest_main's RUN_ALL_TESTS then calls it before each case. gtest owns it.
[[maybe_unused]] const bool listener_registered = [] {
    ::testing::UnitTest::GetInstance()->listeners().Append(new FreshKernelCachePerCase);
    return true;
}();

}  // namespace
}  // namespace fgr::test
