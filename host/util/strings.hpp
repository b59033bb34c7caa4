// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text helpers: a path as messages quote it, a list split at its separators.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

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

// The pieces of `text` between each `separator`, empty ones kept: "a,,b" gives "a", "", "b".
inline std::vector<std::string> split(std::string_view text, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = text.find(separator, start);
        parts.emplace_back(text.substr(start, end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

}  // namespace fgr
