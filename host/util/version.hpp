// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which fgr this is: the version (the project's, set once in the top CMakeLists.txt) and the
// commit it was built from. Only util/version.cpp sees the generated header, so a new commit
// recompiles that one file.

#include <string_view>

namespace fgr {

// "0.2.0": what `fgr --version` prints and what view files record as the fgr that wrote them.
std::string_view fgr_version();

// The abbreviated commit hash the build's source tree was at, "-dirty" appended when it had
// changes; "unknown" when the source was not a git checkout.
std::string_view fgr_commit();

}  // namespace fgr
