// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which moments of a camera path a video shows: frame i is the path at time start + i / fps, for
// every i whose time falls before start + duration. The path's own clock is the keyframes' times
// (seconds), so a video at any fps plays the path at its recorded speed.

#include <cstdint>
#include <optional>
#include <vector>

#include "scene/scene.hpp"

namespace fgr {

// The most frames one video may have: over nine hours at 30 fps. A longer timing is refused
// before anything is computed for its frames (render a longer film in parts, with --start and
// --duration).
inline constexpr std::int64_t kMaxVideoFrames = 1'000'000;

struct VideoTiming {
    double fps = 30.0;
    double start = 0.0;     // path time of frame 0
    double duration = 0.0;  // seconds of path time the video covers
    // Frames in the video: duration x fps rounded to the nearest whole frame (at least one), so
    // 10 s at 30 fps is 300 frames, the last at start + 299/30 (the end keyframe itself would be
    // the first frame of an 11th second). Counted in 64 bits: video_timing refuses more than
    // kMaxVideoFrames.
    std::int64_t frame_count() const;
    // Path time of frame `index`, in float as `fgr render --time` reads it, so the frame equals
    // that render.
    float frame_time(std::int64_t index) const;
};

// The timing for `path`: start defaults to its first keyframe's time, duration to the rest of the
// path from there (to its last keyframe). Throws std::invalid_argument for fps <= 0 or not
// finite, a duration <= 0, a start or end outside the path's keyframe times, or more frames than
// kMaxVideoFrames (the message gives the count and the limit).
VideoTiming video_timing(const CameraPath& path, double fps, std::optional<double> start,
                         std::optional<double> duration);

}  // namespace fgr
