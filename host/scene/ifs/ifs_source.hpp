// SPDX-License-Identifier: Apache-2.0
#pragma once
// The OpenCL C source an IFS scene hands the kernel assembly in place of a distance estimator.

#include <string>

#include "scene/ifs/ifs.hpp"

namespace fgr {

// Defines FGR_GEOMETRY_IFS and the tables kernels/geometry/fgr_ifs.cl traces (each map's inverse
// and forward affine map, contraction factor and colour; the bounding ball), plus a scene_de that
// is the distance to the bounding ball (a lower bound of the distance to the attractor, for the
// code that only needs one).
std::string ifs_kernel_source(const IfsScene& ifs);

}  // namespace fgr
