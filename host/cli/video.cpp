// fgr video: a scene's camera path rendered frame by frame and encoded in-process (FFmpeg's
// libraries) into a video file, and/or written as a PNG or EXR frame sequence. Frame i is
// `fgr render --camera-path P --time t` at t = start + i / fps with the same options.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <numeric>
#include <optional>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "camera/camera.hpp"
#include "camera/view_validation.hpp"
#include "cli/progress.hpp"
#include "commands.hpp"
#include "device/program_cache.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_wire.hpp"
#include "distributed/task_farm.hpp"
#include "output/video/video_encoder.hpp"
#include "output/video/video_frames.hpp"
#include "output/video/video_timing.hpp"
#include "util/timing.hpp"

namespace fgr {
namespace {

// Set by SIGINT (Ctrl-C): the frame loop stops, and the encoder removes its temporary file.
volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int) { interrupted = 1; }

// Catches Ctrl-C while it lives, then gives SIGINT back its previous handler.
class InterruptGuard {
public:
    InterruptGuard() : previous_(std::signal(SIGINT, on_interrupt)) { interrupted = 0; }
    ~InterruptGuard() { std::signal(SIGINT, previous_); }
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void (*previous_)(int);
};

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

// The view at each frame's time, each one checked as `fgr render --time` checks its one.
std::vector<CameraView> frame_views(const CameraPath& path, const VideoTiming& timing) {
    std::vector<CameraView> views;
    for (int i = 0; i < timing.frame_count(); ++i) {
        const float time = timing.frame_time(i);
        views.push_back(evaluate_camera_path(path, time));
        if (const std::string problem = computed_view_problem(views.back()); !problem.empty()) {
            throw UsageError(
                fmt::format("camera path '{}' at time {}: {}", path.name, time, problem));
        }
    }
    return views;
}

std::filesystem::path frame_file(const VideoOptions& options, int index) {
    return std::filesystem::path(options.frames_directory) /
           fmt::format("frame_{:05}.{}", index, options.frames_format);
}

}  // namespace

void add_video_command(CLI::App& app, VideoOptions& options) {
    CLI::App* video = app.add_subcommand(
        "video", "render a camera path into a video file (.mp4 ...) and/or a PNG/EXR sequence");
    video->add_option("scene", options.frame.scene, "scene id (see `fgr list`)")->required();
    video
        ->add_option("--camera-path", options.frame.camera_path,
                     "camera path of the scene, or a .json file saved by `fgr view`")
        ->required();
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
}

