// SPDX-License-Identifier: Apache-2.0
#include "util/version.hpp"

#include "fgr_version_info.h"  // generated into the build tree (cmake/version_header.cmake)

namespace fgr {

std::string_view fgr_version() { return FGR_VERSION_TEXT; }

std::string_view fgr_commit() { return FGR_COMMIT_TEXT; }

}  // namespace fgr
