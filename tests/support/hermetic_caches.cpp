// SPDX-License-Identifier: Apache-2.0
// Keeps the tests off the user's caches. Before main() runs (and so before OpenCL, Mesa or any
// test reads them), this process's environment points:
//   - fgr's kernel cache (FGR_CACHE_DIR) at a fresh directory of its own, removed at exit, so no
//     test sees a binary or a math verdict another run left behind;
//   - the drivers' caches (XDG_CACHE_HOME, POCL_CACHE_DIR: PoCL's compiled kernels, Mesa's shaders
//     under the viewer tests) at FGR_TEST_DRIVER_CACHE (the build tree's test-cache/ unless CMake
//     was told otherwise). PoCL keys its entries by source and options; a cold one costs about
//     8 s per kernel, far too much to pay in every test process.
// Child processes (fgr render, fgr view, the SDK script) inherit all of it: nothing under ~/.cache.
// The test cases that share a process (tests/CMakeLists.txt runs them in groups) each start with
// a fresh kernel cache of their own (fresh_kernel_cache_per_case.cpp).
#include "hermetic_caches.hpp"

#include <cstdlib>
#include <filesystem>
#include <memory>

#include "child_process.hpp"

namespace fgr::test {
namespace {

struct HermeticCaches {
    HermeticCaches() {
        const std::filesystem::path drivers = FGR_TEST_DRIVER_CACHE;
        setenv("XDG_CACHE_HOME", drivers.c_str(), 1);
        setenv("POCL_CACHE_DIR", (drivers / "pocl").c_str(), 1);
        unsetenv("MESA_SHADER_CACHE_DIR");  // Mesa then uses XDG_CACHE_HOME
        start_fresh_kernels();
    }
    void start_fresh_kernels() {
        kernels.reset();  // the last one removed first
        kernels = std::make_unique<TempDir>("fgr_test_cache");
        kernel_cache = kernels->path() / "kernels";
        setenv("FGR_CACHE_DIR", kernel_cache.c_str(), 1);
    }
    std::unique_ptr<TempDir> kernels;
    std::filesystem::path kernel_cache;
};

HermeticCaches caches;

}  // namespace

const std::filesystem::path& test_kernel_cache() { return caches.kernel_cache; }

void start_fresh_kernel_cache() { caches.start_fresh_kernels(); }

}  // namespace fgr::test
