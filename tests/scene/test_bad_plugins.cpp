// SPDX-License-Identifier: Apache-2.0
// Bad plugins: NULL or missing fields, an empty id, duplicate ids across folders, absurd numbers,
// 10^6 parameters, a 100 MiB source, an entry returning NULL and a kernel that does not compile
// are each refused or reported with the file and the reason, and the host keeps working. The
// plugins are real .so files from tests/fixtures/bad. Then a seeded fuzz test of the description
// validator, copy_scene_description, on descriptions mutated from valid random ones.

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "camera/camera.hpp"
#include "device/kernel_assembly.hpp"
#include "device/opencl_device.hpp"
#include "device/program_cache.hpp"
#include "fgr/plugin.h"
#include "fuzz_rng.hpp"
#include "render/renderer.hpp"
#include "scene/description_validation.hpp"
#include "scene/discovery.hpp"
#include "scene/environment_spec.hpp"
#include "scene/ifs/ifs.hpp"
#include "scene/parameters.hpp"
#include "scene/plugin_loader.hpp"
#include "scene/render_mode.hpp"
#include "scene/scene_file.hpp"
#include "test_files.hpp"
#include "test_math.hpp"

namespace fgr {
namespace {
namespace fs = std::filesystem;

const fs::path kBadDir = fs::path(FGR_TEST_FIXTURE_DIR) / "bad";
using test::kPluginDir;

bool is_one_line(const std::string& text) {
    return text.find_first_of("\n\r") == std::string::npos;
}

// Copies the default logger's output into a string while alive (level and message per line).
class LogCapture {
public:
    LogCapture()
        : logger_(spdlog::default_logger()),
          sink_(std::make_shared<spdlog::sinks::ostream_sink_mt>(stream_)),
          old_level_(logger_->level()) {
        sink_->set_pattern("%l %v");
        logger_->sinks().push_back(sink_);
        if (old_level_ > spdlog::level::warn) logger_->set_level(spdlog::level::warn);
    }
    LogCapture(const LogCapture&) = delete;
    LogCapture& operator=(const LogCapture&) = delete;
    ~LogCapture() {
        auto& sinks = logger_->sinks();
        sinks.erase(std::remove(sinks.begin(), sinks.end(), sink_), sinks.end());
        logger_->set_level(old_level_);
    }

    // The captured lines that start with `prefix`.
    std::vector<std::string> lines_starting(const std::string& prefix) const {
        std::vector<std::string> lines;
        std::istringstream in(stream_.str());
        for (std::string line; std::getline(in, line);) {
            if (line.starts_with(prefix)) lines.push_back(line);
        }
        return lines;
    }

private:
    std::ostringstream stream_;
    std::shared_ptr<spdlog::logger> logger_;
    std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink_;
    spdlog::level::level_enum old_level_;
};

// --- One broken fixture at a time ----------------------------------------------------------------

struct BrokenFixture {
    const char* file;    // in kBadDir
    const char* reason;  // part of the one-line reason
};

// Every file in kBadDir but keeps_working.so, each refused for one reason.
const BrokenFixture kBrokenFixtures[] = {
    {"null_id.so", "scene id is NULL"},
    {"empty_id.so", "scene id '' must match [a-z][a-z0-9_-]*"},
    {"null_name.so", "scene name is NULL"},
    {"null_source.so", "source is NULL"},
    {"short_struct.so", "description struct too small (120 bytes)"},
    {"null_params.so", "parameter count is 1 but the array is NULL"},
    {"null_cameras.so", "camera count is 1 but the array is NULL"},
    {"null_lights.so", "light count is 1 but the array is NULL: a scene needs at least one light"},
    {"null_keyframes.so", "camera path 'orbit' keyframe count is 2 but the array is NULL"},
    {"wrapped_steps.so", "march settings: max_steps 4294967295 outside [1, 100000]"},
    {"negative_distance.so", "march settings: max_distance -5 must be finite and > 0"},
    {"nan_default.so", "parameter 'scale': default not finite"},
    {"inverted_range.so", "parameter 'scale': min 2 greater than max 0.5"},
    {"million_params.so", "parameter count 1000000 outside [0, 1024]"},
    {"huge_source.so", "source longer than 4194304 bytes"},
    {"entry_null.so", "entry returned NULL"},
    // Read, the NUL-less source would fault at its end: refused for source_length alone.
    {"long_source_length.so", "source longer than 4194304 bytes (source_length 5242880)"},
    // ABI 1.2: a render mode no host has, and light discs outside [0, 45] degrees.
    {"unknown_mode.so", "default_mode 'pathz' is not a render mode (choose shaded|path|brute)"},
    {"negative_radius.so", "light 0: angular_radius_degrees -1 outside [0, 45]"},
    {"wide_radius.so", "light 0: angular_radius_degrees 46 outside [0, 45]"},
    {"nan_radius.so", "light 0: angular_radius_degrees nan outside [0, 45]"},
    // ABI 1.3: IFS maps, checked as an IFS file's are, and what an IFS scene cannot also have.
    {"ifs_expanding.so", "IFS map 2 is not contractive (largest singular value 1.5 >= 1)"},
    {"ifs_singular.so", "IFS map 1 is singular (smallest singular value 0, largest 0.5)"},
    {"ifs_nan.so", "IFS map 3: matrix numbers must be finite and at most 1e+06 in size"},
    {"ifs_too_many.so", "IFS map count 65 outside [1, 64]"},
    {"ifs_too_deep.so", "ifs_max_depth 25 outside [0, 24]"},
    {"ifs_with_source.so", "IFS maps and a source: a scene with ifs_map_count 4 is an IFS scene"},
    {"ifs_with_params.so", "IFS scenes have no parameters of their own (param_count 1)"},
    {"ifs_soft_shadows.so",
     "IFS scenes cannot have soft_shadows: exact IFS tracing has no "
     "distance estimate"},
};

void PrintTo(const BrokenFixture& fixture, std::ostream* out) { *out << fixture.file; }

class BadPluginFile : public ::testing::TestWithParam<BrokenFixture> {};

TEST_P(BadPluginFile, IsRefusedWithItsReason) {
    const fs::path file = kBadDir / GetParam().file;
    ASSERT_TRUE(fs::exists(file)) << file;
    // Twice: the library was closed and its state (and allocations) released in between.
    for (int attempt = 0; attempt < 2; ++attempt) {
        const LoadResult result = load_scene_plugin(file);
        EXPECT_FALSE(result.scene.has_value()) << file;
        EXPECT_NE(result.error.find(GetParam().reason), std::string::npos)
            << file << ": reason was: " << result.error
            << "\nexpected it to contain: " << GetParam().reason;
        EXPECT_TRUE(is_one_line(result.error)) << result.error;
    }
}

INSTANTIATE_TEST_SUITE_P(BadPlugin, BadPluginFile, ::testing::ValuesIn(kBrokenFixtures),
                         [](const ::testing::TestParamInfo<BrokenFixture>& fixture) {
                             return fs::path(fixture.param.file).stem().string();
                         });

// --- Discovery over a folder of them -------------------------------------------------------------

const SkippedPlugin* find_skipped(const Discovery& discovery, const fs::path& file) {
    for (const SkippedPlugin& skipped : discovery.skipped) {
        if (skipped.file == file) return &skipped;
    }
    return nullptr;
}

TEST(BadPlugin, DiscoveryNamesEachBrokenFileAndReasonAndLoadsTheGoodOne) {
    LogCapture log;
    const Discovery discovery = discover_scenes({kBadDir});

    ASSERT_EQ(discovery.scenes.size(), 1u);
    EXPECT_EQ(discovery.scenes[0].id, "bad-folder-good");
    EXPECT_EQ(discovery.scenes[0].plugin_file, kBadDir / "keeps_working.so");
    EXPECT_EQ(discovery.scenes[0].source_name, "bad_scene.cl");

    EXPECT_EQ(discovery.skipped.size(), std::size(kBrokenFixtures));
    const std::vector<std::string> warnings = log.lines_starting("warning skipping plugin ");
    EXPECT_EQ(warnings.size(), std::size(kBrokenFixtures)) << "one warning per skipped file";
    for (const BrokenFixture& broken : kBrokenFixtures) {
        const fs::path file = kBadDir / broken.file;
        const SkippedPlugin* skipped = find_skipped(discovery, file);
        ASSERT_NE(skipped, nullptr) << file << " was not reported";
        EXPECT_NE(skipped->reason.find(broken.reason), std::string::npos)
            << file << ": reason was: " << skipped->reason;
        // The log line names the file and gives the reason.
        const std::string expected = "warning skipping plugin " + file.string() + ": ";
        const auto line = std::find_if(warnings.begin(), warnings.end(), [&](const auto& text) {
            return text.starts_with(expected);
        });
        ASSERT_NE(line, warnings.end()) << "no warning for " << file;
        EXPECT_NE(line->find(broken.reason), std::string::npos) << *line;
    }
}

// A refusal after the description's id was read names the scene too: the
// warning for a NULL light list says which scene lacks its lights.
TEST(BadPlugin, WarningNamesTheSceneWhoseLightsAreNull) {
    LogCapture log;
    const Discovery discovery = discover_scenes({kBadDir});
    const fs::path file = kBadDir / "null_lights.so";
    const SkippedPlugin* skipped = find_skipped(discovery, file);
    ASSERT_NE(skipped, nullptr);
    EXPECT_EQ(skipped->declared_id, "bad-folder-good");
    const std::vector<std::string> warnings =
        log.lines_starting("warning skipping plugin " + file.string() + ": ");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("scene 'bad-folder-good': light count is 1 but the array is NULL: "
                               "a scene needs at least one light"),
              std::string::npos)
        << warnings[0];
}

TEST(BadPlugin, DuplicateIdInALaterFolderIsReportedAndThatFolderStillLoads) {
    const fs::path second_dir = kBadDir / "second";
    const fs::path good = kBadDir / "keeps_working.so";
    const fs::path duplicate = second_dir / "dup_of_good.so";

    const Discovery discovery = discover_scenes({kBadDir, second_dir});
    ASSERT_EQ(discovery.scenes.size(), 2u);
    EXPECT_EQ(discovery.scenes[0].plugin_file, good) << "the first folder wins";
    EXPECT_EQ(discovery.scenes[1].id, "bad-folder-second") << "loaded after the duplicate";
    const SkippedPlugin* skipped = find_skipped(discovery, duplicate);
    ASSERT_NE(skipped, nullptr);
    EXPECT_EQ(skipped->reason,
              "duplicate scene id 'bad-folder-good' (already loaded from " + good.string() + ")");

    const Discovery reversed = discover_scenes({second_dir, kBadDir});
    ASSERT_EQ(reversed.scenes.size(), 2u);
    EXPECT_EQ(reversed.scenes[0].plugin_file, duplicate) << "now the second folder comes first";
    const SkippedPlugin* now_skipped = find_skipped(reversed, good);
    ASSERT_NE(now_skipped, nullptr);
    EXPECT_NE(now_skipped->reason.find("already loaded from " + duplicate.string()),
              std::string::npos)
        << now_skipped->reason;
}

// --- The 100 MiB source is refused without being copied ------------------------------------------

// A field of /proc/self/status in KiB, or -1.
long status_kib(const std::string& field) {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        if (line.starts_with(field + ":")) return std::atol(line.c_str() + field.size() + 1);
    }
    return -1;
}

