// SPDX-License-Identifier: Apache-2.0
#pragma once
// fgr's own modules: parts of fgr built as shared objects beside the plugin directory
// (<prefix>/lib/fgr/, built or installed) and loaded the first time a command needs them, so the
// libraries only they use are not loaded by every fgr process. Binding a library's symbols costs
// every process that links it, and slows the symbol lookups of every library loaded after it
// (PoCL's LLVM among them): FFmpeg's ~130 libraries took 32 ms of each fgr process, SDL's ~50
// another ~10 with the slower LLVM load (measured; docs/performance.md, "Process start-up").
//
//   libfgr_video_ffmpeg.so  video encoding (host/video_ffmpeg)
//   libfgr_viewer.so        the interactive viewer, `fgr view` (host/viewer)
//
// A module is built from the same tree as fgr, so its entry point hands over C++ types; each
// entry point returns a table whose first member is a version, checked before anything is called.

#include <filesystem>
#include <string>

namespace fgr {

// The directory fgr's modules are loaded from.
std::filesystem::path module_directory();

// The address of `entry` in module `file_name`, loaded on first use (modules stay loaded).
// Throws std::runtime_error, one line naming `needed_for`, when the module or the entry point
// cannot be loaded.
void* module_entry(const std::string& file_name, const std::string& entry,
                   const std::string& needed_for);

// The table module `file_name`'s entry point `entry` returns, after checking its version
// (Table's first member, `int version`) is `version`: a module from another build is refused with
// a std::runtime_error instead of being called.
[[noreturn]] void refuse_module_version(const std::string& file_name, int found, int expected);
template <typename Table>
const Table& module_table(const std::string& file_name, const std::string& entry, int version,
                          const std::string& needed_for) {
    using Entry = const Table* (*)();
    const Table* table = reinterpret_cast<Entry>(module_entry(file_name, entry, needed_for))();
    if (table->version != version) refuse_module_version(file_name, table->version, version);
    return *table;
}

}  // namespace fgr
