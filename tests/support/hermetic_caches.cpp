// Keeps the tests off the user's caches. Before main() runs (and so before OpenCL, Mesa or any
// test reads them), this process's environment points:
//   - fgr's kernel cache (FGR_CACHE_DIR) at a fresh directory of its own, removed at exit, so no
//     test sees a binary or a math verdict another run left behind;
//   - the drivers' caches (XDG_CACHE_HOME, POCL_CACHE_DIR: PoCL's compiled kernels, Mesa's shaders
//     under the viewer tests) at FGR_TEST_DRIVER_CACHE (the build tree's test-cache/ unless CMake
//     was told otherwise). PoCL keys its entries by source and options; a cold one costs about
//     8 s per kernel, far too much to pay in every test process.
// Child processes (fgr render, fgr view, the SDK script) inherit all of it: nothing under ~/.cache.
#include "hermetic_caches.hpp"

#include <cstdlib>
#include <filesystem>

#include "child_process.hpp"

namespace fgr::test {
namespace {

struct HermeticCaches {
    HermeticCaches() {
        const std::filesystem::path drivers = FGR_TEST_DRIVER_CACHE;
        setenv("XDG_CACHE_HOME", drivers.c_str(), 1);
        setenv("POCL_CACHE_DIR", (drivers / "pocl").c_str(), 1);
        unsetenv("MESA_SHADER_CACHE_DIR");  // Mesa then uses XDG_CACHE_HOME
        setenv("FGR_CACHE_DIR", (kernels.path() / "kernels").c_str(), 1);
    }
    TempDir kernels{"fgr_test_cache"};
};

const HermeticCaches caches;

}  // namespace

const std::filesystem::path& test_kernel_cache() {
    static const std::filesystem::path directory = caches.kernels.path() / "kernels";
    return directory;
}

}  // namespace fgr::test
