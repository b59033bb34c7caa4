// SPDX-License-Identifier: Apache-2.0
// The fgr command line, run as a child process: every bad input is one "fgr: error: " line on
// stderr, a non-zero exit and no output file; valid renders write an 8-bit RGB PNG of the asked
// size and print render_ms and hits.

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "cli/commands.hpp"
#include "device/program_cache.hpp"
#include "image/embedded_view.hpp"
#include "image/hdr_io.hpp"
#include "image/image_io.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"
#include "text_scene_example.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

using test::directory_listing;
using test::kFgrExe;

// --- Running fgr ---------------------------------------------------------------------------------

using test::read_file;
using test::run_fgr;
using test::RunResult;

std::string describe(const std::vector<std::string>& args) { return test::describe("fgr", args); }

// --- Fixture: a fresh, empty working directory per test -----------------------------------------

class TempDir : public test::TempDir {
public:
    TempDir() : test::TempDir("fgr_cli_test") {}
};

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text.empty() ? "(empty)" : text;
}

class CliTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_FALSE(dir_.path().empty()) << "cannot create a temporary directory";
        ASSERT_TRUE(fs::exists(kFgrExe)) << kFgrExe << " does not exist; build the fgr target";
    }

    RunResult run(const std::vector<std::string>& args) {
        RunResult result = run_fgr(args, dir_.path());
        EXPECT_FALSE(result.timed_out) << describe(args) << ": " << result;
        EXPECT_EQ(result.term_signal, 0) << describe(args) << ": " << result;
        return result;
    }

    fs::path out_png() const { return dir_.path() / "out.png"; }
    const fs::path& dir() const { return dir_.path(); }

private:
    TempDir dir_;
};

// --- Output checks ------------------------------------------------------------------------------

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool contains_ignoring_case(const std::string& text, const std::string& part) {
    return lower(text).find(lower(part)) != std::string::npos;
}

// The value after `key ` on the line starting with it, or nothing if there is no such line.
std::optional<std::string> line_value(const std::string& text, const std::string& key) {
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.rfind(key + " ", 0) == 0) return line.substr(key.size() + 1);
    }
    return std::nullopt;
}

std::optional<double> parse_double(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return std::nullopt;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<long long> parse_integer(const std::string& text) {
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) {
        return std::nullopt;
    }
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(text.c_str(), &end, 10);
    if (end != text.c_str() + text.size() || errno != 0) return std::nullopt;
    return value;
}

// Checks the render report on stdout and returns the hit count (-1 on failure).
long long expect_render_report(const RunResult& result, int width, int height) {
    const std::optional<std::string> ms = line_value(result.out, "render_ms");
    const std::optional<std::string> hits = line_value(result.out, "hits");
    EXPECT_TRUE(ms.has_value()) << "no `render_ms` line: " << result;
    EXPECT_TRUE(hits.has_value()) << "no `hits` line: " << result;
    if (!ms || !hits) return -1;
    const std::optional<double> ms_value = parse_double(*ms);
    EXPECT_TRUE(ms_value.has_value()) << "render_ms is not a number: '" << *ms << "'";
    if (ms_value) {
        EXPECT_GE(*ms_value, 0.0);
    }
    const std::optional<long long> hit_count = parse_integer(*hits);
    EXPECT_TRUE(hit_count.has_value()) << "hits is not a non-negative integer: '" << *hits << "'";
    if (!hit_count) return -1;
    EXPECT_LE(*hit_count, static_cast<long long>(width) * height);
    return *hit_count;
}

std::uint32_t big_endian_u32(const std::string& bytes, std::size_t offset) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        value = (value << 8) | static_cast<unsigned char>(bytes[offset + i]);
    }
    return value;
}

// Reads the PNG signature and IHDR chunk directly: width x height, 8-bit, colour type 2 (RGB).
void expect_rgb_png(const fs::path& file, std::uint32_t width, std::uint32_t height) {
    std::ifstream in(file, std::ios::binary);
    ASSERT_TRUE(in) << file << " cannot be opened";
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GE(bytes.size(), 33u) << file << " is too short for a PNG";
    const std::string signature("\x89PNG\r\n\x1a\n", 8);
    ASSERT_EQ(bytes.substr(0, 8), signature) << file << " lacks the PNG signature";
    EXPECT_EQ(big_endian_u32(bytes, 8), 13u) << "IHDR length";
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");
    EXPECT_EQ(big_endian_u32(bytes, 16), width) << "IHDR width";
    EXPECT_EQ(big_endian_u32(bytes, 20), height) << "IHDR height";
    EXPECT_EQ(static_cast<unsigned char>(bytes[24]), 8) << "bit depth";
    EXPECT_EQ(static_cast<unsigned char>(bytes[25]), 2) << "colour type (2 = RGB)";
}

// An error is exactly one line on stderr starting with "fgr: error: ".
void expect_one_error_line(const RunResult& result) {
    std::string err = result.err;
    if (!err.empty() && err.back() == '\n') err.pop_back();
    EXPECT_FALSE(err.empty()) << "nothing on stderr: " << result;
    EXPECT_EQ(err.find('\n'), std::string::npos) << "more than one line on stderr: " << result;
    EXPECT_EQ(err.rfind("fgr: error: ", 0), 0u)
        << "stderr does not start with 'fgr: error: ': " << result;
}

// --- Bad input ----------------------------------------------------------------------------------

constexpr int kAnyFailure = -1;  // any non-zero exit code

struct BadInput {
    const char* name;                  // test name suffix
    std::vector<std::string> args;     // "{out}" is replaced by the output path
    int exit_code;                     // expected exit code, or kAnyFailure
    std::vector<std::string> mention;  // each must appear in the message (case-insensitive)
    const char* out_name = "out.png";  // output path, relative to the test's directory
};

void PrintTo(const BadInput& input, std::ostream* os) { *os << input.name; }

