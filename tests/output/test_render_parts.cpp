// SPDX-License-Identifier: Apache-2.0
// Split and merge for schedulers (output/parts/render_parts.hpp, fgr render --part/--tile, fgr
// merge, fgr video --frame-range, fgr merge --frames): tiles merge into exactly the whole render
// (PNG bytes, EXR floats, the brute mode's neighbour-reading shading included); parts of different
// seeds merge into the sample-weighted mean with the summed samples; parts that do not make one
// image are refused by name with nothing written; a frame range renders exactly those frames of
// the whole video, and a frame directory encodes into a video of its frames.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "device_suite.hpp"
#include "image/embedded_view.hpp"
#include "image/image_io.hpp"
#include "output/parts/render_parts.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

// The named float channels of an EXR file over its data window, each as rows of floats.
std::vector<std::vector<float>> read_exr_channels(const fs::path& path,
                                                  const std::vector<std::string>& names) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const size_t width = size_t(window.max.x - window.min.x + 1);
    const size_t height = size_t(window.max.y - window.min.y + 1);
    std::vector<std::vector<float>> channels(names.size(), std::vector<float>(width * height));
    Imf::FrameBuffer frame;
    for (size_t c = 0; c < names.size(); ++c) {
        EXPECT_NE(file.header().channels().findChannel(names[c]), nullptr) << names[c];
        frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, channels[c].data(), window,
                                                sizeof(float), sizeof(float) * width));
    }
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return channels;
}

using test::directory_listing;

// Video packets in the file's video stream: one a frame for the codecs fgr writes.
long video_frame_count(const fs::path& file) {
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) return -1;
    avformat_find_stream_info(format, nullptr);
    const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    long frames = 0;
    AVPacket* packet = av_packet_alloc();
    while (av_read_frame(format, packet) >= 0) {
        frames += packet->stream_index == index;
        av_packet_unref(packet);
    }
    av_packet_free(&packet);
    avformat_close_input(&format);
    return frames;
}

class RenderPartsCli : public ::testing::Test {
protected:
    test::RunResult run(const std::vector<std::string>& args) {
        test::RunResult result = test::run_fgr(args, dir());
        EXPECT_FALSE(result.timed_out) << test::describe("fgr", args);
        return result;
    }
    // `fgr render SCENE` at 96x64 with `extra`, which must succeed.
    void render(const std::vector<std::string>& extra, const std::string& scene = "mandelbulb") {
        std::vector<std::string> args{"render", scene, "--width", "96", "--height", "64"};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::RunResult result = run(args);
        ASSERT_EQ(result.exit_code, 0) << result;
    }
    test::RunResult merge(const std::vector<std::string>& args) {
        std::vector<std::string> all{"merge"};
        all.insert(all.end(), args.begin(), args.end());
        return run(all);
    }
    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_parts"};
};

// Three tiles of 21, 21 and 22 rows (64 / 3 does not divide), merged: the PNG is the whole
// render's byte for byte, the EXR its floats, depth included.
TEST_F(RenderPartsCli, ThreeTilesMergeIntoExactlyTheWholeRender) {
    const std::vector<std::string> settings{"--spp", "2"};
    for (int i = 1; i <= 3; ++i) {
        auto args = settings;
        args.insert(args.end(),
                    {"--tile", fmt::format("{}/3", i), "-o", fmt::format("t{}.exr", i)});
        render(args);
    }
    auto whole_png = settings, whole_exr = settings;
    whole_png.insert(whole_png.end(), {"-o", "whole.png"});
    whole_exr.insert(whole_exr.end(), {"-o", "whole.exr", "--aov", "depth"});
    render(whole_png);
    render(whole_exr);

    const test::RunResult png = merge({"t3.exr", "t1.exr", "t2.exr", "-o", "merged.png"});
    ASSERT_EQ(png.exit_code, 0) << png;
    EXPECT_NE(png.out.find("tiles 3\n"), std::string::npos) << png;
    EXPECT_NE(png.out.find("samples_per_pixel 2\n"), std::string::npos) << png;
    EXPECT_NE(png.out.find("wrote merged.png (96x64)"), std::string::npos) << png;
    EXPECT_TRUE(test::read_file(dir() / "merged.png") == test::read_file(dir() / "whole.png"))
        << "the merged PNG's bytes differ from the whole render's";

    const test::RunResult exr =
        merge({"t1.exr", "t2.exr", "t3.exr", "-o", "merged.exr", "--aov", "depth"});
    ASSERT_EQ(exr.exit_code, 0) << exr;
    const std::vector<std::string> channels{"R", "G", "B", "depth.Z"};
    const auto merged = read_exr_channels(dir() / "merged.exr", channels);
    const auto whole = read_exr_channels(dir() / "whole.exr", channels);
    for (size_t c = 0; c < channels.size(); ++c) {
        long differing = 0;
        for (size_t i = 0; i < whole[c].size(); ++i) differing += !(merged[c][i] == whole[c][i]);
        EXPECT_EQ(differing, 0) << channels[c];
    }
}

