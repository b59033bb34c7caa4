// SPDX-License-Identifier: Apache-2.0
#pragma once
// ASCII lower case, for comparisons that ignore case: file extensions, search words.

#include <cctype>
#include <filesystem>
#include <string>
#include <string_view>

namespace fgr {

inline std::string lower_case(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return result;
}

// ".EXR" and ".exr" alike: the extension with its dot, in lower case ("" when there is none).
inline std::string lower_extension(const std::filesystem::path& path) {
    return lower_case(path.extension().string());
}

}  // namespace fgr