std::vector<std::string> render_args(std::vector<std::string> extra) {
    std::vector<std::string> args{"render",  "mandelbulb", "-o",       "{out}",
                                  "--width", "16",         "--height", "12"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

std::vector<std::string> sized_render_args(std::vector<std::string> extra) {
    std::vector<std::string> args{"render", "mandelbulb", "-o", "{out}"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

const std::vector<BadInput> kBadInputs = {
    {"UnknownScene",
     {"render", "nosuchscene", "-o", "{out}", "--width", "16", "--height", "12"},
     2,
     {"nosuchscene"}},
    {"UnknownParameter", render_args({"--set", "nosuchparam=1"}), 2, {"nosuchparam"}},
    {"SetWithoutEquals", render_args({"--set", "power8"}), 2, {"power8"}},
    {"NonNumericValue", render_args({"--set", "power=abc"}), 2, {"power"}},
    {"TrailingJunkInValue", render_args({"--set", "power=8x"}), 2, {"power"}},
    {"EmptyValue", render_args({"--set", "power="}), 2, {"power"}},
    {"NanValue", render_args({"--set", "power=nan"}), 2, {"power"}},
    {"InfValue", render_args({"--set", "power=inf"}), 2, {"power"}},
    {"NegativeInfValue", render_args({"--set", "power=-inf"}), 2, {"power"}},
    {"ValueAboveRange", render_args({"--set", "power=99"}), 2, {"power", "2", "16"}},
    {"ValueBelowRange", render_args({"--set", "power=1"}), 2, {"power", "2", "16"}},
    {"NonIntegerForIntParameter", render_args({"--set", "iterations=2.5"}), 2, {"iterations"}},
    {"UnknownEnumName", render_args({"--set", "variant=bogus"}), 2, {"variant"}},
    {"ZeroWidth", sized_render_args({"--width", "0", "--height", "12"}), 2, {"width"}},
    {"ZeroHeight", sized_render_args({"--width", "16", "--height", "0"}), 2, {"height"}},
    {"NegativeWidth", sized_render_args({"--width", "-5", "--height", "12"}), 2, {}},
    {"AbsurdWidth", sized_render_args({"--width", "2000000", "--height", "12"}), 2, {"width"}},
    {"NonNumericWidth", sized_render_args({"--width", "abc", "--height", "12"}), 2, {"width"}},
    {"UnknownCamera", render_args({"--camera", "nosuchcam"}), 2, {"nosuchcam"}},
    {"UnknownCameraPath",
     render_args({"--camera-path", "nosuchpath", "--time", "1"}),
     2,
     {"nosuchpath"}},
    {"TimeWithoutCameraPath", render_args({"--time", "1"}), 2, {"time"}},
    {"CameraAndCameraPath",
     render_args({"--camera", "top", "--camera-path", "orbit", "--time", "1"}),
     2,
     {"camera"}},
    {"CameraPathWithoutTime", render_args({"--camera-path", "orbit"}), 2, {"time"}},
    {"OutputInMissingDirectory", render_args({}), 1, {"missing_dir"}, "missing_dir/out.png"},
    {"MissingOutput", {"render", "mandelbulb", "--width", "16", "--height", "12"}, 2, {}},
    {"OutputNotPng", render_args({}), 2, {".png"}, "out.jpg"},
    {"NoSuchDevice", render_args({"--device", "99"}), kAnyFailure, {"device"}},
    {"BadPacketWidth", render_args({"--packet-width", "3"}), 2, {"packet"}},
    {"ZeroSamples", render_args({"--spp", "0"}), 2, {"spp"}},
    {"AbsurdSamples", render_args({"--spp", "100000"}), 2, {"spp"}},
    {"BadBitDepth", render_args({"--bit-depth", "12"}), 2, {"bit-depth"}},
    {"UnknownEffect", render_args({"--effects", "+sparkles"}), 2, {"sparkles", "shadows"}},
    {"UnknownPrecision", render_args({"--precision", "half"}), 2, {"precision", "half"}},
    {"UnknownMode", render_args({"--mode", "raster"}), 2, {"mode", "raster"}},
    {"ViewUnknownMode", {"view", "--mode", "raster"}, 2, {"mode", "raster"}},
    {"BenchUnknownMode",
     {"bench", "mandelbulb", "--frames", "1", "--mode", "raster"},
     2,
     {"mode", "raster"}},
    {"MissingEnvironmentFile",
     render_args({"--mode", "path", "--environment", "no_such_map.hdr"}),
     1,
     {"no_such_map.hdr"}},
    {"EnvironmentNotAnImage",
     render_args({"--mode", "path", "--environment", "/etc/hostname"}),
     1,
     {"hostname"}},
    {"BadUniformRadiance",
     render_args({"--mode", "path", "--environment", "uniform:-1"}),
     2,
     {"uniform"}},
    {"SkyOptionWithoutSky",
     render_args({"--mode", "path", "--environment", "studio", "--turbidity", "3"}),
     2,
     {"turbidity", "sky"}},
    {"TurbidityOutOfRange", render_args({"--mode", "path", "--turbidity", "40"}), 2, {"turbidity"}},
    {"NegativeClamp", render_args({"--mode", "path", "--clamp", "-1"}), 2, {"clamp"}},
    {"DenoiseOutsidePathMode",
     render_args({"--mode", "shaded", "--denoise"}),
     2,
     {"--denoise", "path"}},
    {"DenoiseOneSample",
     render_args({"--mode", "path", "--denoise", "--spp", "1"}),
     2,
     {"--denoise", "2 samples"}},
    {"DenoiseTiled",
     render_args({"--mode", "path", "--denoise", "--tile-size", "64"}),
     2,
     {"--denoise", "tiled"}},
    {"DenoiseAll", {"render", "--all", "-o", "{out}", "--denoise"}, 2, {"--denoise", "--all"}},
    {"AovWithPng", render_args({"--aov", "albedo"}), 2, {"aov", ".exr"}},
    {"UnknownAov", render_args({"--aov", "velocity"}), 2, {"velocity"}, "out.exr"},
    {"ZeroTimeLimit", render_args({"--time-limit", "0"}), 2, {"time-limit"}},
    {"NoiseThresholdInShadedMode",
     render_args({"--mode", "shaded", "--noise-threshold", "0.01"}),
     2,
     {"--noise-threshold", "path"}},
    {"NoiseThresholdOutOfRange",
     render_args({"--mode", "path", "--noise-threshold", "2"}),
     2,
     {"noise-threshold"}},
    {"NoiseThresholdWithTiles",
     render_args({"--mode", "path", "--noise-threshold", "0.01", "--tile", "1/4"}),
     2,
     {"--noise-threshold", "--tile"}},
    {"SamplesLayerInShadedMode",
     render_args({"--mode", "shaded", "--aov", "samples"}),
     2,
     {"samples", "path"},
     "out.exr"},
    {"EnvironmentCommandBadOutput", {"environment", "studio", "-o", "studio.png"}, 2, {".hdr"}},
    {"EnvironmentCommandUnknownKind", {"environment", "disco", "-o", "x.hdr"}, 2, {"disco"}},
    {"ViewUnknownPrecision", {"view", "--precision", "half"}, 2, {"precision", "half"}},
    {"BenchUnknownPrecision",
     {"bench", "mandelbulb", "--frames", "1", "--precision", "half"},
     2,
     {"precision", "half"}},
    {"AllMatchingNoScene", {"render", "--all", "mandel?ulb*x", "-o", "{out}"}, 2, {"mandel?ulb*x"}},
    {"AllWithSet", {"render", "--all", "-o", "{out}", "--set", "power=8"}, 2, {"--all"}},
    {"NoSceneNorAll", {"render", "-o", "{out}"}, 2, {"scene"}},
    // Exact IFS tracing has no distance estimate for soft shadows to read.
    {"IfsSceneWithSoftShadows",
     {"render", "sierpinski-ifs", "-o", "{out}", "--width", "16", "--height", "12", "--effects",
      "+soft_shadows"},
     kAnyFailure,
     {"sierpinski-ifs", "soft_shadows", "distance estimate"}},
    // A scene with an inside test alone renders only by brute force; exact IFS tracing has
    // neither an inside test nor a DE for it.
    {"InsideOnlySceneInShadedMode",
     {"render", "stereographic-julia", "-o", "{out}", "--width", "16", "--height", "12", "--mode",
      "shaded"},
     kAnyFailure,
     {"stereographic-julia", "no distance estimator", "--mode brute"}},
    {"IfsSceneInBruteMode",
     {"render", "sierpinski-ifs", "-o", "{out}", "--width", "16", "--height", "12", "--mode",
      "brute"},
     kAnyFailure,
     {"sierpinski-ifs", "brute"}},
    // --eye, --target, --up and --fov: malformed vectors, views that cannot
    // be rendered, and combinations that contradict each other.
    {"EyeOfTwoNumbers",
     render_args({"--eye", "1,2", "--target", "0,0,0"}),
     2,
     {"--eye '1,2'", "three finite numbers X,Y,Z"}},
    {"EyeNotANumber", render_args({"--eye", "1,x,2"}), 2, {"--eye '1,x,2'"}},
    {"EyeOfFourNumbers", render_args({"--eye", "1,2,3,4"}), 2, {"--eye '1,2,3,4'"}},
    {"TargetNotFinite", render_args({"--target", "inf,0,0"}), 2, {"--target 'inf,0,0'"}},
    {"UpEmptyComponent", render_args({"--up", "0,,1"}), 2, {"--up '0,,1'"}},
    {"EyeAtTarget",
     render_args({"--eye", "1,1,1", "--target", "1,1,1"}),
     2,
     {"position equals target", "eye 1,1,1, target 1,1,1"}},
    {"UpParallelToView",
     render_args({"--eye", "0,0,3", "--target", "0,0,0", "--up", "0,0,-2"}),
     2,
     {"up is zero or parallel to the view direction", "up 0,0,-2"}},
    {"UpZero", render_args({"--up", "0,0,0"}), 2, {"up is zero or parallel"}},
    {"FovZero", render_args({"--fov", "0"}), 2, {"--fov '0'", "between 0 and 180"}},
    {"FovHalfTurn", render_args({"--fov", "180"}), 2, {"--fov '180'"}},
    {"FovNotANumber", render_args({"--fov", "wide"}), 2, {"--fov 'wide'"}},
    {"EyeWithCameraPath",
     render_args({"--camera-path", "orbit", "--time", "1", "--eye", "1,1,1"}),
     2,
     {"--camera-path"}},
    {"FovWithAll", {"render", "--all", "-o", "{out}", "--fov", "30"}, 2, {"--all"}},
    {"BenchEyeWithPath",
     {"bench", "mandelbulb", "--frames", "1", "--path", "orbit", "--eye", "1,1,1"},
     2,
     {"--path", "--eye"}},
    {"BenchEyeAtTarget",
     {"bench", "mandelbulb", "--frames", "1", "--eye", "0,0,0", "--target", "0,0,0"},
     2,
     {"position equals target"}},
    {"ViewMalformedEye", {"view", "--eye", "1;2;3"}, 2, {"--eye '1;2;3'"}},
    {"ViewEyeAtTarget",
     {"view", "mandelbulb", "--eye", "0,0,0", "--target", "0,0,0"},
     2,
     {"position equals target"}},
    {"UnknownSubcommand", {"frobnicate"}, 2, {"frobnicate"}},
    {"NoSubcommand", {}, kAnyFailure, {}},
};

class CliBadInput : public CliTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(CliBadInput, FailsWithOneErrorLineAndNoOutput) {
    const BadInput& input = GetParam();
    const fs::path out = dir() / input.out_name;
    std::vector<std::string> args = input.args;
    for (std::string& arg : args) {
        if (arg == "{out}") arg = out.string();
    }

    const RunResult result = run(args);
    SCOPED_TRACE(describe(args));
    ASSERT_TRUE(result.exited) << result;
    EXPECT_NE(result.exit_code, 0) << result;
    if (input.exit_code != kAnyFailure) {
        EXPECT_EQ(result.exit_code, input.exit_code) << result;
    }
    expect_one_error_line(result);
    for (const std::string& part : input.mention) {
        EXPECT_TRUE(contains_ignoring_case(result.err, part))
            << "message should mention '" << part << "': " << result;
    }
    EXPECT_FALSE(fs::exists(out)) << out << " was written";
    // The working directory and the output's directory are the same fresh directory: anything
    // left there (a partial file, FILE.png.tmp-*, a created missing_dir) is a leftover.
    EXPECT_TRUE(directory_listing(dir()).empty())
        << "left behind: " << joined(directory_listing(dir()));
}

INSTANTIATE_TEST_SUITE_P(Cli, CliBadInput, ::testing::ValuesIn(kBadInputs),
                         [](const ::testing::TestParamInfo<BadInput>& param_info) {
                             return std::string(param_info.param.name);
                         });

TEST_F(CliTest, NoSubcommandPrintsUsage) {
    const RunResult result = run({});
    ASSERT_TRUE(result.exited) << result;
    EXPECT_NE(result.exit_code, 0) << result;
    EXPECT_TRUE(contains_ignoring_case(result.out + result.err, "render"))
        << "no usage shown: " << result;
}

// --- Valid renders ------------------------------------------------------------------------------

constexpr int kCliWidth = 64;
constexpr int kCliHeight = 48;

TEST_F(CliTest, RendersSmallImage) {
    const RunResult result =
        run({"render", "mandelbulb", "-o", out_png().string(), "--width", std::to_string(kCliWidth),
             "--height", std::to_string(kCliHeight)});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    const long long hits = expect_render_report(result, kCliWidth, kCliHeight);
    EXPECT_GT(hits, 0) << "the canonical view of the mandelbulb should hit the surface";
    expect_rgb_png(out_png(), kCliWidth, kCliHeight);
    EXPECT_EQ(directory_listing(dir()), std::vector<std::string>{"out.png"});
}

TEST_F(CliTest, StatsReportStepsEvaluationsAndRaysOutOfSteps) {
    const RunResult result =
        run({"render", "mandelbulb", "-o", out_png().string(), "--width", std::to_string(kCliWidth),
             "--height", std::to_string(kCliHeight), "--stats", "--set", "max_steps=10"});
    ASSERT_EQ(result.exit_code, 0) << result;
    const auto steps = line_value(result.out, "steps_per_pixel");
    const auto evaluations = line_value(result.out, "de_evaluations");
    const auto exhausted = line_value(result.out, "out_of_steps");
    ASSERT_TRUE(steps && evaluations && exhausted) << result;
    EXPECT_GT(std::stod(*steps), 1.0);
    EXPECT_NE(steps->find("(max 10)"), std::string::npos) << *steps;
    EXPECT_GT(std::stol(*evaluations), kCliWidth * kCliHeight);
    EXPECT_GT(std::stod(*exhausted), 0.0) << "10 steps leave rays unresolved";
    expect_rgb_png(out_png(), kCliWidth, kCliHeight);
}

TEST_F(CliTest, PrecisionDoubleRendersAndUnknownPrecisionIsRefused) {
    const RunResult result =
        run({"render", "mandelbulb", "-o", out_png().string(), "--width", std::to_string(kCliWidth),
             "--height", std::to_string(kCliHeight), "--precision", "double"});
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.err.find(", double, effects"), std::string::npos) << result;
    EXPECT_GT(expect_render_report(result, kCliWidth, kCliHeight), 0);
    const RunResult bad =
        run({"render", "mandelbulb", "-o", out_png().string(), "--precision", "half"});
    EXPECT_EQ(bad.exit_code, 2) << bad;
}

// Path mode to an EXR with every layer: the beauty read back is finite, non-negative radiance at
// the size asked for, every layer's channels are in the file, and the figures are on stdout. A
// time limit stops a long render early with what it has, and says so.
TEST_F(CliTest, PathModeWritesAnExrWithItsLayersAndStopsAtATimeLimit) {
    const fs::path exr = dir() / "path.exr";
    const RunResult result =
        run({"render", "mandelbulb", "--mode", "path", "--spp", "2", "-o", exr.string(), "--width",
             "24", "--height", "16", "--aov", "albedo,normal,depth,alpha"});
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.out.find("samples_per_pixel 2\n"), std::string::npos) << result;
    EXPECT_NE(result.err.find("environment: sky"), std::string::npos) << result;
    const HdrImage beauty = read_hdr_image(exr);
    ASSERT_EQ(beauty.width, 24);
    ASSERT_EQ(beauty.height, 16);
    const Imf::RgbaInputFile file(exr.string().c_str());
    const Imf::ChannelList& channels = file.header().channels();
    for (const char* name : {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "normal.X",
                             "normal.Y", "normal.Z", "depth.Z"}) {
        EXPECT_NE(channels.findChannel(name), nullptr) << name;
    }
    for (float value : beauty.rgb) EXPECT_TRUE(std::isfinite(value) && value >= 0.0f);

    const RunResult limited =
        run({"render", "mandelbulb", "--mode", "path", "--spp", "4096", "--time-limit", "0.5", "-o",
             (dir() / "limited.png").string(), "--width", "24", "--height", "16"});
    ASSERT_EQ(limited.exit_code, 0) << limited;
    EXPECT_NE(limited.err.find("--time-limit"), std::string::npos) << limited;
    EXPECT_EQ(limited.out.find("samples_per_pixel 4096"), std::string::npos) << limited;
    EXPECT_TRUE(fs::exists(dir() / "limited.png"));
}

// --denoise: the EXR's R, G, B are the denoised image and raw.R/G/B the estimate as rendered,
// beside the layers asked for, and the view the file carries says it was denoised.
TEST_F(CliTest, DenoisedPathRenderKeepsTheRawImageInItsExr) {
    const fs::path exr = dir() / "denoised.exr";
    const RunResult result =
        run({"render", "mandelbulb", "--mode", "path", "--spp", "4", "--denoise", "-o",
             exr.string(), "--width", "24", "--height", "16", "--aov", "albedo,normal,depth"});
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.out.find("samples_per_pixel 4\n"), std::string::npos) << result;
    EXPECT_NE(result.out.find("denoise_ms"), std::string::npos) << result;
    Imf::InputFile file(exr.string().c_str());
    const auto read = [&](const char* name) {
        std::vector<float> values(24 * 16);
        Imf::FrameBuffer buffer;
        buffer.insert(name, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(values.data()),
                                       sizeof(float), sizeof(float) * 24));
        file.setFrameBuffer(buffer);
        file.readPixels(0, 15);
        return values;
    };
    for (const char* name : {"raw.R", "raw.G", "raw.B", "albedo.R", "normal.X", "depth.Z"}) {
        ASSERT_NE(file.header().channels().findChannel(name), nullptr) << name;
    }
    const std::vector<float> denoised = read("G"), raw = read("raw.G");
    double difference = 0.0;
    for (size_t i = 0; i < raw.size(); ++i) {
        ASSERT_TRUE(std::isfinite(denoised[i]) && std::isfinite(raw[i])) << i;
        difference += std::fabs(denoised[i] - raw[i]);
    }
    EXPECT_GT(difference, 0.0) << "the denoised image is the raw one";
    const std::optional<std::string> view = read_embedded_view(exr);
    ASSERT_TRUE(view.has_value());
    EXPECT_NE(view->find("\"denoise\": true"), std::string::npos) << *view;
}

