// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text for one-line messages: a path as messages quote it.

#include <filesystem>
#include <string>

namespace fgr {

// 'path', as "cannot read 'scenes/x.png': ..." shows it: the path's text between single quotes,
// nothing escaped.
inline std::string quoted(const std::filesystem::path& path) {
    // Appended, not "'" + path.string(): GCC 12 inlines that insert into a false
    // -Wstringop-overflow at some call sites.
    std::string text = "'";
    text += path.native();
    text += '\'';
    return text;
}

}  // namespace fgr