// Resets VmHWM (the peak resident size) to the current size; false where the kernel refuses.
bool reset_peak_rss() {
    std::ofstream clear_refs("/proc/self/clear_refs");
    clear_refs << "5";
    clear_refs.flush();
    return clear_refs.good();
}

TEST(BadPlugin, HugeSourceIsRefusedWithoutBeingCopied) {
    if (!reset_peak_rss() || status_kib("VmHWM") < 0) {
        GTEST_SKIP() << "cannot measure the peak resident size here";
    }
    const long before = status_kib("VmRSS");
    const LoadResult result = load_scene_plugin(kBadDir / "huge_source.so");
    const long grown = status_kib("VmHWM") - before;
    EXPECT_FALSE(result.scene.has_value());
    EXPECT_NE(result.error.find("source longer than 4194304 bytes"), std::string::npos)
        << result.error;
    // The plugin's own 100 MiB were resident (so this measures something); a copy of them by the
    // host would add another 100 MiB.
    EXPECT_GE(grown, 90L * 1024) << "the fixture did not allocate its source";
    EXPECT_LT(grown, 150L * 1024) << "the host copied (part of) the 100 MiB source";
}

// --- A source given by its length (ABI 1.1) -----------------------------------------------------

// The fixture's source has no NUL and ends where readable memory ends: reading one byte past its
// source_length faults, so this test crashes unless the host stops there.
TEST(BadPlugin, SourceWithoutItsNulIsReadToItsLengthOnly) {
    const fs::path file = kBadDir / "length" / "no_nul_source.so";
    for (int attempt = 0; attempt < 2; ++attempt) {
        const LoadResult loaded = load_scene_plugin(file);
        ASSERT_TRUE(loaded.scene.has_value()) << loaded.error;
        EXPECT_EQ(loaded.scene->source,
                  "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_scale; }\n");
    }
}

// --- A kernel that does not compile --------------------------------------------------------------

TEST(BadPluginKernel, BuildErrorNamesTheScenesFileAndLineAndTheHostBuildsTheNextScene) {
    const fs::path file = kBadDir / "kernel" / "bad_kernel.so";
    const LoadResult broken = load_scene_plugin(file);
    ASSERT_TRUE(broken.scene.has_value()) << "only the compiler can tell: " << broken.error;
    EXPECT_EQ(broken.scene->plugin_file, file);

    const ComputeDevice device = open_device(-1);
    ProgramCache cache{fs::path()};
    const KernelSwitches switches{preferred_packet_width(device.info), broken.scene->effects};
    try {
        Renderer renderer(device, cache, *broken.scene, switches);
        FAIL() << "a kernel that does not compile must throw";
    } catch (const KernelBuildError& error) {
        EXPECT_FALSE(std::string(error.what()).empty());
        EXPECT_NE(error.build_log().find("bad_kernel.cl:4:"), std::string::npos)
            << error.build_log();
        EXPECT_NE(error.build_log().find("undeclared_radius"), std::string::npos)
            << error.build_log();
    }

    // The same device and cache still build and render a good scene.
    const LoadResult good = load_scene_plugin(kBadDir / "keeps_working.so");
    ASSERT_TRUE(good.scene.has_value()) << good.error;
    Renderer renderer(device, cache, *good.scene,
                      {preferred_packet_width(device.info), good.scene->effects});
    FrameRequest request;
    request.width = 32;
    request.height = 24;
    request.view = good.scene->cameras.front().view;
    request.params = default_param_values(*good.scene);
    const Frame frame = renderer.render(request);
    EXPECT_GT(frame.hits, 0) << "the sphere must be in view";
}

// --- The host keeps working ----------------------------------------------------------------------

TEST(BadPlugin, RealPluginsStillLoadAfterAllTheBadOnes) {
    for (const fs::path& dir : {kBadDir, kBadDir / "second", kBadDir / "kernel"}) {
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.path().extension() == ".so") (void)load_scene_plugin(entry.path());
        }
    }
    (void)discover_scenes({kBadDir, kBadDir / "second", kBadDir / "kernel"});

    std::size_t plugin_files = 0;
    for (const auto& entry : fs::directory_iterator(kPluginDir)) {
        // Plugins and the shipped IFS files (plugins/ifs/) alike.
        if (is_scene_file_name(entry.path())) ++plugin_files;
    }
    const Discovery discovery = discover_scenes({kPluginDir});
    for (const SkippedPlugin& skipped : discovery.skipped) {
        ADD_FAILURE() << "real plugin skipped: " << skipped.file << ": " << skipped.reason;
    }
    EXPECT_EQ(discovery.scenes.size(), plugin_files);
    EXPECT_TRUE(std::any_of(discovery.scenes.begin(), discovery.scenes.end(),
                            [](const Scene& scene) { return scene.id == "mandelbulb"; }))
        << "mandelbulb (a dependency of fgr_tests) was not discovered";
}

