// SPDX-License-Identifier: Apache-2.0
// What `fgr merge` trusts of the files it is given (output/parts/): a part's header is checked
// field by field (types, ranges, the identity's size, display and layers against the numbers) and
// the parts against one another before anything is allocated or written, so a damaged or forged
// part is refused in one line naming the file and the field, with no file left; a FIFO or a
// directory named like a frame is refused instead of waited on. Seeded fuzz tests mutate part
// headers (structure-aware: values swapped for huge, negative or mistyped ones, keys removed),
// part files (cut short, bytes flipped) and PNG frames. Parts here are written directly, 8x4, so
// nothing is compiled but in the one test that renders the reproducer of a forged size.
// Reproduce a fuzz failure with FGR_FUZZ_SEED=<case seed> FGR_FUZZ_CASES=1.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "child_process.hpp"
#include "fuzz_rng.hpp"
#include "image/image_io.hpp"
#include "json_mutation.hpp"
#include "output/parts/part_file.hpp"
#include "output/parts/render_identity.hpp"
#include "output/parts/render_parts.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr int kPartWidth = 8, kPartHeight = 4;

// The header fgr writes for a part of a kPartWidth x kPartHeight shaded render (part_file.cpp's
// part_header), its region rows first_row .. first_row + rows - 1.
json part_header(int first_row, int rows, int width = kPartWidth, int height = kPartHeight) {
    const DisplayTransform display{1.0f, ToneMap::Aces};
    json identity = {
        {"scene", "sphere"},
        {"size", size_identity(width, height)},
        {"mode", "shaded"},
        {"effects", "none"},
        {"precision", "float"},
        {"projection", "pinhole fisheye 180 separation auto convergence auto"},
        {"view", "eye 0 0 3 target 0 0 0 up 0 1 0 fov 45"},
        {"parameters", "1 0.5 2"},
        {"path tracing", "none"},
        {"display", display_identity(display)},
        {"layers", layers_identity(false)},
        {"kernel", "0123456789abcdef"},
    };
    return {{"fgr_part", 1},
            {"width", width},
            {"height", height},
            {"region", {0, first_row, width, rows}},
            {"samples", 1},
            {"seed", 0},
            {"exposure", display.exposure},
            {"tone_map", static_cast<int>(display.tone_map)},
            {"layers", false},
            {"identity", identity}};
}

// A part file as `fgr render --part` writes one: the display window the whole image, the data
// window `region`, the colour and depth channels (`value` everywhere), `header` as fgr.part.
void write_part(const fs::path& path, const std::string& header, int width, int height,
                const PixelRegion& region, float value = 0.5f) {
    Imf::Header exr(Imath::Box2i({0, 0}, {width - 1, height - 1}),
                    Imath::Box2i({region.x, region.y},
                                 {region.x + region.width - 1, region.y + region.height - 1}));
    const std::vector<std::string> channels = part_channels(false);
    for (const std::string& channel : channels) exr.channels().insert(channel, Imf::FLOAT);
    exr.insert("fgr.part", Imf::StringAttribute(header));
    std::vector<float> plane(size_t(region.width) * size_t(region.height), value);
    Imf::FrameBuffer buffer;
    for (const std::string& channel : channels) {
        buffer.insert(channel,
                      Imf::Slice::Make(Imf::FLOAT, plane.data(), exr.dataWindow(), sizeof(float),
                                       sizeof(float) * size_t(region.width)));
    }
    Imf::OutputFile file(path.c_str(), exr);
    file.setFrameBuffer(buffer);
    file.writePixels(region.height);
}

void write_part(const fs::path& path, const json& header) {
    const json& r = header.at("region");
    write_part(path, header.dump(), header.at("width"), header.at("height"),
               {r[0].get<int>(), r[1].get<int>(), r[2].get<int>(), r[3].get<int>()});
}

