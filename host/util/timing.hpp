// SPDX-License-Identifier: Apache-2.0
#pragma once
// Wall-clock time spent since a moment, on the steady clock, as the figures fgr reports it, and
// deadlines on the same clock.

#include <chrono>
#include <functional>

namespace fgr {

// Seconds from `start` to now.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Milliseconds from `start` to now.
inline double elapsed_ms(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

// True once `seconds` have passed from now (FrameRequest::enough for a time limit).
inline std::function<bool()> deadline_after(double seconds) {
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(seconds));
    return [until] { return std::chrono::steady_clock::now() >= until; };
}

}  // namespace fgr