// =================================================================================================
// Fuzzing copy_scene_description
// =================================================================================================
//
// Each case starts from a valid random description and applies a few random mutations drawn from
// what real plugins get wrong: NULL and odd strings, nasty floats, wrong enums and bits, counts
// that disagree with limits, headers of other sizes and versions. Every array the description
// points to really is as long as its count says (or NULL), and every struct_size stays within the
// memory behind it: the validator may read that far. The checks: nothing escapes
// copy_scene_description, exactly one of scene and error is set, an error is one non-empty line,
// and an accepted scene satisfies ABI.md's invariants, re-checked here independently.
//
// Reproduce a failure with FGR_FUZZ_CASE=<case seed> (printed with it); FGR_FUZZ_CASES=<n> runs
// more or fewer cases.

constexpr uint64_t kDescriptionFuzzSeed = 0x46475246757a7a31;  // "FGRFuzz1"
constexpr int kDescriptionFuzzCases = 20000;

using Rng = test::FuzzRng;

// Owns every string and array one description points into.
class Arena {
public:
    const char* text(std::string value) {
        strings_.push_back(std::make_unique<std::string>(std::move(value)));
        return strings_.back()->c_str();
    }
    // Zero-filled bytes, aligned for every ABI struct.
    unsigned char* bytes(std::size_t size) {
        blocks_.push_back(std::make_unique<unsigned char[]>(std::max<std::size_t>(size, 1)));
        return blocks_.back().get();
    }

private:
    std::vector<std::unique_ptr<std::string>> strings_;
    std::vector<std::unique_ptr<unsigned char[]>> blocks_;
};

constexpr float kInf = std::numeric_limits<float>::infinity();
using test::kNaN;

const float kNastyFloats[] = {
    kNaN,    -kNaN,    kInf,        -kInf,    0.0f,   -0.0f,   FLT_TRUE_MIN, -FLT_TRUE_MIN,
    FLT_MIN, -FLT_MIN, FLT_MAX,     -FLT_MAX, 1e30f,  -1e30f,  1e-30f,       -1e-30f,
    1e20f,   1e-20f,   1e-22f,      0.5f,     1.0f,   -1.0f,   2.0f,         179.99f,
    180.0f,  180.01f,  1e6f,        2e6f,     0.001f, 0.0009f, 1000.0f,      1000.5f,
    0.05f,   0.049f,   16777217.0f, 1e5f,     -5.0f,  3.5f,
};

float nasty_float(Rng& rng) { return rng.pick(kNastyFloats); }

float any_float(Rng& rng) {
    switch (rng.below(3)) {
        case 0:
            return nasty_float(rng);
        case 1:
            return static_cast<float>(rng.range(-10, 10));
        default:
            return rng.uniform(-100.0f, 100.0f);
    }
}

const uint32_t kNastyCounts[] = {0u,     1u,       2u,          3u,         16u,    17u,
                                 256u,   257u,     1024u,       1025u,      10000u, 10001u,
                                 65536u, 1000000u, 0x7fffffffu, 0xffffffffu};

const char* const kBuiltinIds[] = {"max_steps",   "max_distance", "hit_threshold", "iterations",
                                   "step_factor", "exposure",     "tone_map",      "fog_density"};

std::string random_id(Rng& rng, int max_length, bool dash) {
    static const char first[] = "abcdefghijklmnopqrstuvwxyz";
    static const char rest[] = "abcdefghijklmnopqrstuvwxyz0123456789_-";
    const int length = rng.range(1, max_length);
    std::string id(1, first[rng.below(26)]);
    const uint32_t alphabet = dash ? 38 : 37;
    while (static_cast<int>(id.size()) < length) id += rest[rng.below(alphabet)];
    return id;
}

// Any string a plugin might hand over, valid or not, including non-ASCII bytes and control
// characters (never NUL: that ends the string).
std::string any_text(Rng& rng) {
    switch (rng.below(12)) {
        case 0:
            return "";
        case 1:
            return random_id(rng, 63, true);
        case 2:  // at or one past the 63-char id limit
            return std::string(1, 'a') + std::string(rng.below(2) + 62, 'b');
        case 3: {  // arbitrary bytes
            std::string text(rng.range(1, 64), ' ');
            for (char& c : text) c = static_cast<char>(rng.range(1, 255));
            return text;
        }
        case 4: {  // printable ASCII
            std::string text(rng.range(1, 80), ' ');
            for (char& c : text) c = static_cast<char>(rng.range(32, 126));
            return text;
        }
        case 5: {  // long: around the 4096-byte text limit, or just long
            const std::size_t sizes[] = {4095, 4096, 4097, 1000 + rng.below(4000)};
            return std::string(rng.pick(sizes), 'x');
        }
        case 6: {  // almost an identifier
            const char* const odd[] = {"Mandelbulb", "1bulb", "-bulb", "_x",       "bulb box",
                                       "bulb.so",    "a\nb",  "a\tb",  "bail-out", "x\x1b[31m"};
            return rng.pick(odd);
        }
        case 7:
            return rng.pick(kBuiltinIds);
        case 8: {
            const char* const unicode[] = {"caf\xc3\xa9", "\xe5\x90\x8d\xe5\x89\x8d",
                                           "\xff\xfe",    "\xc3",
                                           "a\x7f",       "\xe2\x80\xa8"};
            return rng.pick(unicode);
        }
        default:
            return random_id(rng, 12, rng.chance(0.5));
    }
}

// --- A random valid description, as plain vectors ------------------------------------------------

// An array as it will be laid out: its elements, the struct_size and abi_version their headers
// get, optionally one element with a different header, or NULL with some count.
template <typename T>
struct ArraySpec {
    std::vector<T> elements;
    uint32_t struct_size = sizeof(T);
    uint32_t abi_version = FGR_ABI_VERSION;
    int odd_element = -1;  // index of an element whose header differs
    fgr_struct_header odd_header{};
    bool null = false;        // pass NULL ...
    uint32_t null_count = 0;  // ... with this count
};

struct PathSpec {
    fgr_camera_path path{};
    ArraySpec<fgr_keyframe> keyframes;
};

struct DescSpec {
    fgr_scene_desc desc{};  // pointers and counts of the arrays are filled in by layout()
    uint32_t desc_capacity = sizeof(fgr_scene_desc);  // bytes behind the description
    ArraySpec<fgr_param_desc> params;
    ArraySpec<fgr_camera> cameras;
    std::vector<PathSpec> paths;
    uint32_t path_struct_size = sizeof(fgr_camera_path);
    uint32_t path_abi_version = FGR_ABI_VERSION;
    bool paths_null = false;
    uint32_t paths_null_count = 0;
    ArraySpec<fgr_light> lights;
    ArraySpec<fgr_ifs_map> ifs_maps;  // ABI 1.3: empty for a DE scene
};

// A direction that is never zero or parallel to +z, so +z works as up.
glm::vec3 random_direction(Rng& rng) {
    glm::vec3 direction(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (std::fabs(direction.x) + std::fabs(direction.y) < 0.1f) direction.x = 0.5f;
    return direction * rng.uniform(0.5f, 5.0f);
}

void set3(float (&out)[3], glm::vec3 value) {
    out[0] = value.x;
    out[1] = value.y;
    out[2] = value.z;
}

// position, target, up, fov of a valid view
void random_view(Rng& rng, float (&position)[3], float (&target)[3], float (&up)[3], float& fov) {
    const glm::vec3 from(rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5));
    set3(position, from);
    set3(target, from + random_direction(rng));
    set3(up, glm::vec3(0, 0, rng.uniform(0.5f, 2.0f)));
    fov = rng.uniform(1.0f, 170.0f);
}

