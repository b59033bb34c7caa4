// SPDX-License-Identifier: Apache-2.0
#pragma once
// Writing files so that readers see either the old file or the whole new one, never a partial
// write: the content goes to a temporary beside the target, is flushed to disk, then renamed.

#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "util/interruption.hpp"

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

// Removes the temporaries of `target` (named after it, with the writer's process id) left by
// processes that no longer run: a writer killed with SIGKILL, or one that crashed. Returns how many
// it removed.
int remove_stale_temporaries(const std::filesystem::path& target);

// A file written over time (a streamed image) under a temporary name beside `target`: commit()
// renames it into place; destroying it uncommitted (an error, Ctrl-C) removes the temporary, so
// `target` never holds a partial file. A signal removes the temporary too (interruption.hpp).
class PendingFile {
public:
    explicit PendingFile(std::filesystem::path target);
    ~PendingFile();
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;

    const std::filesystem::path& temporary() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    // Renames the (closed, flushed) temporary over the target; throws std::runtime_error
    // ("cannot write '<target>': <reason>").
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;
    TemporaryFileRegistration registration_{temporary_};  // a signal removes it too
    bool committed_ = false;
};

// Writes `contents` (bytes as they are: text or binary) to `target` atomically and durably
// (fsync'd before the rename). Throws std::runtime_error
// ("cannot write '<target>': <reason>").
void write_text_file_atomically(const std::filesystem::path& target, std::string_view contents);

}  // namespace fgr
