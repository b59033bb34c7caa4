// SPDX-License-Identifier: Apache-2.0
// `fgr check`, `fgr render --dev` and the stale-plugin warning, run as a child process: a report
// that names the fault and the fix, exit 1 on a failed check, compiler errors with the scene's
// file and line, and a plugin whose .cl file changed after it was built said so in one line.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "test_files.hpp"

namespace fgr {
namespace {

namespace fs = std::filesystem;
using test::RunResult;

using test::kFgrExe;
using test::kFixtureDir;
using test::write_text;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The number printed on `fgr render`'s "hits N" line, or -1.
long hits_of(const std::string& out) {
    const size_t at = out.find("\nhits ");
    if (at == std::string::npos) return -1;
    return std::stol(out.substr(at + 6));
}

class CheckCommandTest : public ::testing::Test {
protected:
    // fgr with `args`, finding scenes in `plugin_dir` (and beside itself).
    RunResult run(const std::vector<std::string>& args, const fs::path& plugin_dir = {}) {
        test::ChildOptions options;
        options.working_dir = dir_.path();
        if (plugin_dir.empty()) {
            options.environment["FGR_PLUGIN_PATH"] = std::nullopt;
        } else {
            options.environment["FGR_PLUGIN_PATH"] = plugin_dir.string();
        }
        RunResult result = test::run_child(kFgrExe, args, options);
        EXPECT_FALSE(result.timed_out) << test::describe("fgr", args) << ": " << result;
        return result;
    }
    const fs::path& dir() const { return dir_.path(); }

private:
    test::TempDir dir_{"fgr_check_test"};
};

// The issue's trap: `fgr render` of this scene gives hits 0 and exit 0. `fgr check` fails, and
// says where the DE is NaN and what to do about it.
TEST_F(CheckCommandTest, ANanDistanceFailsWithAReportThatSaysWhereAndWhatToDo) {
    const RunResult result = run({"check", (kFixtureDir / "nan" / "nan_de.so").string()});
    EXPECT_EQ(result.exit_code, 1) << result;
    EXPECT_TRUE(contains(result.out, "FAILED  hard-points")) << result.out;
    EXPECT_TRUE(contains(result.out, "DE is NaN at (0, 0, 0)")) << result.out;
    EXPECT_TRUE(contains(result.out, "fix: a NaN or Inf comes from")) << result.out;
    EXPECT_TRUE(contains(result.out, "fixture-nan: ")) << result.out;
    EXPECT_TRUE(contains(result.out, "checks FAILED")) << result.out;
}

TEST_F(CheckCommandTest, ABuiltInSceneByIdPassesOneCheck) {
    const RunResult result = run({"check", "mandelbulb", "--only", "hard-points"});
    EXPECT_EQ(result.exit_code, 0) << result;
    EXPECT_TRUE(contains(result.out, "ok      hard-points")) << result.out;
    EXPECT_TRUE(contains(result.out, "mandelbulb: all 1 checks passed")) << result.out;
}

// The scaled fixture's DE is exact at its default scale 1 and twice the distance at scale 2:
// `--set` checks at the value a scene's author renders with, and the report says which values it
// checked at; a value the parameter does not take is a usage error naming it.
TEST_F(CheckCommandTest, SetChecksAtTheGivenValuesAndTheReportSaysWhich) {
    const std::string plugin = (kFixtureDir / "scaled" / "scaled_de.so").string();
    const RunResult at_default = run({"check", plugin, "--only", "lipschitz"});
    EXPECT_EQ(at_default.exit_code, 0) << at_default;
    EXPECT_TRUE(contains(at_default.out, "checked at the scene's default parameters"))
        << at_default.out;
    const RunResult set = run({"check", plugin, "--only", "lipschitz", "--set", "scale=2"});
    EXPECT_EQ(set.exit_code, 1) << set;
    EXPECT_TRUE(contains(set.out, "checked at scale=2 (the other parameters at their defaults)"))
        << set.out;
    EXPECT_TRUE(contains(set.out, "FAILED  lipschitz")) << set.out;
    EXPECT_TRUE(contains(set.out, "fix: set step_factor <= 0.5")) << set.out;
    // A view file checks its scene at the view's values.
    std::ofstream(dir() / "scaled.fgrview.json")
        << R"({"format": "fgr-view", "version": 1, "scene": {"id": "scaled", "file": ")" << plugin
        << R"("}, "camera": {"eye": [0, -3, 0], "target": [0, 0, 0]},
               "parameters": {"scale": 2}})";
    const RunResult view =
        run({"check", (dir() / "scaled.fgrview.json").string(), "--only", "lipschitz"});
    EXPECT_EQ(view.exit_code, 1) << view;
    EXPECT_TRUE(contains(view.out, "checked at scale=2 (the other parameters at their defaults)"))
        << view.out;
    const RunResult outside = run({"check", plugin, "--set", "scale=9"});
    EXPECT_EQ(outside.exit_code, 2) << outside;
    EXPECT_TRUE(contains(outside.err, "'scale'")) << outside.err;
}