// A scene with no DE renders by default in the brute mode, with its passes and inside tests
// reported; a DE scene renders in it on request, with the shading's layers in an EXR.
TEST_F(CliTest, BruteModeRendersInsideOnlyScenesByDefaultAndDeScenesOnRequest) {
    const RunResult inside = run({"render", "stereographic-julia", "-o", "julia.png", "--width",
                                  "48", "--height", "36", "--stats"});
    ASSERT_EQ(inside.exit_code, 0) << inside;
    EXPECT_NE(inside.out.find("samples_per_pixel 16\n"), std::string::npos) << inside;
    EXPECT_NE(inside.out.find("inside_tests_per_pixel "), std::string::npos) << inside;
    EXPECT_EQ(inside.out.find("hits 0\n"), std::string::npos) << inside;
    expect_rgb_png(dir() / "julia.png", 48, 36);

    const fs::path exr = dir() / "brute.exr";
    const RunResult de = run({"render", "mandelbulb", "--mode", "brute", "--spp", "2", "-o",
                              exr.string(), "--width", "24", "--height", "16", "--aov",
                              "albedo,normal,depth,alpha", "--effects", "+reflections"});
    ASSERT_EQ(de.exit_code, 0) << de;
    EXPECT_NE(de.err.find("ignores reflections"), std::string::npos) << de;
    const Imf::RgbaInputFile file(exr.string().c_str());
    for (const char* name : {"A", "albedo.R", "normal.X", "depth.Z"}) {
        EXPECT_NE(file.header().channels().findChannel(name), nullptr) << name;
    }
}

TEST_F(CliTest, RelativeOutputPathIsInWorkingDirectory) {
    const RunResult result =
        run({"render", "mandelbulb", "-o", "rel.png", "--width", "24", "--height", "16"});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    expect_rgb_png(dir() / "rel.png", 24, 16);
}

TEST_F(CliTest, NonSquareSizeReachesHeader) {
    const RunResult result =
        run({"render", "mandelbulb", "-o", out_png().string(), "--width", "37", "--height", "5"});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    expect_render_report(result, 37, 5);
    expect_rgb_png(out_png(), 37, 5);
}

TEST_F(CliTest, OverwritesExistingOutput) {
    {
        std::ofstream junk(out_png(), std::ios::binary);
        junk << std::string(10000, 'x');
    }
    const RunResult result =
        run({"render", "mandelbulb", "-o", out_png().string(), "--width", std::to_string(kCliWidth),
             "--height", std::to_string(kCliHeight)});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    expect_rgb_png(out_png(), kCliWidth, kCliHeight);
    EXPECT_EQ(directory_listing(dir()), std::vector<std::string>{"out.png"});
}

