// SPDX-License-Identifier: Apache-2.0
#pragma once
// Files and folders the tests share: where this build put fgr, its plugins and the test fixtures,
// and whole-file reads and writes. (child_process.hpp has read_file and TempDir.)

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

namespace fgr::test {

// The built fgr executable, the plugin folder beside it, and the fixture plugins' folder
// (tests/fixtures in the build tree): FGR_TEST_* from tests/CMakeLists.txt.
inline const std::filesystem::path kFgrExe = FGR_TEST_FGR_EXE;
inline const std::filesystem::path kPluginDir = FGR_TEST_PLUGIN_DIR;
inline const std::filesystem::path kFixtureDir = FGR_TEST_FIXTURE_DIR;

inline std::vector<uint8_t> read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_bytes(const std::filesystem::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

inline void write_text(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << text;
}

// The names of the entries in `directory`, sorted; none when it cannot be read.
inline std::vector<std::string> directory_listing(const std::filesystem::path& directory) {
    std::vector<std::string> names;
    std::error_code error;
    for (const std::filesystem::directory_entry& entry :
         std::filesystem::directory_iterator(directory, error)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace fgr::test
