// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where the running test case keeps fgr's kernel cache: a fresh directory of its own, which
// ProgramCache::default_directory() (FGR_CACHE_DIR) names too. See hermetic_caches.cpp.

#include <filesystem>

namespace fgr::test {

const std::filesystem::path& test_kernel_cache();

// Removes this process's kernel cache and points FGR_CACHE_DIR at a fresh one: what each test case
// starts with when several share a process.
void start_fresh_kernel_cache();

}  // namespace fgr::test
