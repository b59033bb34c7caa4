// SPDX-License-Identifier: Apache-2.0
#include "output/video/video_render.hpp"

#include <fmt/format.h>

#include <numeric>
#include <optional>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "camera/view_validation.hpp"

namespace fgr {
namespace {

constexpr const char* kInterrupted = "interrupted: no video written";

bool asked_to_stop(const VideoHooks& hooks) { return hooks.interrupted && hooks.interrupted(); }

}  // namespace

CameraView frame_view(const CameraPath& path, const VideoTiming& timing, std::int64_t index) {
    const float time = timing.frame_time(index);
    CameraView view = evaluate_camera_path(path, time);
    if (const std::string problem = computed_view_problem(view); !problem.empty()) {
        throw std::invalid_argument(
            fmt::format("camera path '{}' at time {}: {}", path.name, time, problem));
    }
    return view;
}

void check_frame_views(const CameraPath& path, const VideoTiming& timing) {
    for (std::int64_t i = 0; i < timing.frame_count(); ++i) frame_view(path, timing, i);
}

FrameViews frame_views(const CameraPath& path, const VideoTiming& timing) {
    return [path, timing](std::int64_t index) { return frame_view(path, timing, index); };
}

std::filesystem::path video_frame_file(const VideoOutput& output, int index) {
    return output.frames_directory / fmt::format("frame_{:05}.{}", index, output.frames_format);
}

VideoResult render_video(const VideoFrames& frames, FrameRequest request,
                         const VideoFrameRender& render, const VideoOutput& output,
                         FrameDispatch& dispatch, const VideoHooks& hooks) {
    if (hooks.interrupted) {
        request.cancel = hooks.interrupted;
        request.cancel_response = CancelResponse::Batch;
    }
    const bool frame_files = !output.frames_directory.empty();
    // What travels from the rank that rendered a frame is what gets written: the display image,
    // and the planes too when frame files are written (an EXR's layers, a 16-bit PNG's colour).
    const FrameWork work = [&](int64_t index) {
        FrameRequest frame_request = request;
        frame_request.view = frames.view(index);
        Frame frame = render(frame_request);
        if (asked_to_stop(hooks)) throw std::runtime_error(kInterrupted);
        if (frame_files) return frame;
        Frame image_only;
        image_only.image = std::move(frame.image);
        return image_only;
    };
    std::vector<int64_t> tasks(static_cast<size_t>(frames.count()));
    std::iota(tasks.begin(), tasks.end(), int64_t(frames.first));
    if (!dispatch.receives()) {
        dispatch.run(tasks, work, {}, hooks.interrupted);
        return {};
    }

    std::optional<VideoEncoder> encoder;
    if (!output.file.empty()) encoder.emplace(output.file, output.encoding);
    if (frame_files) {
        std::error_code error;
        std::filesystem::create_directories(output.frames_directory, error);
        if (error) {
            throw std::runtime_error(fmt::format("cannot create directory '{}': {}",
                                                 output.frames_directory.string(),
                                                 error.message()));
        }
    }
    VideoResult result;
    result.wrote = true;
    if (encoder) result.encoder = encoder->description();
    if (hooks.started) hooks.started(result.encoder);

    // The dispatch hands the frames over in order, whichever process finished first.
    const FrameSink write = [&](int64_t index, Frame&& frame) {
        if (encoder) encoder->add_frame(frame.image);
        if (frame_files && output.frame_view) {
            StillOutput still = output.still;
            still.embedded_view = output.frame_view(int(index));
            write_still(video_frame_file(output, int(index)), frame, still);
        } else if (frame_files) {
            write_still(video_frame_file(output, int(index)), frame, output.still);
        }
        if (hooks.frame_written) hooks.frame_written(long(index) - frames.first + 1);
    };
    const auto stopped = [&] {
        if (hooks.stopped) hooks.stopped();
    };
    bool finished = false;
    try {
        finished = dispatch.run(tasks, work, write, hooks.interrupted);
    } catch (const std::runtime_error&) {
        stopped();
        if (asked_to_stop(hooks)) throw std::runtime_error(kInterrupted);
        throw;
    }
    stopped();
    if (!finished) throw std::runtime_error(kInterrupted);
    if (encoder) encoder->finish();
    return result;
}

}  // namespace fgr