TEST_F(CliTest, SameRenderTwiceHitsSamePixels) {
    const std::vector<std::string> args{"render",  "mandelbulb", "-o",       out_png().string(),
                                        "--width", "32",         "--height", "24"};
    const RunResult first = run(args);
    const RunResult second = run(args);
    ASSERT_EQ(first.exit_code, 0) << first;
    ASSERT_EQ(second.exit_code, 0) << second;
    EXPECT_EQ(line_value(first.out, "hits"), line_value(second.out, "hits"));
}

// --kernel-source swaps the scene's OpenCL source (here the Mandelbulb's for a small ball, in the
// scene's own view): the render follows the file, and a file that is not there is a usage error.
TEST_F(CliTest, KernelSourceRendersTheSceneWithTheGivenSource) {
    const fs::path ball = dir() / "ball.cl";
    std::ofstream(ball) << "real scene_de(vec3 p, PARAMS) { (void)fgr_params; "
                           "return v3_length(p) - 0.2f; }\n";
    const std::vector<std::string> args{"render",  "mandelbulb", "-o",       out_png().string(),
                                        "--width", "32",         "--height", "24"};
    const RunResult own = run(args);
    std::vector<std::string> with_ball = args;
    with_ball.insert(with_ball.end(), {"--kernel-source", ball.string()});
    const RunResult swapped = run(with_ball);
    ASSERT_EQ(own.exit_code, 0) << own;
    ASSERT_EQ(swapped.exit_code, 0) << swapped;
    // The bulb fills about half the view; a ball of radius 0.2 seen from ~3 units a few percent.
    const long own_hits = std::stol(line_value(own.out, "hits").value());
    const long ball_hits = std::stol(line_value(swapped.out, "hits").value());
    EXPECT_LT(ball_hits * 4, own_hits);
    EXPECT_GT(ball_hits, 0);
    with_ball.back() = (dir() / "missing.cl").string();
    const RunResult missing = run(with_ball);
    EXPECT_EQ(missing.exit_code, 2) << missing;
    EXPECT_NE(missing.err.find("--kernel-source: cannot read"), std::string::npos) << missing;
}

struct ValidRender {
    const char* name;
    std::vector<std::string> extra;
};

void PrintTo(const ValidRender& input, std::ostream* os) { *os << input.name; }

const std::vector<ValidRender> kValidRenders = {
    {"PowerAndEnumByName", {"--set", "power=6", "--set", "variant=latitude"}},
    {"EnumByNumber", {"--set", "variant=1"}},
    {"RangeEndpoints", {"--set", "power=2", "--set", "bailout=64"}},
    {"QualityIterations", {"--set", "iterations=8"}},
    {"CameraTop", {"--camera", "top"}},
    {"CameraClose", {"--camera", "close"}},
    {"CameraPathOrbit", {"--camera-path", "orbit", "--time", "2.5"}},
    {"CameraPathDiveStart", {"--camera-path", "dive", "--time", "0"}},
    {"PacketWidth4", {"--packet-width", "4"}},
    {"Device0", {"--device", "0"}},
};

class CliValidRender : public CliTest, public ::testing::WithParamInterface<ValidRender> {};

TEST_P(CliValidRender, Succeeds) {
    std::vector<std::string> args{"render",  "mandelbulb", "-o",       out_png().string(),
                                  "--width", "32",         "--height", "24"};
    args.insert(args.end(), GetParam().extra.begin(), GetParam().extra.end());
    const RunResult result = run(args);
    SCOPED_TRACE(describe(args));
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    expect_render_report(result, 32, 24);
    expect_rgb_png(out_png(), 32, 24);
}

INSTANTIATE_TEST_SUITE_P(Cli, CliValidRender, ::testing::ValuesIn(kValidRenders),
                         [](const ::testing::TestParamInfo<ValidRender>& param_info) {
                             return std::string(param_info.param.name);
                         });

// --- list and info ------------------------------------------------------------------------------

// `fgr info --math-check` reports each precision and width's self-test verdict, read from the
// cache directory: a planted failing verdict is shown as a failure.
TEST_F(CliTest, InfoReportsTheMathSelfTestVerdicts) {
    const fs::path cache = dir() / "cache";
    ::setenv("FGR_CACHE_DIR", cache.c_str(), 1);
    const RunResult first = run({"info", "--math-check"});
    ASSERT_EQ(first.exit_code, 0) << first;
    EXPECT_NE(first.out.find("math float16:  pass"), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("math float1:   pass"), std::string::npos) << first.out;
    int verdicts = 0;
    for (const auto& entry : fs::directory_iterator(cache)) {
        if (entry.path().extension() != ".txt") continue;
        ++verdicts;
        std::ofstream(entry.path()) << "fail: exp: planted\n";
    }
    EXPECT_GE(verdicts, 4);  // float at 1, 4, 8 and 16 lanes
    const RunResult second = run({"info", "--math-check"});
    ::unsetenv("FGR_CACHE_DIR");
    ASSERT_EQ(second.exit_code, 0) << second;
    EXPECT_NE(second.out.find("math float16:  FAIL: exp: planted"), std::string::npos)
        << second.out;
    EXPECT_EQ(run({"info"}).out.find("math "), std::string::npos);
}

// `--all PATTERN` renders exactly the listed scenes whose ids match, one PNG each. Every scene
// (the pattern left out) would build some sixty kernels; each of those is rendered by its own
// SceneCheck test, so this one picks a plugin, a formula file, a hybrid and an IFS file.
TEST_F(CliTest, RenderAllWritesEveryListedSceneThePatternMatches) {
    const RunResult list = run({"list"});
    ASSERT_EQ(list.exit_code, 0) << list;
    const fs::path gallery = dir() / "gallery";
    const char* pattern = "sierpinski*";
    const RunResult result = run(
        {"render", "--all", pattern, "-o", gallery.string(), "--width", "24", "--height", "16"});
    ASSERT_EQ(result.exit_code, 0) << result;
    // Each scene in `fgr list` (a line starting with its id) whose id matches has its own PNG.
    std::istringstream lines(list.out);
    std::vector<std::string> matching;
    for (std::string line; std::getline(lines, line);) {
        if (line.empty() || line.front() == ' ') continue;
        const std::string id = line.substr(0, line.find(' '));
        if (id.starts_with("sierpinski")) matching.push_back(id);
    }
    for (const std::string& id : matching) expect_rgb_png(gallery / (id + ".png"), 24, 16);
    EXPECT_EQ(matching, (std::vector<std::string>{"sierpinski-box", "sierpinski-kifs",
                                                  "sierpinski-ifs", "sierpinski"}));
    EXPECT_EQ(static_cast<int>(directory_listing(gallery).size()),
              static_cast<int>(matching.size()));
}

TEST_F(CliTest, EffectChangesReachTheKernel) {
    const fs::path plain = dir() / "plain.png";
    const fs::path shadowed = dir() / "shadowed.png";
    const RunResult first = run({"render", "mandelbulb", "-o", plain.string(), "--width", "48",
                                 "--height", "32", "--effects", "-ambient_occlusion"});
    const RunResult second = run({"render", "mandelbulb", "-o", shadowed.string(), "--width", "48",
                                  "--height", "32", "--effects", "+shadows"});
    ASSERT_EQ(first.exit_code, 0) << first;
    ASSERT_EQ(second.exit_code, 0) << second;
    EXPECT_NE(read_file(plain), read_file(shadowed));
    EXPECT_NE(first.err.find("effects: none"), std::string::npos) << first.err;
    EXPECT_NE(second.err.find("effects: shadows,ambient_occlusion"), std::string::npos)
        << second.err;
}

TEST_F(CliTest, SixteenBitOutputIsLinear) {
    const fs::path file = dir() / "linear.png";
    const RunResult result = run({"render", "mandelbulb", "-o", file.string(), "--width", "20",
                                  "--height", "10", "--bit-depth", "16", "--spp", "2"});
    ASSERT_EQ(result.exit_code, 0) << result;
    const std::string bytes = read_file(file);
    ASSERT_GT(bytes.size(), 26u);
    EXPECT_EQ(big_endian_u32(bytes, 16), 20u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[24]), 16u);  // bit depth
    EXPECT_NE(bytes.find("gAMA"), std::string::npos);
}

TEST_F(CliTest, ListShowsMandelbulbParametersCamerasAndPaths) {
    const RunResult result = run({"list", "mandelbulb"});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    for (const char* word : {"mandelbulb", "power", "bailout", "variant", "iterations", "canonical",
                             "top", "close", "orbit", "dive"}) {
        EXPECT_NE(result.out.find(word), std::string::npos)
            << "missing '" << word << "': " << result;
    }
}

