// SPDX-License-Identifier: Apache-2.0
// The view an image file carries (image/embedded_view.hpp): written by the PNG and EXR writers
// and read back the same, pixels unchanged by it; nothing read from a file without one; and the
// reader on untrusted files: truncated and mutated files of every format, other files, FIFOs and
// directories, documents over the limit, each a document, nothing or a one-line error.

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <tiffio.h>
#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "fuzz_rng.hpp"
#include "image/embedded_view.hpp"
#include "image/hdr_io.hpp"
#include "image/image_io.hpp"
#include "output/tiled/streaming_image.hpp"
#include "test_files.hpp"

namespace fgr {
// A namespace of its own: the tests compile in unity batches, beside helpers of the same names.
namespace embedded_view_test {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;
using test::read_bytes;
using test::write_bytes;

// A view with a nested object, numbers and text beyond ASCII.
const std::string kView = R"({"scene":"mandelbulb","camera":{"position":[0,-3,0.5],"fov":45},)"
                          R"("note":"Zoom über die Küste \u2014 ✓"})";

// A JSON document of exactly `bytes` bytes whose text varies (so it does not deflate to nothing).
std::string sized_view(std::size_t bytes) {
    std::string view = R"({"pad":")";
    test::FuzzRng random(bytes);
    while (view.size() + 2 < bytes) view += static_cast<char>('a' + random.below(26));
    return view + "\"}";
}

Image8 rgb8(int width, int height, bool alpha) {
    Image8 image{width, height, {}, {}};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.rgb.push_back(static_cast<uint8_t>(x * 7 + y));
            image.rgb.push_back(static_cast<uint8_t>(y * 11));
            image.rgb.push_back(static_cast<uint8_t>(x * y));
            if (alpha) image.alpha.push_back(static_cast<uint8_t>(x * 8));
        }
    }
    return image;
}

Image16 rgb16(int width, int height, bool alpha) {
    Image16 image{width, height, {}, {}};
    for (int i = 0; i < width * height; ++i) {
        for (int c = 0; c < 3; ++c) image.rgb.push_back(static_cast<uint16_t>(i * 613 + c * 9001));
        if (alpha) image.alpha.push_back(static_cast<uint16_t>(i * 257));
    }
    return image;
}

std::vector<ExrLayer> exr_layers(int width, int height, bool with_layers) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    std::vector<ExrLayer> layers = {{"", {"R", "G", "B"}, {}}};
    if (with_layers) {
        layers.push_back({"albedo", {"R", "G", "B"}, {}});
        layers.push_back({"depth", {"Z"}, {}});
        layers.push_back({"", {"A"}, {}});
    }
    float value = -2.0f;
    for (ExrLayer& layer : layers) {
        for (std::size_t i = 0; i < pixels * layer.channels.size(); ++i) {
            layer.values.push_back(value += 0.37f);
        }
    }
    return layers;
}

// Every channel of an EXR file, by name, as floats.
std::vector<std::pair<std::string, std::vector<float>>> exr_channels(const fs::path& file) {
    Imf::InputFile input(file.c_str());
    const Imath::Box2i window = input.header().dataWindow();
    const std::size_t width = std::size_t(window.max.x - window.min.x + 1);
    const std::size_t height = std::size_t(window.max.y - window.min.y + 1);
    std::vector<std::pair<std::string, std::vector<float>>> channels;
    for (auto it = input.header().channels().begin(); it != input.header().channels().end(); ++it) {
        channels.emplace_back(it.name(), std::vector<float>(width * height));
    }
    Imf::FrameBuffer frame;
    for (auto& [name, values] : channels) {
        frame.insert(name, Imf::Slice::Make(Imf::FLOAT, values.data(), window, sizeof(float),
                                            sizeof(float) * width));
    }
    input.setFrameBuffer(frame);
    input.readPixels(window.min.y, window.max.y);
    return channels;
}

// The reader's verdict on a file that may be anything: the document, nothing, or the one-line
// error naming the file ("error: ..."). A crash, a hang or another exception fails the test.
std::string verdict(const fs::path& file) {
    try {
        const std::optional<std::string> view = read_embedded_view(file);
        if (!view) return "none";
        EXPECT_LE(view->size(), kMaxEmbeddedViewBytes);
        return "view: " + *view;
    } catch (const std::runtime_error& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(message.rfind("cannot read '" + file.string() + "': ", 0), 0u) << message;
        return "error: " + message.substr(message.find("': ") + 3);
    }
}

