// SPDX-License-Identifier: Apache-2.0
#pragma once
// Failure messages fgr gives the same way everywhere: an errno value's text, and a file that
// cannot be written.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>

#include "util/strings.hpp"

namespace fgr {

// "No such file or directory" for ENOENT: the C library's text of a POSIX error number.
inline std::string errno_message(int error) { return std::generic_category().message(error); }

// Stops writing `path` with std::runtime_error("cannot write '<path>': <reason>"), as every file
// writer (images, streamed images, atomic replacements) reports it.
[[noreturn]] inline void fail_write(const std::filesystem::path& path, const std::string& reason) {
    throw std::runtime_error("cannot write " + quoted(path) + ": " + reason);
}

}  // namespace fgr