// The fgr.part header of the part `path` replaced by what `change` makes of it, its pixels kept.
void rewrite_part_header(const fs::path& path, const std::function<void(json&)>& change) {
    Imf::InputFile in(path.c_str());
    Imf::Header header = in.header();
    const Imath::Box2i window = header.dataWindow();
    const size_t width = size_t(window.max.x - window.min.x + 1);
    const size_t height = size_t(window.max.y - window.min.y + 1);
    std::map<std::string, std::vector<float>> planes;
    Imf::FrameBuffer buffer;
    for (auto channel = header.channels().begin(); channel != header.channels().end(); ++channel) {
        std::vector<float>& plane = planes[channel.name()];
        plane.resize(width * height);
        buffer.insert(channel.name(), Imf::Slice::Make(Imf::FLOAT, plane.data(), window,
                                                       sizeof(float), sizeof(float) * width));
    }
    in.setFrameBuffer(buffer);
    in.readPixels(window.min.y, window.max.y);
    json part = json::parse(header.typedAttribute<Imf::StringAttribute>("fgr.part").value());
    change(part);
    header.insert("fgr.part", Imf::StringAttribute(part.dump()));
    const fs::path temporary = path.string() + ".rewritten";
    {
        Imf::OutputFile out(temporary.c_str(), header);
        out.setFrameBuffer(buffer);
        out.writePixels(int(height));
    }
    fs::rename(temporary, path);
}

// `sound` as a disk or a transfer might damage it, written to `damaged`: cut short, bytes flipped
// or replaced, or both. A new file each time: truncating one that holds data makes ext4 flush it
// on close.
void write_damaged_copy(const std::vector<uint8_t>& sound, const fs::path& damaged,
                        test::FuzzRng& rng) {
    std::vector<uint8_t> bytes = sound;
    const int how = rng.below(3);
    if (how != 1) bytes.resize(rng.below(bytes.size()));
    if (how != 0) {
        for (int n = rng.range(1, 8); n > 0 && !bytes.empty(); --n) {
            uint8_t& byte = bytes[rng.below(bytes.size())];
            byte = static_cast<uint8_t>(rng.chance(0.5) ? byte ^ (1u << rng.below(8))
                                                        : rng.below(256));
        }
    }
    fs::remove(damaged);
    test::write_bytes(damaged, bytes);
}

// One line (a trailing newline aside).
bool one_line(const std::string& text) {
    return text.substr(0, text.find_last_not_of('\n') + 1).find('\n') == std::string::npos;
}

// --- Part headers --------------------------------------------------------------------------------

TEST(PartHeader, TheHeaderFgrWritesIsRead) {
    const PartInfo info = parse_part_header(part_header(2, 2).dump(), "p.exr");
    EXPECT_EQ(info.width, kPartWidth);
    EXPECT_EQ(info.height, kPartHeight);
    EXPECT_EQ(info.region.x, 0);
    EXPECT_EQ(info.region.y, 2);
    EXPECT_EQ(info.region.width, kPartWidth);
    EXPECT_EQ(info.region.height, 2);
    EXPECT_EQ(info.display.tone_map, ToneMap::Aces);
    EXPECT_EQ(info.mode, "shaded");
    EXPECT_EQ(info.identity.size(), 12u);
}