// A PNG chunk: length, type, data, CRC.
Bytes png_chunk(const std::string& type, const Bytes& data) {
    Bytes chunk;
    const auto length = static_cast<std::uint32_t>(data.size());
    for (int shift = 24; shift >= 0; shift -= 8) chunk.push_back(uint8_t(length >> shift));
    chunk.insert(chunk.end(), type.begin(), type.end());
    chunk.insert(chunk.end(), data.begin(), data.end());
    const auto crc = static_cast<std::uint32_t>(
        crc32(crc32(0, nullptr, 0), chunk.data() + 4, static_cast<uInt>(data.size() + 4)));
    for (int shift = 24; shift >= 0; shift -= 8) chunk.push_back(uint8_t(crc >> shift));
    return chunk;
}

// iTXt data: keyword, compression flag and method, empty language and translated keyword, text.
Bytes itxt(const std::string& keyword, const std::string& text, bool compressed) {
    Bytes data(keyword.begin(), keyword.end());
    data.insert(data.end(), {0, uint8_t(compressed ? 1 : 0), 0, 0, 0});
    if (!compressed) {
        data.insert(data.end(), text.begin(), text.end());
        return data;
    }
    Bytes deflated(compressBound(static_cast<uLong>(text.size())));
    uLongf size = static_cast<uLongf>(deflated.size());
    EXPECT_EQ(compress(deflated.data(), &size, reinterpret_cast<const Bytef*>(text.data()),
                       static_cast<uLong>(text.size())),
              Z_OK);
    data.insert(data.end(), deflated.begin(), deflated.begin() + long(size));
    return data;
}

// `png` with `chunks` inserted after its header chunk (IHDR: 8 + 25 bytes).
Bytes with_chunks_after_header(const Bytes& png, const std::vector<Bytes>& chunks) {
    Bytes bytes(png.begin(), png.begin() + 33);
    for (const Bytes& chunk : chunks) bytes.insert(bytes.end(), chunk.begin(), chunk.end());
    bytes.insert(bytes.end(), png.begin() + 33, png.end());
    return bytes;
}

