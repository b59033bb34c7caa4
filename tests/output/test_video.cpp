// SPDX-License-Identifier: Apache-2.0
// fgr video, run as a child process, and its library parts: frame times along a camera path, the
// encoder's temporary file, decoded frames against `fgr render --camera-path P --time t` of the
// same settings (PSNR for the lossy H.264, exact for PNG sequences), the frame count and duration
// the container records, and bad input as one error line with nothing written.

#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "child_process.hpp"
#include "image/image_io.hpp"
#include "output/video/video_encoder.hpp"
#include "output/video/video_timing.hpp"
#include "test_files.hpp"
#include "video_decoding.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

using test::decode_video;
using test::DecodedVideo;
using test::directory_listing;
using test::run_fgr;
using test::RunResult;

constexpr int kVideoWidth = 64;
constexpr int kVideoHeight = 48;

// --- Frame times ---------------------------------------------------------------------------------

CameraPath path_from(float first, float last) {
    CameraPath path;
    path.name = "test";
    Keyframe key;
    key.time = first;
    path.keyframes.push_back(key);
    key.time = last;
    path.keyframes.push_back(key);
    return path;
}

TEST(VideoTiming, FrameIIsAtStartPlusIOverFpsUpToThePathsEnd) {
    const VideoTiming timing = video_timing(path_from(0.0f, 10.0f), 30.0, {}, {});
    EXPECT_EQ(timing.frame_count(), 300);  // 10 s at 30 fps; the end keyframe would be frame 300
    EXPECT_EQ(timing.frame_time(0), 0.0f);
    EXPECT_EQ(timing.frame_time(1), static_cast<float>(1.0 / 30.0));
    EXPECT_EQ(timing.frame_time(299), static_cast<float>(299.0 / 30.0));
}

TEST(VideoTiming, StartDefaultsToTheFirstKeyframeAndDurationToTheRest) {
    const VideoTiming shifted = video_timing(path_from(2.0f, 6.0f), 4.0, {}, {});
    EXPECT_EQ(shifted.frame_count(), 16);
    EXPECT_EQ(shifted.frame_time(0), 2.0f);
    EXPECT_EQ(shifted.frame_time(15), 5.75f);
    const VideoTiming part = video_timing(path_from(0.0f, 10.0f), 10.0, 3.0, 2.0);
    EXPECT_EQ(part.frame_count(), 20);
    EXPECT_EQ(part.frame_time(0), 3.0f);
    EXPECT_EQ(part.frame_time(19), 4.9f);
}

TEST(VideoTiming, RefusesFpsDurationAndStartOffThePath) {
    const CameraPath path = path_from(0.0f, 10.0f);
    EXPECT_THROW(video_timing(path, 0.0, {}, {}), std::invalid_argument);
    EXPECT_THROW(video_timing(path, -30.0, {}, {}), std::invalid_argument);
    EXPECT_THROW(video_timing(path, NAN, {}, {}), std::invalid_argument);
    EXPECT_THROW(video_timing(path, 30.0, {}, 0.0), std::invalid_argument);
    EXPECT_THROW(video_timing(path, 30.0, {}, 10.5), std::invalid_argument);
    EXPECT_THROW(video_timing(path, 30.0, 11.0, {}), std::invalid_argument);
    EXPECT_NO_THROW(video_timing(path, 30.0, {}, 10.0));
}

// A camera path long enough for more frames than an int holds (143165577 s at 30 fps is
// 2^32 + 14 frames, which once wrapped to a short video) or than memory holds views for (5e7 s at
// 30 fps): refused with the count and the limit, before any frame's view is computed.
TEST(VideoTiming, FrameCountsPastTheLimitAreRefusedWithTheCountAndTheLimit) {
    for (const auto& [end, frames] :
         {std::pair{143165577.0f, "4294967"}, std::pair{5e7f, "1500000000 frames"}}) {
        try {
            video_timing(path_from(0.0f, end), 30.0, {}, {});
            FAIL() << "a path of " << end << " s was accepted";
        } catch (const std::invalid_argument& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find(frames), std::string::npos) << message;
            EXPECT_NE(message.find("over the limit of 1000000"), std::string::npos) << message;
        }
    }
    EXPECT_EQ(video_timing(path_from(0.0f, 100000.0f), 10.0, {}, {}).frame_count(),
              kMaxVideoFrames);
    EXPECT_THROW(video_timing(path_from(0.0f, 100000.0f), 10.0001, {}, {}), std::invalid_argument);
    EXPECT_THROW(video_timing(path_from(0.0f, 10.0f), 1e300, {}, {}), std::invalid_argument);
}

