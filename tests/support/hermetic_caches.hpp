#pragma once
// Where this test process keeps fgr's kernel cache: a fresh directory of its own, which
// ProgramCache::default_directory() (FGR_CACHE_DIR) names too. See hermetic_caches.cpp.

#include <filesystem>

namespace fgr::test {

const std::filesystem::path& test_kernel_cache();

}  // namespace fgr::test