// `fgr list SCENE` lists that scene alone with each parameter's description on the line under it,
// built-in ones included; `fgr list` keeps one line a parameter.
TEST_F(CliTest, ListOfOneSceneDescribesEachParameter) {
    const RunResult one = run({"list", "mandelbulb"});
    ASSERT_EQ(one.exit_code, 0) << one;
    EXPECT_EQ(one.out.rfind("mandelbulb  ", 0), 0u) << one.out;
    const auto described = [&](const std::string& id, const std::string& description) {
        const std::size_t line = one.out.find("\n    " + id + " ");
        if (line == std::string::npos) return false;
        const std::size_t next = one.out.find('\n', line + 1);
        return one.out.compare(next, description.size() + 9, "\n        " + description) == 0;
    };
    EXPECT_TRUE(described("power", "exponent n of z -> z^n + c")) << one.out;
    EXPECT_TRUE(described("normal_epsilon", "normal stencil size, in pixel footprints at the hit"))
        << one.out;
    const RunResult all = run({"list"});
    ASSERT_EQ(all.exit_code, 0) << all;
    EXPECT_EQ(all.out.find("exponent n of z -> z^n + c"), std::string::npos) << all.out;
    const RunResult unknown = run({"list", "nosuchscene"});
    EXPECT_EQ(unknown.exit_code, 2) << unknown;
    expect_one_error_line(unknown);
}

TEST_F(CliTest, InfoListsADevice) {
    const RunResult result = run({"info"});
    ASSERT_TRUE(result.exited) << result;
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_TRUE(contains_ignoring_case(result.out, "device")) << result;
}

// `fgr info FILE` prints the view an image carries as indented JSON; a file without one, or not
// an image, is one error line and exit 1.
TEST_F(CliTest, InfoPrintsTheViewAnImageCarries) {
    const Image8 image{4, 2, std::vector<uint8_t>(24, 100)};
    const std::string view = R"({"format": "fgr-view", "version": 1, "scene": {"id": "mandelbulb"},
        "image": {"width": 4, "height": 2},
        "camera": {"eye": [2, -2, 1], "target": [0, 0, 0], "fov": 45},
        "parameters": {"power": 7.5}})";
    write_png(dir() / "view.png", image, view);
    const RunResult shown = run({"info", "view.png"});
    ASSERT_EQ(shown.exit_code, 0) << shown;
    EXPECT_EQ(shown.out,
              "scene mandelbulb\n"
              "size 4x2\n"
              "camera --eye 2,-2,1 --target 0,0,0 --up 0,0,1 --fov 45\n"
              "mode shaded --spp 1 precision auto\n"
              "effects none\n"
              "--set power=7.5\n"
              "render it again: fgr render --view view.png -o OUTPUT\n");
    EXPECT_EQ(shown.err, "");

    write_png(dir() / "plain.png", image);
    const RunResult none = run({"info", "plain.png"});
    EXPECT_EQ(none.exit_code, 1) << none;
    EXPECT_EQ(none.out, "");
    EXPECT_EQ(none.err,
              "fgr: error: plain.png: no fgr view embedded (not written by fgr, or written before "
              "views were embedded)\n");

    write_png(dir() / "not_json.png", image, "scene = mandelbulb");
    const RunResult not_json = run({"info", "not_json.png"});
    EXPECT_EQ(not_json.exit_code, 1) << not_json;
    expect_one_error_line(not_json);
    EXPECT_NE(
        not_json.err.find("not_json.png: the fgr view it carries cannot be read: not valid JSON"),
        std::string::npos)
        << not_json;

    const RunResult missing = run({"info", "missing.png"});
    EXPECT_EQ(missing.exit_code, 1) << missing;
    EXPECT_EQ(missing.err, "fgr: error: cannot read 'missing.png': no such file\n");
    const RunResult directory = run({"info", "."});
    EXPECT_EQ(directory.exit_code, 1) << directory;
    expect_one_error_line(directory);
    EXPECT_EQ(run({"info", "view.png", "--math-check"}).exit_code, 2);
}

// --- Views and images fgr cannot compute ---------------------------------------------------------
//
// A render whose camera basis would be NaN or infinite, or whose pixels come out NaN, is an error
// (one line, non-zero exit, no file), never exit 0 with an image of nothing. These children get
// their own kernel cache directory.

// fgr run as a child with a kernel cache directory of its own.
class CliWithOwnCache : public CliTest {
protected:
    using Environment = std::map<std::string, std::optional<std::string>>;

    // fgr with `args` in the test's directory; plugins from beside fgr and from `plugin_dir`;
    // `environment` changed on top.
    RunResult run_with(const std::vector<std::string>& args, const fs::path& plugin_dir = {},
                       const Environment& environment = {}) {
        test::ChildOptions options;
        options.working_dir = dir();
        options.environment = environment;
        options.environment.emplace("FGR_CACHE_DIR", cache_dir().string());
        options.environment["FGR_PLUGIN_PATH"] =
            plugin_dir.empty() ? std::nullopt : std::optional<std::string>(plugin_dir.string());
        RunResult result = test::run_child(kFgrExe, args, options);
        EXPECT_FALSE(result.timed_out) << describe(args) << ": " << result;
        EXPECT_EQ(result.term_signal, 0) << describe(args) << ": " << result;
        return result;
    }

    const fs::path& cache_dir() const { return cache_.path(); }

private:
    test::TempDir cache_{"fgr_cli_cache"};
};

// An IFS file in a folder of FGR_PLUGIN_PATH is listed like a plugin scene, marked as an IFS file.
TEST_F(CliWithOwnCache, ListShowsIfsScenesFromThePluginPath) {
    const fs::path plugins = dir() / "plugins";
    fs::create_directories(plugins);
    std::ofstream(plugins / "two.ifs.json")
        << R"({"format": "fgr-ifs", "version": 1, "id": "two-maps", "name": "Two maps",)"
        << R"( "maps": [{"scale": 0.5}, {"scale": 0.5, "translate": [1, 0, 0]}]})";
    const RunResult listed = run_with({"list"}, plugins);
    ASSERT_EQ(listed.exit_code, 0) << listed;
    // First, as the first folder's; a line, its kind in a column of its own.
    const std::string line = listed.out.substr(0, listed.out.find('\n'));
    EXPECT_EQ(line.rfind("two-maps ", 0), 0u) << listed.out;
    EXPECT_NE(line.find(" IFS "), std::string::npos) << listed.out;
    EXPECT_NE(line.find(" Two maps"), std::string::npos) << listed.out;
    const RunResult result = run_with({"list", "two-maps"}, plugins);
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.out.find("two-maps  Two maps"), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("IFS file: " + (plugins / "two.ifs.json").string() + " (2 maps"),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("ifs_depth"), std::string::npos) << result.out;
}

// A scene file nested 100000 deep and a FIFO named like a scene in a plugin folder (which once
// crashed, and would hang, every command that looks for scenes) are each one warning line: the
// other scenes are listed and loaded. A camera path nested as deep is refused in one line.
TEST_F(CliWithOwnCache, HostileSceneFilesAreOneWarningEachAndBreakNothingElse) {
    const fs::path plugins = dir() / "plugins";
    fs::create_directories(plugins);
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    std::ofstream(plugins / "a.ifs.json") << R"({"format": "fgr-ifs", "version": )" << deep << "}";
    ASSERT_EQ(mkfifo((plugins / "fifo.ifs.json").c_str(), 0600), 0);
    std::ofstream(plugins / "two.ifs.json")
        << R"({"format": "fgr-ifs", "version": 1, "id": "two-maps", "name": "Two maps",)"
        << R"( "maps": [{"scale": 0.5}, {"scale": 0.5, "translate": [1, 0, 0]}]})";
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"list"}, std::vector<std::string>{"list", "two-maps"}}) {
        const RunResult result = run_with(args, plugins);
        ASSERT_EQ(result.exit_code, 0) << result;
        EXPECT_NE(result.out.find("two-maps"), std::string::npos) << result.out;
        if (args.size() > 1) continue;  // a scene found by id reports only what it passed
        std::vector<std::string> warnings;
        std::istringstream lines(result.err);
        for (std::string line; std::getline(lines, line);) {
            if (line.find("skipping plugin") != std::string::npos) warnings.push_back(line);
        }
        ASSERT_EQ(warnings.size(), 2u) << result.err.substr(0, 2000);
        EXPECT_NE(warnings[0].find("a.ifs.json: "), std::string::npos) << warnings[0];
        EXPECT_NE(warnings[0].find("nest deeper than 64 levels"), std::string::npos) << warnings[0];
        EXPECT_LT(warnings[0].size(), 300u);
        EXPECT_NE(warnings[1].find("fifo.ifs.json: not a regular file: a FIFO"), std::string::npos)
            << warnings[1];
    }
    std::ofstream(dir() / "p.json")
        << R"({"format": "fgr-camera-path", "version": )" << deep << R"(, "keyframes": []})";
    const RunResult render =
        run_with({"render", "mandelbulb", "--camera-path", "p.json", "--time", "1", "-o", "x.png"});
    EXPECT_EQ(render.exit_code, 2) << render;
    EXPECT_NE(render.err.find("camera path 'p.json': "), std::string::npos) << render.err;
    EXPECT_LT(render.err.size(), 300u) << render.err.substr(0, 300);
    EXPECT_FALSE(fs::exists(dir() / "x.png"));
}

// A compiled plugin that hands over IFS maps (ABI 1.3) is listed as an IFS plugin, with its maps
// and bounding sphere, not as an IFS file.
TEST_F(CliWithOwnCache, ListShowsAnIfsPluginsMaps) {
    const fs::path plugins = fs::path(FGR_TEST_FIXTURE_DIR) / "ifs_plugin";
    const RunResult result = run_with({"list", "sierpinski-ifs-plugin"}, plugins);
    ASSERT_EQ(result.exit_code, 0) << result;
    EXPECT_NE(result.out.find("sierpinski-ifs-plugin  Sierpinski tetrahedron (IFS plugin)"),
              std::string::npos)
        << result.out;
    EXPECT_NE(result.out.find("IFS plugin: " + (plugins / "sierpinski_ifs_plugin.so").string() +
                              " (4 maps"),
              std::string::npos)
        << result.out;
    EXPECT_EQ(result.err.find("skipping"), std::string::npos) << result.err;
}

