// `fgr bench accuracy`: image error metrics, the Pareto front, and a sweep that measures every knob
// against a reference render, with its CSV, gnuplot script and plot.
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "child_process.hpp"
#include "fgr/accuracy.hpp"
#include "fgr/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

Frame flat_frame(uint8_t value, std::vector<float> depth) {
    Frame frame;
    frame.image = {2, 2, std::vector<uint8_t>(12, value)};
    frame.depth = std::move(depth);
    return frame;
}

TEST(ImageErrorMetrics, RmsePsnrHitsAndDepth) {
    const Frame reference = flat_frame(100, {1.0f, 2.0f, -1.0f, 4.0f});
    const ImageError same = compare_frames(reference, reference);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_EQ(same.psnr, 99.0);
    EXPECT_EQ(same.hit_mismatch_percent, 0.0);

    const Frame other = flat_frame(110, {1.5f, 2.0f, 3.0f, -1.0f});
    const ImageError error = compare_frames(other, reference);
    EXPECT_DOUBLE_EQ(error.rmse, 10.0);
    EXPECT_NEAR(error.psnr, 20.0 * std::log10(25.5), 1e-9);
    EXPECT_DOUBLE_EQ(error.hit_mismatch_percent, 50.0);  // pixels 2 and 3 disagree
    EXPECT_DOUBLE_EQ(error.mean_depth_error, 0.25);       // |1.5 - 1| and 0 where both hit
    EXPECT_DOUBLE_EQ(error.mean_depth_error_relative, 0.25);
}

AccuracyPoint point(double ms, double rmse) {
    AccuracyPoint p;
    p.render_ms = ms;
    p.error.rmse = rmse;
    return p;
}

TEST(ParetoFront, KeepsOnlyPointsNothingBeatsInTimeAndError) {
    std::vector<AccuracyPoint> points = {point(10, 5), point(20, 3), point(15, 6), point(30, 3),
                                         point(5, 9),  point(20, 3)};
    mark_pareto_front(points);
    const std::vector<bool> expected = {true, true, false, false, true, true};
    for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(points[i].pareto, expected[i]) << i;
}