// Each field of the wrong type, outside its range, or disagreeing with the identity: refused in
// one line naming the file and the field. Before these checks, "tone_map": 99 and "exposure": 1e39
// merged into a wrong image with exit 0.
TEST(PartHeader, EachBadFieldIsRefusedNamingTheFileAndTheField) {
    struct Case {
        const char* what;
        std::function<void(json&)> change;
        const char* field;
    };
    const auto set = [](const char* key, json value) {
        return [key, value](json& header) { header[key] = value; };
    };
    const std::vector<Case> cases{
        {"tone map 99", set("tone_map", 99), "\"tone_map\" is 99"},
        {"tone map -1", set("tone_map", -1), "\"tone_map\""},
        {"tone map 1.5", set("tone_map", 1.5), "\"tone_map\""},
        {"exposure 1e39", set("exposure", 1e39), "\"exposure\" is 1e+39"},
        {"exposure 0", set("exposure", 0), "\"exposure\""},
        {"exposure as text", set("exposure", "1"), "\"exposure\""},
        {"width 0", set("width", 0), "\"width\""},
        {"width 2^40", set("width", 1ll << 40), "\"width\""},
        {"height as a float", set("height", 4.5), "\"height\""},
        {"a region of three", set("region", {0, 0, 8}), "\"region\""},
        {"a region below the image", set("region", {0, 2, 8, 3}), "\"region\""},
        {"a region of huge numbers", set("region", {0, 0, 4294967296ull, 1}), "\"region\""},
        {"samples 0", set("samples", 0), "\"samples\""},
        {"samples 1e6", set("samples", 1000000), "\"samples\""},
        {"seed -1", set("seed", -1), "\"seed\""},
        {"seed 2^32", set("seed", 4294967296ull), "\"seed\""},
        {"layers 1", set("layers", 1), "\"layers\""},
        {"no identity", [](json& h) { h.erase("identity"); }, "\"identity\" is missing"},
        {"no samples", [](json& h) { h.erase("samples"); }, "\"samples\" is missing"},
        {"an identity value not text", [](json& h) { h["identity"]["scene"] = 3; }, "\"identity\""},
        {"an unknown key", set("colour", 1), "\"colour\" is not a part header's key"},
        {"a width the identity does not say", set("width", 16), "\"width\" and \"height\""},
        {"an exposure the identity does not say", set("exposure", 2.0),
         "\"exposure\" and \"tone_map\""},
        {"a tone map the identity does not say", set("tone_map", 0),
         "\"exposure\" and \"tone_map\""},
        {"layers the identity does not say", set("layers", true), "\"layers\""},
        {"an unknown mode", [](json& h) { h["identity"]["mode"] = "fast"; }, "\"identity\""},
    };
    for (const Case& c : cases) {
        json header = part_header(0, 2);
        c.change(header);
        try {
            parse_part_header(header.dump(), "dir/p.exr");
            ADD_FAILURE() << c.what << " was read";
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            EXPECT_TRUE(message.starts_with("'dir/p.exr' is a damaged fgr part: its header's "))
                << c.what << ": " << message;
            EXPECT_NE(message.find(c.field), std::string::npos) << c.what << ": " << message;
            EXPECT_TRUE(one_line(message)) << message;
        }
    }
}

// JSON no part header is: nested past the bound, a key twice, bytes after the value, a NUL.
TEST(PartHeader, MalformedJsonIsRefusedNamingTheFile) {
    const std::string header = part_header(0, 2).dump();
    for (const std::string& text :
         {std::string(100000, '[') + std::string(100000, ']'), "{\"width\": 8, " + header.substr(1),
          header + " {}", header + std::string(1, '\0') + "x", std::string("[1, 2]")}) {
        try {
            parse_part_header(text, "dir/p.exr");
            ADD_FAILURE() << "read: " << text.substr(0, 60);
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            EXPECT_TRUE(message.starts_with("'dir/p.exr' is not an fgr part (")) << message;
            EXPECT_TRUE(one_line(message)) << message;
            EXPECT_LT(message.size(), 300u) << message;
        }
    }
}

