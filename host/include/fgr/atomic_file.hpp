#pragma once
// Writing files so that readers see either the old file or the whole new one, never a partial
// write: the content goes to a temporary beside the target, is flushed to disk, then renamed.

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace fgr {

// Calls write_temporary(temporary path) — which returns "" on success, else the reason it
// failed — then renames the temporary over `target`. Returns "" or the reason; the temporary is
// removed on any failure.
std::string replace_file_atomically(
    const std::filesystem::path& target,
    const std::function<std::string(const std::filesystem::path&)>& write_temporary);

// Flushes and fsyncs `file`, then closes it (always; the pointer is set to null). Returns "" or
// the reason.
std::string close_durably(std::FILE*& file);

// Writes `contents` (bytes as they are: text or binary) to `target` atomically and durably
// (fsync'd before the rename). Throws std::runtime_error
// ("cannot write '<target>': <reason>").
void write_text_file_atomically(const std::filesystem::path& target, std::string_view contents);

}  // namespace fgr
