// SPDX-License-Identifier: Apache-2.0
// PNG writing (atomic replacement, failure cleanup) and reading.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image_io.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;

Image8 gradient(int width, int height) {
    Image8 image;
    image.width = width;
    image.height = height;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.rgb.push_back(static_cast<uint8_t>(x * 255 / (width - 1)));
            image.rgb.push_back(static_cast<uint8_t>(y * 255 / (height - 1)));
            image.rgb.push_back(static_cast<uint8_t>((x * 7 + y * 13) % 256));
        }
    }
    return image;
}

Image8 solid(int width, int height, uint8_t value) {
    return {width, height, std::vector<uint8_t>(std::size_t(3 * width * height), value)};
}

using test::read_bytes;
using test::write_bytes;

// Each test gets a fresh directory of its own, removed afterwards.
class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        directory_ = fs::temp_directory_path() /
                     ("fgr_image_io_" + std::to_string(::getpid()) + "_" + test->name());
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

TEST_F(ImageIo, RoundTripsAGradientExactly) {
    const Image8 image = gradient(37, 23);
    const fs::path file = directory_ / "gradient.png";
    write_png(file, image);
    const Image8 read = read_png(file);
    EXPECT_EQ(read.width, 37);
    EXPECT_EQ(read.height, 23);
    EXPECT_EQ(read.rgb, image.rgb);
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageIo, WritingIntoAMissingDirectoryThrowsAndLeavesNothing) {
    const fs::path file = directory_ / "missing" / "x.png";
    try {
        write_png(file, gradient(4, 4));
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& error) {
        EXPECT_EQ(std::string(error.what()),
                  "cannot write '" + file.string() + "': No such file or directory");
    }
    EXPECT_FALSE(fs::exists(directory_ / "missing"));
    EXPECT_TRUE(fs::is_empty(directory_));
}

TEST_F(ImageIo, ReplacesAnExistingFile) {
    const fs::path file = directory_ / "frame.png";
    write_png(file, solid(8, 8, 10));
    write_png(file, gradient(16, 9));
    const Image8 read = read_png(file);
    EXPECT_EQ(read.width, 16);
    EXPECT_EQ(read.rgb, gradient(16, 9).rgb);
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageIo, InvalidImageThrowsAndLeavesTheTargetUntouched) {
    const fs::path file = directory_ / "frame.png";
    write_png(file, solid(8, 8, 10));
    const std::vector<uint8_t> before = read_bytes(file);

    Image8 short_buffer = solid(8, 8, 200);
    short_buffer.rgb.pop_back();
    EXPECT_THROW(write_png(file, short_buffer), std::invalid_argument);
    EXPECT_THROW(write_png(file, Image8{}), std::invalid_argument);
    EXPECT_THROW(write_png(file, Image8{-2, 3, {}}), std::invalid_argument);

    EXPECT_EQ(read_bytes(file), before);
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageIo, FailedRenameRemovesTheTemporary) {
    // A non-empty directory at the target: the whole PNG gets written, then the rename fails
    // (even for root), which exercises cleanup after a complete temporary exists.
    const fs::path target = directory_ / "occupied.png";
    fs::create_directories(target / "inside");
    EXPECT_THROW(write_png(target, gradient(5, 5)), std::runtime_error);
    EXPECT_TRUE(fs::is_directory(target / "inside"));
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageIo, ReadingATextFileThrows) {
    const fs::path file = directory_ / "notes.png";
    std::ofstream(file) << "this is not a PNG file, only text\n";
    EXPECT_THROW(read_png(file), std::runtime_error);
}

// A FIFO named like a frame (fgr merge --frames reads whatever a folder holds) is refused at once
// with the reason, never opened for a read that waits for a writer forever.
TEST_F(ImageIo, ReadingAFifoIsRefusedWithoutBlocking) {
    const fs::path fifo = directory_ / "frame_00001.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    try {
        read_png(fifo);
        FAIL() << "a FIFO was read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("not a regular file (a FIFO)"), std::string::npos)
            << error.what();
    }
}

TEST_F(ImageIo, ReadingAMissingFileThrows) {
    EXPECT_THROW(read_png(directory_ / "absent.png"), std::runtime_error);
}

TEST_F(ImageIo, ReadingATruncatedPngThrows) {
    const fs::path file = directory_ / "truncated.png";
    write_png(file, gradient(64, 64));
    std::vector<uint8_t> bytes = read_bytes(file);
    bytes.resize(bytes.size() / 2);
    write_bytes(file, bytes);
    EXPECT_THROW(read_png(file), std::runtime_error);
}