// Parts made in memory (not read from files, whose headers would be refused): the plan checks the
// numbers against one another, so no part can make the merge write outside its rows.
TEST(PartPlan, PartsOfAnotherSizeLayersOrDisplayAreRefused) {
    const auto part = [](const char* name, int first_row, int rows) {
        PartInfo info = parse_part_header(part_header(first_row, rows).dump(), name);
        return info;
    };
    const auto refused = [](std::vector<PartInfo> parts, const std::string& mention) {
        try {
            plan_merge(std::move(parts));
            ADD_FAILURE() << "planned: " << mention;
        } catch (const std::invalid_argument& error) {
            EXPECT_NE(std::string(error.what()).find(mention), std::string::npos) << error.what();
        }
    };
    EXPECT_NO_THROW(plan_merge({part("a.exr", 0, 2), part("b.exr", 2, 2)}));
    PartInfo wide = part("b.exr", 2, 2);
    wide.width = 16;
    wide.region.width = 16;
    refused({part("a.exr", 0, 2), wide}, "'b.exr' is 16x4 but 'a.exr' is 8x4");
    PartInfo outside = part("b.exr", 2, 2);
    outside.region.height = 3;
    refused({part("a.exr", 0, 2), outside}, "outside");
    PartInfo layered = part("b.exr", 2, 2);
    layered.layers = true;
    refused({part("a.exr", 0, 2), layered}, "layers");
    PartInfo bright = part("b.exr", 2, 2);
    bright.display.exposure = 2.0f;
    refused({part("a.exr", 0, 2), bright}, "display transform");
}

// Identities that differ are quoted in the refusal, each side shortened: a damaged part's identity
// field can hold text of any length, and the message stays one short line.
TEST(PartPlan, DifferingIdentitiesAreQuotedShortened) {
    json long_view = part_header(2, 2);
    long_view["identity"]["view"] = std::string(5000, '7') + " x";
    try {
        plan_merge({parse_part_header(part_header(0, 2).dump(), "a.exr"),
                    parse_part_header(long_view.dump(), "b.exr")});
        ADD_FAILURE() << "planned parts of two views";
    } catch (const std::invalid_argument& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("not parts of one image"), std::string::npos) << message;
        EXPECT_LT(message.size(), 400u) << message;
    }
}

// --- fgr merge on damaged and forged parts -------------------------------------------------------

class MergeRefusals : public ::testing::Test {
protected:
    test::RunResult merge(const std::vector<std::string>& args) {
        std::vector<std::string> all{"merge"};
        all.insert(all.end(), args.begin(), args.end());
        test::RunResult result = test::run_fgr(all, dir());
        EXPECT_FALSE(result.timed_out) << test::describe("fgr", all);
        return result;
    }
    // `fgr merge parts -o out.png` fails with one line naming each of `mentions` and leaves the
    // directory as it was.
    void expect_refused(const std::vector<std::string>& parts,
                        const std::vector<std::string>& mentions) {
        const std::vector<std::string> before = test::directory_listing(dir());
        std::vector<std::string> args = parts;
        args.insert(args.end(), {"-o", "m.png"});
        const test::RunResult result = merge(args);
        const std::string what = test::describe("fgr merge", args);
        EXPECT_TRUE(result.exited) << what << ": " << result;
        EXPECT_NE(result.exit_code, 0) << what << ": " << result;
        EXPECT_TRUE(one_line(result.err)) << what << ": " << result.err;
        for (const std::string& mention : mentions) {
            EXPECT_NE(result.err.find(mention), std::string::npos)
                << what << " must name " << mention << ": " << result.err;
        }
        EXPECT_EQ(test::directory_listing(dir()), before) << what << " left a file";
    }
    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_merge_refusals"};
};

// The second part claims the first's identity but is twice as wide: before the plan checked the
// parts' numbers, the merge wrote its rows past the image's (a heap overflow, SIGSEGV) and left
// m.png.tmp-PID-0 behind.
TEST_F(MergeRefusals, APartOfAnotherWidthWithTheFirstsIdentityIsRefused) {
    write_part(dir() / "a.exr", part_header(0, 2, 100, 48));
    json forged = part_header(2, 46, 200, 48);
    forged["identity"] = part_header(0, 2, 100, 48)["identity"];
    write_part(dir() / "b.exr", forged);
    expect_refused({"a.exr", "b.exr"}, {"'b.exr'", "\"width\""});
}