// A one-strip 8-bit RGB TIFF written by libtiff, with the given Software and ImageDescription.
void write_tiff_with(const fs::path& file, const char* software, const std::string& description) {
    TIFF* tiff = TIFFOpen(file.c_str(), "w");
    ASSERT_NE(tiff, nullptr);
    TIFFSetField(tiff, TIFFTAG_IMAGEWIDTH, 2u);
    TIFFSetField(tiff, TIFFTAG_IMAGELENGTH, 1u);
    TIFFSetField(tiff, TIFFTAG_SAMPLESPERPIXEL, uint16_t(3));
    TIFFSetField(tiff, TIFFTAG_BITSPERSAMPLE, uint16_t(8));
    TIFFSetField(tiff, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
    TIFFSetField(tiff, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    if (software != nullptr) TIFFSetField(tiff, TIFFTAG_SOFTWARE, software);
    TIFFSetField(tiff, TIFFTAG_IMAGEDESCRIPTION, description.c_str());
    uint8_t row[6] = {1, 2, 3, 4, 5, 6};
    EXPECT_EQ(TIFFWriteScanline(tiff, row, 0, 0), 1);
    TIFFClose(tiff);
}

// Streams a 20x12 image of `layout` to `file` through fgr's streaming writer in two bands.
void stream_image(const fs::path& file, ImageFormat format, const RowLayout& layout,
                  const std::string& view) {
    constexpr int kWidth = 20, kHeight = 12;
    Bytes rows(std::size_t(kWidth) * kHeight * layout.pixel_bytes());
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = static_cast<uint8_t>(i * 37 % 251);
    if (layout.type == SampleType::F32) {
        for (std::size_t i = 0; i < rows.size(); i += 4) rows[i + 3] = 0x3f;  // finite floats
    }
    auto writer = open_streaming_image(file, format, kWidth, kHeight, layout, {}, view);
    const std::size_t row_bytes = std::size_t(kWidth) * layout.pixel_bytes();
    writer->write_rows(rows.data(), 5);
    writer->write_rows(rows.data() + 5 * row_bytes, kHeight - 5);
    writer->finish();
}

class EmbeddedView : public ::testing::Test {
protected:
    fs::path file(const std::string& name) const { return dir_.path() / name; }

private:
    test::TempDir dir_{"fgr_embedded_view"};
};

// ---- Round trips ----

TEST_F(EmbeddedView, PngOfEveryKindCarriesTheViewAndTheSamePixels) {
    const std::string large = sized_view(200 * 1024);  // deflated in the file
    const std::string largest = sized_view(kMaxEmbeddedViewBytes);
    struct Case {
        const char* name;
        std::function<void(const fs::path&, const std::string&)> write;
    };
    const std::vector<Case> cases = {
        {"8-bit RGB",
         [](const fs::path& f, const std::string& v) { write_png(f, rgb8(32, 24, false), v); }},
        {"8-bit RGBA",
         [](const fs::path& f, const std::string& v) { write_png(f, rgb8(32, 24, true), v); }},
        {"16-bit RGB",
         [](const fs::path& f, const std::string& v) {
             write_png16_linear(f, rgb16(32, 24, false), v);
         }},
        {"16-bit RGBA",
         [](const fs::path& f, const std::string& v) {
             write_png16_linear(f, rgb16(32, 24, true), v);
         }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        c.write(file("plain.png"), "");
        EXPECT_EQ(read_embedded_view(file("plain.png")), std::nullopt);
        const PngSamples plain = read_png_samples(file("plain.png"));
        // The largest view once: deflating a mebibyte takes 30 ms.
        std::vector<const std::string*> views = {&kView, &large};
        if (c.name == std::string("8-bit RGB")) views.push_back(&largest);
        for (const std::string* view : views) {
            c.write(file("view.png"), *view);
            EXPECT_EQ(read_embedded_view(file("view.png")), *view);
            const PngSamples carrying = read_png_samples(file("view.png"));
            EXPECT_EQ(carrying.samples, plain.samples);
            EXPECT_EQ(carrying.channels, plain.channels);
            EXPECT_EQ(carrying.bit_depth, plain.bit_depth);
        }
    }
    // A small view is plain text in the file, as any PNG tool shows it; a large one is deflated.
    write_png(file("small.png"), rgb8(4, 4, false), kView);
    const Bytes small = read_bytes(file("small.png"));
    const Bytes text(kView.begin(), kView.end());
    EXPECT_NE(std::search(small.begin(), small.end(), text.begin(), text.end()), small.end());
    write_png(file("large.png"), rgb8(4, 4, false), large);
    EXPECT_LT(fs::file_size(file("large.png")), large.size());
}

TEST_F(EmbeddedView, ExrWithAndWithoutLayersCarriesTheViewAndTheSamePixels) {
    for (bool with_layers : {false, true}) {
        SCOPED_TRACE(with_layers ? "with layers" : "beauty only");
        const std::vector<ExrLayer> layers = exr_layers(32, 24, with_layers);
        write_exr(file("plain.exr"), 32, 24, layers);
        EXPECT_EQ(read_embedded_view(file("plain.exr")), std::nullopt);
        for (const std::string& view : {kView, sized_view(kMaxEmbeddedViewBytes)}) {
            write_exr(file("view.exr"), 32, 24, layers, view);
            EXPECT_EQ(read_embedded_view(file("view.exr")), view);
            EXPECT_EQ(exr_channels(file("view.exr")), exr_channels(file("plain.exr")));
            EXPECT_EQ(read_hdr_image(file("view.exr")).rgb, read_hdr_image(file("plain.exr")).rgb);
        }
    }
}

TEST_F(EmbeddedView, TiffOfEveryKindCarriesTheView) {
    const std::vector<RowLayout> layouts = {{{"R", "G", "B"}, SampleType::U8},
                                            {{"R", "G", "B", "A"}, SampleType::U8},
                                            {{"R", "G", "B"}, SampleType::U16}};
    for (const RowLayout& layout : layouts) {
        stream_image(file("plain.tif"), ImageFormat::Tiff, layout, "");
        EXPECT_EQ(read_embedded_view(file("plain.tif")), std::nullopt);
        stream_image(file("view.tif"), ImageFormat::Tiff, layout, kView);
        EXPECT_EQ(read_embedded_view(file("view.tif")), kView);
    }
    // Another program's description is not fgr's view.
    write_tiff_with(file("other.tif"), "ImageJ", "ImageJ=1.54f");
    EXPECT_EQ(read_embedded_view(file("other.tif")), std::nullopt);
    write_tiff_with(file("anonymous.tif"), nullptr, kView);
    EXPECT_EQ(read_embedded_view(file("anonymous.tif")), std::nullopt);
    write_tiff_with(file("fgr.tif"), "fgr", kView);
    EXPECT_EQ(read_embedded_view(file("fgr.tif")), kView);
}

// The format is the file's, whatever its name says.
TEST_F(EmbeddedView, TheFormatIsReadFromTheFileNotItsName) {
    write_png(file("png.exr"), rgb8(4, 4, false), kView);
    write_exr(file("exr.tif"), 4, 4, exr_layers(4, 4, false), kView);
    stream_image(file("tiff.png"), ImageFormat::Tiff, {{"R", "G", "B"}, SampleType::U8}, kView);
    for (const char* name : {"png.exr", "exr.tif", "tiff.png"}) {
        EXPECT_EQ(read_embedded_view(file(name)), kView) << name;
    }
}

// ---- Other chunks, attributes and tags ----

TEST_F(EmbeddedView, PngChunksOfOtherProgramsAreSkippedAndCompressedViewsInflated) {
    write_png(file("plain.png"), rgb8(8, 6, false));
    const Bytes plain = read_bytes(file("plain.png"));
    // A large XMP packet before fgr's view: not fgr's, so neither read whole nor refused.
    const Bytes xmp =
        png_chunk("iTXt", itxt("XML:com.adobe.xmp", std::string(3 << 20, 'x'), false));
    const Bytes text = png_chunk("tEXt", {'C', 'o', 'm', 'm', 'e', 'n', 't', 0, 'h', 'i'});
    write_bytes(file("others.png"), with_chunks_after_header(plain, {xmp, text}));
    EXPECT_EQ(verdict(file("others.png")), "none");
    write_bytes(
        file("compressed.png"),
        with_chunks_after_header(plain, {xmp, png_chunk("iTXt", itxt("fgr:view", kView, true))}));
    EXPECT_EQ(verdict(file("compressed.png")), "view: " + kView);
    // A byte of the view changed: its chunk's checksum no longer holds.
    Bytes damaged = read_bytes(file("compressed.png"));
    const Bytes keyword = {'f', 'g', 'r', ':', 'v', 'i', 'e', 'w'};
    const auto at = std::search(damaged.begin(), damaged.end(), keyword.begin(), keyword.end());
    ASSERT_NE(at, damaged.end());
    at[20] ^= 1;
    write_bytes(file("damaged.png"), damaged);
    EXPECT_EQ(verdict(file("damaged.png")),
              "error: corrupt (the fgr:view chunk fails its checksum)");
    // After the pixels, where fgr never writes it, it is not looked for.
    Bytes after = plain;
    const Bytes chunk = png_chunk("iTXt", itxt("fgr:view", kView, false));
    after.insert(after.end() - 12, chunk.begin(), chunk.end());  // before IEND
    write_bytes(file("after.png"), after);
    EXPECT_EQ(verdict(file("after.png")), "none");
}

TEST_F(EmbeddedView, AnExrViewOfAnotherTypeIsRefused) {
    Imf::Header header(2, 2);
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    header.insert(kExrViewAttribute, Imf::IntAttribute(3));
    {
        Imf::OutputFile output(file("int.exr").c_str(), header);
        std::vector<float> values(4, 1.0f);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()),
                                     sizeof(float), 2 * sizeof(float)));
        output.setFrameBuffer(frame);
        output.writePixels(2);
    }
    EXPECT_EQ(verdict(file("int.exr")),
              "error: corrupt header (fgrView is of type 'int', not a string)");
}

