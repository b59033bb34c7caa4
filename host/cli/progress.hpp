// SPDX-License-Identifier: Apache-2.0
#pragma once
// A progress line for long work on stderr: "tiles 37/120 (31%) | 12.3 Mrays/s | ETA 1m23s",
// redrawn in place on a terminal at most a few times a second, and as a plain line about every
// tenth of the way (or half minute) when stderr is a file or a pipe, so logs stay readable.

#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include "util/timing.hpp"

namespace fgr {

// "45s", "3m05s", "2h07m".
std::string format_duration(double seconds);

// "950 k", "12.3 M", "1.20 G": a rate's number with an SI prefix.
std::string format_rate(double per_second);

// What the line counts in: "tiles 37/120 (31%)", or, for work whose units mean little to a
// reader (bands of a frame), "render 31%".
enum class ProgressShows { Count, Percent };

class ProgressLine {
public:
    explicit ProgressLine(std::string unit, std::FILE* out = stderr,
                          ProgressShows shows = ProgressShows::Count);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // `done` of `total` units after `seconds`, with a detail such as a rate; the ETA follows
    // from the pace of the units done by this run (`fresh` of them, the others resumed).
    void update(long done, long total, long fresh, double seconds, const std::string& detail);
    // Ends the line (on a terminal) after the last update.
    void finish();

private:
    std::string unit_;
    std::FILE* out_;
    ProgressShows shows_;
    bool terminal_;
    bool open_ = false;  // a line is drawn and not ended
    std::chrono::steady_clock::time_point last_draw_{};
    long last_tenth_ = -1;
};

// Seconds since it was first read: a pace measured from the first unit reported, so that the
// kernels' build before it is no part of it.
class PaceClock {
public:
    double seconds() {
        if (!start_) start_ = std::chrono::steady_clock::now();
        return seconds_since(*start_);
    }

private:
    std::optional<std::chrono::steady_clock::time_point> start_;
};

// The seconds a render may take before it shows its progress: 2, or FGR_PROGRESS_DELAY's when set
// (the tests set 0 to see a tiny render's progress).
double progress_delay();

// A progress line for work that is often quick: nothing is drawn until it has run
// progress_delay() seconds, or its first units say the whole will take longer than that.
class DelayedProgress {
public:
    explicit DelayedProgress(std::string unit, ProgressShows shows = ProgressShows::Count,
                             std::FILE* out = stderr);
    // As ProgressLine::update, the units done all by this run.
    void update(long done, long total, double seconds, const std::string& detail);
    void finish() { line_.finish(); }

private:
    ProgressLine line_;
    double delay_;
    bool shown_ = false;
};

}  // namespace fgr