// The brute mode shades from its neighbours' depths: tiles rendered with their padding merge into
// the whole render (without it, the rows at each seam differ).
TEST_F(RenderPartsCli, BruteModeTilesMergeIntoTheWholeRender) {
    const std::vector<std::string> settings{"--mode", "brute", "--spp", "2"};
    for (int i = 1; i <= 3; ++i) {
        auto args = settings;
        args.insert(args.end(),
                    {"--tile", fmt::format("{}/3", i), "-o", fmt::format("t{}.exr", i)});
        render(args);
    }
    auto whole = settings;
    whole.insert(whole.end(), {"-o", "whole.png"});
    render(whole);
    const test::RunResult result = merge({"t1.exr", "t2.exr", "t3.exr", "-o", "merged.png"});
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_TRUE(read_png(dir() / "merged.png").rgb == read_png(dir() / "whole.png").rgb)
        << "the merged tiles differ from the whole render";
}

// Path-traced parts of seeds 1, 2, 3 at 2 samples each merge into 6 samples per pixel, each pixel
// the mean of the three; a part of 4 samples with one of 2 weighs twice as much.
TEST_F(RenderPartsCli, SeedPartsMergeIntoTheSampleWeightedMean) {
    for (int seed : {1, 2, 3}) {
        render({"--mode", "path", "--spp", "2", "--seed", std::to_string(seed), "--part", "-o",
                fmt::format("s{}.exr", seed)});
    }
    render({"--mode", "path", "--spp", "4", "--seed", "4", "--part", "-o", "s4.exr"});
    const test::RunResult equal = merge({"s1.exr", "s2.exr", "s3.exr", "-o", "equal.exr"});
    ASSERT_EQ(equal.exit_code, 0) << equal;
    EXPECT_NE(equal.out.find("samples_per_pixel 6\n"), std::string::npos) << equal;
    EXPECT_NE(equal.out.find("seeds 1,2,3\n"), std::string::npos) << equal;
    const test::RunResult weighted = merge({"s1.exr", "s4.exr", "-o", "weighted.exr"});
    ASSERT_EQ(weighted.exit_code, 0) << weighted;
    EXPECT_NE(weighted.out.find("samples_per_pixel 6\n"), std::string::npos) << weighted;

    const std::vector<std::string> rgb{"R", "G", "B"};
    std::vector<std::vector<std::vector<float>>> parts;
    for (int seed : {1, 2, 3, 4})
        parts.push_back(read_exr_channels(dir() / fmt::format("s{}.exr", seed), rgb));
    const auto merged_equal = read_exr_channels(dir() / "equal.exr", rgb);
    const auto merged_weighted = read_exr_channels(dir() / "weighted.exr", rgb);
    // add_samples rounds to float after each part: a few float roundings of values near 1, so
    // 1e-6 relative (8 ulp) bounds them; a wrong weight is off by a part's noise, far more.
    const auto close = [](double expected, float got) {
        return std::abs(expected - double(got)) <= 1e-6 * std::max(1.0, std::abs(expected));
    };
    long wrong_equal = 0, wrong_weighted = 0, noisy = 0;
    for (size_t c = 0; c < rgb.size(); ++c) {
        for (size_t i = 0; i < merged_equal[c].size(); ++i) {
            const double a = parts[0][c][i], b = parts[1][c][i], s3 = parts[2][c][i];
            const double four = parts[3][c][i];
            wrong_equal += !close((a + b + s3) / 3.0, merged_equal[c][i]);
            wrong_weighted += !close((2.0 * a + 4.0 * four) / 6.0, merged_weighted[c][i]);
            noisy += a != b;
        }
    }
    EXPECT_EQ(wrong_equal, 0);
    EXPECT_EQ(wrong_weighted, 0);
    EXPECT_GT(noisy, long(merged_equal[0].size()) / 4)
        << "different seeds must give different noise";
}

