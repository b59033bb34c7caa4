#pragma once
// The OpenCL C source an IFS scene's kernel is built from: its maps, their inverses and the
// bounding sphere as constants (host/src/ifs/ifs_source.cpp).

#include <string>

#include "fgr/ifs.hpp"

namespace fgr {

std::string ifs_kernel_source(const IfsScene& ifs);

}  // namespace fgr
