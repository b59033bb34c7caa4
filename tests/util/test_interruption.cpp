// SPDX-License-Identifier: Apache-2.0
// How a signal stops a command (util/interruption.hpp), in forked children of the test process: in
// a scope the first signal only sets the flag, a second removes every registered temporary and
// exits 128 + the first signal's number; without a scope a signal removes them and ends the
// process as the signal does. The children only make system calls after fork().
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <memory>

#include "child_process.hpp"
#include "util/atomic_file.hpp"
#include "util/interruption.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// The wait status of a forked child that runs `body` then exits 0.
int status_of_child(const std::function<void()>& body) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        body();
        ::_exit(0);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
}

void create(const fs::path& file) { ::close(::open(file.c_str(), O_CREAT | O_WRONLY, 0600)); }

class Interruption : public ::testing::Test {
protected:
    test::TempDir temp_{"fgr_interruption"};
    fs::path file_ = temp_.path() / "out.png.tmp-1-0";
};

TEST_F(Interruption, WithoutAScopeASignalRemovesTheTemporariesAndEndsAsTheSignalDoes) {
    install_interrupt_handlers();
    const auto registration = std::make_unique<TemporaryFileRegistration>(file_);
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
        const int status = status_of_child([&] {
            create(file_);
            ::raise(signal);
        });
        ASSERT_TRUE(WIFSIGNALED(status)) << status;
        EXPECT_EQ(WTERMSIG(status), signal);
        EXPECT_FALSE(fs::exists(file_)) << signal;
    }
}

TEST_F(Interruption, InAScopeTheFirstSignalIsPolledAndASecondExitsAtOnceLeavingNoFile) {
    const auto registration = std::make_unique<TemporaryFileRegistration>(file_);
    const int status = status_of_child([&] {
        const InterruptScope scope;
        create(file_);
        ::raise(SIGTERM);
        if (!interrupted() || interrupt_signal() != SIGTERM || interrupted_exit_code() != 143) {
            ::_exit(3);
        }
        // Cleaning up after the first, the second arrives.
        ::raise(SIGINT);
        ::_exit(4);
    });
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << "exit 3: flag not set; 4: second ignored";
    EXPECT_FALSE(fs::exists(file_));
}

// A temporary of atomic_file.hpp is registered for as long as it exists.
TEST_F(Interruption, PendingFilesAreRegistered) {
    install_interrupt_handlers();
    const PendingFile pending(temp_.path() / "out.png");
    const int status = status_of_child([&] {
        create(pending.temporary());
        ::raise(SIGTERM);
    });
    ASSERT_TRUE(WIFSIGNALED(status)) << status;
    EXPECT_TRUE(fs::is_empty(temp_.path()));
}

// Temporaries of processes that no longer run go; a running one's stay.
TEST_F(Interruption, StaleTemporariesOfDeadProcessesAreRemoved) {
    const pid_t dead = ::fork();
    if (dead == 0) ::_exit(0);
    ::waitpid(dead, nullptr, 0);
    const fs::path target = temp_.path() / "out.png";
    const fs::path stale = temp_.path() / ("out.png.tmp-" + std::to_string(dead) + "-0");
    const fs::path live = temp_.path() / ("out.png.tmp-" + std::to_string(::getppid()) + "-3");
    const fs::path other = temp_.path() / ("other.png.tmp-" + std::to_string(dead) + "-0");
    for (const fs::path& file : {stale, live, other}) create(file);
    EXPECT_EQ(remove_stale_temporaries(target), 1);
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(live));
    EXPECT_TRUE(fs::exists(other));
}

}  // namespace
}  // namespace fgr
