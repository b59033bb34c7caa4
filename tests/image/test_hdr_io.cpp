// SPDX-License-Identifier: Apache-2.0
// HDR image files: Radiance .hdr and OpenEXR .exr reading (hand-made files, orientation, bad and
// fuzzed input) and writing (round trips, layers as named, atomic replacement).

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfTiledOutputFile.h>
#include <gtest/gtest.h>
#include <half.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/hdr_io.hpp"
#include "image/image_io.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

using Bytes = std::vector<unsigned char>;

using test::read_bytes;
using test::write_bytes;

Bytes text_bytes(const std::string& text) { return Bytes(text.begin(), text.end()); }

void append(Bytes& bytes, std::initializer_list<int> values) {
    for (int value : values) bytes.push_back(static_cast<unsigned char>(value));
}

// Bit-exact float comparison (NaN payloads and the sign of zero included).
bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Distinct positive values over many binades, different in every pixel, row and channel.
std::vector<float> varied_values(std::size_t count, unsigned seed, float low_exp, float high_exp) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> exponent(low_exp, high_exp);
    std::vector<float> values(count);
    for (float& value : values) value = std::exp2(exponent(random));
    return values;
}

// The error read_hdr_image or a writer throws: one line naming the file.
template <typename Exception, typename Function>
std::string one_line_error(const fs::path& file, Function&& function) {
    try {
        function();
    } catch (const Exception& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find("'" + file.string() + "'"), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "no exception for " << file;
    return {};
}

std::string read_error(const fs::path& file) {
    return one_line_error<std::runtime_error>(file, [&] { read_hdr_image(file); });
}

// A tiny file written by OpenEXR itself: half channels, PIZ, a data window away from the origin,
// so reading does not depend on fgr's writer. Pixel (x, y) holds (x + 1, y + 1, 0.5) * 0.25.
void write_half_piz_exr(const fs::path& file, int width, int height) {
    const Imath::Box2i window({10, 20}, {10 + width - 1, 20 + height - 1});
    Imf::Header header(window, window);
    header.compression() = Imf::PIZ_COMPRESSION;
    std::vector<half> pixels(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            half* pixel = &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
            pixel[0] = half(float(x + 1) * 0.25f);
            pixel[1] = half(float(y + 1) * 0.25f);
            pixel[2] = half(0.125f);
        }
    }
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
        const char* name = c == 0 ? "R" : c == 1 ? "G" : "B";
        header.channels().insert(name, Imf::Channel(Imf::HALF));
        frame.insert(name, Imf::Slice::Make(Imf::HALF, pixels.data() + c, window, 3 * sizeof(half),
                                            3 * sizeof(half) * width));
    }
    Imf::OutputFile output(file.c_str(), header);
    output.setFrameBuffer(frame);
    output.writePixels(height);
}

// A tiled, uncompressed float file with 4x4 tiles; pixel (x, y) holds (x, y, x + y) + 1.
void write_tiled_exr(const fs::path& file, int width, int height) {
    Imf::Header header(width, height);
    header.compression() = Imf::NO_COMPRESSION;
    header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    std::vector<float> pixels(std::size_t(width) * std::size_t(height) * 3);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            float* pixel = &pixels[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
            pixel[0] = float(x + 1);
            pixel[1] = float(y + 1);
            pixel[2] = float(x + y + 1);
        }
    }
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
        const char* name = c == 0 ? "R" : c == 1 ? "G" : "B";
        header.channels().insert(name, Imf::Channel(Imf::FLOAT));
        frame.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(pixels.data() + c),
                                      3 * sizeof(float), 3 * sizeof(float) * width));
    }
    Imf::TiledOutputFile output(file.c_str(), header);
    output.setFrameBuffer(frame);
    output.writeTiles(0, output.numXTiles() - 1, 0, output.numYTiles() - 1);
}

// A hand-made Radiance file: the header, then `data` as the scanlines.
Bytes radiance_file(int width, int height, const Bytes& data) {
    Bytes bytes = text_bytes("#?RADIANCE\n# hand-made\nFORMAT=32-bit_rle_rgbe\n\n-Y " +
                             std::to_string(height) + " +X " + std::to_string(width) + "\n");
    bytes.insert(bytes.end(), data.begin(), data.end());
    return bytes;
}

