// SPDX-License-Identifier: Apache-2.0
#include "util/installed_files.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <system_error>

namespace fgr {

namespace fs = std::filesystem;

fs::path executable_dir() {
    std::error_code error;
    const fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) {
        spdlog::debug("cannot resolve /proc/self/exe: {}", error.message());
        return {};
    }
    return exe.parent_path();
}

fs::path schema_dir() {
    const fs::path exe_dir = executable_dir();
    // An unknown executable directory must not turn into a path relative to the working directory.
    if (exe_dir.empty()) return {};
    return (exe_dir / FGR_SCHEMAS_FROM_BIN).lexically_normal();
}

std::string schema_reference(std::string_view schema_file) {
    const fs::path directory = schema_dir();
    if (directory.empty()) return std::string(schema_file);
    return file_uri(directory / schema_file);
}

std::string file_uri(const fs::path& absolute) {
    std::string uri = "file://";
    for (const char c : absolute.string()) {
        const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                           (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' || c == '~' ||
                           c == '/';
        if (plain) {
            uri += c;
        } else {
            uri += fmt::format("%{:02X}", static_cast<unsigned char>(c));
        }
    }
    return uri;
}

}  // namespace fgr
