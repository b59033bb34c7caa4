// SPDX-License-Identifier: Apache-2.0
// The video frame loop (output/video/video_render.hpp) with a stand-in renderer, so it runs
// without a device: which frames are rendered with which view, the order and the names they are
// written under, what travels from the process that rendered a frame, what a process that only
// renders does, and an interruption. The frames go through the task farm of a cluster of this
// process alone (distributed/frame_farm.hpp), as `fgr video` without mpirun sends them, or through
// a dispatch of the test's own where it needs to see what travels.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_farm.hpp"
#include "image/image_io.hpp"
#include "output/video/video_render.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// Six frames at 2 fps whose views say their index (position.x), rendered as 64x48.
VideoFrames six_frames(int first, int last) {
    VideoFrames frames;
    frames.timing.fps = 2.0;
    frames.timing.duration = 3.0;
    frames.view = [](std::int64_t i) {
        CameraView view;
        view.position = {double(i), -3.0, 0.0};
        return view;
    };
    frames.first = first;
    frames.last = last;
    return frames;
}

FrameRequest small_request() {
    FrameRequest request;
    request.width = kWidth;
    request.height = kHeight;
    return request;
}

// A frame of the index its view says, grey level 40 a frame, with a linear plane.
Frame frame_of(const FrameRequest& request) {
    const int index = static_cast<int>(request.view.position.x);
    Frame frame;
    frame.image.width = request.width;
    frame.image.height = request.height;
    frame.image.rgb.assign(size_t(request.width) * size_t(request.height) * 3,
                           static_cast<uint8_t>(40 * index));
    frame.linear.assign(size_t(request.width) * size_t(request.height) * 3, float(index));
    frame.depth.assign(size_t(request.width) * size_t(request.height), 1.0f);
    frame.samples = request.samples;
    return frame;
}

std::vector<std::string> listing(const fs::path& directory) {
    std::vector<std::string> names;
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory, error)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// In this process, in order, keeping every frame the work returned; `receives` as told.
class RecordingDispatch final : public FrameDispatch {
public:
    explicit RecordingDispatch(bool receives = true) : receives_(receives) {}
    bool receives() const override { return receives_; }
    bool run(const std::vector<int64_t>& given, const FrameWork& work, const FrameSink& sink,
             const std::function<bool()>&) override {
        tasks = given;
        for (int64_t task : given) {
            Frame frame = work(task);
            travelled.push_back(frame);
            if (receives_) sink(task, std::move(frame));
        }
        return true;
    }
    std::vector<int64_t> tasks;
    std::vector<Frame> travelled;

private:
    bool receives_;
};

TEST(VideoRender, WritesTheRangesFramesInOrderNumberedAsInTheWholeVideo) {
    const test::TempDir dir("fgr_video_render");
    VideoOutput output;
    output.frames_directory = dir.path() / "frames";  // created by the loop
    std::vector<int> rendered;
    std::vector<std::string> events;
    VideoHooks hooks;
    hooks.started = [&](const std::string& encoder) { events.push_back("started " + encoder); };
    hooks.frame_written = [&](long written) {
        events.push_back("written " + std::to_string(written));
    };
    hooks.stopped = [&] { events.push_back("stopped"); };
    FarmFrameDispatch dispatch(Cluster::current());
    const VideoResult result = render_video(
        six_frames(2, 4), small_request(),
        [&](const FrameRequest& request) {
            rendered.push_back(static_cast<int>(request.view.position.x));
            return frame_of(request);
        },
        output, dispatch, hooks);
    EXPECT_TRUE(result.wrote);
    EXPECT_EQ(result.encoder, "");
    EXPECT_EQ(rendered, (std::vector<int>{2, 3, 4}));
    EXPECT_EQ(events, (std::vector<std::string>{"started ", "written 1", "written 2", "written 3",
                                                "stopped"}));
    ASSERT_EQ(listing(output.frames_directory),
              (std::vector<std::string>{"frame_00002.png", "frame_00003.png", "frame_00004.png"}));
    for (int index : {2, 3, 4}) {
        const Image8 image = read_png(video_frame_file(output, index));
        ASSERT_EQ(image.width, kWidth);
        ASSERT_EQ(image.height, kHeight);
        EXPECT_EQ(image.rgb.front(), 40 * index) << "frame " << index;
    }
    EXPECT_EQ(video_frame_file(output, 42), output.frames_directory / "frame_00042.png");
}