// A scene whose plugin was refused at load is not just "unknown": every command that takes a scene
// names the refused file and the reason. liboops.so declares the id 'oops'
// with a default out of range; no_id_given.so is refused before it gives an id, and is found by
// its file name.
TEST_F(CliWithOwnCache, UnknownSceneNamesTheRefusedPluginAndWhy) {
    const fs::path refused = fs::path(FGR_TEST_FIXTURE_DIR) / "bad" / "refused";
    ASSERT_TRUE(fs::exists(refused / "liboops.so")) << refused;
    const std::string oops_refused = "fgr: error: unknown scene 'oops': plugin " +
                                     (refused / "liboops.so").string() +
                                     " was refused: parameter 'scale': default 3 outside [0.5, 2]";
    const std::vector<std::vector<std::string>> commands = {
        {"render", "oops", "-o", out_png().string(), "--width", "16", "--height", "12"},
        {"bench", "oops", "--frames", "1"},
        {"bench", "accuracy", "oops"},
        {"view", "oops"},  // refused before a window would open
    };
    for (const std::vector<std::string>& args : commands) {
        const RunResult result = run_with(args, refused);
        SCOPED_TRACE(describe(args));
        ASSERT_TRUE(result.exited) << result;
        EXPECT_EQ(result.exit_code, 2) << result;
        // The discovery warnings come first; the error is the last line.
        std::string err = result.err;
        if (!err.empty() && err.back() == '\n') err.pop_back();
        EXPECT_EQ(err.substr(err.rfind('\n') + 1), oops_refused) << result;
    }

    const RunResult nameless = run_with(
        {"render", "no-id-given", "-o", out_png().string(), "--width", "16", "--height", "12"},
        refused);
    EXPECT_EQ(nameless.exit_code, 2) << nameless;
    EXPECT_TRUE(contains_ignoring_case(nameless.err, "unknown scene 'no-id-given': plugin " +
                                                         (refused / "no_id_given.so").string() +
                                                         " was refused: entry returned NULL"))
        << nameless;

    // An id no refused file can be: the scenes there are, and what was refused, on the one line.
    const RunResult other = run_with(
        {"render", "zzz", "-o", out_png().string(), "--width", "16", "--height", "12"}, refused);
    EXPECT_EQ(other.exit_code, 2) << other;
    EXPECT_TRUE(contains_ignoring_case(
        other.err, "unknown scene 'zzz' (`fgr list` lists the scenes; refused: "))
        << other;
    EXPECT_TRUE(contains_ignoring_case(
        other.err,
        (refused / "liboops.so").string() + " (parameter 'scale': default 3 outside [0.5, 2])"))
        << other;
    EXPECT_FALSE(fs::exists(out_png()));
}

// --- Scene files by path; text scenes ------------------------------------------------------------

// A scene file of each kind by path, and the scene id it holds, for `fgr render PATH`.
struct SceneFileByPath {
    std::string path;
    std::string id;
};

std::vector<SceneFileByPath> scene_files_by_path() {
    return {{"my-bulb.cl", "my-bulb"},  // a bare name: its suffix makes it a path
            {(test::kPluginDir / "mandelbulb.so").string(), "mandelbulb"},
            {(fs::path(FGR_TEST_IFS_DIR) / "sierpinski.ifs.json").string(), "sierpinski-ifs"},
            {(fs::path(FGR_TEST_FORMULA_DIR) / "mandelbulb-formula.formula.json").string(),
             "mandelbulb-formula"}};
}

// `fgr render PATH` for each kind of scene file. The file alone is loaded: a refused text scene in
// the plugin folder would be warned about by a command that scanned it. The text scene (the SDK
// guide's example, as the guide shows it) and the plugin (whose kernel the other renders of the
// Mandelbulb share) render; the IFS and formula files are loaded as far as the camera, which
// comes before any kernel is compiled (TheOtherSceneFilesRenderByPath renders them, slow tier).
TEST_F(CliWithOwnCache, RendersEveryKindOfSceneFileByPath) {
    const fs::path plugins = dir() / "plugins";
    fs::create_directories(plugins);
    test::write_text(plugins / "refused.cl", "/* fgr-scene {\"id\": \"refused\"} */\n");
    test::write_text(dir() / "my-bulb.cl", test::sdk_guide_text_scene_example());
    for (const auto& [path, id] : scene_files_by_path()) {
        SCOPED_TRACE(path);
        fs::remove(out_png());
        const bool rendered = path.ends_with(".cl") || path.ends_with(".so");
        std::vector<std::string> args = {"render",  path, "-o",       out_png().string(),
                                         "--width", "32", "--height", "24"};
        if (!rendered) args.insert(args.end(), {"--camera", "nosuch"});
        const RunResult result = run_with(args, plugins);
        EXPECT_EQ(result.err.find("skipping"), std::string::npos)
            << "a plugin folder was scanned: " << result;
        if (!rendered) {
            EXPECT_EQ(result.exit_code, 2) << result;
            EXPECT_EQ(result.err, "fgr: error: scene '" + id +
                                      "' has no camera 'nosuch' (`fgr list " + id +
                                      "` lists its cameras)\n")
                << result;
            continue;
        }
        ASSERT_EQ(result.exit_code, 0) << result;
        EXPECT_GT(expect_render_report(result, 32, 24), 0) << result;
        expect_rgb_png(out_png(), 32, 24);
    }
}

// The IFS and formula files by path render too (slow: two kernels no other test compiles).
TEST_F(CliWithOwnCache, TheOtherSceneFilesRenderByPath) {
    for (const auto& [path, id] : scene_files_by_path()) {
        if (path.ends_with(".cl") || path.ends_with(".so")) continue;
        SCOPED_TRACE(path);
        fs::remove(out_png());
        const RunResult result =
            run_with({"render", path, "-o", out_png().string(), "--width", "32", "--height", "24"});
        ASSERT_EQ(result.exit_code, 0) << result;
        EXPECT_GT(expect_render_report(result, 32, 24), 0) << result;
        expect_rgb_png(out_png(), 32, 24);
    }
}

// Every command that takes a scene refuses a bad scene file in one line that names the file (and
// the header's key), before it opens a device or a window.
TEST_F(CliWithOwnCache, ABadSceneFileIsRefusedInOneLineNamingIt) {
    std::string bad = test::sdk_guide_text_scene_example();
    const std::size_t max = bad.find("\"max\": 16");
    ASSERT_NE(max, std::string::npos);
    bad.replace(max, 9, "\"max\": \"16\"");
    test::write_text(dir() / "bad.cl", bad);
    test::write_text(dir() / "notes.txt", "not a scene");
    const std::string refused =
        R"(fgr: error: bad.cl: header "parameters[0].max": must be a number)";
    const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
        {{"render", "bad.cl", "-o", out_png().string()}, refused},
        {{"video", "bad.cl", "--camera-path", "orbit", "-o", (dir() / "v.mp4").string()}, refused},
        {{"check", "bad.cl"}, refused},
        {{"bench", "bad.cl", "--frames", "1"}, refused},
        {{"list", "bad.cl"}, refused},
        {{"view", "bad.cl"}, refused},  // refused before a window would open
        {{"render", "missing.ifs.json", "-o", out_png().string()},
         "fgr: error: missing.ifs.json: No such file or directory"},
        {{"render", "./notes.txt", "-o", out_png().string()},
         "fgr: error: ./notes.txt: not a scene file: fgr opens scene plugins (*.so), IFS files "
         "(*.ifs.json), formula files (*.formula.json) and text scenes (*.cl), or a scene id "
         "(`fgr list`)"},
    };
    for (const auto& [args, expected] : cases) {
        SCOPED_TRACE(describe(args));
        const RunResult result = run_with(args);
        ASSERT_TRUE(result.exited) << result;
        EXPECT_EQ(result.exit_code, 2) << result;
        if (args[0] != "view") expect_one_error_line(result);
        std::string err = result.err;
        if (!err.empty() && err.back() == '\n') err.pop_back();
        EXPECT_EQ(err.substr(err.rfind('\n') + 1), expected) << result;
    }
    EXPECT_FALSE(fs::exists(out_png()));
}

// A text scene that does not compile: the compiler's messages, and the one-line error after them,
// name the file and the line, as the file has them (its header comment included).
TEST_F(CliWithOwnCache, ATextSceneThatDoesNotCompileNamesItsFileAndLine) {
    std::string typo = test::sdk_guide_text_scene_example();
    const std::size_t at = typo.find("param_power)");
    ASSERT_NE(at, std::string::npos);
    typo.replace(at, 11, "param_powr");
    const long line = 1 + std::count(typo.begin(), typo.begin() + long(at), '\n');
    test::write_text(dir() / "typo.cl", typo);
    const RunResult result = run_with(
        {"render", "typo.cl", "-o", out_png().string(), "--width", "16", "--height", "12"});
    EXPECT_EQ(result.exit_code, 1) << result;
    const std::string where = "typo.cl:" + std::to_string(line) + ":";
    EXPECT_NE(result.err.find(where + "40: error: use of undeclared identifier 'param_powr'"),
              std::string::npos)
        << result;
    std::string err = result.err;
    if (!err.empty() && err.back() == '\n') err.pop_back();
    EXPECT_EQ(err.substr(err.rfind('\n') + 1)
                  .rfind("fgr: error: OpenCL program failed to compile: " + where, 0),
              0u)
        << result;
    EXPECT_FALSE(fs::exists(out_png()));
}

