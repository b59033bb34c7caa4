// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text helpers: a path or a name as messages show it, a list split at its separators.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace fgr {

// `text` as a one-line message may show it: control characters (C0, DEL and C1) and bytes that are
// not UTF-8 are escaped ("\n", "\t", "\r", else "\xNN" for each byte), as are the characters
// that reorder a terminal's text (U+202A..U+202E, U+2066..U+2069, as "\u202e"); anything else,
// valid non-ASCII text included, is kept. A file name with a newline or a terminal escape in it
// then cannot break a message into lines or colour the terminal.
std::string printable_text(std::string_view text);

// The start of `text` as a one-line message may quote a name it does not know: at most
// `length` bytes of it, as printable_text shows them, and "..." when there was more. A name of
// thousands of characters then costs the message no more than a short one.
std::string printable_excerpt(std::string_view text, std::size_t length = 40);

// A path's text as printable_text shows it, unquoted ("skipping plugin /p/x.so: ...").
inline std::string printable_path(const std::filesystem::path& path) {
    return printable_text(path.native());
}

// 'path', as "cannot read 'scenes/x.png': ..." shows it: the path's text, as printable_path shows
// it, between single quotes (a quote inside is not escaped).
inline std::string quoted(const std::filesystem::path& path) {
    // Appended, not "'" + ...: GCC 12 inlines that insert into a false -Wstringop-overflow at
    // some call sites.
    std::string text = "'";
    text += printable_path(path);
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