// ---- Limits ----

TEST_F(EmbeddedView, ADocumentOverOneMebibyteIsRefusedByWritersAndReader) {
    const std::string over = sized_view(kMaxEmbeddedViewBytes + 1);
    const std::string expected = "the embedded view is 1048577 bytes (at most 1048576)";
    const auto message = [](auto&& write) {
        try {
            write();
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message([&] { write_png(file("a.png"), rgb8(4, 4, false), over); }),
              "cannot write '" + file("a.png").string() + "': " + expected);
    EXPECT_NE(message([&] {
                  write_png16_linear(file("a.png"), rgb16(4, 4, false), over);
              }).find(expected),
              std::string::npos);
    EXPECT_NE(message([&] {
                  write_exr(file("a.exr"), 4, 4, exr_layers(4, 4, false), over);
              }).find(expected),
              std::string::npos);
    for (ImageFormat format : {ImageFormat::Png, ImageFormat::Tiff}) {
        EXPECT_NE(message([&] {
                      open_streaming_image(file("a.tif"), format, 4, 4,
                                           {{"R", "G", "B"}, SampleType::U8}, {}, over);
                  }).find(expected),
                  std::string::npos);
    }
    EXPECT_NE(message([&] {
                  open_streaming_image(file("a.exr"), ImageFormat::Exr, 4, 4,
                                       {{"R"}, SampleType::F32}, {}, over);
              }).find(expected),
              std::string::npos);
    // A NUL ends PNG's and TIFF's text early; iTXt is UTF-8.
    EXPECT_NE(message([&] {
                  write_png(file("a.png"), rgb8(4, 4, false), std::string("{\0}", 3));
              }).find("holds a NUL byte at 1"),
              std::string::npos);
    EXPECT_NE(message([&] {
                  write_png(file("a.png"), rgb8(4, 4, false), "{\"\xc3\x28\"}");
              }).find("not UTF-8 at byte 2"),
              std::string::npos);
    EXPECT_TRUE(test::directory_listing(file("")).empty()) << "a refused write leaves no file";

    // Files written by others.
    write_png(file("plain.png"), rgb8(8, 6, false));
    const Bytes plain = read_bytes(file("plain.png"));
    write_bytes(file("over.png"), with_chunks_after_header(
                                      plain, {png_chunk("iTXt", itxt("fgr:view", over, false))}));
    EXPECT_EQ(verdict(file("over.png")), "error: " + expected);
    // Deflated, a few KiB in the file, past the limit once inflated.
    write_bytes(file("bomb.png"),
                with_chunks_after_header(
                    plain, {png_chunk("iTXt", itxt("fgr:view", std::string(8 << 20, ' '), true))}));
    EXPECT_LT(fs::file_size(file("bomb.png")), 256u * 1024);
    EXPECT_EQ(verdict(file("bomb.png")),
              "error: the embedded view is over 1048576 bytes once inflated");

    Imf::Header header(2, 2);
    header.channels().insert("R", Imf::Channel(Imf::FLOAT));
    header.insert(kExrViewAttribute, Imf::StringAttribute(over));
    {
        Imf::OutputFile output(file("over.exr").c_str(), header);
        std::vector<float> values(4, 1.0f);
        Imf::FrameBuffer frame;
        frame.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()),
                                     sizeof(float), 2 * sizeof(float)));
        output.setFrameBuffer(frame);
        output.writePixels(2);
    }
    EXPECT_EQ(verdict(file("over.exr")), "error: " + expected);

    write_tiff_with(file("over.tif"), "fgr", over);
    EXPECT_EQ(verdict(file("over.tif")), "error: " + expected);
}