fgr_param_desc random_param(Rng& rng, Arena& arena, int index) {
    fgr_param_desc param{};
    param.header = FGR_HEADER(fgr_param_desc);
    std::string id = "p";
    id += std::to_string(index);
    id += '_';
    id += random_id(rng, 10, false);
    param.id = arena.text(std::move(id));
    param.label = rng.chance(0.5) ? arena.text("Label " + random_id(rng, 20, true)) : nullptr;
    param.group = rng.chance(0.5) ? "Group" : nullptr;
    param.description = rng.chance(0.5) ? "a parameter" : nullptr;
    param.type = rng.below(5);
    switch (param.type) {
        case FGR_PARAM_INT: {
            param.min_value = static_cast<float>(rng.range(-5, 5));
            param.max_value = param.min_value + static_cast<float>(rng.range(0, 4));
            param.default_value[0] = param.min_value;
            if (rng.chance(0.5)) {
                std::string choices = "c0";
                for (int i = 1; i <= static_cast<int>(param.max_value - param.min_value); ++i) {
                    choices += "|c" + std::to_string(i);
                }
                param.choices = arena.text(choices);
            }
            break;
        }
        case FGR_PARAM_BOOL:
            param.min_value = 0.0f;
            param.max_value = 1.0f;
            param.default_value[0] = static_cast<float>(rng.below(2));
            break;
        default: {
            param.min_value = rng.uniform(-10.0f, 10.0f);
            param.max_value = param.min_value + rng.uniform(0.0f, 20.0f);
            for (float& value : param.default_value) {
                value = rng.uniform(param.min_value, param.max_value);
                value = std::clamp(value, param.min_value, param.max_value);
            }
            break;
        }
    }
    return param;
}

fgr_keyframe random_keyframe(Rng& rng, float time) {
    fgr_keyframe keyframe{};
    keyframe.header = FGR_HEADER(fgr_keyframe);
    keyframe.time = time;
    random_view(rng, keyframe.position, keyframe.target, keyframe.up, keyframe.fov_degrees);
    return keyframe;
}

DescSpec random_valid_spec(Rng& rng, Arena& arena) {
    DescSpec spec;
    fgr_scene_desc& desc = spec.desc;
    desc.header = FGR_HEADER(fgr_scene_desc);
    desc.id = arena.text(random_id(rng, 63, true));
    desc.name = arena.text("Scene " + random_id(rng, 20, true));
    desc.description = rng.chance(0.8) ? "a fuzzed scene" : "";
    desc.source = "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 1.0f; }\n";
    desc.source_name = rng.chance(0.5) ? "fuzz.cl" : nullptr;
    for (int i = 0, n = rng.range(0, 6); i < n; ++i) {
        spec.params.elements.push_back(random_param(rng, arena, i));
    }
    for (int i = 0, n = rng.range(1, 3); i < n; ++i) {
        fgr_camera camera{};
        camera.header = FGR_HEADER(fgr_camera);
        camera.name = arena.text("cam" + std::to_string(i));
        random_view(rng, camera.position, camera.target, camera.up, camera.fov_degrees);
        spec.cameras.elements.push_back(camera);
    }
    for (int i = 0, n = rng.range(0, 2); i < n; ++i) {
        PathSpec path;
        path.path.header = FGR_HEADER(fgr_camera_path);
        path.path.name = arena.text("path-" + std::to_string(i));
        float time = rng.uniform(-5.0f, 5.0f);
        for (int k = 0, frames = rng.range(2, 5); k < frames; ++k) {
            path.keyframes.elements.push_back(random_keyframe(rng, time));
            time += rng.uniform(0.1f, 3.0f);
        }
        spec.paths.push_back(std::move(path));
    }
    for (int i = 0, n = rng.range(1, 4); i < n; ++i) {
        fgr_light light{};
        light.header = FGR_HEADER(fgr_light);
        light.type = rng.below(2);
        set3(light.vector, random_direction(rng));
        set3(light.colour, glm::vec3(rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0, 1)));
        light.intensity = rng.uniform(0.0f, 5.0f);
        // ABI 1.2: a disc of up to 45 degrees, often none.
        light.angular_radius_degrees = rng.chance(0.5) ? 0.0f : rng.uniform(0.0f, 45.0f);
        spec.lights.elements.push_back(light);
    }
    desc.effects = rng.next() & FGR_EFFECT_ALL_V1;
    desc.march.header = FGR_HEADER(fgr_march_settings);
    desc.march.max_steps = static_cast<uint32_t>(rng.range(1, 100000));
    desc.march.max_distance = rng.uniform(0.001f, 1e6f);
    desc.march.hit_threshold = rng.uniform(0.001f, 1000.0f);
    desc.march.de_iterations = static_cast<uint32_t>(rng.range(1, 1000));
    desc.march.step_factor = rng.chance(0.3) ? 0.0f : rng.uniform(0.05f, 1.0f);
    const char* const modes[] = {nullptr, "", "shaded", "path"};
    desc.default_mode = rng.pick(modes);
    // ABI 1.5: often none, else one fgr generates.
    const char* const environments[] = {
        nullptr, "", "sky", "studio", "uniform", "uniform:0.5", "uniform:1,0.5,0"};
    desc.environment = rng.pick(environments);
    return spec;
}

// --- Mutations -----------------------------------------------------------------------------------

const char* any_string(Rng& rng, Arena& arena) {
    return rng.chance(0.15) ? nullptr : arena.text(any_text(rng));
}

uint32_t any_struct_size(Rng& rng, uint32_t natural) {
    const uint32_t sizes[] = {
        natural,     natural, natural + 8, natural + 16, natural + 4,
        natural - 4, 0,       8,           natural / 2,  rng.below(natural + 65)};
    return rng.pick(sizes);
}

uint32_t any_abi_version(Rng& rng) {
    const uint32_t versions[] = {FGR_ABI_VERSION,
                                 FGR_ABI_VERSION + 1,
                                 (1u << 16) | 0xffffu,
                                 0u,
                                 2u << 16,
                                 0xffffu,
                                 static_cast<uint32_t>(rng.next())};
    return rng.pick(versions);
}

uint32_t any_count(Rng& rng) {
    return rng.chance(0.7) ? rng.pick(kNastyCounts) : static_cast<uint32_t>(rng.next());
}

// Counts for arrays the fuzzer really allocates: up to just past each limit.
template <typename T>
void mutate_array_shape(Rng& rng, ArraySpec<T>& array, uint32_t limit) {
    switch (rng.below(6)) {
        case 0:  // NULL, with any count
            array.null = true;
            array.null_count = any_count(rng);
            break;
        case 1:  // empty
            array.elements.clear();
            break;
        case 2:  // just past the limit, or at it: copies of one element
            if (!array.elements.empty()) {
                array.elements.resize(limit + rng.below(2), array.elements[0]);
            }
            break;
        case 3:  // the header every element gets
            array.struct_size = any_struct_size(rng, sizeof(T));
            break;
        case 4:
            array.abi_version = any_abi_version(rng);
            break;
        default:  // one element with another header
            if (!array.elements.empty()) {
                array.odd_element = static_cast<int>(rng.below(array.elements.size()));
                array.odd_header = {any_struct_size(rng, sizeof(T)), any_abi_version(rng)};
            }
            break;
    }
}

void mutate_view(Rng& rng, float (&position)[3], float (&target)[3], float (&up)[3], float& fov) {
    switch (rng.below(5)) {
        case 0:
            position[rng.below(3)] = any_float(rng);
            break;
        case 1:
            target[rng.below(3)] = any_float(rng);
            break;
        case 2:
            up[rng.below(3)] = any_float(rng);
            break;
        case 3:  // looks at itself, or up along the view
            if (rng.chance(0.5)) {
                std::copy(std::begin(position), std::end(position), target);
            } else {
                for (int i = 0; i < 3; ++i) up[i] = (target[i] - position[i]) * -2.0f;
            }
            break;
        default:
            fov = any_float(rng);
            break;
    }
}

