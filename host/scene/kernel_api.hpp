// SPDX-License-Identifier: Apache-2.0
#pragma once
// The version of the kernel library's API a scene's OpenCL source is written for (see
// kernels/core/fgr_types.cl): the host reads it from the source and defines it before the library,
// so the library shows each scene the names and signatures of its version.

#include <string>
#include <string_view>
#include <vector>

namespace fgr {

// The newest version the kernel library offers (FGR_KERNEL_API_LATEST in
// kernels/core/fgr_types.cl).
inline constexpr int kKernelApiLatest = 4;

// N from `#define FGR_KERNEL_API N` on a line of its own outside comments; 1 (the version before
// versions were counted) when the source has no such line. Throws std::invalid_argument, saying
// which versions this fgr has, when N is not one of them.
int declared_kernel_api(std::string_view source);

// The parameters a scene lets the host compile in as constants, from
// `#define FGR_SPECIALISABLE id id ...` on a line of its own outside comments (none without one):
// integer parameters that shape its DE loop (a power, an iteration count), whose values the
// compiler can then fold. The ids as written; kernel assembly checks them.
std::vector<std::string> declared_specialisable(std::string_view source);

}  // namespace fgr
