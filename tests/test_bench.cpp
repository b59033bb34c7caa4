// The benchmark protocol: figures from frame times, the choice of camera path, fixed-frame and
// fixed-duration runs, the precision of each frame, and the JSON / CSV / command-line outputs.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "child_process.hpp"
#include "fgr/bench.hpp"
#include "deep_zoom.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

TEST(BenchFigures, SummariseAndAverage) {
    const RunFigures run = summarise_run({10.0, 20.0, 40.0, 30.0}, 0.5);
    EXPECT_EQ(run.frames, 4);
    EXPECT_DOUBLE_EQ(run.min_ms, 10.0);
    EXPECT_DOUBLE_EQ(run.max_ms, 40.0);
    EXPECT_DOUBLE_EQ(run.mean_ms, 25.0);
    EXPECT_DOUBLE_EQ(run.mean_fps, 8.0);
    EXPECT_DOUBLE_EQ(run.min_fps, 25.0);
    EXPECT_DOUBLE_EQ(run.max_fps, 100.0);
    EXPECT_EQ(summarise_run({}, 1.0).frames, 0);

    const RunFigures other = summarise_run({20.0, 20.0}, 0.25);
    const RunFigures mean = average_runs({run, other});
    EXPECT_EQ(mean.frames, 3);
    EXPECT_DOUBLE_EQ(mean.mean_ms, 22.5);
    EXPECT_DOUBLE_EQ(mean.mean_fps, 8.0);
    EXPECT_DOUBLE_EQ(mean.seconds, 0.375);
}

Scene scene_with_paths(std::vector<std::string> names) {
    Scene scene = test::sphere_scene();
    for (const std::string& name : names) {
        CameraPath path{name, {{0.0f, scene.cameras.front().view}, {2.0f, scene.cameras.front().view}}};
        path.keyframes[1].view.position.x = 1.0f;
        scene.camera_paths.push_back(path);
    }
    return scene;
}

TEST(BenchPath, PrefersTheBenchmarkPathThenTheFirst) {
    EXPECT_EQ(bench_path(scene_with_paths({"orbit", "benchmark"}), "").name, "benchmark");
    EXPECT_EQ(bench_path(scene_with_paths({"orbit", "dive"}), "").name, "orbit");
    EXPECT_EQ(bench_path(scene_with_paths({"orbit", "dive"}), "dive").name, "dive");
    EXPECT_THROW(bench_path(scene_with_paths({"orbit"}), "nope"), std::invalid_argument);
    EXPECT_THROW(bench_path(scene_with_paths({}), ""), std::invalid_argument);
}

class BenchRun : public ::testing::Test {
protected:
    static void SetUpTestSuite() { device_ = new ComputeDevice(open_device(-1)); }
    static void TearDownTestSuite() { delete device_; }
    static ComputeDevice* device_;
    ProgramCache cache_{std::filesystem::path()};
    Scene scene_ = scene_with_paths({"benchmark"});
};
ComputeDevice* BenchRun::device_ = nullptr;

TEST_F(BenchRun, FixedFramesPerRunWithConsistentFigures) {
    BenchSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.frames = 5;
    settings.runs = 2;
    std::vector<std::pair<int, double>> progress;
    const BenchReport report = run_benchmark(
        scene_, *device_, cache_, settings, [&](int run, double done) { progress.emplace_back(run, done); });
    ASSERT_EQ(report.runs.size(), 2u);
    for (const RunFigures& run : report.runs) {
        EXPECT_EQ(run.frames, 5);
        EXPECT_LE(run.min_ms, run.mean_ms);
        EXPECT_LE(run.mean_ms, run.max_ms);
        EXPECT_GT(run.min_ms, 0.0);
        EXPECT_NEAR(run.min_fps, 1000.0 / run.max_ms, 1e-9);
        EXPECT_GE(run.seconds * 1000.0, 5 * run.min_ms);
    }
    EXPECT_EQ(report.average.frames, 5);
    EXPECT_EQ(report.path, "benchmark");
    EXPECT_EQ(report.build_origin, "compiled");
    EXPECT_GT(report.build_ms, 0.0);
    // Progress: both runs, fractions rising to 1.
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), std::make_pair(1, 1.0));
    EXPECT_EQ(progress.front(), std::make_pair(0, 0.0));

    const nlohmann::json json = nlohmann::json::parse(bench_json(report));
    EXPECT_EQ(json["scene"], "inline");
    EXPECT_EQ(json["settings"]["mode"], "frames");
    EXPECT_EQ(json["runs"].size(), 2u);
    EXPECT_EQ(json["average"]["frames"], 5);
    EXPECT_FALSE(json["system"]["opencl"]["device"].get<std::string>().empty());
    EXPECT_GT(json["system"]["cpu_threads"].get<int>(), 0);
    EXPECT_GT(json["system"]["memory_bytes"].get<uint64_t>(), 0u);

    std::istringstream csv(bench_csv(report));
    std::vector<std::string> lines;
    for (std::string line; std::getline(csv, line);) lines.push_back(line);
    ASSERT_EQ(lines.size(), 4u);  // header, two runs, average
    for (const std::string& line : lines) EXPECT_EQ(std::count(line.begin(), line.end(), ','), 15);
    EXPECT_EQ(lines[3].rfind("inline,average,48,32,5,", 0), 0u) << lines[3];
}

