// SPDX-License-Identifier: Apache-2.0
#pragma once
// A video of a camera path, frame by frame: the view of each frame, rendering the frames and
// writing them, in order, into the encoder and/or a sequence of frame files. Frame i is the still
// of the same settings at path time start + i / fps (video_timing.hpp), so `fgr video` and
// `fgr render --camera-path P --time t` give the same pixels. Where the frames are rendered is the
// caller's FrameDispatch: this process, or the ranks of an MPI job.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "output/frame_dispatch.hpp"
#include "output/still_image.hpp"
#include "output/video/video_encoder.hpp"
#include "output/video/video_timing.hpp"

namespace fgr {

// The view of frame `index` along `path`, checked as a still's view is: throws
// std::invalid_argument "camera path 'P' at time t: <problem>" when it cannot be rendered (a path
// whose camera passes through its target).
CameraView frame_view(const CameraPath& path, const VideoTiming& timing, std::int64_t index);

// Checks every frame's view (frame_view) one at a time, keeping none: a path that cannot be
// rendered somewhere fails before the first frame. Throws as frame_view.
void check_frame_views(const CameraPath& path, const VideoTiming& timing);

// A frame's view, computed when the frame is rendered: a video never holds all its views at once.
using FrameViews = std::function<CameraView(std::int64_t index)>;

// The frames of a video, and which of them to render.
struct VideoFrames {
    VideoTiming timing;
    FrameViews view;  // every frame's, so a range renders as the whole video does
    int first = 0;    // the frames to render: first .. last, inclusive
    int last = 0;

    long count() const { return long(last) - long(first) + 1; }
};

// The frames of `path` at `timing`, their views frame_view's.
FrameViews frame_views(const CameraPath& path, const VideoTiming& timing);

// What a video writes: a video file, frame files, or both.
struct VideoOutput {
    std::filesystem::path file;              // .mp4, .mkv, .webm, .gif ...; empty: none
    VideoSettings encoding;                  // the file's codec, size, fps and quality
    std::filesystem::path frames_directory;  // frame_00000.png ...; empty: none
    std::string frames_format = "png";       // png or exr
    StillOutput still;                       // how a frame file is written
    // The document frame file `index` carries (image/embedded_view.hpp: e.g. that frame's view),
    // when set; unset, every frame file carries still.embedded_view. Called as the frame is
    // written, on the process that writes it.
    std::function<std::string(int index)> frame_view{};
};

// DIRECTORY/frame_00042.FORMAT: frame `index`'s file, numbered as in the whole video.
std::filesystem::path video_frame_file(const VideoOutput& output, int index);

// Renders one frame: `request` with the frame's view.
using VideoFrameRender = std::function<Frame(const FrameRequest& request)>;

// What render_video tells its caller as it goes, each when set.
struct VideoHooks {
    // Polled between and after frames (and as FrameRequest::cancel): true stops the video, which
    // is then not written.
    std::function<bool()> interrupted;
    // The outputs are open, the first frame not yet rendered: the encoder's description ("" with
    // no video file).
    std::function<void(const std::string& encoder)> started;
    // Frame `written` (counted from 1) of frames.count() was written.
    std::function<void(long written)> frame_written;
    // The frames ended: all written, or the job stopped (an error, an interruption), before the
    // video file is finished.
    std::function<void()> stopped;
};

struct VideoResult {
    bool wrote = false;   // false on a process that only renders (an MPI job's worker)
    std::string encoder;  // the encoder's description; empty with no video file
};

// Renders frames.first .. frames.last through `dispatch` (each with `render`) and, on the
// process that receives them, writes them in order: the video file opened first (so a codec that
// cannot open fails before any frame is rendered), the frame directory created, and the file
// finished at the end. Frames travel with their planes only when frame files need them. Throws
// std::runtime_error "interrupted: no video written" when hooks.interrupted stopped it (the
// unfinished file is removed), and what rendering, encoding or writing throws.
VideoResult render_video(const VideoFrames& frames, FrameRequest request,
                         const VideoFrameRender& render, const VideoOutput& output,
                         FrameDispatch& dispatch, const VideoHooks& hooks = {});

}  // namespace fgr
