// SPDX-License-Identifier: Apache-2.0
#include "util/interruption.hpp"

#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <thread>

namespace fgr {
namespace {

constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};

// The registry the handler reads: fixed storage and lock-free atomics only, so that reading it
// from a signal handler is async-signal-safe. A slot is free (0), being filled or emptied (1), or
// holds a registered path (2).
constexpr int kSlots = 256;
constexpr std::size_t kPathBytes = 4096;
struct Slot {
    std::atomic<int> state{0};
    char path[kPathBytes];
};
Slot registry[kSlots];

std::atomic<int> caught_signal{0};
std::atomic<int> scopes{0};
static_assert(std::atomic<int>::is_always_lock_free);

void remove_registered_files() {
    for (Slot& slot : registry) {
        if (slot.state.load() == 2) ::unlink(slot.path);
    }
}

extern "C" void on_interrupt_signal(int signal) {
    if (scopes.load() > 0) {
        int none = 0;
        // The first signal in a scope: the command polls the flag and unwinds.
        if (caught_signal.compare_exchange_strong(none, signal)) return;
        // A second one: stop now, leaving no temporary behind.
        remove_registered_files();
        ::_exit(128 + none);
    }
    remove_registered_files();
    // End as the signal would have: its default action, delivered once this handler returns.
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    ::sigaction(signal, &fallback, nullptr);
    ::raise(signal);
}

}  // namespace

void install_interrupt_handlers() {
    static std::once_flag installed;
    std::call_once(installed, [] {
        struct sigaction action {};
        action.sa_handler = on_interrupt_signal;
        sigemptyset(&action.sa_mask);
        // Both signals of a pair wait for the handler of the first: the second sees its flag.
        for (int signal : kSignals) sigaddset(&action.sa_mask, signal);
        for (int signal : kSignals) ::sigaction(signal, &action, nullptr);
    });
}

InterruptScope::InterruptScope() {
    install_interrupt_handlers();
    if (scopes.fetch_add(1) == 0) caught_signal.store(0);
}

InterruptScope::~InterruptScope() { scopes.fetch_sub(1); }

bool interrupted() { return caught_signal.load() != 0; }

int interrupt_signal() { return caught_signal.load(); }

int interrupted_exit_code() {
    const int signal = caught_signal.load();
    return 128 + (signal != 0 ? signal : SIGINT);
}

TemporaryFileRegistration::TemporaryFileRegistration(const std::filesystem::path& path) {
    const std::string& text = path.native();
    if (text.size() >= kPathBytes) return;
    for (int i = 0; i < kSlots; ++i) {
        int free = 0;
        if (!registry[i].state.compare_exchange_strong(free, 1)) continue;
        std::memcpy(registry[i].path, text.c_str(), text.size() + 1);
        registry[i].state.store(2);
        slot_ = i;
        return;
    }
}

TemporaryFileRegistration::~TemporaryFileRegistration() {
    if (slot_ >= 0) registry[slot_].state.store(0);
}

void hold_for_test(std::string_view event) {
    static std::atomic<bool> held{false};
    const char* wanted = std::getenv("FGR_TEST_HOLD");
    if (wanted == nullptr || event != wanted || held.exchange(true)) return;
    std::fprintf(stderr,
                 "fgr: holding after the first %s until a signal (FGR_TEST_HOLD, pid %ld)\n",
                 wanted, static_cast<long>(::getpid()));
    std::fflush(stderr);
    const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (!interrupted() && std::chrono::steady_clock::now() < until) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

}  // namespace fgr