void mutate_param(Rng& rng, Arena& arena, fgr_param_desc& param,
                  const std::vector<fgr_param_desc>& all) {
    switch (rng.below(10)) {
        case 0:
            param.id = rng.chance(0.3) && !all.empty() ? all[rng.below(all.size())].id
                                                       : any_string(rng, arena);
            break;
        case 1:
            param.label = any_string(rng, arena);
            break;
        case 2:
            param.group = any_string(rng, arena);
            break;
        case 3:
            param.description = any_string(rng, arena);
            break;
        case 4: {
            const uint32_t types[] = {0, 1, 2, 3, 4, 5, 255, 0xffffffffu};
            param.type = rng.pick(types);
            break;
        }
        case 5:
            param.min_value = any_float(rng);
            break;
        case 6:
            param.max_value = any_float(rng);
            break;
        case 7:
            param.default_value[rng.below(3)] = any_float(rng);
            break;
        case 8: {
            const char* const choices[] = {"a|b", "a|b|c", "a||c", "|", "", "a", "a|b|c|d|e|f"};
            param.choices = rng.chance(0.5) ? rng.pick(choices) : any_string(rng, arena);
            break;
        }
        default:
            std::swap(param.min_value, param.max_value);
            break;
    }
}

void mutate_light(Rng& rng, fgr_light& light) {
    switch (rng.below(6)) {
        case 0: {
            const uint32_t types[] = {0, 1, 2, 7, 0xffffffffu};
            light.type = rng.pick(types);
            break;
        }
        case 1:
            light.vector[rng.below(3)] = any_float(rng);
            break;
        case 2:
            light.colour[rng.below(3)] = any_float(rng);
            break;
        case 3:
            light.intensity = any_float(rng);
            break;
        case 4: {  // ABI 1.2: at and around [0, 45], or anything
            const float radii[] = {0.0f, -0.0f, 45.0f, 45.00001f, -FLT_TRUE_MIN, 0.27f, 90.0f};
            light.angular_radius_degrees = rng.chance(0.5) ? rng.pick(radii) : any_float(rng);
            break;
        }
        default: {  // zero, or a valid direction whose squared length under- or overflows float
            const float sizes[] = {0.0f, -0.0f, 1e-22f, FLT_TRUE_MIN, 1e20f, FLT_MAX};
            const float size = rng.pick(sizes);
            for (float& v : light.vector) v = rng.chance(0.5) ? size : -size;
            break;
        }
    }
}

void mutate_march(Rng& rng, fgr_march_settings& march) {
    const uint32_t integers[] = {0u, 1u, 1000u, 1001u, 100000u, 100001u, 0xffffffffu};
    switch (rng.below(7)) {
        case 0:
            march.max_steps = rng.chance(0.7) ? rng.pick(integers) : uint32_t(rng.next());
            break;
        case 1:
            march.max_distance = any_float(rng);
            break;
        case 2:
            march.hit_threshold = any_float(rng);
            break;
        case 3:
            march.de_iterations = rng.chance(0.7) ? rng.pick(integers) : uint32_t(rng.next());
            break;
        case 4:
            march.step_factor = any_float(rng);
            break;
        case 5:
            march.header.struct_size = any_struct_size(rng, sizeof(fgr_march_settings));
            break;
        default:
            march.header.abi_version = any_abi_version(rng);
            break;
    }
}

// Shared by every case that wants a source at or over the 4 MiB limit.
const std::string& source_of_size(std::size_t size) {
    static std::map<std::size_t, std::string> sources;
    auto [it, inserted] = sources.try_emplace(size);
    if (inserted) it->second.assign(size, ' ');
    return it->second;
}

// ABI 1.3: a map that is mostly a fine contraction (a scaled rotation-like matrix and an offset),
// now and then one that grows, flattens or holds a NaN.
fgr_ifs_map random_ifs_map(Rng& rng) {
    fgr_ifs_map map{};
    map.header = FGR_HEADER(fgr_ifs_map);
    const float scale = rng.chance(0.9) ? rng.uniform(0.2f, 0.6f) : rng.uniform(0.0f, 1.5f);
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            map.matrix[4 * row + column] =
                (row == column ? scale : 0.0f) + rng.uniform(-0.1f, 0.1f) * scale;
        }
        map.matrix[4 * row + 3] = rng.uniform(-1.0f, 1.0f);
        map.colour[row] = rng.chance(0.95) ? rng.uniform(0.0f, 1.0f) : rng.uniform(-1.0f, 2.0f);
    }
    if (rng.chance(0.05)) map.matrix[rng.below(12)] = std::numeric_limits<float>::quiet_NaN();
    return map;
}

// ABI 1.3: the scene becomes an IFS (maps, depths, and usually no source and no parameters, as
// such a scene must have), or its maps change.
void mutate_ifs(Rng& rng, Arena& arena, DescSpec& spec) {
    fgr_scene_desc& desc = spec.desc;
    if (spec.ifs_maps.elements.empty() || rng.chance(0.3)) {
        spec.ifs_maps.elements.clear();
        for (int i = 0, n = rng.range(1, 6); i < n; ++i) {
            spec.ifs_maps.elements.push_back(random_ifs_map(rng));
        }
        if (rng.chance(0.85)) desc.source = rng.chance(0.5) ? nullptr : "";
        if (rng.chance(0.85)) spec.params.elements.clear();
        if (rng.chance(0.85)) desc.effects &= FGR_EFFECT_SHADOWS | FGR_EFFECT_FOG;
        desc.ifs_default_depth = rng.chance(0.8) ? rng.below(8) : rng.below(40);
        desc.ifs_max_depth =
            rng.chance(0.8) ? desc.ifs_default_depth + rng.below(8) : rng.below(40);
    } else if (rng.chance(0.5)) {
        spec.ifs_maps.elements[rng.below(spec.ifs_maps.elements.size())] = random_ifs_map(rng);
    } else {
        mutate_array_shape(rng, spec.ifs_maps, 100);
    }
    (void)arena;
}

void mutate(Rng& rng, Arena& arena, DescSpec& spec) {
    fgr_scene_desc& desc = spec.desc;
    switch (rng.below(23)) {
        case 0:
            desc.id = any_string(rng, arena);
            break;
        case 1:
            desc.name = any_string(rng, arena);
            break;
        case 2:
            desc.description = any_string(rng, arena);
            break;
        case 3:
            if (rng.chance(0.1)) {
                desc.source = source_of_size((4u << 20) + rng.below(2)).c_str();
            } else {
                desc.source = any_string(rng, arena);
            }
            if (desc.source != nullptr && rng.chance(0.3)) {
                // ABI 1.1: a length within the string and its NUL (all that is behind it), or
                // one over the limit (refused before anything is read).
                const uint64_t bytes = std::strlen(desc.source) + 1;
                desc.source_length =
                    rng.chance(0.2) ? uint64_t{1} << rng.range(22, 40) : 1 + rng.below(bytes);
            }
            break;
        case 4:
            desc.source_name = any_string(rng, arena);
            break;
        case 5:
            desc.header.struct_size = any_struct_size(rng, sizeof(fgr_scene_desc));
            // Bigger than sizeof: the plugin's newer struct really is that big.
            spec.desc_capacity = std::max<uint32_t>(spec.desc_capacity, desc.header.struct_size);
            break;
        case 6:
            desc.header.abi_version = any_abi_version(rng);
            break;
        case 7:
        case 8:
            if (!spec.params.elements.empty()) {
                const auto index = rng.below(spec.params.elements.size());
                mutate_param(rng, arena, spec.params.elements[index], spec.params.elements);
            }
            break;
        case 9:
            mutate_array_shape(rng, spec.params, 1024);
            break;
        case 10:
            if (!spec.cameras.elements.empty()) {
                fgr_camera& camera = spec.cameras.elements[rng.below(spec.cameras.elements.size())];
                if (rng.chance(0.2)) {
                    camera.name = any_string(rng, arena);
                } else {
                    mutate_view(rng, camera.position, camera.target, camera.up, camera.fov_degrees);
                }
            }
            break;
        case 11:
            mutate_array_shape(rng, spec.cameras, 256);
            break;
        case 12:
            if (!spec.paths.empty()) {
                PathSpec& path = spec.paths[rng.below(spec.paths.size())];
                auto& frames = path.keyframes.elements;
                switch (rng.below(5)) {
                    case 0:
                        path.path.name = any_string(rng, arena);
                        break;
                    case 1:
                        mutate_array_shape(rng, path.keyframes, 10000);
                        break;
                    case 2:
                        if (!frames.empty()) frames[rng.below(frames.size())].time = any_float(rng);
                        break;
                    case 3:
                        if (frames.size() >= 2) frames.back().time = frames.front().time;
                        break;
                    default:
                        if (!frames.empty()) {
                            fgr_keyframe& frame = frames[rng.below(frames.size())];
                            mutate_view(rng, frame.position, frame.target, frame.up,
                                        frame.fov_degrees);
                        }
                        break;
                }
            }
            break;
        case 13:
            switch (rng.below(5)) {
                case 0:
                    spec.paths_null = true;
                    spec.paths_null_count = any_count(rng);
                    break;
                case 1:
                    spec.path_struct_size = any_struct_size(rng, sizeof(fgr_camera_path));
                    break;
                case 2:
                    spec.path_abi_version = any_abi_version(rng);
                    break;
                case 3:  // a duplicate name
                    if (!spec.paths.empty()) spec.paths.push_back(spec.paths.front());
                    break;
                default:
                    if (!spec.paths.empty()) spec.paths.resize(257, spec.paths.front());
                    break;
            }
            break;
        case 14:
            if (!spec.lights.elements.empty()) {
                mutate_light(rng, spec.lights.elements[rng.below(spec.lights.elements.size())]);
            }
            break;
        case 15:
            mutate_array_shape(rng, spec.lights, 16);
            break;
        case 16:
            desc.effects =
                rng.chance(0.5) ? desc.effects | (uint64_t{1} << rng.below(64)) : rng.next();
            break;
        case 17:
        case 18:
            mutate_march(rng, desc.march);
            break;
        case 20:
            mutate_ifs(rng, arena, spec);
            break;
        case 19: {  // ABI 1.2: a mode, almost a mode, or any text
            const char* const modes[] = {"shaded", "path", "pathz", "Path", "shaded ", "brute"};
            desc.default_mode = rng.chance(0.5) ? rng.pick(modes) : any_string(rng, arena);
            break;
        }
        case 21: {  // ABI 1.5: an environment, almost one, a file, or any text
            const char* const environments[] = {"studio",       "uniform:2", "uniform:1,1",
                                                "uniform:-0.5", "uniform:",  "uniform:inf",
                                                "Studio",       "sky.hdr",   "/dev/zero",
                                                "uniform:1e39"};
            desc.environment = rng.chance(0.5) ? rng.pick(environments) : any_string(rng, arena);
            break;
        }
        default:  // a camera name repeated
            if (spec.cameras.elements.size() >= 2) {
                spec.cameras.elements[1].name = spec.cameras.elements[0].name;
            }
            break;
    }
}