// The SDK guide's example and what `fgr new-scene --text` writes pass `fgr check`, which renders
// them too (slow: two scenes' checks).
TEST_F(CliWithOwnCache, TextScenesPassFgrCheck) {
    test::write_text(dir() / "my-bulb.cl", test::sdk_guide_text_scene_example());
    ASSERT_EQ(run_with({"new-scene", "--text", "my-scene"}).exit_code, 0);
    for (const char* file : {"my-bulb.cl", "my-scene.cl"}) {
        const RunResult result = run_with({"check", file});
        EXPECT_EQ(result.exit_code, 0) << result;
        EXPECT_NE(result.out.find(": all "), std::string::npos) << result;
        EXPECT_NE(result.out.find(" checks passed"), std::string::npos) << result;
    }
}

// Off a terminal, a bench that runs past the delay (FGR_PROGRESS_DELAY, 0 here) says how far it is
// over all its runs, about every tenth, with the run and the pace: three frames a run and two runs
// are sixths of the whole, the end of the first run and the start of the second one line.
TEST_F(CliWithOwnCache, BenchProgressLinesRunToTheEndWithTheRunAndPace) {
    const RunResult result =
        run_with({"bench", "mandelbulb", "--frames", "3", "--runs", "2", "--width", "16",
                  "--height", "12", "-o", (dir() / "bench").string()},
                 {}, {{"FGR_PROGRESS_DELAY", "0"}});
    ASSERT_EQ(result.exit_code, 0) << result;
    std::vector<std::string> progress;
    std::istringstream lines(result.err);
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("bench ")) continue;
        const std::size_t pace = line.find(" fps | ");
        EXPECT_NE(pace, std::string::npos) << line;
        progress.push_back(line.substr(0, line.rfind(" | ", pace)));
    }
    const std::vector<std::string> expected = {
        "bench 0% | run 1/2",  "bench 17% | run 1/2", "bench 33% | run 1/2", "bench 50% | run 1/2",
        "bench 67% | run 2/2", "bench 83% | run 2/2", "bench 100% | run 2/2"};
    EXPECT_EQ(progress, expected) << result;
    EXPECT_NE(result.err.find(" fps | took "), std::string::npos) << result;
}

// A view typed as --eye/--target/--up/--fov is the view a camera path file with the same numbers
// gives at a keyframe: the same pixels, bit for bit. The numbers are ones
// float and double round differently (0.1...), so a conversion on one side only would show.
TEST_F(CliWithOwnCache, ViewpointOptionsRenderWhatTheSameCameraPathKeyframeRenders) {
    std::ofstream(dir() / "same.json") << R"({"format": "fgr-camera-path", "version": 1,
        "keyframes": [
          {"time": 0, "position": [1.7, -2.1, 0.9], "target": [0.1, 0, -0.2], "up": [0, 0.3, 1],
           "fov": 47.5},
          {"time": 1, "position": [2, -2, 1], "target": [0, 0, 0]}]})";
    const std::vector<std::string> size = {"--width", "40", "--height", "30"};
    const auto render = [&](const std::string& file, std::vector<std::string> view) {
        std::vector<std::string> args{"render", "mandelbulb", "-o", (dir() / file).string()};
        args.insert(args.end(), size.begin(), size.end());
        args.insert(args.end(), view.begin(), view.end());
        const RunResult result = run_with(args);
        EXPECT_EQ(result.exit_code, 0) << result;
        return expect_render_report(result, 40, 30);
    };
    const long long typed_hits = render(
        "typed.png",
        {"--eye", "1.7,-2.1,0.9", "--target", "0.1,0,-0.2", "--up", "0,0.3,1", "--fov", "47.5"});
    const long long file_hits = render("file.png", {"--camera-path", "same.json", "--time", "0"});
    const long long default_hits = render("default.png", {});
    ASSERT_TRUE(fs::exists(dir() / "typed.png") && fs::exists(dir() / "file.png"));
    const Image8 typed = read_png(dir() / "typed.png");
    const Image8 file = read_png(dir() / "file.png");
    const Image8 fallback = read_png(dir() / "default.png");
    EXPECT_GT(typed_hits, 0);
    EXPECT_EQ(typed_hits, file_hits);
    ASSERT_EQ(typed.rgb.size(), file.rgb.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < typed.rgb.size(); ++i) {
        differing += typed.rgb[i] != file.rgb[i] ? 1 : 0;
    }
    EXPECT_EQ(differing, 0u) << "of " << typed.rgb.size() << " channel values";
    // The options did change the view: the scene's default camera sees another image.
    EXPECT_TRUE(default_hits != typed_hits || fallback.rgb != typed.rgb);

    // --fov over a named camera keeps the rest of that camera; the same override of the default
    // camera is another view.
    const long long top_narrow = render("top30.png", {"--camera", "top", "--fov", "30"});
    const long long top = render("top.png", {"--camera", "top"});
    EXPECT_NE(read_png(dir() / "top30.png").rgb, read_png(dir() / "top.png").rgb);
    EXPECT_NE(read_png(dir() / "top30.png").rgb, read_png(dir() / "default.png").rgb);
    EXPECT_GT(top_narrow, 0);
    EXPECT_GT(top, 0);
}

class CliUncomputable : public CliWithOwnCache {
protected:
    // A camera path file in the test's directory with these keyframes (JSON objects).
    std::string path_file(const std::string& name, const std::string& keyframes) {
        std::ofstream(dir() / name)
            << R"({"format": "fgr-camera-path", "version": 1, "keyframes": [)" << keyframes << "]}";
        return name;
    }

    // Exit `code`, one error line mentioning each of `mention` (after the build's log lines, if
    // it got that far), and nothing but `inputs` left in the directory.
    void expect_refused(const RunResult& result, int code, const std::vector<std::string>& mention,
                        const std::vector<std::string>& inputs) {
        ASSERT_TRUE(result.exited) << result;
        EXPECT_EQ(result.exit_code, code) << result;
        RunResult error = result;
        std::istringstream lines(result.err);
        error.err.clear();
        for (std::string line; std::getline(lines, line);) {
            if (!line.starts_with("fgr: info: ")) error.err += line + "\n";
        }
        expect_one_error_line(error);
        for (const std::string& part : mention) {
            EXPECT_TRUE(contains_ignoring_case(result.err, part))
                << "should mention '" << part << "': " << result;
        }
        EXPECT_EQ(directory_listing(dir()), inputs)
            << "left behind: " << joined(directory_listing(dir()));
    }
};

// Each keyframe is fine, but the camera passes through its target half-way: that moment has no
// view direction.
TEST_F(CliUncomputable, CameraPathMomentWithoutAViewDirectionIsRefused) {
    const std::string file =
        path_file("cross.json", R"({"time": 0, "position": [2, -2, 1], "target": [0, 0, 0]},
                         {"time": 1, "position": [0, 0, 0], "target": [2, -2, 1]})");
    const RunResult result =
        run_with({"render", "mandelbulb", "-o", out_png().string(), "--width", "16", "--height",
                  "12", "--camera-path", file, "--time", "0.5"});
    expect_refused(result, 2, {"camera path 'cross.json' at time 0.5: position equals target"},
                   {"cross.json"});
    // Beside that moment the path renders.
    const RunResult fine =
        run_with({"render", "mandelbulb", "-o", out_png().string(), "--width", "16", "--height",
                  "12", "--camera-path", file, "--time", "0.25"});
    EXPECT_EQ(fine.exit_code, 0) << fine;
}

TEST_F(CliUncomputable, KeyframesWhoseBasisWouldNotBeFiniteAreRefused) {
    const std::string huge =
        path_file("huge.json",
                  R"({"time": 0, "position": [1e30, 1e30, 1e30], "target": [-1e30, -1e30, -1e30]},
           {"time": 1, "position": [2, -2, 1], "target": [0, 0, 0]})");
    const RunResult result =
        run_with({"render", "mandelbulb", "-o", out_png().string(), "--width", "16", "--height",
                  "12", "--camera-path", huge, "--time", "1"});
    expect_refused(result, 2, {"huge.json", "keyframe 0", "too far apart"}, {"huge.json"});

    const std::string parallel =
        path_file("parallel.json", R"({"time": 0, "position": [0, 0, 3], "target": [0, 0, 0]},
                            {"time": 1, "position": [2, -2, 1], "target": [0, 0, 0]})");
    const RunResult up =
        run_with({"render", "mandelbulb", "-o", out_png().string(), "--width", "16", "--height",
                  "12", "--camera-path", parallel, "--time", "1"});
    expect_refused(up, 2, {"parallel.json", "keyframe 0", "up is zero or parallel"},
                   {"huge.json", "parallel.json"});
}