// ---- What is not an image ----

TEST_F(EmbeddedView, WhatIsNotARegularImageFileIsRefusedWithoutOpeningIt) {
    EXPECT_EQ(verdict(file("absent.png")), "error: no such file");
    fs::create_directories(file("folder.png"));
    EXPECT_EQ(verdict(file("folder.png")), "error: is a directory");
    // Opening a FIFO for reading would wait for a writer that never comes.
    ASSERT_EQ(::mkfifo(file("fifo.png").c_str(), 0600), 0);
    EXPECT_EQ(verdict(file("fifo.png")), "error: not a regular file");
    EXPECT_EQ(verdict("/dev/null"), "error: not a regular file");
    write_bytes(file("empty.png"), {});
    EXPECT_EQ(verdict(file("empty.png")), "error: empty file");
    test::write_text(file("text.png"), "{\"scene\": \"mandelbulb\"}\n");
    EXPECT_EQ(verdict(file("text.png")), "error: not a PNG, TIFF or OpenEXR image");
    write_bytes(file("jpeg.png"), {0xff, 0xd8, 0xff, 0xe0, 0, 0x10, 'J', 'F', 'I', 'F', 0});
    EXPECT_EQ(verdict(file("jpeg.png")), "error: not a PNG, TIFF or OpenEXR image");
    write_radiance_hdr(file("image.hdr"), HdrImage{1, 1, {1, 2, 3}});
    EXPECT_EQ(verdict(file("image.hdr")), "error: not a PNG, TIFF or OpenEXR image");
}