// --- Laying a spec out in memory as a plugin would -----------------------------------------------

// The array as the validator will walk it: element i at i * struct_size when that stride is
// usable, so the memory behind it covers (count - 1) * struct_size + sizeof(T) either way. Gaps
// between elements (fields of a "newer minor version") hold random bytes. A stride smaller than
// sizeof(T) is an older minor version's: each element then overwrites the previous one's fields
// beyond that stride, which the validator must not read.
template <typename T>
const T* layout(Rng& rng, Arena& arena, const ArraySpec<T>& array, uint32_t* count) {
    if (array.null) {
        *count = array.null_count;
        return nullptr;
    }
    *count = static_cast<uint32_t>(array.elements.size());
    if (array.elements.empty())
        return rng.chance(0.5) ? nullptr : reinterpret_cast<T*>(arena.bytes(64));
    // The validator's stride is the first element's struct_size.
    const std::size_t declared =
        array.odd_element == 0 ? array.odd_header.struct_size : array.struct_size;
    const bool usable = declared >= sizeof(fgr_struct_header) && declared % alignof(T) == 0;
    const std::size_t stride = usable ? declared : sizeof(T);
    const std::size_t size = array.elements.size() * std::max(declared, sizeof(T)) + 64;
    unsigned char* bytes = arena.bytes(size);
    for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<unsigned char>(rng.next());
    for (std::size_t i = 0; i < array.elements.size(); ++i) {
        T element = array.elements[i];
        element.header = {array.struct_size, array.abi_version};
        if (static_cast<int>(i) == array.odd_element) element.header = array.odd_header;
        std::memcpy(bytes + i * stride, &element, sizeof(T));
    }
    return reinterpret_cast<const T*>(bytes);
}

const fgr_scene_desc* layout(Rng& rng, Arena& arena, DescSpec& spec) {
    fgr_scene_desc desc = spec.desc;
    desc.params = layout(rng, arena, spec.params, &desc.param_count);
    desc.cameras = layout(rng, arena, spec.cameras, &desc.camera_count);
    desc.lights = layout(rng, arena, spec.lights, &desc.light_count);
    ArraySpec<fgr_camera_path> paths;
    paths.struct_size = spec.path_struct_size;
    paths.abi_version = spec.path_abi_version;
    paths.null = spec.paths_null;
    paths.null_count = spec.paths_null_count;
    for (const PathSpec& path : spec.paths) {
        fgr_camera_path copy = path.path;
        copy.keyframes = layout(rng, arena, path.keyframes, &copy.keyframe_count);
        paths.elements.push_back(copy);
    }
    desc.camera_paths = layout(rng, arena, paths, &desc.camera_path_count);
    desc.ifs_maps = layout(rng, arena, spec.ifs_maps, &desc.ifs_map_count);
    unsigned char* bytes = arena.bytes(spec.desc_capacity);
    std::memcpy(bytes, &desc, sizeof(desc));
    return reinterpret_cast<const fgr_scene_desc*>(bytes);
}

// --- Invariants of an accepted scene, checked independently of the loader -----------------------

const std::regex kSceneIdPattern("[a-z][a-z0-9_-]{0,62}");
const std::regex kParamIdPattern("[a-z][a-z0-9_]{0,62}");
const std::regex kNamePattern("[a-z0-9_-]{1,63}");
const char* const kQualityKnobs[] = {"max_steps", "max_distance", "hit_threshold", "iterations",
                                     "step_factor"};