int command_video(const VideoOptions& options) {
    check_video_options(options);
    const RenderOptions& frame_options = options.frame;
    const Discovery found = discover_for(frame_options.scene);
    const Scene scene =
        with_kernel_source(scene_as_used(find_scene(found, frame_options.scene), frame_options.dev),
                           frame_options.kernel_source);
    const CameraPath path = find_camera_path(scene, *frame_options.camera_path);
    VideoTiming timing;
    try {
        timing = video_timing(path, options.fps, options.start, options.duration);
    } catch (const std::invalid_argument& error) {
        throw UsageError(error.what());
    }
    const std::vector<CameraView> views = frame_views(path, timing);
    const auto [first_frame, last_frame] = frames_to_render(options, timing.frame_count());
    StillJob job = still_job(scene, scene_request(scene, frame_options), frame_options);
    const ComputeDevice device = open_requested_device(frame_options.device);
    ProgramCache cache(ProgramCache::default_directory());
    VideoFrameRenderer renderer(scene, device, cache, job.settings);
    // From every view of the video, so a frame range renders its frames as the whole video does.
    const bool in_double = renderer.choose_precision(views, job.request.width, job.request.params);

    InterruptGuard interrupt_guard;
    job.request.cancel = [] { return interrupted != 0; };
    const bool keep_planes = !options.frames_directory.empty();
    // Any rank renders any frame (distributed/task_farm.hpp); what travels is what rank 0
    // writes: the display image, and the planes too when it writes frame files.
    const TaskWork work = [&](int64_t index) {
        FrameRequest request = job.request;
        request.view = views[size_t(index)];
        Frame frame = renderer.render(request);
        if (interrupted) throw RuntimeFailure("interrupted: no video written");
        if (keep_planes) return frame_to_bytes(frame);
        Frame image_only;
        image_only.image = std::move(frame.image);
        return frame_to_bytes(image_only);
    };
    Cluster& cluster = Cluster::current();
    if (!cluster.coordinator()) {
        run_farm(cluster, {}, work, {});
        return 0;
    }
    std::optional<VideoEncoder> encoder;
    if (!options.output.empty()) {
        encoder.emplace(options.output,
                        VideoSettings{options.codec, job.request.width, job.request.height,
                                      options.fps, options.crf});
    }
    if (!options.frames_directory.empty()) {
        std::error_code error;
        std::filesystem::create_directories(options.frames_directory, error);
        if (error) {
            throw RuntimeFailure(fmt::format("cannot create directory '{}': {}",
                                             options.frames_directory, error.message()));
        }
    }
    spdlog::info("{} frames at {:g} fps: path time {:g} to {:g} s, {}{}{}", views.size(),
                 timing.fps, timing.start, timing.frame_time(timing.frame_count() - 1),
                 in_double ? "double" : "float",
                 encoder ? ", encoding " + encoder->description() : "",
                 cluster.alone() ? "" : fmt::format(", over {} MPI ranks", cluster.size()));
    const long total_frames = last_frame - first_frame + 1;
    if (options.frame_range) {
        spdlog::info("rendering frames {} to {} ({} of {})", first_frame, last_frame, total_frames,
                     views.size());
    }
    ProgressLine progress("frames");
    const auto started = std::chrono::steady_clock::now();
    const auto write_frame = [&](const Frame& frame, int64_t index) {
        if (encoder) encoder->add_frame(frame.image);
        if (!options.frames_directory.empty()) {
            try {
                write_still(frame_file(options, static_cast<int>(index)), frame,
                            StillOutput{frame_options.bit_depth,
                                        display_transform(scene, job.request.params),
                                        frame_options.alpha, job.aovs});
            } catch (const std::runtime_error& error) {
                throw RuntimeFailure(error.what());
            }
        }
    };
    // Frames go into the file in order, whichever rank finished first.
    InTaskOrder in_order(
        [&](int64_t index, std::vector<uint8_t>&& bytes) {
            write_frame(frame_from_bytes(bytes), index);
            const long done = static_cast<long>(index) - first_frame + 1;
            const double seconds = seconds_since(started);
            progress.update(
                done, total_frames, done, seconds,
                fmt::format("{:.2f} fps", seconds > 0.0 ? double(done) / seconds : 0.0));
        },
        first_frame);
    const ResultSink collect = [&](int64_t index, std::vector<uint8_t>&& bytes) {
        in_order.add(index, std::move(bytes));
    };
    std::vector<int64_t> frames(static_cast<size_t>(total_frames));
    std::iota(frames.begin(), frames.end(), int64_t(first_frame));
    FarmSettings farm;
    farm.interrupted = [] { return interrupted != 0; };
    FarmOutcome outcome;
    try {
        outcome = run_farm(cluster, frames, work, collect, farm);
    } catch (const std::runtime_error&) {
        progress.finish();
        if (interrupted) throw RuntimeFailure("interrupted: no video written");
        throw;
    }
    if (!outcome.finished) {
        progress.finish();
        throw RuntimeFailure("interrupted: no video written");
    }
    progress.finish();
    if (encoder) {
        encoder->finish();
        fmt::print("wrote {} ({} frames, {}x{}, {:g} fps, {})\n", options.output, views.size(),
                   job.request.width, job.request.height, timing.fps, encoder->description());
    }
    if (!options.frames_directory.empty()) {
        fmt::print("wrote {} frames ({} to {}) to {}\n", total_frames, first_frame, last_frame,
                   options.frames_directory);
    }
    if (!cluster.alone()) print_mpi_figures(cluster, outcome);
    return 0;
}

}  // namespace fgr