// A part's display transform outside its range: before, a wrong image with exit 0.
TEST_F(MergeRefusals, ADisplayTransformOutOfRangeIsRefused) {
    write_part(dir() / "a.exr", part_header(0, 2));
    for (const auto& [key, value] : {std::pair<const char*, json>{"tone_map", 99},
                                     std::pair<const char*, json>{"exposure", 1e39}}) {
        json bad = part_header(2, 2);
        bad[key] = value;
        write_part(dir() / "b.exr", bad);
        expect_refused({"a.exr", "b.exr"}, {"'b.exr'", std::string("\"") + key + "\""});
        fs::remove(dir() / "b.exr");
    }
}

// Not regular files: refused, never waited on.
TEST_F(MergeRefusals, AFifoOrADirectoryGivenAsAPartIsRefused) {
    write_part(dir() / "a.exr", part_header(0, 2));
    ASSERT_EQ(::mkfifo((dir() / "fifo.exr").c_str(), 0600), 0);
    fs::create_directory(dir() / "folder.exr");
    expect_refused({"a.exr", "fifo.exr"}, {"'fifo.exr'", "not a regular file"});
    expect_refused({"a.exr", "folder.exr"}, {"'folder.exr'", "not a regular file"});
}

// The reproducer as found, through fgr render: --tile 1/2 at 100x48 and --tile 2/2 at 200x48,
// the second given the first's identity.
TEST_F(MergeRefusals, RenderedTilesOfTwoWidthsWithOneIdentityAreRefused) {
    for (const auto& [tile, width, name] :
         {std::tuple<const char*, const char*, const char*>{"1/2", "100", "t1.exr"},
          std::tuple<const char*, const char*, const char*>{"2/2", "200", "t2.exr"}}) {
        const test::RunResult rendered =
            test::run_fgr({"render", "mandelbulb", "--width", width, "--height", "48", "--tile",
                           tile, "-o", name},
                          dir());
        ASSERT_EQ(rendered.exit_code, 0) << rendered;
    }
    json first;
    rewrite_part_header(dir() / "t1.exr", [&](json& header) { first = header; });
    rewrite_part_header(dir() / "t2.exr",
                        [&](json& header) { header["identity"] = first["identity"]; });
    expect_refused({"t1.exr", "t2.exr"}, {"'t2.exr'", "\"width\" and \"height\""});
}

// --- fgr merge --frames --------------------------------------------------------------------------

// A FIFO or a directory named like a frame: one line naming it, at once (before, the FIFO hung
// the merge), and no video.
TEST_F(MergeRefusals, AFifoOrADirectoryNamedLikeAFrameIsRefused) {
    fs::create_directory(dir() / "frames");
    const Image8 frame{8, 4, std::vector<uint8_t>(8 * 4 * 3, 100)};
    write_png(dir() / "frames" / "frame_00000.png", frame);
    write_png(dir() / "frames" / "frame_00002.png", frame);
    const fs::path odd = dir() / "frames" / "frame_00001.png";
    for (const bool fifo : {true, false}) {
        SCOPED_TRACE(fifo ? "a FIFO" : "a directory");
        if (fifo) {
            ASSERT_EQ(::mkfifo(odd.c_str(), 0600), 0);
        } else {
            fs::create_directory(odd);
        }
        const test::RunResult result = merge({"--frames", "frames", "-o", "v.mp4"});
        EXPECT_TRUE(result.exited) << result;
        EXPECT_NE(result.exit_code, 0) << result;
        EXPECT_TRUE(one_line(result.err)) << result.err;
        EXPECT_NE(result.err.find("frame_00001.png"), std::string::npos) << result.err;
        EXPECT_NE(result.err.find("not a regular file"), std::string::npos) << result.err;
        EXPECT_FALSE(fs::exists(dir() / "v.mp4"));
        fs::remove(odd);
    }
}

