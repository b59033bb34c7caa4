// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading a whole file into memory in one read at the file's size (a cache entry, a band of a
// tiled render, an image, a plugin to copy), only ever from a regular file, and a C file closed by
// its owner.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fgr {

// A C stdio file closed when its owner goes: for reading, or for writing when the close that
// reports write errors (close_durably) is called on the released pointer.
struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePointer = std::unique_ptr<std::FILE, FileCloser>;

// Reads all of `file` into `bytes` with one read of the file's size, never a byte at a time
// through a stream iterator (which costs 1 ms of a 570 KB kernel binary's 11 ms load). Returns ""
// or the reason, bytes then empty: the errno text when it cannot be opened or read, "not a regular
// file (a FIFO)" and the like for anything else (opened without blocking, so a FIFO named like a
// file never hangs the reader), "file too large (N bytes; the limit is M)" past max_bytes (checked
// before anything is allocated), "file shrank while read".
std::string read_file_bytes(const std::filesystem::path& file, std::string& bytes,
                            std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());
std::string read_file_bytes(const std::filesystem::path& file, std::vector<unsigned char>& bytes,
                            std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

// Opens `file` for reading as a C file only if it is a regular file of at most max_bytes, checked
// on the opened descriptor (no window between the check and the open): for libraries that read
// through a FILE* (libpng). Returns the file, or null with `reason` set as read_file_bytes says it.
FilePointer open_regular_file(
    const std::filesystem::path& file, std::string& reason,
    std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

// Why `file` cannot be read as a regular file of at most max_bytes ("" when it can), in the words
// of read_file_bytes: for libraries that open a path themselves (OpenEXR, dlopen). A check of the
// path, so the file can still change before the library opens it; readers that can open the file
// themselves use open_regular_file or read_file_bytes.
std::string regular_file_problem(
    const std::filesystem::path& file,
    std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

// "a FIFO", "a directory", "a socket", "a character device", "a block device", "a symbolic link"
// or "not a regular file": what a stat mode that is not a regular file's names.
std::string file_kind_name(unsigned mode);

}  // namespace fgr