// Parts that do not make one image: a one-line error naming the files, exit 2, nothing written.
TEST_F(RenderPartsCli, PartsThatDoNotMakeOneImageAreRefusedByName) {
    render({"--tile", "1/2", "-o", "top.exr"}, "mandelbulb");
    render({"--tile", "2/2", "-o", "bottom.exr"}, "mandelbulb");
    render({"--tile", "2/2", "-o", "bright.exr", "--set", "exposure=2"}, "mandelbulb");
    render({"--tile", "2/2", "-o", "bottom_spp2.exr", "--spp", "2"}, "mandelbulb");
    render({"--tile", "2/3", "-o", "middle.exr"}, "mandelbulb");
    render({"--mode", "path", "--spp", "1", "--seed", "5", "--part", "-o", "seed5.exr"},
           "mandelbulb");
    fs::copy_file(dir() / "seed5.exr", dir() / "seed5_again.exr");
    fs::copy_file(dir() / "top.exr", dir() / "top_again.exr");
    const std::vector<std::string> inputs = directory_listing(dir());

    struct Refusal {
        std::vector<std::string> parts;
        std::vector<std::string> mentions;
    };
    const std::vector<Refusal> refusals{
        {{"top.exr", "bright.exr"}, {"'top.exr'", "'bright.exr'", "parameters"}},
        {{"top.exr", "bottom.exr", "middle.exr"}, {"'top.exr'", "'middle.exr'", "overlap"}},
        {{"top.exr"}, {"rows 32..63", "missing"}},
        {{"bottom.exr"}, {"rows 0..31", "missing"}},
        {{"seed5.exr", "seed5_again.exr"}, {"'seed5.exr'", "'seed5_again.exr'", "seed 5"}},
        {{"top.exr", "top_again.exr", "bottom.exr"}, {"'top.exr'", "'top_again.exr'", "shaded"}},
        {{"top.exr", "bottom_spp2.exr"}, {"'top.exr'", "'bottom_spp2.exr'", "samples per pixel"}},
        {{"top.exr", "whole.png"}, {"whole.png"}},
    };
    for (const Refusal& refusal : refusals) {
        auto args = refusal.parts;
        args.insert(args.end(), {"-o", "out.png"});
        const test::RunResult result = merge(args);
        const std::string what = test::describe("fgr merge", args);
        EXPECT_EQ(result.exit_code, 2) << what << ": " << result;
        const std::string err = result.err.substr(0, result.err.find_last_not_of('\n') + 1);
        EXPECT_EQ(err.find('\n'), std::string::npos) << "one line: " << result.err;
        for (const std::string& mention : refusal.mentions) {
            EXPECT_NE(err.find(mention), std::string::npos)
                << what << " must name " << mention << ": " << err;
        }
        EXPECT_EQ(directory_listing(dir()), inputs) << what << " wrote something";
    }
    // Layers the parts were rendered without.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"top.exr", "bottom.exr", "-o", "out.png", "--alpha"},
          std::vector<std::string>{"top.exr", "bottom.exr", "-o", "out.exr", "--aov", "normal"}}) {
        const test::RunResult result = merge(args);
        EXPECT_EQ(result.exit_code, 2) << result;
        EXPECT_NE(result.err.find("--alpha or --aov"), std::string::npos) << result;
        EXPECT_EQ(directory_listing(dir()), inputs)
            << test::describe("fgr merge", args) << " wrote something";
    }
    // A part is an EXR, and a tile is I of N.
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"render", "mandelbulb", "--part", "-o", "p.png"},
          std::vector<std::string>{"render", "mandelbulb", "--tile", "3/2", "-o", "p.exr"},
          std::vector<std::string>{"render", "mandelbulb", "--tile", "1/1000", "--height", "64",
                                   "-o", "p.exr"}}) {
        const test::RunResult result = run(args);
        EXPECT_EQ(result.exit_code, 2) << result;
        EXPECT_EQ(directory_listing(dir()), inputs)
            << test::describe("fgr", args) << " wrote something";
    }
}