// --- Fuzzing -------------------------------------------------------------------------------------

// The header's keys and its region's numbers, for mutations aimed at them.
const char* const kHeaderKeys[] = {"fgr_part", "width",    "height",   "region", "samples",
                                   "seed",     "exposure", "tone_map", "layers", "identity"};

// A number a reader must refuse or bound: huge, negative, fractional, just outside a limit.
json nasty_number(test::FuzzRng& rng) {
    switch (rng.below(10)) {
        case 0:
            return 1e39;
        case 1:
            return -(1ll << rng.below(63));
        case 2:
            return 1ull << rng.below(64);
        case 3:
            return 18446744073709551615ull;
        case 4:
            return rng.range(-3, 12);
        case 5:
            return rng.unit() * 10.0;
        case 6:
            return 1048577;
        case 7:
            return 4097;
        case 8:
            return 2147483648ll;
        default:
            return rng.range(-1, 4) + 0.5;
    }
}

// One structure-aware mutation of a part header: a field (or a region's number) given a nasty
// number or value or removed, an identity field changed, or anywhere in the document.
void mutate_header(json& header, test::FuzzRng& rng) {
    const char* key = rng.pick(kHeaderKeys);
    if (!header.is_object()) return;  // an earlier mutation replaced it all
    switch (rng.below(6)) {
        case 0:
            header[key] = nasty_number(rng);
            break;
        case 1:
            header[key] = test::nasty_value(rng);
            break;
        case 2:
            header.erase(key);
            break;
        case 3:
            if (header.contains("region") && header["region"].is_array() &&
                !header["region"].empty()) {
                header["region"][rng.below(header["region"].size())] = nasty_number(rng);
            }
            break;
        case 4:
            if (header.contains("identity") && header["identity"].is_object()) {
                const char* field = rng.pick({"size", "display", "layers", "mode", "scene"});
                if (rng.chance(0.3)) {
                    header["identity"].erase(field);
                } else {
                    header["identity"][field] = rng.chance(0.5)
                                                    ? json(test::nasty_value(rng))
                                                    : json(rng.chance(0.5) ? "16x4" : "path");
                }
            }
            break;
        default:
            test::mutate_value(header, rng);
            break;
    }
}

// Whatever a read header holds is what the merge may rely on.
void expect_sound(const PartInfo& info, std::uint64_t seed) {
    ASSERT_GE(info.width, 1) << "case seed " << seed;
    ASSERT_LE(info.width, kMaxTiledImageSide) << "case seed " << seed;
    ASSERT_GE(info.height, 1) << "case seed " << seed;
    ASSERT_LE(info.height, kMaxTiledImageSide) << "case seed " << seed;
    const PixelRegion& r = info.region;
    ASSERT_TRUE(r.x >= 0 && r.y >= 0 && r.width >= 1 && r.height >= 1 &&
                r.x + r.width <= info.width && r.y + r.height <= info.height)
        << "case seed " << seed;
    ASSERT_TRUE(info.samples >= 1 && info.samples <= 4096) << "case seed " << seed;
    ASSERT_TRUE(std::isfinite(info.display.exposure) && info.display.exposure > 0.0f)
        << "case seed " << seed;
    ASSERT_TRUE(info.display.tone_map == ToneMap::Clamp ||
                info.display.tone_map == ToneMap::Reinhard ||
                info.display.tone_map == ToneMap::Aces)
        << "case seed " << seed;
}

