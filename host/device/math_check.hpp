// SPDX-License-Identifier: Apache-2.0
#pragma once
// The device math self-test: before fgr renders at a (precision, packet width) on a device, the
// OpenCL built-ins its kernels use run on vectors of that width with edge lanes (0, -0,
// denormals, +-Inf, NaN beside ordinary values) and every lane is compared with the host's libm.
// A vector built-in can be wrong where the scalar one is right (Debian's PoCL AVX-512 library
// computes double8/double16 pow, pown and frexp with a mis-sized lane mask, so an edge lane
// corrupts another lane), and a broken pair is replaced by a narrower width that passes.
// Verdicts are cached per device, driver and PoCL kernel library: in memory, and as small files
// beside the program cache.

#include <functional>
#include <string>
#include <vector>

#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"

namespace fgr {

struct MathCheckReport {
    bool double_precision = false;
    int packet_width = 1;
    int lanes_checked = 0;
    // One line per failing built-in, e.g. "pow: lane 2 of (0.3, 0.3, 0, ...) gave nan, libm 0.01"
    // (the first failing lane of each).
    std::vector<std::string> failures;
    bool passed() const { return failures.empty(); }
};

// The self-test's program at this width and precision: the library's types and lane-safe maths,
// then the check kernels (fgr_math_check.cl), with the switches a render there gets.
AssembledProgram math_check_program(bool double_precision, int packet_width);

// Runs the self-test now (no cached verdict is used or stored). Throws KernelBuildError when the
// check kernel does not compile, std::runtime_error when double is asked of a device without it.
// `extra_options` are added to the check kernel's build options (tests plant a fault with
// -DFGR_CHECK_SWAP_EXP_LANES to show the check catches one).
MathCheckReport run_math_check(const ComputeDevice& device, ProgramCache& cache,
                               bool double_precision, int packet_width,
                               const std::string& extra_options = "");

// The verdict for one (precision, width): from memory, else from the cache directory, else by
// running the check (and storing its verdict). "" when the device's built-ins pass, else a
// one-line summary of what failed.
std::string math_check_verdict(const ComputeDevice& device, ProgramCache& cache,
                               bool double_precision, int packet_width);

// The widest packet width not above `requested` (the widths fgr builds: 16, 8, 4, 1; double
// needs at least 4) whose built-ins pass the self-test. When `requested` fails, `warn` gets one
// line naming the device, the broken pair, what failed and the width used instead. When no width
// passes, `requested` is kept and `warn` says so.
int trusted_packet_width(const ComputeDevice& device, ProgramCache& cache, bool double_precision,
                         int requested, const std::function<void(const std::string&)>& warn);

}  // namespace fgr