// Each test gets a fresh directory of its own, removed afterwards.
class HdrIo : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        directory_ = fs::temp_directory_path() /
                     ("fgr_hdr_io_" + std::to_string(::getpid()) + "_" + test->name());
        fs::remove_all(directory_);
        fs::create_directories(directory_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(directory_, ignored);
    }

    // Names of leftover temporaries ("<name>.tmp-<pid>-<n>") in the test directory.
    std::vector<std::string> temporaries() const {
        std::vector<std::string> found;
        for (const auto& entry : fs::recursive_directory_iterator(directory_)) {
            const std::string name = entry.path().filename().string();
            if (name.find(".tmp-") != std::string::npos) found.push_back(name);
        }
        return found;
    }

    fs::path directory_;
};

// ---- Round trips ----

TEST_F(HdrIo, ExrBeautyRoundTripsBitExactly) {
    const int width = 13;
    const int height = 7;
    std::vector<float> beauty = varied_values(std::size_t(width) * height * 3, 1, -126.0f, 127.0f);
    beauty[0] = 0.0f;
    beauty[4] = std::numeric_limits<float>::denorm_min();
    beauty[5] = std::numeric_limits<float>::max();
    const fs::path file = directory_ / "beauty.exr";
    write_exr(file, width, height, {{"", {"R", "G", "B"}, beauty}});
    const HdrImage image = read_hdr_image(file);
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    ASSERT_EQ(image.rgb.size(), beauty.size());
    for (std::size_t i = 0; i < beauty.size(); ++i) {
        EXPECT_TRUE(same_bits(image.rgb[i], beauty[i]))
            << "sample " << i << ": " << image.rgb[i] << " != " << beauty[i];
    }
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(HdrIo, ExrLayersAreWrittenAsNamedTopRowFirst) {
    const int width = 5;
    const int height = 4;
    const std::size_t pixels = std::size_t(width) * height;
    std::vector<ExrLayer> layers = {
        {"", {"R", "G", "B"}, varied_values(pixels * 3, 2, -10.0f, 10.0f)},
        {"", {"A"}, varied_values(pixels, 3, -3.0f, 0.0f)},
        {"albedo", {"R", "G", "B"}, varied_values(pixels * 3, 4, -5.0f, 0.0f)},
        {"normal", {"X", "Y", "Z"}, varied_values(pixels * 3, 5, -5.0f, 0.0f)},
        {"depth", {"Z"}, varied_values(pixels, 6, 0.0f, 20.0f)},
    };
    for (std::size_t i = 0; i < layers[3].values.size(); i += 2) layers[3].values[i] *= -1.0f;
    layers[4].values[7] = std::numeric_limits<float>::infinity();  // stored as it is

    const fs::path file = directory_ / "layers.exr";
    write_exr(file, width, height, layers);

    Imf::InputFile input(file.c_str());
    const Imf::Header& header = input.header();
    EXPECT_EQ(header.compression(), Imf::ZIP_COMPRESSION);
    EXPECT_EQ(header.lineOrder(), Imf::INCREASING_Y);
    EXPECT_FALSE(header.hasTileDescription());
    const Imath::Box2i window = header.dataWindow();
    ASSERT_EQ(window.min, Imath::V2i(0, 0));
    ASSERT_EQ(window.max, Imath::V2i(width - 1, height - 1));
    EXPECT_EQ(header.displayWindow(), window);

    // Every channel the layers name, and nothing else; each read back separately.
    std::map<std::string, std::vector<float>> expected;
    for (const ExrLayer& layer : layers) {
        const std::size_t count = layer.channels.size();
        for (std::size_t c = 0; c < count; ++c) {
            const std::string name =
                layer.name.empty() ? layer.channels[c] : layer.name + "." + layer.channels[c];
            std::vector<float>& values = expected[name];
            for (std::size_t p = 0; p < pixels; ++p) values.push_back(layer.values[p * count + c]);
        }
    }
    std::vector<std::string> present;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        present.push_back(it.name());
        EXPECT_EQ(it.channel().type, Imf::FLOAT) << it.name();
    }
    std::vector<std::string> named;
    for (const auto& [name, values] : expected) named.push_back(name);
    EXPECT_EQ(present, named);  // both sorted

    std::map<std::string, std::vector<float>> read;
    Imf::FrameBuffer frame;
    for (const std::string& name : named) {
        std::vector<float>& values = read[name];
        values.assign(pixels, -1.0f);
        frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window));
    }
    input.setFrameBuffer(frame);
    input.readPixels(window.min.y, window.max.y);
    for (const std::string& name : named) {
        for (std::size_t p = 0; p < pixels; ++p) {
            EXPECT_TRUE(same_bits(read[name][p], expected[name][p]))
                << name << " at pixel (" << p % width << ", " << p / width << ")";
        }
    }
}