TEST_F(CheckCommandTest, AnUnknownSceneOrFileIsAUsageError) {
    EXPECT_EQ(run({"check", "no-such-scene"}).exit_code, 2);
    const RunResult missing = run({"check", (dir() / "missing.so").string()});
    EXPECT_EQ(missing.exit_code, 2) << missing;
    EXPECT_TRUE(contains(missing.err, "missing.so")) << missing.err;
}

// What the SDK template's build runs: a kernel that does not compile fails with the scene's own
// file and line (the fixture's source is one line, named fixture.cl).
TEST_F(CheckCommandTest, CompileReportsTheScenesFileAndLine) {
    const RunResult broken =
        run({"check", "--compile", (kFixtureDir / "broken" / "broken_kernel.so").string()});
    EXPECT_EQ(broken.exit_code, 1) << broken;
    EXPECT_TRUE(contains(broken.err, "fixture.cl:1:")) << broken.err;
    EXPECT_TRUE(contains(broken.err, "undeclared_radius")) << broken.err;
    const RunResult good = run({"check", "--compile", (kFixtureDir / "good_scene.so").string()});
    EXPECT_EQ(good.exit_code, 0) << good;
    EXPECT_TRUE(contains(good.out, "the kernel compiles")) << good.out;
}

// The stale_scene fixture embeds the sphere of radius `scale` (1) and records
// FGR_TEST_FIXTURE_DIR/stale/stale_scene.cl as its source file. Copied into a plugin folder of its
// own with an old time, then that file written: unchanged, no warning; changed after the plugin,
// a warning from render and check, and `render --dev` draws the changed source (a ball of half the
// radius: a quarter of the hits, 0.246 by the angles it spans, allowed 0.15-0.35); changed but
// older than the plugin, no warning.
TEST_F(CheckCommandTest, AChangedSourceIsNoticedAndDevRendersIt) {
    const fs::path plugins = dir() / "plugins";
    fs::create_directories(plugins);
    const fs::path plugin = plugins / "stale_scene.so";
    fs::copy_file(kFixtureDir / "stale" / "stale_scene.so", plugin);
    const auto now = fs::file_time_type::clock::now();
    fs::last_write_time(plugin, now - std::chrono::hours(1));
    const fs::path source = kFixtureDir / "stale" / "stale_scene.cl";
    const std::string embedded =
        "real scene_de(vec3 p, PARAMS) { return v3_length(p) - param_scale; }\n";
    const std::vector<std::string> render = {"render", "fixture-stale", "-o", "out.png", "--width",
                                             "64",     "--height",      "48"};
    const std::string warning =
        "stale_scene.cl changed after stale_scene.so was built: rebuild the plugin";

    write_text(source, embedded);
    const RunResult same = run(render, plugins);
    ASSERT_EQ(same.exit_code, 0) << same;
    EXPECT_FALSE(contains(same.err, "changed after")) << same.err;
    const long full_hits = hits_of(same.out);
    ASSERT_GT(full_hits, 200) << same.out;

    write_text(source,
               "real scene_de(vec3 p, PARAMS) { return v3_length(p) - 0.5f * param_scale; }\n");
    const RunResult stale = run(render, plugins);
    EXPECT_EQ(stale.exit_code, 0) << stale;
    EXPECT_TRUE(contains(stale.err, warning)) << stale.err;
    EXPECT_EQ(hits_of(stale.out), full_hits) << "without --dev the embedded source renders";
    const RunResult checked = run({"check", "--compile", plugin.string()}, plugins);
    EXPECT_TRUE(contains(checked.err, warning)) << checked.err;

    std::vector<std::string> dev = render;
    dev.push_back("--dev");
    const RunResult from_disk = run(dev, plugins);
    ASSERT_EQ(from_disk.exit_code, 0) << from_disk;
    EXPECT_FALSE(contains(from_disk.err, "changed after")) << from_disk.err;
    const double ratio = double(hits_of(from_disk.out)) / double(full_hits);
    EXPECT_GT(ratio, 0.15) << from_disk.out;
    EXPECT_LT(ratio, 0.35) << from_disk.out;

    fs::last_write_time(source, now - std::chrono::hours(2));
    const RunResult older = run(render, plugins);
    EXPECT_FALSE(contains(older.err, "changed after")) << older.err;
    write_text(source, embedded);
}

// --dev needs a recorded file to read: a scene that records only a name is refused, saying so.
TEST_F(CheckCommandTest, DevWithoutARecordedSourceFileIsAUsageError) {
    const RunResult result =
        run({"render", "fixture-good", "-o", "out.png", "--width", "16", "--height", "16", "--dev"},
            kFixtureDir);
    EXPECT_EQ(result.exit_code, 2) << result;
    EXPECT_TRUE(contains(result.err, "records no .cl file")) << result.err;
}

}  // namespace
}  // namespace fgr
