// SPDX-License-Identifier: Apache-2.0
// The benchmark protocol: figures from frame times, the choice of camera path, fixed-frame and
// fixed-duration runs, the precision of each frame, and the JSON / CSV / command-line outputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "camera/camera.hpp"
#include "child_process.hpp"
#include "deep_zoom.hpp"
#include "diagnostics/bench.hpp"
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

    // Each figure is the mean over the runs: (8 + 12) / 2 = 10 fps, where pooling the runs'
    // frames and seconds would give 7 / 0.75 = 9.33.
    const RunFigures other = summarise_run({20.0, 20.0, 20.0}, 0.25);
    EXPECT_DOUBLE_EQ(other.mean_fps, 12.0);
    const RunFigures mean = average_runs({run, other});
    EXPECT_EQ(mean.frames, 4);  // 3.5, rounded
    EXPECT_DOUBLE_EQ(mean.mean_ms, 22.5);
    EXPECT_DOUBLE_EQ(mean.mean_fps, 10.0);
    EXPECT_DOUBLE_EQ(mean.min_fps, 37.5);  // (25 + 50) / 2
    EXPECT_DOUBLE_EQ(mean.max_fps, 75.0);  // (100 + 50) / 2
    EXPECT_DOUBLE_EQ(mean.seconds, 0.375);
}