// RGBE stores each component as floor(c * 256 / 2^e) * 2^(e - 8), e being the exponent of the
// pixel's largest component m (2^(e-1) <= m < 2^e): truncation loses less than one unit of
// 2^(e-8), i.e. relative to m less than 2^-7, and less than 2^-8 of 2^e. stb_image_write scales
// by a float factor before truncating, which can land an exact multiple one unit low, so the
// bound asserted is <= 2^(e-8).
void expect_within_rgbe(const std::vector<float>& written, const HdrImage& read) {
    ASSERT_EQ(read.rgb.size(), written.size());
    for (std::size_t p = 0; p < written.size(); p += 3) {
        const float largest = std::max({written[p], written[p + 1], written[p + 2]});
        int exponent = 0;
        std::frexp(largest, &exponent);
        const double unit = std::ldexp(1.0, exponent - 8);
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_LE(std::abs(double(read.rgb[p + c]) - double(written[p + c])), unit)
                << "pixel " << p / 3 << " component " << c << ": wrote " << written[p + c]
                << ", read " << read.rgb[p + c];
        }
    }
}

TEST_F(HdrIo, RadianceRoundTripIsWithinRgbeQuantisation) {
    // 37 wide: run-length-encoded scanlines; 5 wide: flat ones (RGBE files need width >= 8 to
    // encode). Components spread over 2^-30..2^30, and within a pixel over 2^10, so small
    // components of bright pixels lose most of their bits.
    for (const int width : {37, 5}) {
        const int height = 6;
        HdrImage image{
            width, height,
            varied_values(std::size_t(width) * height * 3, unsigned(width), -30.0f, 30.0f)};
        for (std::size_t p = 0; p < image.rgb.size(); p += 3) {
            image.rgb[p + 1] = image.rgb[p] * std::exp2(-float(p % 11));
        }
        image.rgb[3] = image.rgb[4] = image.rgb[5] = 0.0f;
        const fs::path file = directory_ / ("round_trip_" + std::to_string(width) + ".hdr");
        write_radiance_hdr(file, image);
        const HdrImage read = read_hdr_image(file);
        ASSERT_EQ(read.width, width);
        ASSERT_EQ(read.height, height);
        expect_within_rgbe(image.rgb, read);
        EXPECT_EQ(read.rgb[3], 0.0f);
    }
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(HdrIo, RadianceWriterClampsNegativesAndRefusesNaN) {
    const fs::path file = directory_ / "values.hdr";
    HdrImage image{2, 1, {-1.0f, 0.5f, 0.25f, 1.0f, 2.0f, 4.0f}};
    write_radiance_hdr(file, image);
    const HdrImage read = read_hdr_image(file);
    EXPECT_EQ(read.rgb, (std::vector<float>{0.0f, 0.5f, 0.25f, 1.0f, 2.0f, 4.0f}));

    image.rgb[4] = std::nanf("");
    const std::string message =
        one_line_error<std::invalid_argument>(file, [&] { write_radiance_hdr(file, image); });
    EXPECT_NE(message.find("NaN value at pixel (1, 0)"), std::string::npos) << message;
    image.rgb[4] = std::numeric_limits<float>::infinity();
    EXPECT_THROW(write_radiance_hdr(file, image), std::invalid_argument);
    EXPECT_EQ(read_hdr_image(file).rgb, read.rgb);  // the earlier file is untouched
}

// ---- Hand-made files and orientation ----

// RGBE texel (r, g, b, e) is (r, g, b) * 2^(e - 136), and black when e is 0.
TEST_F(HdrIo, ReadsAHandMadeFlatRadianceFileTopRowFirst) {
    Bytes data;
    append(data, {128, 64, 32, 129, 255, 0, 1, 136, 9, 9, 9, 0});      // top row
    append(data, {200, 100, 50, 128, 1, 2, 3, 140, 16, 16, 16, 120});  // bottom row
    const fs::path file = directory_ / "flat.hdr";
    write_bytes(file, radiance_file(3, 2, data));
    const HdrImage image = read_hdr_image(file);
    ASSERT_EQ(image.width, 3);
    ASSERT_EQ(image.height, 2);
    const float tiny = std::exp2(-12.0f);
    EXPECT_EQ(image.rgb,
              (std::vector<float>{1.0f, 0.5f, 0.25f, 255.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.78125f,
                                  0.390625f, 0.1953125f, 16.0f, 32.0f, 48.0f, tiny, tiny, tiny}));
}

TEST_F(HdrIo, ReadsAHandMadeRunLengthEncodedRadianceFileTopRowFirst) {
    // 8 x 2; each scanline is 2 2 0 8, then each of R, G, B, E as runs (128 + n, value) and
    // literals (n, n values).
    Bytes data;
    append(data, {2, 2, 0, 8});
    append(data, {128 + 8, 128});                       // R: 128 everywhere
    append(data, {8, 0, 16, 32, 48, 64, 80, 96, 112});  // G: literal
    append(data, {128 + 4, 0, 4, 1, 2, 3, 4});          // B: run of 0, then literal
    append(data, {128 + 8, 129});                       // E: 2^-7
    append(data, {2, 2, 0, 8});
    append(data, {8, 8, 16, 24, 32, 40, 48, 56, 64});  // R: literal
    append(data, {128 + 8, 64});                       // G: run
    append(data, {128 + 2, 7, 128 + 6, 9});            // B: two runs
    append(data, {128 + 7, 130, 1, 0});                // E: 2^-6, then black
    const fs::path file = directory_ / "rle.hdr";
    write_bytes(file, radiance_file(8, 2, data));
    const HdrImage image = read_hdr_image(file);
    ASSERT_EQ(image.width, 8);
    ASSERT_EQ(image.height, 2);
    for (int x = 0; x < 8; ++x) {
        const float* top = &image.rgb[image.pixel_index(x, 0)];
        EXPECT_EQ(top[0], 1.0f) << x;
        EXPECT_EQ(top[1], float(16 * x) / 128.0f) << x;
        EXPECT_EQ(top[2], x < 4 ? 0.0f : float(x - 3) / 128.0f) << x;
        const float* bottom = &image.rgb[image.pixel_index(x, 1)];
        const float scale = x < 7 ? 1.0f / 64.0f : 0.0f;
        EXPECT_EQ(bottom[0], float(8 * (x + 1)) * scale) << x;
        EXPECT_EQ(bottom[1], 64.0f * scale) << x;
        EXPECT_EQ(bottom[2], (x < 2 ? 7.0f : 9.0f) * scale) << x;
    }
}

TEST_F(HdrIo, ReadsHalfPizExrWithAnOffsetDataWindowTopRowFirst) {
    const fs::path file = directory_ / "half.exr";
    write_half_piz_exr(file, 4, 3);
    const HdrImage image = read_hdr_image(file);
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 3);
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 4; ++x) {
            const float* pixel = &image.rgb[image.pixel_index(x, y)];
            EXPECT_EQ(pixel[0], float(x + 1) * 0.25f);
            EXPECT_EQ(pixel[1], float(y + 1) * 0.25f);
            EXPECT_EQ(pixel[2], 0.125f);
        }
    }
}

