// SPDX-License-Identifier: Apache-2.0
#pragma once
// How a command that writes files stops on SIGINT, SIGTERM or SIGHUP (Ctrl-C, kill, a closed
// terminal) without leaving a temporary or partial file behind.
//
// Every temporary file a writer makes is registered while it exists (TemporaryFileRegistration:
// atomic_file.hpp's temporaries and the video's partial file are). A command that can stop
// cleanly holds an InterruptScope and polls interrupted() between units of work: the first signal
// only sets the flag, the command unwinds (its writers remove their temporaries) and returns
// interrupted_exit_code(), 128 + the signal's number. A second signal while it does, or a signal
// while no scope is held (a command that does not poll: fgr merge, a plain render), removes every
// registered temporary at once, then ends the process: _exit(128 + N) inside a scope, otherwise by
// the signal itself (its default action, which shells also report as 128 + N).

#include <filesystem>
#include <string_view>

namespace fgr {

// Installs the handlers of SIGINT, SIGTERM and SIGHUP (once; later calls do nothing). The commands
// that write files call it first; InterruptScope calls it too.
void install_interrupt_handlers();

// While one lives, the first signal only sets interrupted() (cleared when the first scope
// starts), for the command to poll.
class InterruptScope {
public:
    InterruptScope();
    ~InterruptScope();
    InterruptScope(const InterruptScope&) = delete;
    InterruptScope& operator=(const InterruptScope&) = delete;
};

// Whether a signal arrived while a scope was held, and which (0: none).
bool interrupted();
int interrupt_signal();
// 128 + the signal's number (130 for SIGINT, 143 for SIGTERM); 130 when none arrived.
int interrupted_exit_code();

// Registers `path` as a temporary to remove on a signal for as long as it lives. Registering
// before the file is created leaves no moment in which a signal could miss it. Paths of 4 KiB and
// more, or more than 256 at once, are not registered (their owner still removes them).
class TemporaryFileRegistration {
public:
    explicit TemporaryFileRegistration(const std::filesystem::path& path);
    ~TemporaryFileRegistration();
    TemporaryFileRegistration(const TemporaryFileRegistration&) = delete;
    TemporaryFileRegistration& operator=(const TemporaryFileRegistration&) = delete;

private:
    int slot_ = -1;
};

// For the fault tests: when the environment variable FGR_TEST_HOLD names `event` ("band": a tiled
// render's first band is in its tile store; "frame": a video's first frame is encoded; "merge": a
// merge's first band or frame is written; "task": an MPI worker sent its first result), the first
// time it happens the process says so on stderr, with its process id, and waits there (at most a
// minute) until a signal arrives, so that a test can signal it at a moment it observed rather than
// after a guessed delay.
void hold_for_test(std::string_view event);

}  // namespace fgr