TEST(VideoRender, FramesTravelWithTheirPlanesOnlyWhenFrameFilesNeedThem) {
    const test::TempDir dir("fgr_video_render");
    const auto render = [](const FrameRequest& request) { return frame_of(request); };
    VideoOutput image_only;  // a video file alone needs the display image alone
    RecordingDispatch without_files;
    render_video(six_frames(0, 1), small_request(), render, image_only, without_files);
    ASSERT_EQ(without_files.travelled.size(), 2u);
    for (const Frame& frame : without_files.travelled) {
        EXPECT_FALSE(frame.image.rgb.empty());
        EXPECT_TRUE(frame.linear.empty());
        EXPECT_TRUE(frame.depth.empty());
    }

    VideoOutput exr_files;
    exr_files.frames_directory = dir.path();
    exr_files.frames_format = "exr";
    RecordingDispatch with_files;
    render_video(six_frames(0, 1), small_request(), render, exr_files, with_files);
    ASSERT_EQ(with_files.travelled.size(), 2u);
    for (const Frame& frame : with_files.travelled) EXPECT_FALSE(frame.linear.empty());
    EXPECT_EQ(listing(dir.path()),
              (std::vector<std::string>{"frame_00000.exr", "frame_00001.exr"}));
}

TEST(VideoRender, AProcessThatOnlyRendersOpensNoOutputs) {
    const test::TempDir dir("fgr_video_render");
    VideoOutput output;
    output.file = dir.path() / "video.mp4";
    output.encoding = VideoSettings{"", kWidth, kHeight, 2.0, {}};
    output.frames_directory = dir.path() / "frames";
    bool started = false;
    VideoHooks hooks;
    hooks.started = [&](const std::string&) { started = true; };
    RecordingDispatch worker(false);
    const VideoResult result = render_video(
        six_frames(1, 3), small_request(),
        [](const FrameRequest& request) { return frame_of(request); }, output, worker, hooks);
    EXPECT_FALSE(result.wrote);
    EXPECT_FALSE(started);
    EXPECT_EQ(worker.tasks, (std::vector<int64_t>{1, 2, 3}));
    EXPECT_TRUE(listing(dir.path()).empty()) << listing(dir.path()).front();
}

TEST(VideoRender, AnInterruptionStopsTheLoopAndLeavesNoVideo) {
    const test::TempDir dir("fgr_video_render");
    VideoOutput output;
    output.file = dir.path() / "video.mp4";
    output.encoding = VideoSettings{"", kWidth, kHeight, 2.0, {}};
    int rendered = 0;
    bool stopped = false, cancel_set = false;
    VideoHooks hooks;
    hooks.interrupted = [&] { return rendered >= 2; };
    hooks.stopped = [&] { stopped = true; };
    FarmFrameDispatch dispatch(Cluster::current());
    try {
        render_video(
            six_frames(0, 5), small_request(),
            [&](const FrameRequest& request) {
                cancel_set = static_cast<bool>(request.cancel);
                ++rendered;
                return frame_of(request);
            },
            output, dispatch, hooks);
        FAIL() << "an interrupted video was written";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()), "interrupted: no video written");
    }
    EXPECT_EQ(rendered, 2);
    EXPECT_TRUE(cancel_set) << "a frame under way is abandoned too";
    EXPECT_TRUE(stopped);
    EXPECT_TRUE(listing(dir.path()).empty()) << listing(dir.path()).front();
}

TEST(VideoRender, FrameViewsRefuseAMomentThatCannotBeRendered) {
    CameraPath path;
    path.name = "through";
    Keyframe key;
    key.time = 0.0f;
    key.view.position = {0.0, 0.0, 0.0};  // at its target
    path.keyframes.push_back(key);
    key.time = 1.0f;
    key.view.position = {0.0, -3.0, 0.0};
    path.keyframes.push_back(key);
    const VideoTiming timing = video_timing(path, 4.0, {}, {});
    try {
        check_frame_views(path, timing);
        FAIL() << "a view at its target was accepted";
    } catch (const std::invalid_argument& error) {
        EXPECT_EQ(std::string(error.what()).rfind("camera path 'through' at time 0: ", 0), 0u)
            << error.what();
    }
    path.keyframes.front().view.position = {0.0, -2.0, 0.0};
    EXPECT_NO_THROW(check_frame_views(path, timing));
    const FrameViews views = frame_views(path, timing);
    EXPECT_EQ(views(0).position, path.keyframes.front().view.position);
    EXPECT_EQ(views(3).position, evaluate_camera_path(path, timing.frame_time(3)).position);
}

}  // namespace
}  // namespace fgr