TEST_F(HdrIo, ReadsTiledExr) {
    const fs::path file = directory_ / "tiled.exr";
    write_tiled_exr(file, 9, 6);
    const HdrImage image = read_hdr_image(file);
    ASSERT_EQ(image.width, 9);
    ASSERT_EQ(image.height, 6);
    for (int y = 0; y < 6; ++y) {
        for (int x = 0; x < 9; ++x) {
            const float* pixel = &image.rgb[image.pixel_index(x, y)];
            EXPECT_EQ(pixel[0], float(x + 1));
            EXPECT_EQ(pixel[1], float(y + 1));
            EXPECT_EQ(pixel[2], float(x + y + 1));
        }
    }
}

TEST_F(HdrIo, ChoosesTheFormatByContentNotName) {
    const fs::path exr_named_hdr = directory_ / "really_exr.hdr";
    write_exr(exr_named_hdr, 2, 1, {{"", {"R", "G", "B"}, {1, 2, 3, 4, 5, 6}}});
    EXPECT_EQ(read_hdr_image(exr_named_hdr).rgb, (std::vector<float>{1, 2, 3, 4, 5, 6}));
    const fs::path hdr_named_exr = directory_ / "really_hdr.exr";
    write_radiance_hdr(hdr_named_exr, HdrImage{2, 1, {1, 2, 4, 8, 16, 32}});
    EXPECT_EQ(read_hdr_image(hdr_named_exr).rgb, (std::vector<float>{1, 2, 4, 8, 16, 32}));
}