bool finite3(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_view(const CameraView& view, const std::string& where) {
    EXPECT_TRUE(finite3(view.position) && finite3(view.target) && finite3(view.up)) << where;
    EXPECT_NE(view.position, view.target) << where;
    EXPECT_TRUE(view.fov_degrees > 0.0f && view.fov_degrees < 180.0f)
        << where << " fov " << view.fov_degrees;
    const glm::dvec3 direction = glm::dvec3(view.target) - glm::dvec3(view.position);
    EXPECT_GT(glm::length(glm::cross(direction, glm::dvec3(view.up))), 0.0)
        << where << ": up parallel to the view";
    // What the kernel gets: a finite orthonormal basis, built from the view's own up.
    const CameraBasis basis = camera_basis(view);
    EXPECT_TRUE(finite3(basis.forward) && finite3(basis.right) && finite3(basis.up) &&
                std::abs(glm::length(basis.forward) - 1.0f) < 1e-3f &&
                std::abs(glm::length(basis.right) - 1.0f) < 1e-3f)
        << where << ": camera basis not finite";
    EXPECT_TRUE(up_defines_roll(basis.forward, view.up)) << where << ": up replaced";
}

void check_param(const ParamInfo& param) {
    const std::string where = "param " + param.id;
    EXPECT_TRUE(std::isfinite(param.min_value) && std::isfinite(param.max_value)) << where;
    EXPECT_LE(param.min_value, param.max_value) << where;
    const bool vector = param.type == ParamType::Vec3 || param.type == ParamType::Colour;
    for (int i = 0; i < (vector ? 3 : 1); ++i) {
        const float value = param.default_value[static_cast<std::size_t>(i)];
        EXPECT_TRUE(std::isfinite(value)) << where;
        EXPECT_TRUE(value >= param.min_value && value <= param.max_value)
            << where << " default " << value;
    }
    if (!vector && !param.builtin) {
        EXPECT_EQ(param.default_value[1], 0.0f) << where;
        EXPECT_EQ(param.default_value[2], 0.0f) << where;
    }
    if (param.type == ParamType::Int) {
        EXPECT_EQ(std::trunc(param.min_value), param.min_value) << where;
        EXPECT_EQ(std::trunc(param.max_value), param.max_value) << where;
        EXPECT_EQ(std::trunc(param.default_value[0]), param.default_value[0]) << where;
        if (!param.choices.empty()) {
            EXPECT_EQ(static_cast<double>(param.choices.size()),
                      double{param.max_value} - double{param.min_value} + 1.0)
                << where;
            for (const std::string& choice : param.choices) EXPECT_FALSE(choice.empty()) << where;
        }
    } else {
        EXPECT_TRUE(param.choices.empty()) << where;
    }
    if (param.type == ParamType::Bool) {
        EXPECT_EQ(param.min_value, 0.0f) << where;
        EXPECT_EQ(param.max_value, 1.0f) << where;
        EXPECT_TRUE(param.default_value[0] == 0.0f || param.default_value[0] == 1.0f) << where;
    }
}

// An accepted IFS plugin (ABI 1.3): its maps, all contractive and invertible, a depth slider
// within the limits, no parameters of its own, only the effects exact tracing has.
void check_accepted_ifs(const Scene& scene, const fgr_scene_desc& desc) {
    ASSERT_GE(desc.header.struct_size, offsetof(fgr_scene_desc, ifs_max_depth) + sizeof(uint32_t));
    const IfsScene& ifs = *scene.ifs;
    EXPECT_EQ(ifs.maps.size(), desc.ifs_map_count);
    EXPECT_LE(ifs.maps.size(), std::size_t(kIfsMaxMaps));
    for (const IfsMap& map : ifs.maps) {
        const glm::dvec3 sigma = singular_values(map.linear);
        EXPECT_LT(sigma[0], 1.0);
        EXPECT_GT(sigma[2], 0.0);
        for (int i = 0; i < 3; ++i) {
            EXPECT_TRUE(std::isfinite(map.offset[i]));
            EXPECT_GE(map.colour[i], 0.0f);
            EXPECT_LE(map.colour[i], 1.0f);
        }
    }
    EXPECT_LE(0, ifs.default_depth);
    EXPECT_LE(ifs.default_depth, ifs.max_depth);
    EXPECT_LE(ifs.max_depth, kIfsMaxDepth);
    EXPECT_TRUE(std::isfinite(ifs.bounds.radius) && ifs.bounds.radius > 0.0);
    ASSERT_EQ(scene.params.size(), 1 + builtin_param_count());
    EXPECT_EQ(scene.params[0].id, "ifs_depth");
    EXPECT_EQ(desc.param_count, 0u);
    EXPECT_EQ(scene.effects & ~kIfsEffects, 0u);
}

void check_accepted(const Scene& scene, const fgr_scene_desc& desc) {
    // Identity and texts, copied faithfully.
    EXPECT_TRUE(std::regex_match(scene.id, kSceneIdPattern)) << scene.id;
    EXPECT_EQ(scene.id, desc.id);
    EXPECT_FALSE(scene.name.empty());
    EXPECT_EQ(scene.name, desc.name);
    if (scene.ifs) {
        check_accepted_ifs(scene, desc);
        return;
    }
    EXPECT_FALSE(scene.source.empty());
    EXPECT_LE(scene.source.size(), std::size_t{4} << 20);
    // ABI 1.1: at most source_length bytes when the struct has it, up to a NUL.
    const bool has_length = desc.header.struct_size >= offsetof(fgr_scene_desc, source_length) +
                                                           sizeof(desc.source_length) &&
                            desc.source_length > 0;
    EXPECT_EQ(scene.source, has_length
                                ? std::string(desc.source, strnlen(desc.source, desc.source_length))
                                : std::string(desc.source));
    EXPECT_TRUE(scene.plugin_file.empty());

    // Parameters: the scene's own (valid, unique, not built-in names), then the built-ins.
    std::size_t own = 0;
    while (own < scene.params.size() && !scene.params[own].builtin) ++own;
    EXPECT_EQ(own, desc.param_count);
    EXPECT_EQ(scene.params.size(), own + builtin_param_count());
    std::set<std::string> ids;
    for (std::size_t i = 0; i < scene.params.size(); ++i) {
        const ParamInfo& param = scene.params[i];
        EXPECT_EQ(param.builtin, i >= own) << param.id << ": built-ins come last";
        EXPECT_TRUE(ids.insert(param.id).second) << param.id << " twice";
        if (!param.builtin) {
            EXPECT_TRUE(std::regex_match(param.id, kParamIdPattern)) << param.id;
            for (const char* knob : kBuiltinIds) EXPECT_NE(param.id, knob);
        }
        check_param(param);
    }
    for (const char* knob : kQualityKnobs) {
        const ParamInfo* param = scene.find_param(knob);
        ASSERT_NE(param, nullptr) << knob;
        EXPECT_TRUE(param->builtin) << knob;
    }

    // Cameras and paths.
    ASSERT_GE(scene.cameras.size(), 1u);
    EXPECT_LE(scene.cameras.size(), 256u);
    EXPECT_EQ(scene.cameras.size(), desc.camera_count);
    std::set<std::string> camera_names;
    for (const NamedCamera& camera : scene.cameras) {
        EXPECT_TRUE(std::regex_match(camera.name, kNamePattern)) << camera.name;
        EXPECT_TRUE(camera_names.insert(camera.name).second) << camera.name << " twice";
        check_view(camera.view, "camera " + camera.name);
    }
    EXPECT_EQ(scene.camera_paths.size(), desc.camera_path_count);
    std::set<std::string> path_names;
    for (const CameraPath& path : scene.camera_paths) {
        EXPECT_TRUE(std::regex_match(path.name, kNamePattern)) << path.name;
        EXPECT_TRUE(path_names.insert(path.name).second) << path.name << " twice";
        ASSERT_GE(path.keyframes.size(), 2u) << path.name;
        EXPECT_LE(path.keyframes.size(), 10000u) << path.name;
        for (std::size_t k = 0; k < path.keyframes.size(); ++k) {
            EXPECT_TRUE(std::isfinite(path.keyframes[k].time)) << path.name;
            if (k > 0) {
                EXPECT_GT(path.keyframes[k].time, path.keyframes[k - 1].time) << path.name;
            }
            check_view(path.keyframes[k].view, "path " + path.name);
        }
    }

    // Lights.
    ASSERT_GE(scene.lights.size(), 1u);
    EXPECT_LE(scene.lights.size(), 16u);
    EXPECT_EQ(scene.lights.size(), desc.light_count);
    for (const Light& light : scene.lights) {
        EXPECT_TRUE(finite3(light.vector) && finite3(light.colour) &&
                    std::isfinite(light.intensity));
        EXPECT_TRUE(light.colour.r >= 0.0f && light.colour.g >= 0.0f && light.colour.b >= 0.0f);
        EXPECT_GE(light.intensity, 0.0f);
        if (light.type == LightType::Directional) {
            EXPECT_NEAR(glm::length(glm::dvec3(light.vector)), 1.0, 1e-5)
                << "directional lights are normalised";
        }
    }
    // ABI 1.2: a directional light's disc in radians, read only when its struct has the field (the
    // array's stride is the first light's struct_size); point lights have none.
    const uint32_t light_stride = desc.lights[0].header.struct_size;
    const bool has_radius = light_stride >= offsetof(fgr_light, angular_radius_degrees) + 4;
    for (uint32_t i = 0; i < desc.light_count; ++i) {
        fgr_light given;
        std::memcpy(&given, reinterpret_cast<const unsigned char*>(desc.lights) + i * light_stride,
                    sizeof given);
        const float radius = scene.lights[i].angular_radius;
        EXPECT_TRUE(radius >= 0.0f && radius <= 0.7853982f) << "light " << i << ": " << radius;
        if (has_radius && given.type == FGR_LIGHT_DIRECTIONAL) {
            const double expected = double{given.angular_radius_degrees} * 0.017453292519943295;
            // Float's rounding: relative, or absolute where the angle is subnormal.
            EXPECT_NEAR(radius, expected, 1e-7 * expected + FLT_TRUE_MIN) << "light " << i;
        } else {
            EXPECT_EQ(radius, 0.0f) << "light " << i << ": no disc";
        }
    }

    // ABI 1.2: the mode asked for by name, when the struct has the field; shaded otherwise.
    const bool has_mode =
        desc.header.struct_size >= offsetof(fgr_scene_desc, default_mode) + sizeof(const char*);
    if (has_mode && desc.default_mode != nullptr && desc.default_mode[0] != '\0') {
        EXPECT_EQ(render_mode_name(scene.default_mode), desc.default_mode);
    } else {
        EXPECT_EQ(scene.default_mode, RenderMode::Shaded);
    }

    // ABI 1.5: the environment named, when the struct has the field; none otherwise. Only what
    // check_scene_environment takes is accepted.
    const bool has_environment =
        desc.header.struct_size >= offsetof(fgr_scene_desc, environment) + sizeof(const char*);
    if (has_environment && desc.environment != nullptr) {
        EXPECT_EQ(scene.environment, desc.environment);
        EXPECT_NO_THROW(check_scene_environment(scene.environment)) << scene.environment;
    } else {
        EXPECT_EQ(scene.environment, "");
    }

    // Effects and march settings, which also become the quality knobs' defaults.
    EXPECT_EQ(scene.effects & ~uint64_t{FGR_EFFECT_ALL_V1}, 0u);
    EXPECT_EQ(scene.effects, desc.effects);
    const MarchSettings& march = scene.march;
    EXPECT_TRUE(march.max_steps >= 1 && march.max_steps <= 100000) << march.max_steps;
    EXPECT_TRUE(march.max_distance > 0.0f && std::isfinite(march.max_distance));
    EXPECT_TRUE(march.hit_threshold > 0.0f && std::isfinite(march.hit_threshold));
    EXPECT_TRUE(march.de_iterations >= 1 && march.de_iterations <= 1000) << march.de_iterations;
    EXPECT_TRUE(march.step_factor > 0.0f && march.step_factor <= 1.0f) << march.step_factor;
    EXPECT_EQ(scene.find_param("max_steps")->default_value[0], static_cast<float>(march.max_steps));
    EXPECT_EQ(scene.find_param("max_distance")->default_value[0], march.max_distance);
    EXPECT_EQ(scene.find_param("hit_threshold")->default_value[0], march.hit_threshold);
    EXPECT_EQ(scene.find_param("iterations")->default_value[0],
              static_cast<float>(march.de_iterations));
    EXPECT_EQ(scene.find_param("step_factor")->default_value[0], march.step_factor);
}

// Found by the fuzzer: a refusal quoted a bad id as it was, so a newline in it split the one-line
// reason (and an escape sequence reached the terminal through the log).
TEST(BadPlugin, RefusalsEscapeNonPrintableBytesInQuotedPluginText) {
    Rng rng(kDescriptionFuzzSeed);
    Arena arena;
    const auto refusal = [&](const std::function<void(DescSpec&)>& change) {
        DescSpec spec = random_valid_spec(rng, arena);
        spec.params.elements.push_back(random_param(rng, arena, 9));
        change(spec);
        const LoadResult result = copy_scene_description(layout(rng, arena, spec));
        EXPECT_FALSE(result.scene.has_value());
        return result.error;
    };
    EXPECT_EQ(refusal([](DescSpec& spec) { spec.desc.id = "bad\nid\x1b[31m\xc3\xa9"; }),
              "scene id 'bad\\x0aid\\x1b[31m\\xc3\\xa9' must match [a-z][a-z0-9_-]*");
    EXPECT_EQ(refusal([](DescSpec& spec) { spec.params.elements[0].id = "a\rb"; }),
              "parameter 'a\\x0db': id must match [a-z][a-z0-9_]*");
    EXPECT_EQ(refusal([](DescSpec& spec) { spec.cameras.elements[0].name = "Top\nView"; }),
              "camera 0: name 'Top\\x0aView' must match [a-z0-9_-]+");
}

// A refusal's kind: the message with quoted text and numbers blanked, for counting how many
// different checks the fuzzer reached.
std::string reason_kind(const std::string& reason) {
    std::string unquoted;
    bool quoted = false;
    for (const char c : reason) {
        if (c == '\'') quoted = !quoted;
        if (!quoted || c == '\'') unquoted += c;
    }
    std::istringstream words(unquoted);
    std::string kind;
    for (std::string word; words >> word;) {
        const bool number = word.find_first_of("0123456789") != std::string::npos ||
                            word.find("nan") != std::string::npos ||
                            word.find("inf") != std::string::npos;
        kind += number ? "#" : word;
        kind += ' ';
    }
    return kind;
}

struct FuzzTally {
    int accepted = 0;
    int refused = 0;
    std::set<std::string> reason_kinds;
};

void run_fuzz_case(uint64_t case_seed, FuzzTally& tally) {
    SCOPED_TRACE(::testing::Message() << "fuzz case seed " << case_seed
                                      << " (rerun alone with FGR_FUZZ_CASE=" << case_seed << ")");
    Rng rng(case_seed);
    Arena arena;
    DescSpec spec = random_valid_spec(rng, arena);
    const int mutations = std::array{0, 0, 0, 1, 1, 1, 1, 2, 2, 3, 4, 6}[rng.below(12)];
    for (int i = 0; i < mutations; ++i) mutate(rng, arena, spec);
    const fgr_scene_desc* desc = layout(rng, arena, spec);

    LoadResult result;
    try {
        result = copy_scene_description(desc);
    } catch (const std::exception& error) {
        ADD_FAILURE() << "copy_scene_description threw: " << error.what();
        return;
    } catch (...) {
        ADD_FAILURE() << "copy_scene_description threw";
        return;
    }
    if (result.scene) {
        ++tally.accepted;
        EXPECT_TRUE(result.error.empty()) << "a scene and an error: " << result.error;
        check_accepted(*result.scene, *desc);
    } else {
        ++tally.refused;
        EXPECT_FALSE(result.error.empty()) << "neither a scene nor an error";
        const bool control = std::any_of(result.error.begin(), result.error.end(), [](char c) {
            return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        });
        EXPECT_FALSE(control) << "the reason must be one printable line: " << result.error;
        tally.reason_kinds.insert(reason_kind(result.error));
    }
    if (mutations == 0) {
        EXPECT_TRUE(result.scene) << "an unmutated description must load: " << result.error;
    }
}

std::optional<uint64_t> env_number(const char* name) {
    const char* value = std::getenv(name);
    if (value == nullptr || *value == '\0') return std::nullopt;
    return std::strtoull(value, nullptr, 0);
}

int failed_parts() {
    return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
}

TEST(PluginFuzz, CopySceneDescriptionSurvivesMutatedDescriptions) {
    FuzzTally tally;
    if (const auto only = env_number("FGR_FUZZ_CASE")) {
        run_fuzz_case(*only, tally);
        return;
    }
    const int cases =
        static_cast<int>(env_number("FGR_FUZZ_CASES").value_or(kDescriptionFuzzCases));
    int failing_cases = 0;
    for (int i = 0; i < cases; ++i) {
        const int failures_before = failed_parts();
        run_fuzz_case(kDescriptionFuzzSeed + static_cast<uint64_t>(i), tally);
        if (failed_parts() > failures_before && ++failing_cases == 10) {
            ADD_FAILURE() << "stopping after 10 failing cases";
            break;
        }
    }
    // The fuzzer must exercise both outcomes and many different refusals, or it tests nothing.
    const int total = tally.accepted + tally.refused;
    EXPECT_GT(tally.accepted, total / 10) << tally.accepted << " of " << total << " accepted";
    EXPECT_GT(tally.refused, total / 3) << tally.refused << " of " << total << " refused";
    std::string kinds;
    for (const std::string& kind : tally.reason_kinds) kinds += "\n  " + kind;
    EXPECT_GE(tally.reason_kinds.size(), 80u) << "different refusals reached:" << kinds;
    RecordProperty("accepted", tally.accepted);
    RecordProperty("refused", tally.refused);
    RecordProperty("reason_kinds", static_cast<int>(tally.reason_kinds.size()));
}

}  // namespace
}  // namespace fgr
