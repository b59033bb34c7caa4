// SPDX-License-Identifier: Apache-2.0
// Every writer of the output library passes the view on (image/embedded_view.hpp): write_still in
// each format, the streamed writers of tiled stills and merges, a video's frame files (one view
// for all, or each frame its own) and its container's metadata. Frames are made by hand and the
// video loop runs a stand-in renderer, so no kernel is built.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

extern "C" {
#include <libavformat/avformat.h>
#include <libavutil/dict.h>
}

#include "child_process.hpp"
#include "distributed/cluster.hpp"
#include "distributed/frame_farm.hpp"
#include "image/embedded_view.hpp"
#include "image/image_io.hpp"
#include "output/still_image.hpp"
#include "output/tiled/streaming_image.hpp"
#include "output/video/video_encoder.hpp"
#include "output/video/video_render.hpp"

namespace fgr {
// A namespace of its own: the tests compile in unity batches, beside helpers of the same names.
namespace embedded_view_outputs_test {
namespace {

namespace fs = std::filesystem;

const std::string kView = R"({"scene":"menger","camera":{"position":[1,2,3]},"note":"ünï ✓"})";

// A 32x24 frame with every plane write_still reads, varied per pixel.
Frame hand_made_frame(int width = 32, int height = 24, float level = 0.5f) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    Frame frame;
    frame.image = Image8{width, height, std::vector<uint8_t>(pixels * 3), {}};
    for (std::size_t i = 0; i < pixels * 3; ++i) {
        frame.image.rgb[i] = static_cast<uint8_t>(i * 7 + std::size_t(level * 100));
        frame.linear.push_back(level * float(i % 17) / 16.0f);
        frame.foreground.push_back(0.5f * frame.linear.back());
        frame.albedo.push_back(0.25f);
        frame.normal.push_back(i % 3 == 2 ? 1.0f : 0.0f);
    }
    for (std::size_t i = 0; i < pixels; ++i) {
        frame.depth.push_back(i % 5 == 0 ? -1.0f : float(i));
        frame.alpha.push_back(i % 5 == 0 ? 0.0f : 0.5f);
    }
    frame.samples = 1;
    return frame;
}

std::optional<std::string> container_comment(const fs::path& file) {
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) {
        ADD_FAILURE() << "cannot open " << file;
        return std::nullopt;
    }
    std::optional<std::string> comment;
    if (const AVDictionaryEntry* entry = av_dict_get(format->metadata, "comment", nullptr, 0)) {
        comment = entry->value;
    }
    avformat_close_input(&format);
    return comment;
}

TEST(EmbeddedViewOutputs, WriteStillCarriesTheViewInEveryFormat) {
    const test::TempDir dir("fgr_view_outputs");
    const Frame frame = hand_made_frame();
    struct Case {
        const char* name;
        StillOutput output;
    };
    StillOutput exr_with_layers;
    exr_with_layers.aovs = Aovs{true, true, true, false};
    exr_with_layers.alpha = true;
    const std::vector<Case> cases = {
        {"a.png", StillOutput{}},
        {"a16.png", StillOutput{16, {}, false, {}}},
        {"alpha.png", StillOutput{8, {}, true, {}}},
        {"alpha16.png", StillOutput{16, {}, true, {}}},
        {"a.exr", StillOutput{}},
        {"layers.exr", exr_with_layers},
    };
    for (Case c : cases) {
        SCOPED_TRACE(c.name);
        const fs::path plain = dir.path() / (std::string("plain_") + c.name);
        const fs::path carrying = dir.path() / c.name;
        write_still(plain, frame, c.output);
        c.output.embedded_view = kView;
        write_still(carrying, frame, c.output);
        EXPECT_EQ(read_embedded_view(plain), std::nullopt);
        EXPECT_EQ(read_embedded_view(carrying), kView);
        if (carrying.extension() == ".png") {
            EXPECT_EQ(read_png_samples(carrying).samples, read_png_samples(plain).samples);
        }
    }
}

// The writers tiled stills (TiledFile) and fgr merge (merge_parts) stream through.
TEST(EmbeddedViewOutputs, StreamedImagesCarryTheViewInEveryFormat) {
    const test::TempDir dir("fgr_view_outputs");
    const std::vector<std::pair<ImageFormat, RowLayout>> cases = {
        {ImageFormat::Png, {{"R", "G", "B"}, SampleType::U8}},
        {ImageFormat::Png, {{"R", "G", "B", "A"}, SampleType::U16}},
        {ImageFormat::Tiff, {{"R", "G", "B"}, SampleType::U8}},
        {ImageFormat::Tiff, {{"R", "G", "B", "A"}, SampleType::U16}},
        {ImageFormat::Exr, {{"R", "G", "B", "depth.Z"}, SampleType::F32}},
    };
    constexpr int kWidth = 24, kHeight = 10;
    int index = 0;
    for (const auto& [format, layout] : cases) {
        const fs::path plain = dir.path() / ("plain" + std::to_string(index));
        const fs::path carrying = dir.path() / ("view" + std::to_string(index++));
        std::vector<uint8_t> rows(std::size_t(kWidth) * kHeight * layout.pixel_bytes());
        if (format != ImageFormat::Exr) {
            for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<uint8_t>(i * 13);
        }
        for (const fs::path& file : {plain, carrying}) {
            auto writer = open_streaming_image(file, format, kWidth, kHeight, layout, {},
                                               file == carrying ? kView : "");
            writer->write_rows(rows.data(), kHeight);
            writer->finish();
        }
        EXPECT_EQ(read_embedded_view(plain), std::nullopt) << plain;
        EXPECT_EQ(read_embedded_view(carrying), kView) << carrying;
        if (format == ImageFormat::Png) {
            EXPECT_EQ(read_png_samples(carrying).samples, read_png_samples(plain).samples);
        }
    }
}

// Six 64x48 frames whose views say their index; frames 1 .. 3 rendered.
VideoFrames three_frames() {
    VideoFrames frames;
    frames.timing.fps = 2.0;
    frames.timing.duration = 3.0;
    frames.view = [](std::int64_t i) {
        CameraView view;
        view.position = {double(i), -3.0, 0.0};
        return view;
    };
    frames.first = 1;
    frames.last = 3;
    return frames;
}

VideoResult render_three_frames(const VideoOutput& output) {
    FrameRequest request;
    request.width = 64;
    request.height = 48;
    FarmFrameDispatch dispatch(Cluster::current());
    return render_video(
        three_frames(), request,
        [](const FrameRequest& frame) {
            return hand_made_frame(frame.width, frame.height, float(frame.view.position.x));
        },
        output, dispatch);
}

TEST(EmbeddedViewOutputs, VideoFrameFilesCarryOneViewOrEachTheirOwn) {
    const test::TempDir dir("fgr_view_outputs");
    VideoOutput output;
    output.frames_directory = dir.path() / "same";
    output.still.embedded_view = kView;
    render_three_frames(output);
    for (int index : {1, 2, 3}) {
        EXPECT_EQ(read_embedded_view(video_frame_file(output, index)), kView) << index;
    }

    output.frames_directory = dir.path() / "own";
    output.frames_format = "exr";
    output.frame_view = [](int index) { return "{\"frame\":" + std::to_string(index) + "}"; };
    render_three_frames(output);
    for (int index : {1, 2, 3}) {
        EXPECT_EQ(read_embedded_view(video_frame_file(output, index)),
                  "{\"frame\":" + std::to_string(index) + "}");
    }
}

// MP4 and Matroska keep the view as the container's comment, up to the 1 MiB a view may have;
// a GIF keeps no metadata; a MOV file keeps 65535 bytes, so a longer view is refused.
TEST(EmbeddedViewOutputs, AVideoCarriesTheViewAsItsComment) {
    const test::TempDir dir("fgr_view_outputs");
    const std::string largest(kMaxEmbeddedViewBytes, 'v');
    for (const char* name : {"v.mp4", "v.mkv", "v.gif"}) {
        SCOPED_TRACE(name);
        const bool keeps = fs::path(name).extension() != ".gif";
        VideoOutput output;
        output.file = dir.path() / name;
        const std::string codec = keeps ? "mpeg4" : "";
        for (const std::string* view : {&kView, &largest}) {
            output.encoding = VideoSettings{codec, 64, 48, 2.0, {}, *view};
            EXPECT_FALSE(render_three_frames(output).encoder.empty());
            const std::optional<std::string> comment = container_comment(output.file);
            EXPECT_EQ(comment.has_value(), keeps);
            EXPECT_TRUE(!comment || *comment == *view)
                << "a comment of " << comment->size() << " bytes, not the view's " << view->size();
        }
        output.encoding.embedded_view.clear();
        render_three_frames(output);
        EXPECT_EQ(container_comment(output.file), std::nullopt);
    }
    EXPECT_NO_THROW(check_video_settings(
        "a.mov", VideoSettings{"mpeg4", 64, 48, 2.0, {}, std::string(0xffff, 'v')}));
    EXPECT_THROW(check_video_settings(
                     "a.mov", VideoSettings{"mpeg4", 64, 48, 2.0, {}, std::string(0x10000, 'v')}),
                 std::invalid_argument);
    EXPECT_THROW(check_video_settings("a.mkv", VideoSettings{"mpeg4", 64, 48, 2.0, {}, "\xff"}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace embedded_view_outputs_test
}  // namespace fgr