TEST_F(HdrIo, ExrNaNAndInfinityAreRefusedNegativesBecomeZero) {
    const fs::path file = directory_ / "values.exr";
    write_exr(file, 2, 2, {{"", {"R", "G", "B"}, {1, -2, 3, -0.0f, 5, 6, 7, 8, 9, 10, 11, 12}}});
    const HdrImage image = read_hdr_image(file);
    EXPECT_EQ(image.rgb, (std::vector<float>{1, 0, 3, 0, 5, 6, 7, 8, 9, 10, 11, 12}));
    EXPECT_FALSE(std::signbit(image.rgb[3]));

    write_exr(file, 2, 2,
              {{"", {"R", "G", "B"}, {1, 2, 3, 4, 5, 6, 7, std::nanf(""), 9, 10, 11, 12}}});
    EXPECT_NE(read_error(file).find("NaN value at pixel (0, 1)"), std::string::npos);
    write_exr(file, 2, 2,
              {{"",
                {"R", "G", "B"},
                {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, -std::numeric_limits<float>::infinity()}}});
    EXPECT_NE(read_error(file).find("infinite value at pixel (1, 1)"), std::string::npos);
}

TEST_F(HdrIo, ExrWithoutRgbChannelsIsRefused) {
    const fs::path file = directory_ / "depth_only.exr";
    write_exr(file, 2, 1, {{"depth", {"Z"}, {1, 2}}});
    EXPECT_NE(read_error(file).find("no R, G and B channels (it has: depth.Z)"), std::string::npos);
}

// ---- Bad input ----

TEST_F(HdrIo, MissingEmptyDirectoryAndOtherFilesGiveOneLineErrors) {
    EXPECT_NE(read_error(directory_ / "absent.hdr").find("no such file"), std::string::npos);
    EXPECT_NE(read_error(directory_).find("is a directory"), std::string::npos);

    const fs::path empty = directory_ / "empty.exr";
    write_bytes(empty, {});
    EXPECT_NE(read_error(empty).find("empty file"), std::string::npos);

    const fs::path png = directory_ / "image.hdr";
    write_png(png, Image8{2, 2, std::vector<uint8_t>(12, 100)});
    EXPECT_NE(read_error(png).find("a PNG image"), std::string::npos);

    const fs::path text = directory_ / "text.exr";
    write_bytes(text, text_bytes("hello\n"));
    EXPECT_NE(read_error(text).find("not a Radiance .hdr or OpenEXR file"), std::string::npos);

    const fs::path xyze = directory_ / "xyze.hdr";
    write_bytes(xyze,
                text_bytes("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\x80\x80\x80\x80"));
    EXPECT_NE(read_error(xyze).find("unsupported pixel format '32-bit_rle_xyze'"),
              std::string::npos);

    // Bottom-up rows: valid Radiance, but not the orientation read_hdr_image promises.
    const fs::path bottom_up = directory_ / "bottom_up.hdr";
    write_bytes(bottom_up, text_bytes("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 1 +X 1\nabcd"));
    EXPECT_NE(read_error(bottom_up).find("unsupported resolution line '+Y 1 +X 1'"),
              std::string::npos);
}

// stb_image 2.27 alone decodes a truncated flat file as black and hangs on a truncated
// run-length-encoded one (CVE-2021-42715).
TEST_F(HdrIo, TruncatedRadianceFilesAreRefused) {
    const fs::path source = directory_ / "source.hdr";
    HdrImage image{20, 6, varied_values(20 * 6 * 3, 7, -4.0f, 4.0f)};
    write_radiance_hdr(source, image);  // run-length encoded (width >= 8)
    const Bytes whole = read_bytes(source);
    const Bytes flat = radiance_file(3, 2, Bytes(24, 130));
    for (const Bytes* original : {&whole, &flat}) {
        for (std::size_t length :
             {std::size_t{12}, std::size_t{30}, original->size() / 2, original->size() - 1}) {
            const fs::path file = directory_ / "truncated.hdr";
            write_bytes(file, Bytes(original->begin(), original->begin() + long(length)));
            const std::string message = read_error(file);
            EXPECT_NE(message.find("truncated"), std::string::npos) << length << ": " << message;
        }
    }
}