Scene scene_with_paths(std::vector<std::string> names) {
    Scene scene = test::sphere_scene();
    for (const std::string& name : names) {
        CameraPath path{name,
                        {{0.0f, scene.cameras.front().view}, {2.0f, scene.cameras.front().view}}};
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

// What the test saw of a run: each frame's view, path time and render time (BenchSettings::
// on_frame), and its own stopwatch around the whole call.
struct Observed {
    std::vector<CameraView> views;
    std::vector<float> times;
    std::vector<std::vector<double>> frame_ms;  // per run
    double wall_seconds = 0.0;
};

BenchReport observed_run(const Scene& scene, const ComputeDevice& device, ProgramCache& cache,
                         BenchSettings settings, Observed* seen,
                         const BenchProgress& progress = {}) {
    settings.on_frame = [&](const CameraView& view, float time, double ms) {
        seen->views.push_back(view);
        seen->times.push_back(time);
        seen->frame_ms.back().push_back(ms);
    };
    // Progress comes before every frame, naming its run: a new run starts a new list.
    const BenchProgress next_run = [&](int run, double done) {
        while (seen->frame_ms.size() <= size_t(run)) seen->frame_ms.emplace_back();
        if (progress) progress(run, done);
    };
    const auto start = std::chrono::steady_clock::now();
    BenchReport report = run_benchmark(scene, device, cache, settings, next_run);
    seen->wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

// A run's figures against what the test observed of it, not against the formulas that made them:
// the frame count and times are the frames it saw; the run's wall time covers every frame's
// render but not the kernel build (its clock stops while a kernel builds), so it lies between the
// sum of the frame times and the test's stopwatch less the build.
void expect_figures_match(const RunFigures& run, const std::vector<double>& frame_ms,
                          double wall_seconds, double build_ms) {
    ASSERT_FALSE(frame_ms.empty());
    EXPECT_EQ(run.frames, int(frame_ms.size()));
    EXPECT_EQ(run.min_ms, *std::min_element(frame_ms.begin(), frame_ms.end()));
    EXPECT_EQ(run.max_ms, *std::max_element(frame_ms.begin(), frame_ms.end()));
    const double total_ms = std::accumulate(frame_ms.begin(), frame_ms.end(), 0.0);
    EXPECT_NEAR(run.mean_ms, total_ms / double(frame_ms.size()), 1e-9 * total_ms);
    EXPECT_GE(run.seconds * 1000.0, total_ms);
    EXPECT_LE(run.seconds * 1000.0, wall_seconds * 1000.0 - build_ms);
    // Frames per second of wall time: no faster than the frames' own times allow, no slower than
    // the test's stopwatch says.
    EXPECT_LE(run.mean_fps, 1000.0 * double(frame_ms.size()) / total_ms * (1.0 + 1e-12));
    EXPECT_GE(run.mean_fps, double(frame_ms.size()) / wall_seconds);
    EXPECT_LE(run.min_fps, run.max_fps);
    EXPECT_LE(run.mean_fps, run.max_fps);
}

TEST_F(BenchRun, FixedFramesPerRunWithConsistentFigures) {
    BenchSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.frames = 5;
    settings.runs = 2;
    std::vector<std::pair<int, double>> progress;
    Observed seen;
    const BenchReport report =
        observed_run(scene_, *device_, cache_, settings, &seen,
                     [&](int run, double done) { progress.emplace_back(run, done); });
    ASSERT_EQ(report.runs.size(), 2u);
    ASSERT_EQ(seen.frame_ms.size(), 2u);
    for (size_t run = 0; run < 2; ++run) {
        SCOPED_TRACE("run " + std::to_string(run));
        expect_figures_match(report.runs[run], seen.frame_ms[run], seen.wall_seconds,
                             report.build_ms);
    }
    // The build happened once, outside both runs' clocks.
    EXPECT_LE((report.runs[0].seconds + report.runs[1].seconds) * 1000.0,
              seen.wall_seconds * 1000.0 - report.build_ms);
    // Five frames spread evenly over the two-second path, the last on its end, in every run.
    ASSERT_EQ(seen.times.size(), 10u);
    for (size_t i = 0; i < seen.times.size(); ++i) {
        EXPECT_FLOAT_EQ(seen.times[i], 0.5f * float(i % 5)) << i;
        EXPECT_EQ(seen.views[i].position,
                  evaluate_camera_path(scene_.camera_paths[0], seen.times[i]).position);
    }
    EXPECT_EQ(report.average.frames, 5);
    EXPECT_EQ(report.path, "benchmark");
    EXPECT_EQ(report.build_origin, "compiled");
    EXPECT_GT(report.build_ms, 0.0);
    // Progress: both runs, fractions rising to 1.
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), std::make_pair(1, 1.0));
    EXPECT_EQ(progress.front(), std::make_pair(0, 0.0));

    const nlohmann::json report_json = nlohmann::json::parse(bench_json(report));
    EXPECT_EQ(report_json["scene"], "inline");
    EXPECT_EQ(report_json["settings"]["mode"], "frames");
    EXPECT_EQ(report_json["runs"].size(), 2u);
    EXPECT_EQ(report_json["average"]["frames"], 5);
    EXPECT_FALSE(report_json["system"]["opencl"]["device"].get<std::string>().empty());
    EXPECT_GT(report_json["system"]["cpu_threads"].get<int>(), 0);
    EXPECT_GT(report_json["system"]["memory_bytes"].get<uint64_t>(), 0u);

    std::istringstream csv(bench_csv(report));
    std::vector<std::string> lines;
    for (std::string line; std::getline(csv, line);) lines.push_back(line);
    ASSERT_EQ(lines.size(), 4u);  // header, two runs, average
    for (const std::string& line : lines) EXPECT_EQ(std::count(line.begin(), line.end(), ','), 17);
    EXPECT_EQ(lines[3].rfind("inline,average,48,32,5,", 0), 0u) << lines[3];
    // Samples per second: every run's frames x spp x pixels over its seconds.
    for (const RunFigures& run : report.runs) {
        EXPECT_NEAR(run.samples_per_second,
                    double(run.frames) * settings.samples * 48 * 32 / run.seconds,
                    1e-9 * run.samples_per_second);
        EXPECT_GT(run.samples_per_second, 0.0);
    }
    EXPECT_NE(lines[0].find(",render_mode,samples_per_second"), std::string::npos) << lines[0];
    EXPECT_NE(lines[3].find(",shaded,"), std::string::npos) << lines[3];
    EXPECT_EQ(report_json["settings"]["render_mode"], "shaded");
}

// A path from the Mandelbulb's canonical view into a deep zoom, two frames: one at each end.
// Auto renders the deep one in double, building that kernel only then; float renders neither.
TEST_F(BenchRun, EachFrameRendersInThePrecisionItsViewNeeds) {
    Scene bulb = test::built_scene("mandelbulb.so");
    bulb.camera_paths = {
        {"dive", {{0.0f, bulb.cameras.front().view}, {1.0f, test::mandelbulb_deep_zoom(bulb)}}}};
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

    const nlohmann::json report_json = nlohmann::json::parse(bench_json(automatic));
    EXPECT_EQ(report_json["settings"]["precision"], "auto");
    EXPECT_EQ(report_json["runs"][0]["double_frames"], 1);
    EXPECT_EQ(report_json["average"]["double_frames"], 1);
    EXPECT_GT(report_json["double_kernel_build_ms"].get<double>(), 0.0);
    EXPECT_NE(bench_csv(automatic).find(",auto,1,"), std::string::npos) << bench_csv(automatic);
    EXPECT_NE(bench_table(automatic).find("double kernel build"), std::string::npos);
}

// Real time: each frame shows the path where it is at that moment, so between two frames the
// path moves on by at least the earlier frame's own render time (the clock ran while it
// rendered), and each frame's view is the path's at its time. A camera stuck at the start, or a
// path played slower than the clock, fails. (The two-second path outlasts the 0.3 s run: no wrap.)
TEST_F(BenchRun, FixedDurationPlaysThePathInRealTime) {
    BenchSettings settings;
    settings.width = 16;
    settings.height = 16;
    settings.duration_seconds = 0.3;
    Observed seen;
    const BenchReport report = observed_run(scene_, *device_, cache_, settings, &seen);
    ASSERT_EQ(report.runs.size(), 1u);
    ASSERT_GE(seen.times.size(), 2u) << "a 0.3 s run of 16x16 frames shows more than one";
    expect_figures_match(report.runs[0], seen.frame_ms[0], seen.wall_seconds, report.build_ms);
    EXPECT_GE(report.runs[0].seconds, 0.3);
    const CameraPath& path = scene_.camera_paths[0];
    EXPECT_LT(seen.times.front(), seen.times.back());
    for (size_t i = 0; i < seen.times.size(); ++i) {
        EXPECT_EQ(seen.views[i].position, evaluate_camera_path(path, seen.times[i]).position) << i;
        EXPECT_LE(seen.times[i], float(report.runs[0].seconds)) << i;
        if (i == 0) continue;
        // (1e-4 ms: the float rounding of path times below 0.3 s.)
        EXPECT_GE(double(seen.times[i] - seen.times[i - 1]) * 1000.0,
                  seen.frame_ms[0][i - 1] - 1e-4)
            << "frame " << i << ": the path did not move on while frame " << i - 1 << " rendered";
    }
    EXPECT_NE(seen.views.front().position, seen.views.back().position) << "the camera never moved";
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
