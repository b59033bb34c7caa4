// SPDX-License-Identifier: Apache-2.0
#pragma once
// Running a program as a child process for tests: arguments, working directory and environment
// changes in; exit status, signal, timeout and captured stdout / stderr out. Plus a temporary
// directory that removes itself.

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace fgr::test {

struct RunResult {
    int exit_code = -1;   // valid when exited
    bool exited = false;  // terminated through exit()
    int term_signal = 0;  // the signal that killed it, 0 if none
    bool timed_out = false;
    std::chrono::seconds timeout{0};
    std::string out;
    std::string err;
};

std::ostream& operator<<(std::ostream& os, const RunResult& result);

// "NAME 'arg1' 'arg2'" for messages.
std::string describe(const std::string& name, const std::vector<std::string>& args);

struct ChildOptions {
    std::filesystem::path working_dir = ".";
    // Variables set (a value) or removed (nullopt) in the child's copy of this environment.
    std::map<std::string, std::optional<std::string>> environment;
    std::chrono::seconds timeout{120};  // then the child is killed and reported as timed out
    // Called every few milliseconds while the child runs, with its pid and its stderr so far,
    // until it returns true: a test acts on an event it observes (a file appearing, a line
    // printed), e.g. by signalling the child.
    std::function<bool(pid_t, const std::string&)> watch{};
};

// Runs `program` with `args` (stdin from /dev/null), capturing stdout and stderr.
RunResult run_child(const std::filesystem::path& program, const std::vector<std::string>& args,
                    const ChildOptions& options);

// Runs the built fgr with `args` in `working_dir`. The child gets this environment minus
// FGR_PLUGIN_PATH, so it finds its plugins next to itself, as an installed fgr does.
RunResult run_fgr(const std::vector<std::string>& args, const std::filesystem::path& working_dir);
// The same with `options` (their environment minus FGR_PLUGIN_PATH).
RunResult run_fgr(const std::vector<std::string>& args, ChildOptions options);

class TempDir {
public:
    // A fresh directory under the system temp directory, named after `prefix`.
    explicit TempDir(const std::string& prefix = "fgr_test");
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    ~TempDir();
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

std::string read_file(const std::filesystem::path& file);

}  // namespace fgr::test