// Run lengths no writer emits: zero (stb_image skips it; at the end of a truncated file,
// where it reads zeros, it loops on them forever: see TruncatedRadianceFilesAreRefused) and past
// the end of the scanline.
TEST_F(HdrIo, ZeroLengthRunInARadianceScanlineIsRefused) {
    // Otherwise whole: R, G, B and E each a run of 8 after the zero-length literal.
    Bytes data;
    append(data, {2, 2, 0, 8, 0, 128 + 8, 1, 128 + 8, 1, 128 + 8, 1, 128 + 8, 128});
    const fs::path file = directory_ / "zero_run.hdr";
    write_bytes(file, radiance_file(8, 1, data));
    EXPECT_NE(read_error(file).find("bad run length in scanline 0"), std::string::npos);

    data = {};
    append(data, {2, 2, 0, 8, 128 + 9, 1});  // a run past the end of the scanline
    data.resize(data.size() + 64, 1);
    write_bytes(file, radiance_file(8, 1, data));
    EXPECT_NE(read_error(file).find("bad run length in scanline 0"), std::string::npos);
}

TEST_F(HdrIo, TruncatedExrFilesAreRefused) {
    const fs::path source = directory_ / "source.exr";
    const int width = 24;
    const int height = 40;  // 3 ZIP chunks of 16 scanlines
    write_exr(source, width, height,
              {{"", {"R", "G", "B"}, varied_values(std::size_t(width) * height * 3, 8, -4, 4)}});
    const Bytes whole = read_bytes(source);
    for (std::size_t length :
         {std::size_t{4}, std::size_t{60}, whole.size() / 2, whole.size() - 1}) {
        const fs::path file = directory_ / "truncated.exr";
        write_bytes(file, Bytes(whole.begin(), whole.begin() + long(length)));
        read_error(file);
    }
}

// Overwrites the data window in the header of an EXR written by write_exr.
Bytes with_data_window(Bytes bytes, int max_x, int max_y) {
    const std::string attribute("dataWindow\0box2i\0", 17);
    const auto found = std::search(bytes.begin(), bytes.end(), attribute.begin(), attribute.end());
    EXPECT_NE(found, bytes.end());
    // size (4 bytes), then xMin, yMin, xMax, yMax, little-endian.
    const auto at = std::size_t(found - bytes.begin()) + attribute.size() + 4 + 8;
    for (int i = 0; i < 4; ++i) {
        bytes[at + std::size_t(i)] = static_cast<unsigned char>(unsigned(max_x) >> (8 * i));
        bytes[at + 4 + std::size_t(i)] = static_cast<unsigned char>(unsigned(max_y) >> (8 * i));
    }
    return bytes;
}

TEST_F(HdrIo, ExrWithAbsurdDimensionsIsRefused) {
    const fs::path source = directory_ / "source.exr";
    write_exr(source, 4, 4, {{"", {"R", "G", "B"}, std::vector<float>(48, 1.0f)}});
    const Bytes whole = read_bytes(source);
    const fs::path file = directory_ / "absurd.exr";
    // Past OpenEXR's per-side limit (which read_hdr_image sets to 16384), past the byte budget
    // (16384 x 16384 x 12 bytes is 3 GiB), and empty.
    const std::vector<std::pair<int, int>> windows = {
        {1 << 30, 1 << 30}, {3, 20000}, {16383, 16383}, {-5, 3}};
    for (const auto& [max_x, max_y] : windows) {
        // Room for the line offset table a 16384-line file has, so that OpenEXR gets as far as
        // handing over the header.
        Bytes patched = with_data_window(whole, max_x, max_y);
        patched.resize(patched.size() + 16384, 0);
        write_bytes(file, patched);
        const std::string message = read_error(file);
        SCOPED_TRACE(message);
        if (max_x == 16383) {
            EXPECT_NE(message.find("image too large"), std::string::npos);
        }
    }
}

