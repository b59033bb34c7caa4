// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading a whole file into memory in one read at the file's size (a cache entry, a band of a
// tiled render, an image, a plugin to copy), and a C file closed by its owner.

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
// or the reason, bytes then empty: the errno text when it cannot be opened or read, the file
// system's when its size cannot be had, "file too large (N bytes; the limit is M)" past max_bytes
// (checked before anything is allocated), "file shrank while read".
std::string read_file_bytes(const std::filesystem::path& file, std::string& bytes,
                            std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());
std::string read_file_bytes(const std::filesystem::path& file, std::vector<unsigned char>& bytes,
                            std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max());

}  // namespace fgr
