// SPDX-License-Identifier: Apache-2.0
#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

extern char** environ;

namespace fgr::test {
namespace {

namespace fs = std::filesystem;

// A pipe whose ends close themselves; both ends are close-on-exec.
class Pipe {
public:
    Pipe() {
        if (pipe2(fds_.data(), O_CLOEXEC) != 0) fds_ = {-1, -1};
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;
    ~Pipe() {
        close_read();
        close_write();
    }
    bool ok() const { return fds_[0] >= 0; }
    int read_end() const { return fds_[0]; }
    int write_end() const { return fds_[1]; }
    void close_read() { close_fd(fds_[0]); }
    void close_write() { close_fd(fds_[1]); }

private:
    static void close_fd(int& fd) {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
    std::array<int, 2> fds_{};
};

// This process's environment with `changes` applied, as NAME=VALUE strings.
std::vector<std::string> child_environment(
    const std::map<std::string, std::optional<std::string>>& changes) {
    std::vector<std::string> entries;
    for (char** entry = environ; *entry != nullptr; ++entry) {
        const std::string text = *entry;
        if (!changes.count(text.substr(0, text.find('=')))) entries.push_back(text);
    }
    for (const auto& [name, value] : changes) {
        if (value) entries.push_back(name + "=" + *value);
    }
    return entries;
}

}  // namespace

std::string describe(const std::string& name, const std::vector<std::string>& args) {
    std::string text = name;
    for (const std::string& arg : args) text += " '" + arg + "'";
    return text;
}

std::ostream& operator<<(std::ostream& os, const RunResult& result) {
    if (result.timed_out) os << "timed out after " << result.timeout.count() << " s; ";
    if (result.exited) os << "exit " << result.exit_code;
    if (result.term_signal != 0) os << "killed by signal " << result.term_signal;
    return os << "\n--- stdout ---\n" << result.out << "--- stderr ---\n" << result.err << "---";
}

// Everything the child needs is prepared before fork(): after it only async-signal-safe calls.
RunResult run_child(const fs::path& program, const std::vector<std::string>& args,
                    const ChildOptions& options) {
    RunResult result;
    result.timeout = options.timeout;

    const std::string exe = program.string();
    const std::string cwd = options.working_dir.string();
    std::vector<std::string> storage;
    storage.push_back(exe);
    storage.insert(storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& arg : storage) argv.push_back(arg.data());
    argv.push_back(nullptr);
    std::vector<std::string> environment = child_environment(options.environment);
    std::vector<char*> envp;
    for (std::string& entry : environment) envp.push_back(entry.data());
    envp.push_back(nullptr);

    Pipe out_pipe;
    Pipe err_pipe;
    if (!out_pipe.ok() || !err_pipe.ok()) {
        result.err = std::string("test harness: pipe2 failed: ") + std::strerror(errno);
        return result;
    }

    const pid_t pid = fork();
    if (pid < 0) {
        result.err = std::string("test harness: fork failed: ") + std::strerror(errno);
        return result;
    }
    if (pid == 0) {
        const int null_fd = ::open("/dev/null", O_RDONLY);
        if (null_fd < 0 || dup2(null_fd, STDIN_FILENO) < 0) _exit(126);
        if (dup2(out_pipe.write_end(), STDOUT_FILENO) < 0) _exit(126);
        if (dup2(err_pipe.write_end(), STDERR_FILENO) < 0) _exit(126);
        if (chdir(cwd.c_str()) != 0) _exit(126);
        execve(exe.c_str(), argv.data(), envp.data());
        _exit(127);
    }
    out_pipe.close_write();
    err_pipe.close_write();

    const auto deadline = std::chrono::steady_clock::now() + options.timeout;
    std::array<pollfd, 2> polled{
        {{out_pipe.read_end(), POLLIN, 0}, {err_pipe.read_end(), POLLIN, 0}}};
    std::array<std::string*, 2> sinks{&result.out, &result.err};
    int open_streams = 2;
    bool watched = false;
    while (open_streams > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            result.timed_out = true;
            kill(pid, SIGKILL);
            break;
        }
        // With a watch, a look every few milliseconds until it has acted.
        const long wait_ms = options.watch && !watched ? std::min<long>(left.count(), 5)
                                                       : static_cast<long>(left.count());
        const int ready = poll(polled.data(), polled.size(), static_cast<int>(wait_ms));
        if (options.watch && !watched) watched = options.watch(pid, result.err);
        if (ready < 0) {
            if (errno == EINTR) continue;
            kill(pid, SIGKILL);
            break;
        }
        for (std::size_t i = 0; i < polled.size(); ++i) {
            if (polled[i].fd < 0 || polled[i].revents == 0) continue;
            char buffer[4096];
            const ssize_t n = ::read(polled[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, static_cast<std::size_t>(n));
            } else if (n == 0 || errno != EINTR) {
                polled[i].fd = -1;  // poll() ignores negative descriptors
                --open_streams;
            }
        }
    }

    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status)) {
        result.exited = true;
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        result.term_signal = WTERMSIG(status);
    }
    return result;
}

TempDir::TempDir(const std::string& prefix) {
    std::string pattern = (fs::temp_directory_path() / (prefix + ".XXXXXX")).string();
    if (mkdtemp(pattern.data()) != nullptr) path_ = pattern;
}

TempDir::~TempDir() {
    std::error_code ignored;
    if (!path_.empty()) fs::remove_all(path_, ignored);
}

std::string read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

RunResult run_fgr(const std::vector<std::string>& args, const std::filesystem::path& working_dir) {
    ChildOptions options;
    options.working_dir = working_dir;
    return run_fgr(args, options);
}

RunResult run_fgr(const std::vector<std::string>& args, ChildOptions options) {
    options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
    return run_child(FGR_TEST_FGR_EXE, args, options);
}

}  // namespace fgr::test
