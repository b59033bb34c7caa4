// SPDX-License-Identifier: Apache-2.0
#pragma once
// The SDK guide's text scene example (docs/sdk/text-scenes.md, "A scene in ten lines of text"),
// read from the guide itself so the tests render what the guide shows and the two cannot drift.
// Needs FGR_TEST_SOURCE_DIR (tests/CMakeLists.txt defines it for the files that include this).

#include <filesystem>
#include <stdexcept>
#include <string>

#include "child_process.hpp"

namespace fgr::test {

// The source tree's sdk/ folder: the template and the examples.
inline const std::filesystem::path kSdkDir =
    std::filesystem::path(FGR_TEST_SOURCE_DIR).parent_path() / "sdk";
inline const std::filesystem::path kSdkGuide =
    std::filesystem::path(FGR_TEST_SOURCE_DIR).parent_path() / "docs" / "sdk" / "text-scenes.md";

// The first ```c block after the page's title, without its fences.
inline std::string sdk_guide_text_scene_example() {
    const std::string guide = read_file(kSdkGuide);
    const std::size_t section = guide.find("# A scene in ten lines of text\n");
    const std::size_t open = guide.find("\n```c\n", section);
    const std::size_t close = guide.find("\n```\n", open + 1);
    if (section == std::string::npos || open == std::string::npos || close == std::string::npos) {
        throw std::runtime_error("no text scene example in " + kSdkGuide.string());
    }
    return guide.substr(open + 6, close - open - 5);  // its last line keeps its newline
}

}  // namespace fgr::test