TEST_F(CliUncomputable, VersionThatOnlyWrapsToOneIsRefused) {
    std::ofstream(dir() / "v.json")
        << R"({"format": "fgr-camera-path", "version": 4294967297, "keyframes": [
              {"time": 0, "position": [2, -2, 1], "target": [0, 0, 0]},
              {"time": 1, "position": [2, -2, 1.5], "target": [0, 0, 0]}]})";
    const RunResult result =
        run_with({"render", "mandelbulb", "-o", out_png().string(), "--width", "16", "--height",
                  "12", "--camera-path", "v.json", "--time", "0.5"});
    expect_refused(result, 2, {"v.json", "unsupported \"version\" 4294967297"}, {"v.json"});
}

// A scene whose colour is NaN: the kernel runs, but the pixels it hits are not an image.
TEST_F(CliUncomputable, NonFinitePixelsAreAnErrorAndNoFile) {
    const fs::path plugins = fs::path(FGR_TEST_FIXTURE_DIR) / "bad" / "nan";
    ASSERT_TRUE(fs::exists(plugins / "nan_colour.so")) << plugins;
    const RunResult result = run_with(
        {"render", "bad-nan-colour", "-o", out_png().string(), "--width", "16", "--height", "12"},
        plugins);
    expect_refused(result, 1, {"bad-nan-colour", "non-finite colour or depth"}, {});
}

// --- fgr cache and the disk cache's limits -------------------------------------------------------

class CliCache : public CliWithOwnCache {
protected:
    // fgr render, storing its programs' binaries as it does for a driver that keeps none (PoCL,
    // the tests' driver, keeps its own: StoredPrograms).
    RunResult render(const std::vector<std::string>& extra = {}, Environment environment = {}) {
        std::vector<std::string> args{"render",  "mandelbulb", "-o",       out_png().string(),
                                      "--width", "16",         "--height", "12"};
        args.insert(args.end(), extra.begin(), extra.end());
        environment.emplace(kStoredProgramsVariable, "always");
        return run_with(args, {}, environment);
    }

    // Entries (programs, math verdicts and the scene index) and their bytes, as the directory
    // holds them.
    std::pair<long long, long long> entries_and_bytes() const {
        long long entries = 0, bytes = 0;
        for (const fs::directory_entry& entry : fs::directory_iterator(cache_dir())) {
            const std::string name = entry.path().filename().string();
            if (name.ends_with(".bin") || (name.starts_with("math-") && name.ends_with(".txt")) ||
                name == "scene-index.json") {
                ++entries;
                bytes += static_cast<long long>(entry.file_size());
            }
        }
        return {entries, bytes};
    }
};

TEST_F(CliCache, SizeReportsTheEntriesAndClearRemovesThemAll) {
    ASSERT_EQ(render().exit_code, 0);
    const auto [entries, bytes] = entries_and_bytes();
    ASSERT_GT(entries, 1) << "a program and the math self-test's verdicts";
    const bool has_verdict = std::any_of(
        fs::directory_iterator(cache_dir()), fs::directory_iterator(),
        [](const auto& entry) { return entry.path().filename().string().starts_with("math-"); });
    EXPECT_TRUE(has_verdict) << joined(directory_listing(cache_dir()));
    EXPECT_TRUE(fs::exists(cache_dir() / "scene-index.json"))
        << "finding mandelbulb indexed the scene files: " << joined(directory_listing(cache_dir()));
    std::ofstream(cache_dir() / "notes.txt") << "not fgr's";

    const RunResult size = run_with({"cache", "size"});
    ASSERT_EQ(size.exit_code, 0) << size;
    EXPECT_EQ(line_value(size.out, "directory"), cache_dir().string()) << size;
    EXPECT_EQ(line_value(size.out, "entries"), std::to_string(entries)) << size;
    const std::optional<std::string> reported = line_value(size.out, "bytes");
    ASSERT_TRUE(reported.has_value()) << size;
    EXPECT_EQ(parse_integer(reported->substr(0, reported->find(' '))), bytes) << size;
    const std::optional<std::string> limit = line_value(size.out, "limit");
    ASSERT_TRUE(limit.has_value()) << size;
    EXPECT_EQ(parse_integer(limit->substr(0, limit->find(' '))), 256LL << 20) << size;
    const RunResult custom = run_with({"cache", "size"}, {}, {{"FGR_CACHE_MAX_MB", "3"}});
    EXPECT_TRUE(contains_ignoring_case(line_value(custom.out, "limit").value_or(""),
                                       "3145728 (3.0 MiB, from"))
        << custom;

    const RunResult clear = run_with({"cache", "clear"});
    ASSERT_EQ(clear.exit_code, 0) << clear;
    EXPECT_TRUE(
        contains_ignoring_case(clear.out, "removed " + std::to_string(entries) + " entries"))
        << clear;
    EXPECT_EQ(directory_listing(cache_dir()), std::vector<std::string>{"notes.txt"});
    const RunResult empty = run_with({"cache", "size"});
    EXPECT_EQ(line_value(empty.out, "entries"), "0") << empty;
}

TEST_F(CliCache, WithoutASubcommandItSaysWhichThereAre) {
    const RunResult result = run_with({"cache"});
    EXPECT_EQ(result.exit_code, 2) << result;
    expect_one_error_line(result);
    EXPECT_TRUE(contains_ignoring_case(result.err, "size or clear")) << result;
}

// PoCL, the tests' driver, keeps the programs it compiles in its own cache: by default a render
// leaves no program binary in fgr's (StoredPrograms), and a value of FGR_CACHE_PROGRAMS that fgr
// does not know is one warning, the default kept.
TEST_F(CliWithOwnCache, OnPoclTheProgramsStayInPoclsOwnCache) {
    const std::vector<std::string> args{"render",  "mandelbulb", "-o",       out_png().string(),
                                        "--width", "16",         "--height", "12"};
    const auto no_binaries = [&] {
        for (const std::string& name : directory_listing(cache_dir())) {
            EXPECT_FALSE(name.ends_with(".bin")) << name;
        }
    };
    const RunResult result = run_with(args);
    ASSERT_EQ(result.exit_code, 0) << result;
    no_binaries();
    const RunResult unknown = run_with(args, {}, {{kStoredProgramsVariable, "sometimes"}});
    ASSERT_EQ(unknown.exit_code, 0) << unknown;
    EXPECT_NE(unknown.err.find("warning: FGR_CACHE_PROGRAMS='sometimes' is neither 'auto' nor "
                               "'always'"),
              std::string::npos)
        << unknown;
    no_binaries();
}

// Three programs of ~0.5 MB each (and the math self-test's) against a 1 MiB limit.
TEST_F(CliCache, DiskCacheStaysUnderItsLimit) {
    const Environment one_mib{{"FGR_CACHE_MAX_MB", "1"}};
    for (const char* effects : {"none", "+shadows", "+fog"}) {
        const RunResult result = render({"--effects", effects}, one_mib);
        ASSERT_EQ(result.exit_code, 0) << result;
        EXPECT_LE(entries_and_bytes().second, 1LL << 20)
            << "after --effects " << effects << ": " << joined(directory_listing(cache_dir()));
    }
    EXPECT_GE(entries_and_bytes().first, 1);
}

// Entries are written through the atomic, fsync'd helper: with fsync failing in the cache
// directory (an LD_PRELOAD shim), the render still succeeds, and no entry and no temporary is left
// there; without the shim the same render stores its entries.
TEST_F(CliCache, EntriesAreFsyncedAndAFailedWriteLeavesNothing) {
    const fs::path shim = fs::path(FGR_TEST_FIXTURE_DIR) / "preload" / "fail_fsync.so";
    ASSERT_TRUE(fs::exists(shim)) << shim;
    const Environment failing{{"LD_PRELOAD", shim.string()},
                              {"FGR_TEST_FAIL_FSYNC_UNDER", cache_dir().string()},
                              {"ASAN_OPTIONS", "verify_asan_link_order=0"}};
    const RunResult result = render({}, failing);
    ASSERT_EQ(result.exit_code, 0) << result;
    expect_rgb_png(out_png(), 16, 12);
    EXPECT_EQ(directory_listing(cache_dir()), std::vector<std::string>{})
        << "an entry whose fsync failed was kept, or its temporary left behind";

    const RunResult stored = render();
    ASSERT_EQ(stored.exit_code, 0) << stored;
    EXPECT_GT(entries_and_bytes().first, 0);
}

// Without --environment the path mode takes the scene's own environment; --environment (the sky
// too) and the sky's own settings are the user's choice and win.
TEST(CliPathMode, TheScenesOwnEnvironmentLightsItWhenTheUserNamesNone) {
    Scene scene = test::inline_scene("real scene_de(vec3 p, PARAMS) { return p.x; }");
    scene.environment = "uniform:0.5";
    ModeOptions options;
    EXPECT_EQ(chosen_path_settings(options, scene).environment->description,
              "uniform radiance 0.5 0.5 0.5");
    options.environment = "sky";
    EXPECT_EQ(chosen_path_settings(options, scene).environment->description.rfind("sky", 0), 0u);
    ModeOptions hazy;
    hazy.turbidity = 6.0f;
    EXPECT_EQ(chosen_path_settings(hazy, scene).environment->description.rfind("sky", 0), 0u);
    scene.environment.clear();
    EXPECT_EQ(chosen_path_settings(ModeOptions{}, scene).environment->description.rfind("sky", 0),
              0u);
}

}  // namespace
}  // namespace fgr