// Hand-built 2 x 1 PNGs in the flavours read_png converts.
TEST_F(ImageIo, ReadsGreyPaletteAndAlphaImagesAsRgb) {
    const std::vector<uint8_t> grey = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
        0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
        0x00, 0xd1, 0x49, 0x20, 0x56, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
        0xda, 0x63, 0x10, 0xf8, 0x00, 0x00, 0x01, 0x13, 0x01, 0x01, 0xe6, 0xff, 0x11, 0x1b,
        0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    const std::vector<uint8_t> rgba = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
        0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0xf4,
        0x22, 0x7f, 0x8a, 0x00, 0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0x60,
        0x64, 0x62, 0x66, 0x38, 0x91, 0x62, 0xd4, 0x00, 0x00, 0x05, 0x61, 0x01, 0xe5, 0x22, 0xe3,
        0x1c, 0xa7, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    const std::vector<uint8_t> palette = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
        0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x03, 0x00, 0x00, 0x00, 0xc3,
        0xfc, 0x8f, 0xb8, 0x00, 0x00, 0x00, 0x06, 0x50, 0x4c, 0x54, 0x45, 0x09, 0x08, 0x07, 0x28,
        0x32, 0x3c, 0xdb, 0x8e, 0xa4, 0xd1, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
        0xda, 0x63, 0x60, 0x64, 0x00, 0x00, 0x00, 0x05, 0x00, 0x02, 0x42, 0xc2, 0x44, 0x9f, 0x00,
        0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
    const fs::path file = directory_ / "flavour.png";

    write_bytes(file, grey);
    EXPECT_EQ(read_png(file).rgb, (std::vector<uint8_t>{16, 16, 16, 240, 240, 240}));
    write_bytes(file, rgba);  // alpha 0 and 128: dropped, not composited
    EXPECT_EQ(read_png(file).rgb, (std::vector<uint8_t>{1, 2, 3, 200, 100, 50}));
    write_bytes(file, palette);  // indices 1, 0
    EXPECT_EQ(read_png(file).rgb, (std::vector<uint8_t>{40, 50, 60, 9, 8, 7}));
}

}  // namespace
}  // namespace fgr

namespace fgr {
namespace {

std::string file_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

class ImageIo16 : public ImageIo {};

TEST_F(ImageIo16, WritesSixteenBitLinearSamples) {
    Image16 image{3, 2, {}};
    for (int i = 0; i < 18; ++i) image.rgb.push_back(static_cast<uint16_t>(i * 3641 + 7));
    const fs::path file = directory_ / "linear.png";
    write_png16_linear(file, image);
    const std::string bytes = file_bytes(file);
    ASSERT_GT(bytes.size(), 33u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[24]), 16u);  // IHDR bit depth
    EXPECT_EQ(static_cast<unsigned char>(bytes[25]), 2u);   // RGB
    EXPECT_NE(bytes.find("gAMA"), std::string::npos);       // tagged linear, not sRGB
    EXPECT_EQ(bytes.find("sRGB"), std::string::npos);
    // Reading back reduces to 8 bits: the high byte of each sample.
    const Image8 read = read_png(file);
    ASSERT_EQ(read.rgb.size(), image.rgb.size());
    for (size_t i = 0; i < image.rgb.size(); ++i) EXPECT_EQ(read.rgb[i], image.rgb[i] >> 8);
    EXPECT_TRUE(temporaries().empty());
}

TEST_F(ImageIo16, EightBitFilesAreTaggedSrgb) {
    const fs::path file = directory_ / "display.png";
    write_png(file, gradient(4, 4));
    EXPECT_NE(file_bytes(file).find("sRGB"), std::string::npos);
}

TEST_F(ImageIo16, InvalidImageLeavesTheTargetUntouched) {
    const fs::path file = directory_ / "keep.png";
    write_png(file, gradient(4, 4));
    const std::string before = file_bytes(file);
    EXPECT_THROW(write_png16_linear(file, Image16{2, 2, {1, 2, 3}}), std::invalid_argument);
    EXPECT_EQ(file_bytes(file), before);
}

// With alpha the file is RGBA and keeps every sample as given (straight alpha: the colour is not
// multiplied by it), in 8 and 16 bits; read_png drops the alpha; an alpha of the wrong size is
// refused before anything is written.
TEST_F(ImageIo16, AlphaMakesAnRgbaFileWithTheSamplesAsGiven) {
    const fs::path file8 = directory_ / "rgba8.png", file16 = directory_ / "rgba16.png";
    Image8 image8 = gradient(3, 2);
    image8.alpha = {0, 1, 128, 254, 255, 7};
    write_png(file8, image8);
    const PngSamples read8 = read_png_samples(file8);
    ASSERT_EQ(read8.channels, 4);
    ASSERT_EQ(read8.bit_depth, 8);
    ASSERT_EQ(read8.samples.size(), 24u);
    for (std::size_t i = 0; i < 6; ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(read8.samples[i * 4 + c], image8.rgb[i * 3 + c]);
        }
        EXPECT_EQ(read8.samples[i * 4 + 3], image8.alpha[i]);
    }
    EXPECT_EQ(read_png(file8).rgb, image8.rgb);

    Image16 image16{2, 1, {1, 256, 65535, 40000, 0, 3}, {65535, 12345}};
    write_png16_linear(file16, image16);
    const PngSamples read16 = read_png_samples(file16);
    ASSERT_EQ(read16.channels, 4);
    ASSERT_EQ(read16.bit_depth, 16);
    EXPECT_EQ(read16.samples, (std::vector<uint16_t>{1, 256, 65535, 65535, 40000, 0, 3, 12345}));

    image8.alpha.pop_back();
    EXPECT_THROW(write_png(directory_ / "short.png", image8), std::invalid_argument);
    EXPECT_FALSE(fs::exists(directory_ / "short.png"));
}

}  // namespace
}  // namespace fgr
