// SPDX-License-Identifier: Apache-2.0
#include "util/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <system_error>

#include "util/errors.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

std::string too_large(std::uintmax_t size, std::uintmax_t max_bytes) {
    return "file too large (" + std::to_string(size) + " bytes; the limit is " +
           std::to_string(max_bytes) + ")";
}

// Why a file with this status is not one to read: not regular, or larger than max_bytes.
std::string status_problem(const struct stat& status, std::uintmax_t max_bytes) {
    if (!S_ISREG(status.st_mode))
        return "not a regular file (" + file_kind_name(status.st_mode) + ")";
    if (static_cast<std::uintmax_t>(status.st_size) > max_bytes) {
        return too_large(static_cast<std::uintmax_t>(status.st_size), max_bytes);
    }
    return "";
}

// Opens `file` read-only without blocking (a FIFO with no writer would otherwise block the open
// forever) and checks the opened descriptor: a regular file of at most max_bytes. Sets `size`.
FilePointer open_checked(const fs::path& file, std::string& reason, std::uintmax_t max_bytes,
                         std::uintmax_t& size) {
    const int descriptor = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (descriptor < 0) {
        reason = errno_message(errno);
        return nullptr;
    }
    struct stat status {};
    if (::fstat(descriptor, &status) != 0) {
        reason = errno_message(errno);
        ::close(descriptor);
        return nullptr;
    }
    reason = status_problem(status, max_bytes);
    if (!reason.empty()) {
        ::close(descriptor);
        return nullptr;
    }
    // Reads of a regular file never block; the flag only mattered for the open.
    ::fcntl(descriptor, F_SETFL, ::fcntl(descriptor, F_GETFL) & ~O_NONBLOCK);
    FilePointer handle(::fdopen(descriptor, "rb"));
    if (handle == nullptr) {
        reason = errno_message(errno);
        ::close(descriptor);
        return nullptr;
    }
    size = static_cast<std::uintmax_t>(status.st_size);
    return handle;
}

template <typename Bytes>
std::string read_whole(const fs::path& file, Bytes& bytes, std::uintmax_t max_bytes) {
    bytes.clear();
    std::string reason;
    std::uintmax_t size = 0;
    const FilePointer handle = open_checked(file, reason, max_bytes, size);
    if (handle == nullptr) return reason;
    bytes.resize(static_cast<std::size_t>(size));
    if (std::fread(bytes.data(), 1, bytes.size(), handle.get()) != bytes.size()) {
        reason = std::ferror(handle.get()) ? errno_message(errno) : "file shrank while read";
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

FilePointer open_regular_file(const fs::path& file, std::string& reason, std::uintmax_t max_bytes) {
    std::uintmax_t size = 0;
    reason.clear();
    return open_checked(file, reason, max_bytes, size);
}

std::string regular_file_problem(const fs::path& file, std::uintmax_t max_bytes) {
    struct stat status {};
    if (::stat(file.c_str(), &status) != 0) return errno_message(errno);
    return status_problem(status, max_bytes);
}

std::string file_kind_name(unsigned mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISLNK(mode)) return "a symbolic link";
    return "not a regular file";
}

}  // namespace fgr
