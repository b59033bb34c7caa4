// SPDX-License-Identifier: Apache-2.0
#pragma once
// The version of the kernel library's API a scene's OpenCL source is written for (see
// kernels/core/fgr_types.cl): the host reads it from the source and defines it before the library,
// so the library shows each scene the names and signatures of its version.

#include <string_view>

namespace fgr {

// The newest version the kernel library offers (FGR_KERNEL_API_LATEST in
// kernels/core/fgr_types.cl).
inline constexpr int kKernelApiLatest = 4;

// N from `#define FGR_KERNEL_API N` on a line of its own outside comments; 1 (the version before
// versions were counted) when the source has no such line. Throws std::invalid_argument, saying
// which versions this fgr has, when N is not one of them.
int declared_kernel_api(std::string_view source);

}  // namespace fgr