// An attribute of a type OpenEXR 3.1 does not know, whose value it allocates at the stated size
// before reading it.
TEST_F(HdrIo, ExrWithAnOversizedAttributeIsRefused) {
    const fs::path file = directory_ / "attribute.exr";
    write_exr(file, 4, 4, {{"", {"R", "G", "B"}, std::vector<float>(48, 1.0f)}});
    Bytes bytes = read_bytes(file);
    const std::string attribute("lineOrder\0lineOrder\0", 20);
    const auto found = std::search(bytes.begin(), bytes.end(), attribute.begin(), attribute.end());
    ASSERT_NE(found, bytes.end());
    const std::size_t at = std::size_t(found - bytes.begin()) + attribute.size();
    ASSERT_EQ(bytes[at], 1);  // a one-byte value
    bytes[at + 3] = 0x7f;     // now 2 GiB - 255 bytes
    bytes[at - 2] = 'X';      // of type "lineOrdeX"
    write_bytes(file, bytes);
    EXPECT_NE(read_error(file).find("an attribute of 2130706433 bytes"), std::string::npos);

    // A known fixed-size type with another size: OpenEXR would read one byte and lose step.
    bytes[at + 3] = 0;
    bytes[at - 2] = 'r';
    bytes[at] = 2;
    write_bytes(file, bytes);
    EXPECT_NE(read_error(file).find("attribute 'lineOrder' has the wrong size"), std::string::npos);
}

// ---- Writing: validation and atomicity ----

