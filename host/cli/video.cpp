// SPDX-License-Identifier: Apache-2.0
// fgr video: a scene's camera path rendered frame by frame and encoded in-process (FFmpeg's
// libraries) into a video file, and/or written as a PNG or EXR frame sequence. Frame i is
// `fgr render --camera-path P --time t` at t = start + i / fps with the same options. The frame
// loop is output/video/video_render.hpp's; here are the options, their checks and the report.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <regex>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "camera/camera.hpp"
#include "camera/camera_path_file.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "device/program_cache.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_farm.hpp"
#include "output/denoised_frame.hpp"
#include "output/video/video_encoder.hpp"
#include "output/video/video_frames.hpp"
#include "output/video/video_render.hpp"
#include "output/video/video_timing.hpp"
#include "render/sample_budget.hpp"
#include "scene/scene_json.hpp"
#include "util/interruption.hpp"
#include "util/timing.hpp"
#include "view_options.hpp"

namespace fgr {
namespace {

// Throws UsageError unless `file`'s directory exists and can be written into.
void check_writable_directory_of(const std::filesystem::path& file) {
    check_output_directory(file);
    const auto directory = file.has_parent_path() ? file.parent_path() : ".";
    if (access(directory.c_str(), W_OK) != 0) {
        throw UsageError(fmt::format("cannot write '{}': directory '{}' is not writable",
                                     file.string(), directory.string()));
    }
}

// The frames "A:B" names, first and last (0-based, inclusive); UsageError unless 0 <= A <= B.
std::pair<int, int> parse_frame_range(const std::string& text) {
    const std::regex form(R"((\d{1,9}):(\d{1,9}))");
    std::smatch match;
    if (!std::regex_match(text, match, form)) {
        throw UsageError(
            fmt::format("--frame-range '{}' must be A:B, the first and last frame "
                        "(0-based), e.g. 0:99",
                        text));
    }
    const int first = std::stoi(match[1]), last = std::stoi(match[2]);
    if (first > last) {
        throw UsageError(
            fmt::format("--frame-range {}: the first frame comes after the last", text));
    }
    return {first, last};
}

// The frames to render: all, or --frame-range's (UsageError past the video's last frame).
std::pair<int, int> frames_to_render(const VideoOptions& options, int frame_count) {
    if (!options.frame_range) return {0, frame_count - 1};
    const auto [first, last] = parse_frame_range(*options.frame_range);
    if (last >= frame_count) {
        throw UsageError(
            fmt::format("--frame-range {} goes past the last frame: this video has "
                        "{} frames, 0:{}",
                        *options.frame_range, frame_count, frame_count - 1));
    }
    return {first, last};
}

// Checks that need no scene: outputs, formats, codec and size, so bad input fails before any
// kernel is built or file written.
void check_video_options(const VideoOptions& options) {
    check_frame_options(options.frame);
    if (options.output.empty() && options.frames_directory.empty()) {
        throw UsageError("video needs -o FILE (.mp4 ...) or --frames DIR, or both");
    }
    const bool exr_frames = options.frames_format == "exr";
    if (!options.frame.aovs.empty() && !(exr_frames && !options.frames_directory.empty())) {
        throw UsageError("--aov needs EXR frames: --frames DIR --frames-format exr");
    }
    if (options.frame.bit_depth != 8 && (exr_frames || options.frames_directory.empty())) {
        throw UsageError("--bit-depth is for PNG frames (--frames DIR); a video is 8-bit");
    }
    if (!(options.fps > 0.0)) {
        throw UsageError(fmt::format("--fps must be positive (got {})", options.fps));
    }
    if (!options.output.empty()) {
        check_writable_directory_of(options.output);
        try {
            check_video_settings(options.output,
                                 VideoSettings{options.codec, options.frame.width,
                                               options.frame.height, options.fps, options.crf});
        } catch (const std::invalid_argument& error) {
            throw UsageError(error.what());
        }
    } else if (!options.codec.empty() || options.crf) {
        throw UsageError("--codec and --crf are for a video file (-o)");
    }
    if (options.frame_range) {
        if (options.frames_directory.empty() || !options.output.empty()) {
            throw UsageError(
                "--frame-range renders some frames of a sequence: give --frames DIR "
                "and no -o (encode the whole directory with fgr merge --frames DIR "
                "-o FILE)");
        }
        parse_frame_range(*options.frame_range);  // a malformed range fails before any loading
    }
    if (!options.frames_directory.empty()) {
        const std::filesystem::path directory = options.frames_directory;
        if (std::error_code error; std::filesystem::exists(directory, error) &&
                                   !std::filesystem::is_directory(directory, error)) {
            throw UsageError(fmt::format("--frames '{}' is not a directory", directory.string()));
        }
        // An existing directory is written into, a new one created (in a writable directory).
        check_writable_directory_of(std::filesystem::is_directory(directory) ? directory / "frame"
                                                                             : directory);
    }
}

}  // namespace

void add_video_command(CLI::App& app, VideoOptions& options) {
    CLI::App* video = app.add_subcommand(
        "video", "render a camera path into a video file (.mp4 ...) and/or a PNG/EXR sequence");
    video->add_option("scene", options.frame.scene,
                      "scene id (see `fgr list`), scene file (.so, .ifs.json, .formula.json, .cl) "
                      "or view file (.fgrview.json) to start from");
    video->add_option("--camera-path", options.frame.camera_path,
                      "camera path of the scene, or a .json file saved by `fgr view` (default "
                      "with a view: a turn around the view's target, starting at the view)");
    video->add_option("-o,--output", options.output,
                      "video file: .mp4/.mkv/.mov (H.264), .webm (VP9), .gif, .webp, .apng");
    video->add_option("--frames", options.frames_directory,
                      "also (or instead) write each frame as DIR/frame_00000.png ...");
    video
        ->add_option("--frames-format", options.frames_format,
                     "png (tone-mapped, as `fgr render -o x.png`) or exr (linear, with --aov)")
        ->check(CLI::IsMember({"png", "exr"}));
    video->add_option("--fps", options.fps, "frames per second (default 30)");
    video->add_option("--start", options.start,
                      "path time of the first frame, seconds (default: the first keyframe's)");
    video->add_option("--duration", options.duration,
                      "seconds of path time to render (default: to the last keyframe)");
    video->add_option("--codec", options.codec,
                      "FFmpeg encoder: libx264 (default for .mp4), mpeg4, libvpx-vp9, ...");
    video->add_option("--crf", options.crf,
                      "constant quality: lower is better and bigger (libx264 default 18, 0 "
                      "lossless; libvpx-vp9 default 24)");
    video->add_option("--frame-range", options.frame_range,
                      "A:B: render only frames A..B (0-based, inclusive) into --frames DIR, "
                      "numbered as in the whole video (share a video out to machines, then "
                      "fgr merge --frames DIR -o FILE)");
    add_frame_options(video, options.frame);
    video->add_option("--view", options.frame.view,
                      "start from a view: a .fgrview.json file, or an image fgr wrote; each frame "
                      "renders with its settings, any option typed overriding them");
    record_typed_options(video, options.frame.typed);
}

namespace {

// The options with a view's settings under those typed, when a view was given.
std::optional<ViewFile> apply_view_argument(VideoOptions& options) {
    const std::optional<std::string> argument = view_argument(options.frame);
    if (!argument) return std::nullopt;
    ViewFile view = load_view_argument(*argument);
    apply_view(options.frame, view);
    return view;
}

// What a video file carries in its metadata: the camera path, the timing and the view every frame
// is rendered with (its camera the first frame's).
std::string video_metadata(ViewFile view, const CameraPathFile& path, const VideoTiming& timing) {
    view.camera = evaluate_camera_path(path.path, timing.frame_time(0));
    nlohmann::ordered_json document;
    document["format"] = "fgr-video";
    document["version"] = 1;
    document["fps"] = timing.fps;
    document["start"] = timing.start;
    document["frames"] = timing.frame_count();
    document["camera_path"] = nlohmann::ordered_json::parse(camera_path_json(path));
    document["view"] = nlohmann::ordered_json::parse(view_file_text(view));
    return document.dump(2);
}

// The camera path the video follows: --camera-path's, else a turn around the view's target that
// starts at the view.
CameraPath video_camera_path(const Scene& scene, const RenderOptions& frame_options,
                             const std::optional<ViewFile>& view) {
    if (frame_options.camera_path) return find_camera_path(scene, *frame_options.camera_path);
    const CameraView start = overridden_view(view->camera, frame_options.view_override);
    return scene_json::default_orbit(NamedCamera{"view", start});
}

}  // namespace

int command_video(const VideoOptions& typed_options) {
    install_interrupt_handlers();
    VideoOptions options = typed_options;
    const std::optional<ViewFile> view = apply_view_argument(options);
    if (options.frame.scene.empty()) {
        throw UsageError("video needs a SCENE (see `fgr list`) or a view file");
    }
    if (!options.frame.camera_path && !view) {
        throw UsageError(
            "video needs --camera-path (a scene's path or a .json file), or a view "
            "to turn around");
    }
    check_video_options(options);
    const RenderOptions& frame_options = options.frame;
    const Scene scene = with_kernel_source(
        scene_as_used(scene_from_argument(frame_options.scene), frame_options.dev),
        frame_options.kernel_source);
    if (view) warn_if_scene_changed(*view, scene);
    const CameraPath path = video_camera_path(scene, frame_options, view);
    VideoFrames frames;
    try {
        frames.timing = video_timing(path, options.fps, options.start, options.duration);
        check_frame_views(path, frames.timing);
        frames.view = frame_views(path, frames.timing);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    const VideoTiming& timing = frames.timing;
    // video_timing bounds the count by kMaxVideoFrames, well inside an int.
    const int frame_count = static_cast<int>(timing.frame_count());
    std::tie(frames.first, frames.last) = frames_to_render(options, frame_count);
    if (frame_options.mode.denoise) {
        const RenderMode mode = chosen_mode(frame_options.mode, scene);
        check_denoise(mode, still_samples(mode, frame_options.samples));
    }
    const StillJob job = still_job(scene, scene_request(scene, frame_options), frame_options);
    const ComputeDevice device = open_requested_device(frame_options.device);
    check_render_cost(scene, job, frame_options, device.info, double(frames.count()),
                      static_cast<double>(Cluster::current().size()));
    ProgramCache cache(ProgramCache::default_directory());
    VideoFrameRenderer renderer(scene, device, cache, job.settings);
    // From every view of the video, so a frame range renders its frames as the whole video does.
    const bool in_double =
        renderer.choose_precision(frame_count, frames.view, job.request.width, job.request.params);

    VideoOutput output;
    output.file = options.output;
    output.encoding = VideoSettings{options.codec, job.request.width, job.request.height,
                                    options.fps, options.crf};
    output.frames_directory = options.frames_directory;
    output.frames_format = options.frames_format;
    output.still =
        StillOutput{frame_options.bit_depth, display_transform(scene, job.request.params),
                    frame_options.alpha, job.aovs};
    // Each frame file carries its own view, the container the path and the frames' settings.
    ViewFile frame_view = view_of_render(scene, job.request, frame_options);
    frame_view.precision = in_double ? Precision::Double : Precision::Float;
    output.frame_view = [&frames, frame_view](int index) mutable {
        frame_view.camera = frames.view(index);
        return view_file_text(frame_view);
    };
    output.encoding.embedded_view =
        video_metadata(frame_view, CameraPathFile{scene.id, path}, timing);

    Cluster& cluster = Cluster::current();
    // Ctrl-C or SIGTERM stops between frames (and within one); the encoder and the frame writer
    // remove their temporaries.
    const InterruptScope interrupt_scope;
    std::optional<ProgressLine> progress;
    std::chrono::steady_clock::time_point started;
    VideoHooks hooks;
    hooks.interrupted = interrupted;
    hooks.started = [&](const std::string& encoder) {
        spdlog::info("{} frames at {:g} fps: path time {:g} to {:g} s, {}{}{}", frame_count,
                     timing.fps, timing.start, timing.frame_time(timing.frame_count() - 1),
                     in_double ? "double" : "float", encoder.empty() ? "" : ", encoding " + encoder,
                     cluster.alone() ? "" : fmt::format(", over {} MPI ranks", cluster.size()));
        if (options.frame_range) {
            spdlog::info("rendering frames {} to {} ({} of {})", frames.first, frames.last,
                         frames.count(), frame_count);
        }
        progress.emplace("frames");
        started = std::chrono::steady_clock::now();
    };
    hooks.frame_written = [&](long done) {
        const double seconds = seconds_since(started);
        progress->update(done, frames.count(), done, seconds,
                         fmt::format("{:.2f} fps", seconds > 0.0 ? double(done) / seconds : 0.0));
        hold_for_test("frame");
    };
    hooks.stopped = [&] { progress->finish(); };
    FarmFrameDispatch dispatch(cluster);
    VideoResult result;
    try {
        result = render_video(
            frames, job.request,
            [&](const FrameRequest& request) {
                if (!frame_options.mode.denoise) return renderer.render(request);
                // Each frame on its own: two halves of its samples for the noise, then filtered.
                Frame frame = render_with_variance(
                    request, [&](const FrameRequest& half) { return renderer.render(half); });
                if (!frame.cancelled) {
                    denoise_frame(frame, output.still.display, DenoiseSettings{});
                }
                return frame;
            },
            output, dispatch, hooks);
    } catch (const std::runtime_error&) {
        if (!dispatch.lost().empty()) throw RuntimeFailure(dispatch.lost());
        if (!interrupted()) throw;
        spdlog::error("interrupted: no video written{}",
                      options.output.empty() ? "" : fmt::format(" to '{}'", options.output));
        return interrupted_exit_code();
    }
    if (!result.wrote) return 0;
    if (!options.output.empty()) {
        fmt::print("wrote {} ({} frames, {}x{}, {:g} fps, {})\n", options.output, frame_count,
                   job.request.width, job.request.height, timing.fps, result.encoder);
    }
    if (!options.frames_directory.empty()) {
        fmt::print("wrote {} frames ({} to {}) to {}\n", frames.count(), frames.first, frames.last,
                   options.frames_directory);
    }
    if (!cluster.alone()) print_mpi_figures(cluster, dispatch.outcome());
    return 0;
}

}  // namespace fgr
