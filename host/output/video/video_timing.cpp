// SPDX-License-Identifier: Apache-2.0
#include "output/video/video_timing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace fgr {

namespace {

// duration x fps rounded, at least one, before any conversion to an integer: a product past the
// 64-bit range (or not finite) is reported as over the limit rather than wrapped.
double frames_in(double duration, double fps) { return std::max(1.0, std::round(duration * fps)); }

}  // namespace

std::int64_t VideoTiming::frame_count() const {
    const double frames = frames_in(duration, fps);
    return frames < 9e18 ? static_cast<std::int64_t>(frames)
                         : std::numeric_limits<std::int64_t>::max();
}

float VideoTiming::frame_time(std::int64_t index) const {
    return static_cast<float>(start + static_cast<double>(index) / fps);
}

VideoTiming video_timing(const CameraPath& path, double fps, std::optional<double> start,
                         std::optional<double> duration) {
    const double first = path.keyframes.front().time, last = path.keyframes.back().time;
    if (!(fps > 0.0) || !std::isfinite(fps)) {
        throw std::invalid_argument(fmt::format("--fps must be a positive number (got {})", fps));
    }
    VideoTiming timing;
    timing.fps = fps;
    timing.start = start.value_or(first);
    if (!(timing.start >= first && timing.start < last)) {
        throw std::invalid_argument(fmt::format("--start {} is outside camera path '{}' [{}, {})",
                                                timing.start, path.name, first, last));
    }
    timing.duration = duration.value_or(last - timing.start);
    if (!(timing.duration > 0.0) || !std::isfinite(timing.duration)) {
        throw std::invalid_argument(fmt::format(
            "--duration must be a positive number of seconds (got {})", timing.duration));
    }
    if (const double frames = frames_in(timing.duration, fps);
        !(frames <= static_cast<double>(kMaxVideoFrames))) {
        throw std::invalid_argument(fmt::format(
            "{:g} s of camera path '{}' at {:g} fps is {:.0f} frames, over the limit of {} "
            "frames a video (render it in parts with --start and --duration, or at a lower --fps)",
            timing.duration, path.name, fps, frames, kMaxVideoFrames));
    }
    // The last frame's time must lie on the path, as `fgr render --time` would take it.
    const float last_frame = timing.frame_time(timing.frame_count() - 1);
    if (last_frame > path.keyframes.back().time) {
        throw std::invalid_argument(fmt::format(
            "--duration {} from {} runs past the end of camera path '{}' at {} (its length from "
            "there is {} s)",
            timing.duration, timing.start, path.name, last, last - timing.start));
    }
    return timing;
}

}  // namespace fgr
