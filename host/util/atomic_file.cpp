// SPDX-License-Identifier: Apache-2.0
#include "util/atomic_file.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <regex>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "util/errors.hpp"
#include "util/interruption.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// Beside the target, so the final rename stays within one file system and is atomic. The pid and
// a counter keep concurrent writers (processes or threads) off each other's temporaries.
fs::path temporary_path_for(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    const std::string suffix =
        ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1));
    return target.parent_path() / (target.filename().string() + suffix);
}

// Deletes the file on scope exit unless it was committed (renamed into place).
struct TemporaryFile {
    fs::path path;
    TemporaryFileRegistration registration{path};  // a signal removes it too
    bool committed = false;

    explicit TemporaryFile(fs::path temporary) : path(std::move(temporary)) {}
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;
    ~TemporaryFile() {
        if (!committed) {
            std::error_code ignored;
            fs::remove(path, ignored);
        }
    }
};

}  // namespace

int remove_stale_temporaries(const fs::path& target) {
    const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string prefix = target.filename().string() + ".tmp-";
    const std::regex suffix(R"(([0-9]{1,9})-[0-9]{1,9})");
    int removed = 0;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(directory, error)) {
        const std::string name = entry.path().filename().string();
        std::smatch match;
        const std::string rest = name.starts_with(prefix) ? name.substr(prefix.size()) : "";
        if (rest.empty() || !std::regex_match(rest, match, suffix)) continue;
        const pid_t pid = static_cast<pid_t>(std::stol(match[1]));
        // A process that still runs (or that this one may not signal) may still be writing it.
        if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code ignored;
        removed += fs::remove(entry.path(), ignored) ? 1 : 0;
    }
    return removed;
}

PendingFile::PendingFile(fs::path target)
    : target_(std::move(target)), temporary_(temporary_path_for(target_)) {}

PendingFile::~PendingFile() {
    if (committed_) return;
    std::error_code ignored;
    fs::remove(temporary_, ignored);
}

void PendingFile::commit() {
    std::error_code error;
    fs::rename(temporary_, target_, error);
    if (error) fail_write(target_, error.message());
    committed_ = true;
}

std::string replace_file_atomically(
    const fs::path& target, const std::function<std::string(const fs::path&)>& write_temporary) {
    if (!target.has_filename()) return "not a file name";
    TemporaryFile temporary(temporary_path_for(target));
    if (std::string failure = write_temporary(temporary.path); !failure.empty()) return failure;
    std::error_code error;
    fs::rename(temporary.path, target, error);
    if (error) return error.message();
    temporary.committed = true;
    return {};
}

// Flushes to the disk before the rename, so a crash cannot leave the target renamed but empty.
std::string close_durably(std::FILE*& owned_file) {
    std::FILE* file = std::exchange(owned_file, nullptr);
    if (std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0) {
        const int error = errno;
        std::fclose(file);
        return errno_message(error);
    }
    if (std::fclose(file) != 0) return errno_message(errno);
    return {};
}

void write_text_file_atomically(const fs::path& target, std::string_view contents) {
    const std::string failure = replace_file_atomically(target, [&](const fs::path& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (file == nullptr) return errno_message(errno);
        if (std::fwrite(contents.data(), 1, contents.size(), file) != contents.size()) {
            const int error = errno;
            std::fclose(file);
            return errno_message(error);
        }
        return close_durably(file);
    });
    if (!failure.empty()) fail_write(target, failure);
}

}  // namespace fgr
