// SPDX-License-Identifier: Apache-2.0
#pragma once
// Building a test kernel on top of the kernel library, so device-side helpers (the sampler, the
// BSDFs, the environment) are tested as the kernels run them: at each packet width and precision,
// not through a host re-typing of the same formulas.

#include <string>
#include <string_view>

#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"

namespace fgr::test {

// The prelude (types, lane-safe maths, vec3, SDF toolkit...), the layouts the host shares
// (shared/fgr_layout_*.h), then the path library (fgr_sampler.cl, fgr_bsdf.cl,
// fgr_environment.cl), then `test_source`, built with the switches a render at `packet_width`
// and `double_precision` gets. Throws KernelBuildError with the log.
cl::Program build_library_test_program(const ComputeDevice& device, ProgramCache& cache,
                                       std::string_view test_source, int packet_width,
                                       bool double_precision);

// The same source as one string (for reading what was built).
std::string library_test_source(std::string_view test_source);

}  // namespace fgr::test