// A farm renders a video as frame ranges into one directory and encodes it once: the range's
// frames are the whole run's, byte for byte, and only they are written; the directory then
// encodes into a video of every frame, and a gap or a frame of another size is refused.
TEST_F(RenderPartsCli, FrameRangesRenderThoseFramesAndMergeIntoAVideo) {
    const std::vector<std::string> video{"video",   "mandelbulb", "--camera-path", "orbit",
                                         "--width", "48",         "--height",      "32",
                                         "--fps",   "6",          "--duration",    "1"};
    auto whole = video;
    whole.insert(whole.end(), {"--frames", "all"});
    ASSERT_EQ(run(whole).exit_code, 0);
    auto range = video;
    range.insert(range.end(), {"--frames", "some", "--frame-range", "2:4"});
    const test::RunResult ranged = run(range);
    ASSERT_EQ(ranged.exit_code, 0) << ranged;
    ASSERT_EQ(directory_listing(dir() / "some"),
              (std::vector<std::string>{"frame_00002.png", "frame_00003.png", "frame_00004.png"}));
    for (int i = 2; i <= 4; ++i) {
        const std::string name = fmt::format("frame_{:05}.png", i);
        EXPECT_TRUE(test::read_file(dir() / "some" / name) == test::read_file(dir() / "all" / name))
            << name << " differs from the whole run's";
    }
    ASSERT_EQ(directory_listing(dir() / "all").size(), 6u);

    const test::RunResult encoded = merge({"--frames", "all", "-o", "all.mp4", "--fps", "6"});
    ASSERT_EQ(encoded.exit_code, 0) << encoded;
    EXPECT_EQ(video_frame_count(dir() / "all.mp4"), 6);

    auto past_the_end = video;
    past_the_end.insert(past_the_end.end(), {"--frames", "late", "--frame-range", "4:6"});
    EXPECT_EQ(run(past_the_end).exit_code, 2);
    auto into_a_file = video;
    into_a_file.insert(into_a_file.end(), {"-o", "v.mp4", "--frames", "x", "--frame-range", "0:1"});
    EXPECT_EQ(run(into_a_file).exit_code, 2);

    fs::remove(dir() / "all" / "frame_00003.png");
    const test::RunResult gap = merge({"--frames", "all", "-o", "gap.mp4"});
    EXPECT_EQ(gap.exit_code, 2) << gap;
    EXPECT_NE(gap.err.find("frame_00003.png"), std::string::npos) << gap;
    write_png(dir() / "all" / "frame_00003.png", Image8{50, 32, std::vector<uint8_t>(50 * 32 * 3)});
    const test::RunResult sizes = merge({"--frames", "all", "-o", "sizes.mp4"});
    EXPECT_EQ(sizes.exit_code, 2) << sizes;
    EXPECT_NE(sizes.err.find("frame_00003.png"), std::string::npos) << sizes;
    EXPECT_FALSE(fs::exists(dir() / "gap.mp4"));
    EXPECT_FALSE(fs::exists(dir() / "sizes.mp4"));
}

// --- The library ---------------------------------------------------------------------------------

