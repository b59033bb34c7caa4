// SPDX-License-Identifier: Apache-2.0
#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace fgr {

std::string format_duration(double seconds) {
    const long s = std::lround(std::max(seconds, 0.0));
    if (s < 60) return fmt::format("{}s", s);
    if (s < 3600) return fmt::format("{}m{:02d}s", s / 60, s % 60);
    return fmt::format("{}h{:02d}m", s / 3600, (s % 3600) / 60);
}

std::string format_rate(double per_second) {
    if (per_second >= 1e9) return fmt::format("{:.2f} G", per_second / 1e9);
    if (per_second >= 1e6) return fmt::format("{:.1f} M", per_second / 1e6);
    if (per_second >= 1e3) return fmt::format("{:.0f} k", per_second / 1e3);
    return fmt::format("{:.0f} ", per_second);
}

ProgressLine::ProgressLine(std::string unit, std::FILE* out, ProgressShows shows)
    : unit_(std::move(unit)), out_(out), shows_(shows), terminal_(::isatty(::fileno(out)) == 1) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::update(long done, long total, long fresh, double seconds,
                          const std::string& detail) {
    const auto now = std::chrono::steady_clock::now();
    const long tenth = total > 0 ? done * 10 / total : 10;
    const bool last = done >= total;
    if (terminal_) {
        if (!last && now - last_draw_ < std::chrono::milliseconds(250)) return;
    } else if (!last && tenth == last_tenth_ && now - last_draw_ < std::chrono::seconds(30)) {
        return;
    }
    last_draw_ = now;
    last_tenth_ = tenth;
    std::string eta = "ETA --";
    if (fresh > 0 && !last) {
        eta = "ETA " + format_duration(seconds / double(fresh) * double(total - done));
    } else if (last) {
        eta = "took " + format_duration(seconds);
    }
    const double percent = total > 0 ? 100.0 * double(done) / double(total) : 100.0;
    const std::string text =
        shows_ == ProgressShows::Count
            ? fmt::format("{} {}/{} ({:.0f}%) | {} | {}", unit_, done, total, percent, detail, eta)
            : fmt::format("{} {:.0f}% | {} | {}", unit_, percent, detail, eta);
    if (terminal_) {
        fmt::print(out_, "\r{}\x1b[K", text);
        open_ = true;
    } else {
        fmt::print(out_, "{}\n", text);
    }
    std::fflush(out_);
}

void ProgressLine::finish() {
    if (!open_) return;
    fmt::print(out_, "\n");
    std::fflush(out_);
    open_ = false;
}

double progress_delay() {
    constexpr double kDelaySeconds = 2.0;
    const char* text = std::getenv("FGR_PROGRESS_DELAY");
    if (text == nullptr || *text == '\0') return kDelaySeconds;
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    return *end == '\0' && std::isfinite(seconds) && seconds >= 0.0 ? seconds : kDelaySeconds;
}

DelayedProgress::DelayedProgress(std::string unit, ProgressShows shows, std::FILE* out)
    : line_(std::move(unit), out, shows), delay_(progress_delay()) {}

void DelayedProgress::update(long done, long total, double seconds, const std::string& detail) {
    if (!shown_) {
        // The pace of the first units says how long the whole takes; a few of them first, so that
        // one quick band does not speak for the rest.
        const bool long_so_far = seconds >= delay_;
        const bool long_in_all =
            done > 0 && seconds >= delay_ / 4.0 && seconds / double(done) * double(total) > delay_;
        if (!long_so_far && !long_in_all) return;
        shown_ = true;
    }
    line_.update(done, total, done, seconds, detail);
}

}  // namespace fgr