TEST_F(HdrIo, FailedWritesThrowOneLineAndLeaveNoFile) {
    const HdrImage image{2, 1, {1, 2, 3, 4, 5, 6}};
    const std::vector<ExrLayer> beauty = {{"", {"R", "G", "B"}, image.rgb}};
    const fs::path missing = directory_ / "missing" / "out";
    for (const char* extension : {".hdr", ".exr"}) {
        const fs::path file = fs::path(missing).concat(extension);
        const std::string message = one_line_error<std::runtime_error>(file, [&] {
            if (file.extension() == ".hdr") {
                write_radiance_hdr(file, image);
            } else {
                write_exr(file, 2, 1, beauty);
            }
        });
        EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
    }
    EXPECT_FALSE(fs::exists(directory_ / "missing"));

    // A non-empty directory at the target: the temporary is written whole, then the rename
    // fails (even for root, who could write into a read-only directory).
    const fs::path occupied = directory_ / "occupied";
    fs::create_directories(occupied / "inside");
    EXPECT_THROW(write_radiance_hdr(occupied, image), std::runtime_error);
    EXPECT_THROW(write_exr(occupied, 2, 1, beauty), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(occupied / "inside"));
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(HdrIo, BadExrLayersAreRefusedBeforeWriting) {
    const fs::path file = directory_ / "out.exr";
    write_exr(file, 1, 1, {{"", {"R", "G", "B"}, {1, 2, 3}}});
    const Bytes before = read_bytes(file);
    const std::vector<std::pair<std::vector<ExrLayer>, std::string>> cases = {
        {{}, "no layers"},
        {{{"", {"R", "G", "B"}, {1, 2}}}, "needs 1 x 3 values, has 2"},
        {{{"", {}, {}}}, "has no channels"},
        {{{"", {"R", "R"}, {1, 2}}}, "channel 'R' appears twice"},
        {{{"albedo", {"R"}, {1}}, {"albedo", {"R"}, {2}}}, "channel 'albedo.R' appears twice"},
        {{{"", {"R.G"}, {1}}}, "bad channel name 'R.G'"},
        {{{"", {""}, {1}}}, "bad channel name ''"},
        {{{"a..b", {"R"}, {1}}}, "bad layer 'a..b' name"},
        {{{".x", {"R"}, {1}}}, "bad layer '.x' name"},
    };
    for (const auto& [layers, expected] : cases) {
        const std::string message =
            one_line_error<std::invalid_argument>(file, [&] { write_exr(file, 1, 1, layers); });
        EXPECT_NE(message.find(expected), std::string::npos) << message;
    }
    EXPECT_THROW(write_exr(file, 0, 1, {{"", {"R"}, {}}}), std::invalid_argument);
    EXPECT_THROW(write_radiance_hdr(file, HdrImage{2, 2, {1, 2, 3}}), std::invalid_argument);
    EXPECT_EQ(read_bytes(file), before);
    EXPECT_TRUE(temporaries().empty());
}

// ---- Fuzzing ----

// Byte mutations of small valid files of every kind read_hdr_image reads, with a fixed seed:
// each must read as an image within the limits, finite and non-negative, or fail with a
// one-line runtime_error; a crash, hang or other exception fails the test. ~5000 reads of
// files under 2 KiB.
TEST_F(HdrIo, FuzzedFilesNeverCrashOrHang) {
    std::vector<Bytes> seeds;
    const fs::path scratch = directory_ / "seed";
    write_radiance_hdr(scratch, HdrImage{12, 3, varied_values(12 * 3 * 3, 9, -8, 8)});
    seeds.push_back(read_bytes(scratch));
    write_radiance_hdr(scratch, HdrImage{5, 4, varied_values(5 * 4 * 3, 10, -8, 8)});
    seeds.push_back(read_bytes(scratch));
    write_exr(scratch, 6, 20,
              {{"", {"R", "G", "B"}, varied_values(6 * 20 * 3, 11, -8, 8)},
               {"depth", {"Z"}, varied_values(6 * 20, 12, -8, 8)}});
    seeds.push_back(read_bytes(scratch));
    write_half_piz_exr(scratch, 7, 5);
    seeds.push_back(read_bytes(scratch));
    write_tiled_exr(scratch, 9, 6);
    seeds.push_back(read_bytes(scratch));

    std::mt19937 random(20261123);
    const int interesting[] = {0,     1,     -1,   0x7f, 0x80, 0xff, 0x7fffffff, int(0x80000000u),
                               16384, 16385, 65535};
    const fs::path file = directory_ / "fuzzed";
    int read_ok = 0;
    int refused = 0;
    for (const Bytes& seed : seeds) {
        for (int iteration = 0; iteration < 1000; ++iteration) {
            Bytes bytes = seed;
            const int mutations = 1 + int(random() % 4);
            for (int m = 0; m < mutations && !bytes.empty(); ++m) {
                const std::size_t at = random() % bytes.size();
                switch (random() % 6) {
                    case 0:
                        bytes[at] = static_cast<unsigned char>(random());
                        break;
                    case 1:
                        bytes[at] ^= static_cast<unsigned char>(1u << (random() % 8));
                        break;
                    case 2:
                        bytes.resize(at);
                        break;
                    case 3:
                        bytes.insert(bytes.begin() + long(at), 1 + random() % 8,
                                     static_cast<unsigned char>(random()));
                        break;
                    case 4:
                        bytes.erase(
                            bytes.begin() + long(at),
                            bytes.begin() + long(std::min(bytes.size(), at + 1 + random() % 8)));
                        break;
                    default: {
                        const int value = interesting[random() % std::size(interesting)];
                        for (std::size_t i = 0; i < 4 && at + i < bytes.size(); ++i) {
                            bytes[at + i] = static_cast<unsigned char>(unsigned(value) >> (8 * i));
                        }
                    }
                }
            }
            // A new file each time: ext4 flushes a truncated-and-rewritten file to disk on close.
            fs::remove(file);
            write_bytes(file, bytes);
            try {
                const HdrImage image = read_hdr_image(file);
                ASSERT_GE(image.width, 1);
                ASSERT_GE(image.height, 1);
                ASSERT_LE(image.width, kMaxHdrImageSide);
                ASSERT_LE(image.height, kMaxHdrImageSide);
                ASSERT_EQ(image.rgb.size(), std::size_t(image.width) * image.height * 3);
                for (float value : image.rgb) ASSERT_TRUE(std::isfinite(value) && value >= 0);
                ++read_ok;
            } catch (const std::runtime_error& error) {
                const std::string message = error.what();
                ASSERT_EQ(message.find('\n'), std::string::npos) << message;
                ASSERT_EQ(message.rfind("cannot read '" + file.string() + "': ", 0), 0u) << message;
                ++refused;
            }
        }
    }
    // Both outcomes occur: the mutations neither all miss nor all break the files.
    EXPECT_GT(read_ok, 100);
    EXPECT_GT(refused, 100);
    std::cout << "fuzzed reads: " << read_ok << " read, " << refused << " refused\n";
}

}  // namespace
}  // namespace fgr