// Every knob of the sweep must reach the image: each swept setting's point differs from the
// default point in its error against the reference or in its work (renders are deterministic,
// so a knob that does nothing reproduces the default's figures exactly). The Menger sponge, where
// every knob has something to act on at 40x30: a sphere has no DE iterations, and the
// Mandelbulb's rays all escape in under 6 iterations at this size (6, 9 and 18 give the default's
// image exactly, as the README's sweep table shows at 320x240). Where the effect's direction is
// certain it is checked too: a looser hit threshold stops rays sooner (fewer steps, more
// silhouette pixels disagree), fewer allowed steps cap the work, a smaller step factor or plain
// steps take more of them.
TEST(AccuracySweep, MeasuresEveryKnobAgainstTheReference) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    const Scene scene = test::built_scene("menger.so");
    AccuracySettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.reference_samples = 4;
    settings.repeats = 1;
    int calls = 0;
    const AccuracyReport report =
        run_accuracy_sweep(scene, device, cache, settings,
                           [&](int done, int total, const std::string&) {
                               EXPECT_LE(done, total);
                               ++calls;
                           });
    ASSERT_GT(report.points.size(), 15u);
    EXPECT_EQ(report.points.front().knob, "default");
    EXPECT_EQ(calls, int(report.points.size()) + 2);  // the reference, each point, done
    EXPECT_NE(report.reference_settings.find("hit_threshold=0.1"), std::string::npos);
    std::set<std::string> knobs;
    bool any_pareto = false;
    for (const AccuracyPoint& p : report.points) {
        knobs.insert(p.knob);
        any_pareto |= p.pareto;
        EXPECT_TRUE(std::isfinite(p.error.rmse) && p.render_ms > 0.0) << p.knob << p.value;
    }
    std::set<std::string> expected_knobs = {"default",         "hit_threshold", "max_steps",
                                            "iterations",      "step_factor",   "over_relaxation",
                                            "normal_epsilon",  "spp"};
    // The float/double point and a double reference need cl_khr_fp64 (PoCL has it).
    if (device.info.has_fp64) expected_knobs.insert("precision");
    EXPECT_EQ(knobs, expected_knobs);
    EXPECT_NE(report.reference_settings.find("over_relaxation=1 "), std::string::npos);
    EXPECT_NE(report.reference_settings.find(device.info.has_fp64 ? "precision=double"
                                                                  : "precision=float"),
              std::string::npos);
    EXPECT_TRUE(any_pareto);
    const AccuracyPoint& defaults = report.points.front();
    for (const AccuracyPoint& p : report.points) {
        if (p.knob == "default") continue;
        const bool same = p.error.rmse == defaults.error.rmse &&
                          p.error.hit_mismatch_percent == defaults.error.hit_mismatch_percent &&
                          p.error.mean_depth_error == defaults.error.mean_depth_error &&
                          p.steps_per_pixel == defaults.steps_per_pixel;
        EXPECT_FALSE(same) << p.knob << "=" << p.value
                           << " gives the default's image and work: the knob does nothing";
    }
    // A loose hit threshold fattens silhouettes: more pixels disagree with the reference's
    // (threshold 0.1) hit/miss than with a tight one.
    double tight = -1.0, loose = -1.0;
    for (const AccuracyPoint& p : report.points) {
        if (p.knob == "hit_threshold" && p.value == "0.25") tight = p.error.hit_mismatch_percent;
        if (p.knob == "hit_threshold" && p.value == "8") loose = p.error.hit_mismatch_percent;
    }
    ASSERT_GE(tight, 0.0);
    EXPECT_GT(loose, tight);
    // The work per pixel is counted: a tighter threshold and plain steps (over-relaxation 1,
    // against the default 1.6) both take more steps than the defaults.
    const auto steps_of = [&](const std::string& knob, const std::string& value) {
        for (const AccuracyPoint& p : report.points) {
            if (p.knob == knob && p.value == value) return p.steps_per_pixel;
        }
        return -1.0;
    };
    const double default_steps = steps_of("default", "");
    EXPECT_GT(default_steps, 1.0);
    EXPECT_GT(steps_of("hit_threshold", "0.25"), default_steps);
    EXPECT_LT(steps_of("hit_threshold", "8"), default_steps);
    EXPECT_GT(steps_of("over_relaxation", "1"), default_steps);
    const double max_steps = param_value(scene, default_param_values(scene), "max_steps");
    const std::string eighth = fmt::format("{:.4g}", std::round(max_steps / 8));
    EXPECT_GE(steps_of("max_steps", eighth), 0.0) << "no max_steps=" << eighth << " point";
    EXPECT_LE(steps_of("max_steps", eighth), max_steps / 8);
    EXPECT_LE(steps_of("max_steps", eighth), default_steps);
    const double step_factor = param_value(scene, default_param_values(scene), "step_factor");
    const std::string smaller = fmt::format("{:.4g}", step_factor * 0.6);
    EXPECT_GT(steps_of("step_factor", smaller), default_steps) << "step_factor=" << smaller;

    std::istringstream csv(accuracy_csv(report));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "knob,value,render_ms,rmse,psnr_db,hit_mismatch_percent,mean_depth_error,"
                    "mean_depth_error_relative,pareto,steps_per_pixel");
    int rows = 0;
    while (std::getline(csv, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 9) << line;
        ++rows;
    }
    EXPECT_EQ(rows, int(report.points.size()));
    const std::string script = accuracy_gnuplot(report, "inline", "a.csv", "a.png");
    for (const std::string& knob : knobs) {
        if (knob != "default") {
            EXPECT_NE(script.find("title '" + knob + "'"), std::string::npos);
        }
    }
    EXPECT_NE(script.find("set output 'a.png'"), std::string::npos);
}

TEST(AccuracyCommand, WritesTheCsvScriptAndPlot) {
    test::TempDir dir("fgr_accuracy_test");
    const test::RunResult run = test::run_fgr(
        {"bench", "accuracy", "mandelbulb", "--width", "32", "--height", "24", "--reference-spp",
         "2", "--repeats", "1", "-o", "acc"},
        dir.path());
    ASSERT_EQ(run.exit_code, 0) << run;
    EXPECT_NE(run.out.find("hit_threshold"), std::string::npos) << run;
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "acc.csv"));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "acc.gp"));
    // CI installs gnuplot (build.sh); without it fgr says so and writes no plot.
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "acc.png")) << run;
    const test::RunResult bad = test::run_fgr({"bench", "accuracy", "no-such-scene"}, dir.path());
    EXPECT_EQ(bad.exit_code, 2) << bad;
}

}  // namespace
}  // namespace fgr