// --- The encoder's file -------------------------------------------------------------------------

Image8 grey_image(int width, int height, uint8_t level) {
    return Image8{width, height,
                  std::vector<uint8_t>(static_cast<size_t>(width) * height * 3, level)};
}

TEST(VideoEncoder, LeavesNoFileUnlessFinished) {
    const test::TempDir dir("fgr_video_test");
    const fs::path output = dir.path() / "unfinished.mp4";
    {
        VideoEncoder encoder(output, VideoSettings{"", kVideoWidth, kVideoHeight, 10.0, {}});
        encoder.add_frame(grey_image(kVideoWidth, kVideoHeight, 128));
        EXPECT_EQ(directory_listing(dir.path()).size(), 1u)
            << "the temporary exists while encoding";
        EXPECT_FALSE(fs::exists(output)) << "the output appears only at finish()";
    }
    EXPECT_TRUE(directory_listing(dir.path()).empty())
        << "left behind: " << directory_listing(dir.path()).front();
}

TEST(VideoEncoder, DefaultsToH264ForMp4AndRefusesOddSizesForYuv420) {
    EXPECT_EQ(default_video_codec("a.mp4"), "libx264") << "Debian's libavcodec has x264";
    EXPECT_EQ(default_video_codec("a.webm"), "libvpx-vp9");
    EXPECT_THROW(check_video_settings("a.mp4", VideoSettings{"", 65, 48, 30.0, {}}),
                 std::invalid_argument);
    EXPECT_THROW(check_video_settings("a.mp4", VideoSettings{"nosuchcodec", 64, 48, 30.0, {}}),
                 std::invalid_argument);
    EXPECT_THROW(check_video_settings("a.nosuchcontainer", VideoSettings{"", 64, 48, 30.0, {}}),
                 std::invalid_argument);
    EXPECT_NO_THROW(check_video_settings("a.mp4", VideoSettings{"mpeg4", 64, 48, 30.0, {}}));
}

// --- Decoding what fgr video wrote --------------------------------------------------------------