// ---- Untrusted files ----

// Each seed file truncated at 200 random lengths and mutated 300 times (bytes flipped, set, cut
// or inserted), with a fixed seed: every read must give the document, nothing or a one-line
// error. ~2500 reads of files of a few KiB.
TEST_F(EmbeddedView, TruncatedAndMutatedFilesNeverCrash) {
    std::vector<std::pair<std::string, Bytes>> seeds;
    write_png(file("seed"), rgb8(12, 8, false), kView);
    seeds.emplace_back("png", read_bytes(file("seed")));
    write_png16_linear(file("seed"), rgb16(6, 4, true), sized_view(6000));
    seeds.emplace_back("deflated png", read_bytes(file("seed")));
    write_exr(file("seed"), 6, 4, exr_layers(6, 4, true), kView);
    seeds.emplace_back("exr", read_bytes(file("seed")));
    stream_image(file("seed"), ImageFormat::Tiff, {{"R", "G", "B"}, SampleType::U8}, kView);
    seeds.emplace_back("tiff", read_bytes(file("seed")));
    write_tiff_with(file("seed"), "fgr", "{}");  // a description stored in the entry itself
    seeds.emplace_back("small tiff", read_bytes(file("seed")));

    const uint8_t kInteresting[] = {0, 1, 0x7f, 0x80, 0xfe, 0xff};
    test::FuzzRng random(20260311);
    const fs::path fuzzed = file("fuzzed");
    int views = 0, nones = 0, errors = 0;
    for (const auto& [name, seed] : seeds) {
        SCOPED_TRACE(name);
        write_bytes(fuzzed, seed);
        ASSERT_EQ(verdict(fuzzed).rfind("view: ", 0), 0u);
        for (int i = 0; i < 500; ++i) {
            Bytes bytes = seed;
            if (i < 200) {
                bytes.resize(random.below(seed.size()));
            } else {
                for (int m = 0, count = random.range(1, 4); m < count && !bytes.empty(); ++m) {
                    const std::size_t at = random.below(bytes.size());
                    switch (random.below(4)) {
                        case 0:
                            bytes[at] ^= static_cast<uint8_t>(1u << random.below(8));
                            break;
                        case 1:
                            bytes[at] = random.pick(kInteresting);
                            break;
                        case 2:
                            bytes.erase(bytes.begin() + long(at),
                                        bytes.begin() +
                                            long(std::min(bytes.size(), at + 1 + random.below(8))));
                            break;
                        default:
                            bytes.insert(bytes.begin() + long(at), 1 + random.below(8),
                                         static_cast<uint8_t>(random.next()));
                    }
                }
            }
            fs::remove(fuzzed);
            write_bytes(fuzzed, bytes);
            const std::string result = verdict(fuzzed);
            views += result.rfind("view", 0) == 0;
            nones += result == "none";
            errors += result.rfind("error", 0) == 0;
        }
    }
    // Both outcomes occur: the document survives truncation past it, and most cuts before it
    // are refused.
    EXPECT_GT(views, 100);
    EXPECT_GT(errors, 500);
    RecordProperty("views", views);
    RecordProperty("none", nones);
    RecordProperty("errors", errors);
}

}  // namespace
}  // namespace embedded_view_test
}  // namespace fgr