// A path from the Mandelbulb's canonical view into a deep zoom, two frames: one at each end.
// Auto renders the deep one in double, building that kernel only then; float renders neither.
TEST_F(BenchRun, EachFrameRendersInThePrecisionItsViewNeeds) {
    Scene bulb = test::built_scene("mandelbulb.so");
    bulb.camera_paths = {{"dive",
                          {{0.0f, bulb.cameras.front().view},
                           {1.0f, test::mandelbulb_deep_zoom(bulb)}}}};
    BenchSettings settings;
    settings.width = 16;
    settings.height = 12;
    settings.frames = 2;
    const auto run = [&](Precision precision) {
        settings.precision = precision;
        return run_benchmark(bulb, *device_, cache_, settings);
    };
    const BenchReport in_float = run(Precision::Float);
    const BenchReport automatic = run(Precision::Auto);
    const BenchReport in_double = run(Precision::Double);
    EXPECT_EQ(in_float.average.double_frames, 0);
    EXPECT_EQ(automatic.average.double_frames, 1);
    EXPECT_EQ(in_double.average.double_frames, 2);
    EXPECT_TRUE(in_float.double_build_origin.empty()) << "no double kernel built";
    EXPECT_FALSE(automatic.build_origin.empty());
    EXPECT_FALSE(automatic.double_build_origin.empty());
    EXPECT_TRUE(in_double.build_origin.empty()) << "no float kernel built";
    EXPECT_FALSE(in_double.double_build_origin.empty());

    const nlohmann::json json = nlohmann::json::parse(bench_json(automatic));
    EXPECT_EQ(json["settings"]["precision"], "auto");
    EXPECT_EQ(json["runs"][0]["double_frames"], 1);
    EXPECT_EQ(json["average"]["double_frames"], 1);
    EXPECT_GT(json["double_kernel_build_ms"].get<double>(), 0.0);
    EXPECT_NE(bench_csv(automatic).find(",auto,1,"), std::string::npos) << bench_csv(automatic);
    EXPECT_NE(bench_table(automatic).find("double kernel build"), std::string::npos);
}

TEST_F(BenchRun, FixedDurationPlaysThePathInRealTime) {
    BenchSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.duration_seconds = 0.3;
    const BenchReport report = run_benchmark(scene_, *device_, cache_, settings);
    ASSERT_EQ(report.runs.size(), 1u);
    EXPECT_GE(report.runs[0].frames, 1);
    EXPECT_GE(report.runs[0].seconds, 0.3);
    EXPECT_NEAR(report.runs[0].mean_fps, report.runs[0].frames / report.runs[0].seconds, 1e-9);
    EXPECT_NE(bench_table(report).find("avg fps"), std::string::npos);
}

TEST(BenchCommand, WritesJsonAndCsvAndRefusesBadInput) {
    test::TempDir dir("fgr_bench_test");
    const test::RunResult ok = test::run_fgr(
        {"bench", "mandelbulb", "--width", "32", "--height", "24", "--frames", "2", "-o", "out"},
        dir.path());
    ASSERT_EQ(ok.exit_code, 0) << ok;
    EXPECT_NE(ok.out.find("avg fps"), std::string::npos) << ok;
    EXPECT_EQ(nlohmann::json::parse(test::read_file(dir.path() / "out.json"))["average"]["frames"],
              2);
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "out.csv"));

    const std::vector<std::vector<std::string>> bad = {
        {"bench", "mandelbulb", "--path", "nope"},
        {"bench", "mandelbulb", "--frames", "2", "--duration", "1"},
        {"bench", "mandelbulb", "--runs", "0"},
        {"bench", "mandelbulb", "-o", "missing/dir/out"},
        {"bench", "no-such-scene"}};
    for (const auto& args : bad) {
        const test::RunResult result = test::run_fgr(args, dir.path());
        EXPECT_EQ(result.exit_code, 2) << test::describe("fgr", args) << result;
        EXPECT_NE(result.err.find("fgr: error: "), std::string::npos) << result;
    }
}

}  // namespace
}  // namespace fgr