// `image` through the video's pixel format and back (RGB to 4:2:0 YUV, BT.709 limited range, as
// fgr encodes, and back as a player shows it): what a perfect encoder would give. 4:2:0 keeps one
// colour sample per 2x2 pixels, which costs a fractal's pixel-sized colour detail far more than
// the codec does (about 26 dB on the 64x48 orbit at any CRF, x264's lossless CRF 0 included), so
// the codec's own loss is measured against this.
Image8 through_yuv420(const Image8& image) {
    const int flags = SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT;
    const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
    AVFrame* yuv = av_frame_alloc();
    yuv->format = AV_PIX_FMT_YUV420P;
    yuv->width = image.width;
    yuv->height = image.height;
    av_frame_get_buffer(yuv, 0);
    SwsContext* to_yuv =
        sws_getContext(image.width, image.height, AV_PIX_FMT_RGB24, image.width, image.height,
                       AV_PIX_FMT_YUV420P, flags, nullptr, nullptr, nullptr);
    sws_setColorspaceDetails(to_yuv, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
    const uint8_t* source[1] = {image.rgb.data()};
    const int stride[1] = {3 * image.width};
    sws_scale(to_yuv, source, stride, 0, image.height, yuv->data, yuv->linesize);
    SwsContext* to_rgb =
        sws_getContext(image.width, image.height, AV_PIX_FMT_YUV420P, image.width, image.height,
                       AV_PIX_FMT_RGB24, flags, nullptr, nullptr, nullptr);
    sws_setColorspaceDetails(to_rgb, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
    Image8 back{image.width, image.height, std::vector<uint8_t>(image.rgb.size())};
    uint8_t* destination[1] = {back.rgb.data()};
    sws_scale(to_rgb, yuv->data, yuv->linesize, 0, image.height, destination, stride);
    sws_freeContext(to_yuv);
    sws_freeContext(to_rgb);
    av_frame_free(&yuv);
    return back;
}

double psnr(const Image8& a, const Image8& b) {
    double squared = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        const double difference = double(a.rgb[i]) - double(b.rgb[i]);
        squared += difference * difference;
    }
    const double mse = squared / static_cast<double>(a.rgb.size());
    return mse == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
}

// "R +0.12, G -0.40, B +1.03": the mean difference a - b per channel, which tells a colour
// conversion's bias (a wrong matrix or range) from coding noise (means near 0).
std::string mean_differences(const Image8& a, const Image8& b) {
    double sums[3] = {0.0, 0.0, 0.0};
    for (size_t i = 0; i < a.rgb.size(); ++i) sums[i % 3] += double(a.rgb[i]) - double(b.rgb[i]);
    const double pixels = static_cast<double>(a.rgb.size() / 3);
    return fmt::format("R {:+.2f}, G {:+.2f}, B {:+.2f}", sums[0] / pixels, sums[1] / pixels,
                       sums[2] / pixels);
}

// --- fgr video, end to end ----------------------------------------------------------------------

class VideoCommandTest : public ::testing::Test {
protected:
    RunResult run(const std::vector<std::string>& args) {
        RunResult result = run_fgr(args, dir_.path());
        EXPECT_FALSE(result.timed_out) << test::describe("fgr", args) << ": " << result;
        return result;
    }

    // `fgr render --camera-path orbit --time t` with `extra` options, read back.
    Image8 single_render(float time, const std::vector<std::string>& extra) {
        const fs::path still = dir_.path() / "still.png";
        std::vector<std::string> args{"render",
                                      "mandelbulb",
                                      "--camera-path",
                                      "orbit",
                                      "--time",
                                      fmt::format("{:.9g}", time),
                                      "-o",
                                      still.string(),
                                      "--width",
                                      std::to_string(kVideoWidth),
                                      "--height",
                                      std::to_string(kVideoHeight)};
        args.insert(args.end(), extra.begin(), extra.end());
        const RunResult result = run(args);
        EXPECT_EQ(result.exit_code, 0) << result;
        Image8 image = read_png(still);
        fs::remove(still);
        return image;
    }

    std::vector<std::string> video_args(const std::vector<std::string>& extra) const {
        std::vector<std::string> args{"video",         "mandelbulb",
                                      "--camera-path", "orbit",
                                      "--width",       std::to_string(kVideoWidth),
                                      "--height",      std::to_string(kVideoHeight)};
        args.insert(args.end(), extra.begin(), extra.end());
        return args;
    }

    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_video_test"};
};

// Orbit at 4 fps for 1 s of path time: frames at t = 0, 0.25, 0.5, 0.75, each a distinct view.
// CRF 10 rather than the default 18: x264's psychovisual tuning spends CRF 18's bits on what a
// viewer sees, not on PSNR, and a 64x48 fractal is all pixel-sized detail (36-39 dB at CRF 18,
// 44-46 dB at CRF 10); the test is about the frames being the right ones, through a lossy codec.
TEST_F(VideoCommandTest, Mp4FramesMatchSingleRendersAndTheContainerHasTheirCountAndDuration) {
    const fs::path video = dir() / "orbit.mp4";
    const RunResult result = run(video_args(
        {"-o", video.string(), "--fps", "4", "--duration", "1", "--spp", "2", "--crf", "10"}));
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.err.find("frames 4/4"), std::string::npos) << "no progress line: " << result;
    EXPECT_EQ(directory_listing(dir()), std::vector<std::string>{"orbit.mp4"});

    const DecodedVideo decoded = decode_video(video);
    EXPECT_EQ(decoded.codec, "h264");
    EXPECT_EQ(decoded.frames_in_header, 4);
    EXPECT_NEAR(decoded.duration, 1.0, 1e-3);  // 4 frames of 1/4 s
    ASSERT_EQ(decoded.frames.size(), 4u);
    // PSNR >= 40 dB against the still in the video's 4:2:0 pixel format (through_yuv420): H.264
    // at CRF 10 is lossy but close; a frame of another time (the orbit turns 9 degrees per
    // frame) scores far below it.
    for (int i : {0, 1, 3}) {
        const Image8 still =
            through_yuv420(single_render(static_cast<float>(i / 4.0), {"--spp", "2"}));
        ASSERT_EQ(decoded.frames[i].rgb.size(), still.rgb.size());
        EXPECT_GE(psnr(decoded.frames[i], still), 40.0)
            << "frame " << i << ", mean differences " << mean_differences(decoded.frames[i], still);
    }
}

