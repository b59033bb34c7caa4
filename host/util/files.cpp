// SPDX-License-Identifier: Apache-2.0
#include "util/files.hpp"

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "util/errors.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

template <typename Bytes>
std::string read_whole(const fs::path& file, Bytes& bytes, std::uintmax_t max_bytes) {
    bytes.clear();
    const FilePointer handle(std::fopen(file.c_str(), "rb"));
    if (handle == nullptr) return errno_message(errno);
    std::error_code error;
    const std::uintmax_t size = fs::file_size(file, error);
    if (error) return error.message();
    if (size > max_bytes) {
        return "file too large (" + std::to_string(size) + " bytes; the limit is " +
               std::to_string(max_bytes) + ")";
    }
    bytes.resize(static_cast<std::size_t>(size));
    if (std::fread(bytes.data(), 1, bytes.size(), handle.get()) != bytes.size()) {
        std::string reason =
            std::ferror(handle.get()) ? errno_message(errno) : "file shrank while read";
        bytes.clear();
        return reason;
    }
    return "";
}

}  // namespace

std::string read_file_bytes(const fs::path& file, std::string& bytes, std::uintmax_t max_bytes) {
    return read_whole(file, bytes, max_bytes);
}

std::string read_file_bytes(const fs::path& file, std::vector<unsigned char>& bytes,
                            std::uintmax_t max_bytes) {
    return read_whole(file, bytes, max_bytes);
}

}  // namespace fgr