// Seeded mutations of a part's header (1 to 3 each; now and then the text itself cut or changed):
// each is read, and then sound, or refused in one line naming the file.
TEST(FuzzPartFile, MutatedHeadersAreReadSoundOrRefusedInOneLine) {
    const std::uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed();
    std::uint64_t read = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        json header = part_header(rng.range(0, 2), 2);
        for (int m = rng.range(0, 3); m > 0; --m) mutate_header(header, rng);
        std::string text = header.dump(-1, ' ', false, json::error_handler_t::replace);
        if (rng.chance(0.1)) test::mutate_text(text, rng);
        try {
            const PartInfo info = parse_part_header(text, "fuzz.exr");
            ++read;
            expect_sound(info, seed);
            if (::testing::Test::HasFatalFailure()) return;
        } catch (const std::runtime_error& error) {
            const std::string message = error.what();
            ASSERT_TRUE(message.starts_with("'fuzz.exr' "))
                << "case seed " << seed << ": " << message;
            ASSERT_TRUE(one_line(message)) << "case seed " << seed << ": " << message;
        }
    }
    if (cases >= 1000) {
        EXPECT_GT(read, cases / 50) << "sound headers are exercised too";
    }
}

// Seeded damage to a part file (cut short, bytes flipped or overwritten, both), merged with a
// sound part: the pair is read and merged, or refused, never a crash. Two tiles of an 8x4 image;
// the first 10 pairs that read and plan are merged into a PNG (each merge ends in an fsync), the
// rest read every row of the damaged part, as the merge would.
TEST(FuzzPartFile, DamagedPartFilesAreMergedOrRefused) {
    const test::TempDir dir("fgr_fuzz_parts");
    write_part(dir.path() / "top.exr", part_header(0, 2));
    write_part(dir.path() / "bottom.exr", part_header(2, 2));
    const std::vector<uint8_t> sound = test::read_bytes(dir.path() / "bottom.exr");
    const PartInfo top = read_part_info(dir.path() / "top.exr");
    const fs::path damaged = dir.path() / "damaged.exr";
    const std::uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed();
    int merged = 0;
    std::uint64_t planned = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        write_damaged_copy(sound, damaged, rng);
        try {
            const MergePlan plan = plan_merge({top, read_part_info(damaged)});
            ++planned;
            if (merged < 10) {
                ++merged;
                TiledOutput output;
                output.path = dir.path() / "merged.png";
                output.format = ImageFormat::Png;
                merge_parts(plan, output);
            } else {
                const PartInfo& part = plan.parts[1];
                PartReader(part).read_rows(part.region.y, part.region.height);
            }
        } catch (const std::runtime_error& error) {
            ASSERT_TRUE(one_line(error.what())) << "case seed " << seed << ": " << error.what();
        } catch (const std::invalid_argument& error) {
            ASSERT_TRUE(one_line(error.what())) << "case seed " << seed << ": " << error.what();
        }
    }
    if (cases >= 1000) {
        EXPECT_GT(planned, cases / 100) << "damage that reads is exercised too";
    }
}

// Seeded damage to the PNG frames `fgr merge --frames` reads (cut short, bytes flipped): read as
// an image of at most the sizes a frame has, or refused in one line, never a crash.
TEST(FuzzMergeFrames, DamagedFramesAreReadOrRefused) {
    const test::TempDir dir("fgr_fuzz_frames");
    std::vector<uint8_t> pixels(8 * 4 * 3);
    for (size_t i = 0; i < pixels.size(); ++i) pixels[i] = uint8_t(i * 37);
    write_png(dir.path() / "frame.png", Image8{8, 4, pixels});
    const std::vector<uint8_t> sound = test::read_bytes(dir.path() / "frame.png");
    const fs::path damaged = dir.path() / "frame_00000.png";
    const std::uint64_t cases = test::fuzz_case_count(), base = test::fuzz_base_seed();
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = base + i;
        test::FuzzRng rng(seed);
        write_damaged_copy(sound, damaged, rng);
        try {
            const Image8 image = read_png(damaged);
            ASSERT_EQ(image.rgb.size(), size_t(image.width) * size_t(image.height) * 3)
                << "case seed " << seed;
        } catch (const std::runtime_error& error) {
            ASSERT_TRUE(one_line(error.what())) << "case seed " << seed << ": " << error.what();
        }
    }
}

}  // namespace
}  // namespace fgr