TEST_F(VideoCommandTest, PngFramesEqualSingleRendersExactly) {
    const fs::path frames = dir() / "frames";
    const std::vector<std::string> settings{"--spp", "3", "--set", "power=7"};
    std::vector<std::string> args = video_args(
        {"--frames", frames.string(), "--fps", "2", "--start", "1", "--duration", "1.5"});
    args.insert(args.end(), settings.begin(), settings.end());
    const RunResult result = run(args);
    ASSERT_EQ(result.exit_code, 0) << result;
    ASSERT_EQ(directory_listing(frames),
              (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png"}));
    for (int i = 0; i < 3; ++i) {
        const Image8 frame = read_png(frames / fmt::format("frame_{:05}.png", i));
        const Image8 still = single_render(static_cast<float>(1.0 + i / 2.0), settings);
        EXPECT_TRUE(frame.rgb == still.rgb) << "frame " << i << " differs from its still";
    }
}

TEST_F(VideoCommandTest, ExrFramesCarryTheAovLayers) {
    const fs::path frames = dir() / "frames";
    const RunResult result =
        run(video_args({"--frames", frames.string(), "--frames-format", "exr", "--aov",
                        "depth,alpha", "--fps", "1", "--duration", "2"}));
    ASSERT_EQ(result.exit_code, 0) << result;
    ASSERT_EQ(directory_listing(frames),
              (std::vector<std::string>{"frame_00000.exr", "frame_00001.exr"}));
    Imf::InputFile file((frames / "frame_00001.exr").c_str());
    std::vector<std::string> channels;
    const Imf::ChannelList& list = file.header().channels();
    for (auto channel = list.begin(); channel != list.end(); ++channel) {
        channels.push_back(channel.name());
    }
    EXPECT_EQ(channels, (std::vector<std::string>{"A", "B", "G", "R", "depth.Z"}));
}

// A camera path file of `keyframes` keyframes, one second apart (the last at `last_time` when
// given), looking at the origin from -3 y.
void write_path_file(const fs::path& file, long keyframes, double last_time = -1.0) {
    std::string text = R"({"format": "fgr-camera-path", "version": 1, "keyframes": [)";
    text.reserve(static_cast<size_t>(keyframes) * 60 + 100);
    for (long i = 0; i < keyframes; ++i) {
        const bool last = i + 1 == keyframes && last_time >= 0.0;
        text += i == 0 ? R"({"time": )" : R"(,{"time": )";
        text += last ? fmt::format("{}", last_time) : std::to_string(i);
        text += R"(, "position": [0, -3, 0], "target": [0, 0, 0]})";
    }
    text += "]}\n";
    test::write_text(file, text);
}

// `fgr video mandelbulb --camera-path FILE`: one error line mentioning `mention`, nothing written
// beside the path file.
void expect_path_refused(const fs::path& dir, const fs::path& path_file,
                         const std::string& mention) {
    const std::vector<std::string> args{
        "video",    "mandelbulb", "--camera-path", path_file.string(),
        "-o",       "v.mp4",      "--width",       "64",
        "--height", "48"};
    const RunResult result = run_fgr(args, dir);
    ASSERT_TRUE(result.exited) << result;
    EXPECT_NE(result.exit_code, 0) << result;
    std::string err = result.err;
    if (!err.empty() && err.back() == '\n') err.pop_back();
    EXPECT_EQ(err.rfind("fgr: error: ", 0), 0u) << result;
    EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line: " << result;
    EXPECT_NE(err.find(mention), std::string::npos)
        << "should mention " << mention << ": " << result;
    EXPECT_EQ(directory_listing(dir), std::vector<std::string>{path_file.filename().string()});
}

// Keyframes at 0 and 143165577 s made 224 frames with exit 0 (the count wrapped), at 0 and 5e7 s
// 1.5e9 views before the first frame; a file of 10^6 keyframes ran past a minute at 2.7 GB.
TEST(VideoLimits, LongPathsAndHugeKeyframeCountsAreRefusedInOneLine) {
    const test::TempDir dir("fgr_video_limits");
    const fs::path path_file = dir.path() / "p.json";
    write_path_file(path_file, 2, 143165577.0);
    expect_path_refused(dir.path(), path_file, "over the limit of 1000000");
    write_path_file(path_file, 2, 5e7);
    expect_path_refused(dir.path(), path_file, "1500000000 frames");
    write_path_file(path_file, 10001);
    expect_path_refused(dir.path(), path_file, "10001 keyframes: a camera path has at most 10000");
    write_path_file(path_file, 1000000);
    expect_path_refused(dir.path(), path_file, "file too large");
}

// --- Bad input ----------------------------------------------------------------------------------

struct BadVideo {
    const char* name;
    std::vector<std::string> args;  // after `fgr video mandelbulb`
    std::string mention;            // must appear in the message
};

void PrintTo(const BadVideo& input, std::ostream* os) { *os << input.name; }

const BadVideo kBadVideos[] = {
    {"UnknownCodec", {"--camera-path", "orbit", "-o", "v.mp4", "--codec", "nosuch"}, "nosuch"},
    {"OddWidthForYuv420", {"--camera-path", "orbit", "-o", "v.mp4", "--width", "65"}, "65x480"},
    {"OddHeightForYuv420", {"--camera-path", "orbit", "-o", "v.mp4", "--height", "47"}, "640x47"},
    {"AbsurdSize", {"--camera-path", "orbit", "-o", "v.mp4", "--width", "100000"}, "width"},
    {"UnwritablePath", {"--camera-path", "orbit", "-o", "no/such/dir/v.mp4"}, "no/such/dir"},
    {"UnknownContainer", {"--camera-path", "orbit", "-o", "v.nosuch"}, "v.nosuch"},
    {"UnknownCameraPath", {"--camera-path", "nosuchpath", "-o", "v.mp4"}, "nosuchpath"},
    {"ZeroFps", {"--camera-path", "orbit", "-o", "v.mp4", "--fps", "0"}, "fps"},
    {"NegativeFps", {"--camera-path", "orbit", "-o", "v.mp4", "--fps", "-24"}, "fps"},
    {"DurationPastThePath",
     {"--camera-path", "orbit", "-o", "v.mp4", "--duration", "11"},
     "duration"},
    {"NoOutput", {"--camera-path", "orbit"}, "-o"},
    {"NoCameraPath", {"-o", "v.mp4"}, "camera-path"},
    {"AovWithoutExrFrames", {"--camera-path", "orbit", "-o", "v.mp4", "--aov", "depth"}, "exr"},
    {"CrfOutOfRange", {"--camera-path", "orbit", "-o", "v.mp4", "--crf", "52"}, "52"},
    {"CrfForACodecWithout", {"--camera-path", "orbit", "-o", "v.gif", "--crf", "10"}, "gif"},
    {"FramesNotADirectory", {"--camera-path", "orbit", "--frames", "/dev/null"}, "directory"},
};

class VideoBadInput : public VideoCommandTest, public ::testing::WithParamInterface<BadVideo> {};

TEST_P(VideoBadInput, FailsWithOneErrorLineAndWritesNothing) {
    std::vector<std::string> args{"video", "mandelbulb"};
    args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
    const RunResult result = run(args);
    ASSERT_TRUE(result.exited) << result;
    EXPECT_NE(result.exit_code, 0) << result;
    std::string err = result.err;
    if (!err.empty() && err.back() == '\n') err.pop_back();
    EXPECT_EQ(err.rfind("fgr: error: ", 0), 0u) << result;
    EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line: " << result;
    EXPECT_NE(err.find(GetParam().mention), std::string::npos)
        << "should mention '" << GetParam().mention << "': " << result;
    EXPECT_TRUE(directory_listing(dir()).empty())
        << "left behind: " << directory_listing(dir()).front();
}

INSTANTIATE_TEST_SUITE_P(Video, VideoBadInput, ::testing::ValuesIn(kBadVideos),
                         [](const ::testing::TestParamInfo<BadVideo>& param_info) {
                             return std::string(param_info.param.name);
                         });

}  // namespace
}  // namespace fgr