// Tile I of N is rows floor((I-1)*H/N) .. floor(I*H/N)-1: the tiles of any split are adjacent and
// cover the image; 1/1 is all of it.
TEST(TileRegion, TilesOfASplitAreAdjacentAndCoverTheImage) {
    for (int count : {1, 2, 3, 7, 64}) {
        int next_row = 0;
        for (int index = 1; index <= count; ++index) {
            const PixelRegion tile = tile_region(96, 64, index, count);
            EXPECT_EQ(tile.x, 0);
            EXPECT_EQ(tile.width, 96);
            EXPECT_EQ(tile.y, next_row) << index << "/" << count;
            EXPECT_EQ(tile.y + tile.height, index * 64 / count) << index << "/" << count;
            next_row = tile.y + tile.height;
        }
        EXPECT_EQ(next_row, 64);
    }
    EXPECT_THROW(tile_region(96, 64, 0, 3), std::invalid_argument);
    EXPECT_THROW(tile_region(96, 64, 4, 3), std::invalid_argument);
    EXPECT_THROW(tile_region(96, 64, 1, 65), std::invalid_argument);  // a tile of no rows
}

// Merging in bands that cut across parts.

class RenderPartsTest : public test::DeviceSuite<> {
protected:
    test::TempDir temp_{"fgr_parts_lib"};
};

// Tiles of 17, 18 and 18 rows merged in bands of 4 rows (a budget of a few rows), so bands
// straddle the tiles' seams: every layer of every pixel is the untiled frame's.
TEST_F(RenderPartsTest, BandsAcrossTileSeamsMergeIntoTheUntiledFrame) {
    const Scene scene = test::built_scene("mandelbulb.so");
    Renderer renderer(*device_, *cache_, scene,
                      KernelSwitches{preferred_packet_width(device_->info), scene.effects, false,
                                     false, RenderMode::Path, true});
    FrameRequest whole{40, 53, scene.cameras.front().view, default_param_values(scene)};
    whole.samples = 2;
    const Frame frame = renderer.render(whole);
    std::vector<PartInfo> parts;
    for (int i = 1; i <= 3; ++i) {
        FrameRequest tile = whole;
        tile.region = tile_region(whole.width, whole.height, i, 3);
        const fs::path path = temp_.path() / fmt::format("t{}.exr", i);
        const PartResult result = render_part(renderer, tile, DisplayTransform{}, path, {});
        ASSERT_FALSE(result.interrupted);
        parts.push_back(read_part_info(path));
    }
    EXPECT_EQ(parts[1].region.y, 17);  // floor(53 / 3)
    EXPECT_EQ(parts[1].region.height, 18);
    const MergePlan plan = plan_merge(parts);
    TiledOutput output;
    output.path = temp_.path() / "merged.exr";
    output.format = ImageFormat::Exr;
    output.aovs = Aovs{true, true, true, true};
    output.embedded_view = R"({"scene":"mandelbulb"})";
    const size_t row_bytes = size_t(whole.width) * (11 * 4 + 2 * 14 * 4 + 3);
    const MergeResult result = merge_parts(plan, output, 4 * row_bytes);
    EXPECT_EQ(result.band_rows, 4);
    EXPECT_EQ(read_embedded_view(output.path), output.embedded_view);
    const auto read =
        read_exr_channels(output.path, {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B",
                                        "normal.X", "normal.Y", "normal.Z", "depth.Z", "A"});
    // With alpha the colour is the premultiplied foreground (output/still_layers.hpp).
    const std::vector<std::pair<const std::vector<float>*, int>> planes{{&frame.foreground, 3},
                                                                        {&frame.albedo, 3},
                                                                        {&frame.normal, 3},
                                                                        {&frame.depth, 1},
                                                                        {&frame.alpha, 1}};
    size_t channel = 0;
    for (const auto& [plane, count] : planes) {
        for (int c = 0; c < count; ++c, ++channel) {
            long differing = 0;
            for (size_t i = 0; i < read[channel].size(); ++i) {
                const float x = (*plane)[i * size_t(count) + size_t(c)], y = read[channel][i];
                differing += !(x == y || (x < 0.0f && std::isinf(y)));  // a miss: -1 in, +Inf out
            }
            EXPECT_EQ(differing, 0) << "channel " << channel;
        }
    }
}

}  // namespace
}  // namespace fgr
