#pragma once
// Wall-clock time spent since a moment, on the steady clock, as the figures fgr reports it.

#include <chrono>

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

}  // namespace fgr
