// SPDX-License-Identifier: Apache-2.0
// `fgr bench accuracy`: image error metrics, the Pareto front, and a sweep that measures every knob
// against a reference render, with its CSV, gnuplot script and plot.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <tuple>

#include "child_process.hpp"
#include "diagnostics/accuracy.hpp"
#include "scene/parameters.hpp"
#include "test_scenes.hpp"

namespace fgr {
namespace {

// A flat 12x12 frame (SSIM's window needs 11x11) whose first pixels have the given depths and the
// rest depth 1.
Frame flat_frame(uint8_t value, const std::vector<float>& first_depths) {
    Frame frame;
    frame.image = {12, 12, std::vector<uint8_t>(12 * 12 * 3, value)};
    frame.depth.assign(12 * 12, 1.0f);
    std::copy(first_depths.begin(), first_depths.end(), frame.depth.begin());
    return frame;
}

TEST(ImageErrorMetrics, RmsePsnrSsimHitsAndDepth) {
    const Frame reference = flat_frame(100, {1.0f, 2.0f, -1.0f, 4.0f});
    const ImageError same = compare_frames(reference, reference);
    EXPECT_EQ(same.rmse, 0.0);
    EXPECT_EQ(same.psnr, 99.0);
    EXPECT_EQ(same.one_minus_ssim, 0.0);
    EXPECT_EQ(same.hit_mismatch_percent, 0.0);

    const Frame other = flat_frame(110, {1.5f, 2.0f, 3.0f, -1.0f});
    const ImageError error = compare_frames(other, reference);
    EXPECT_DOUBLE_EQ(error.rmse, 10.0);
    EXPECT_NEAR(error.psnr, 20.0 * std::log10(25.5), 1e-9);
    // Flat grey images: SSIM is its luminance term on the levels / 255 (L = 1, C1 = 0.01^2).
    const double a = 110.0 / 255.0, b = 100.0 / 255.0;
    EXPECT_NEAR(error.one_minus_ssim, 1.0 - (2.0 * a * b + 1e-4) / (a * a + b * b + 1e-4), 1e-6);
    EXPECT_DOUBLE_EQ(error.hit_mismatch_percent, 200.0 / 144.0);  // pixels 2 and 3 disagree
    // |1.5 - 1| at pixel 0, and 0 at the 141 other pixels where both hit.
    EXPECT_DOUBLE_EQ(error.mean_depth_error, 0.5 / 142.0);
    EXPECT_DOUBLE_EQ(error.mean_depth_error_relative, 0.5 / 142.0);
    // SSIM needs 11x11 pixels.
    Frame tiny;
    tiny.image = {4, 4, std::vector<uint8_t>(48, 0)};
    tiny.depth.assign(16, 1.0f);
    EXPECT_THROW(compare_frames(tiny, tiny), std::invalid_argument);
}

AccuracyPoint point(double ms, double rmse, double one_minus_ssim = 0.0,
                    const std::string& reference = "geometry") {
    AccuracyPoint p;
    p.render_ms = ms;
    p.error.rmse = rmse;
    p.error.one_minus_ssim = one_minus_ssim;
    p.reference = reference;
    return p;
}

TEST(ParetoFront, KeepsOnlyPointsNothingBeatsInTimeAndError) {
    std::vector<AccuracyPoint> points = {point(10, 5), point(20, 3), point(15, 6),
                                         point(30, 3), point(5, 9),  point(20, 3)};
    mark_pareto_front(points);
    const std::vector<bool> expected = {true, true, false, false, true, true};
    for (size_t i = 0; i < points.size(); ++i) EXPECT_EQ(points[i].pareto, expected[i]) << i;
}

// Each error has its own front, and points measured against different references never beat
// each other (their errors are not comparable).
TEST(ParetoFront, OneFrontPerErrorAndPerReference) {
    std::vector<AccuracyPoint> points = {
        point(10, 5, 0.01), point(20, 3, 0.02), point(30, 2, 0.005),  // geometry
        point(40, 9, 0.5, "samples"), point(80, 6, 0.3, "samples")};  // beaten by all geometry
    mark_pareto_front(points);
    const std::vector<bool> rmse_front = {true, true, true, true, true};
    const std::vector<bool> ssim_front = {true, false, true, true, true};
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_EQ(points[i].pareto, rmse_front[i]) << i;
        EXPECT_EQ(points[i].pareto_ssim, ssim_front[i]) << i;
    }
}

// Every knob of the sweep must reach the image: each swept setting's point differs from the
// default point in its error against the reference or in its work (renders are deterministic,
// so a knob that does nothing reproduces the default's figures exactly). The Menger sponge, where
// every knob has something to act on at 40x30: a sphere has no DE iterations, and the
// Mandelbulb's rays all escape in under 6 iterations at this size (6, 9 and 18 give the default's
// image exactly, as docs/performance.md's table shows at 320x240). Where the effect's direction is
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
    settings.reference_samples = 32;
    settings.repeats = 1;
    int calls = 0;
    const AccuracyReport report = run_accuracy_sweep(scene, device, cache, settings,
                                                     [&](int done, int total, const std::string&) {
                                                         EXPECT_LE(done, total);
                                                         ++calls;
                                                     });
    ASSERT_GT(report.points.size(), 15u);
    EXPECT_EQ(report.points.front().knob, "default");
    // The two references, each point, done.
    EXPECT_EQ(calls, int(report.points.size()) + 3);
    ASSERT_EQ(report.references.size(), 2u);
    EXPECT_EQ(report.references[0].name, "geometry");
    EXPECT_EQ(report.references[1].name, "samples");
    const std::string& fine = report.references[0].settings;
    EXPECT_NE(fine.find("hit_threshold=0.1"), std::string::npos) << fine;
    EXPECT_NE(fine.find("spp=1 "), std::string::npos) << fine;
    EXPECT_NE(report.references[1].settings.find("spp=32"), std::string::npos);
    std::set<std::string> knobs;
    bool any_pareto = false;
    for (const AccuracyPoint& p : report.points) {
        knobs.insert(p.knob);
        any_pareto |= p.pareto;
        EXPECT_TRUE(std::isfinite(p.error.rmse) && p.render_ms > 0.0) << p.knob << p.value;
        EXPECT_TRUE(p.error.one_minus_ssim > 0.0 && p.error.one_minus_ssim <= 2.0)
            << p.knob << p.value << " " << p.error.one_minus_ssim;
        EXPECT_EQ(p.reference, p.knob == "spp" ? "samples" : "geometry") << p.knob << p.value;
    }
    std::set<std::string> expected_knobs = {
        "default",     "hit_threshold",   "max_steps",      "iterations",
        "step_factor", "over_relaxation", "normal_epsilon", "spp"};
    // The float/double point and a double reference need cl_khr_fp64 (PoCL has it).
    if (device.info.has_fp64) expected_knobs.insert("precision");
    EXPECT_EQ(knobs, expected_knobs);
    EXPECT_NE(fine.find("over_relaxation=1 "), std::string::npos);
    EXPECT_NE(fine.find(device.info.has_fp64 ? "precision=double" : "precision=float"),
              std::string::npos);
    EXPECT_TRUE(any_pareto);
    const auto point_of = [&](const std::string& knob, const std::string& value) {
        for (const AccuracyPoint& p : report.points) {
            if (p.knob == knob && p.value == value) return p;
        }
        ADD_FAILURE() << "no " << knob << "=" << value << " point";
        return AccuracyPoint{};
    };
    // The default's image is the spp=1 point, against the other reference.
    EXPECT_EQ(point_of("spp", "1").steps_per_pixel, report.points.front().steps_per_pixel);
    for (const AccuracyPoint& p : report.points) {
        if (p.knob == "default" || (p.knob == "spp" && p.value == "1")) continue;
        const AccuracyPoint defaults =
            p.reference == "samples" ? point_of("spp", "1") : report.points.front();
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

    // What anti-aliasing buys, against the samples reference (the default geometry at 32 spp):
    // with independent per-sample errors of variance s^2 the mean square error at n samples is
    // s^2 (1/n - 1/32) (the reference shares the point's samples), so the RMSE falls at every
    // doubling (by 0.70, 0.68, 0.65, 0.58 from 1 to 16) and 16 spp have sqrt(1/31) = 0.18 of 1
    // spp's; it is measured over the few hundred edge pixels of a 40x30 image, so 0.5 leaves
    // room. 1 - SSIM must fall at every doubling too.
    const std::vector<std::string> spps = {"1", "2", "4", "8", "16"};
    for (size_t i = 1; i < spps.size(); ++i) {
        const AccuracyPoint fewer = point_of("spp", spps[i - 1]), more = point_of("spp", spps[i]);
        EXPECT_LT(more.error.rmse, fewer.error.rmse) << "spp " << spps[i];
        EXPECT_LT(more.error.one_minus_ssim, fewer.error.one_minus_ssim) << "spp " << spps[i];
    }
    EXPECT_LT(point_of("spp", "16").error.rmse, 0.5 * point_of("spp", "1").error.rmse);

    std::istringstream csv(accuracy_csv(report));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line,
              "knob,value,reference,render_ms,rmse,psnr_db,one_minus_ssim,hit_mismatch_percent,"
              "mean_depth_error,mean_depth_error_relative,pareto,pareto_ssim,steps_per_pixel");
    int rows = 0;
    while (std::getline(csv, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), 12) << line;
        ++rows;
    }
    EXPECT_EQ(rows, int(report.points.size()));
    const std::string script = accuracy_gnuplot(report, "inline", "a.csv", "a.png");
    for (const std::string& knob : knobs) {
        if (knob != "default") {
            EXPECT_NE(script.find("title '" + knob), std::string::npos) << knob;
        }
    }
    EXPECT_NE(script.find("set output 'a.png'"), std::string::npos);
    EXPECT_NE(script.find("1 - SSIM"), std::string::npos);
    // The fronts travel as inline data (a line drawn from the CSV would break at every row off it).
    EXPECT_NE(script.find("$front_rmse << EOD"), std::string::npos);
    EXPECT_NE(script.find("$front_ssim << EOD"), std::string::npos);
    EXPECT_NE(script.find("title 'spp (vs samples reference)'"), std::string::npos);
}

// The perceptual column agrees with RMSE where the order is clear: a loose hit threshold (8
// pixel footprints) against a tight one (0.25), and 1 against 16 samples per pixel, each pair
// against its own reference; and it is the column the CSV says it is.
TEST(AccuracySweep, SsimOrdersClearlyOrderedSettingsAsRmseDoes) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    const Scene scene = test::built_scene("menger.so");
    AccuracySettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.reference_samples = 32;
    settings.repeats = 1;
    const AccuracyReport report = run_accuracy_sweep(scene, device, cache, settings);
    const auto point_of = [&](const std::string& knob, const std::string& value) {
        for (const AccuracyPoint& p : report.points) {
            if (p.knob == knob && p.value == value) return p;
        }
        ADD_FAILURE() << "no " << knob << "=" << value << " point";
        return AccuracyPoint{};
    };
    for (const auto& [knob, worse, better] :
         {std::tuple{"hit_threshold", "8", "0.25"}, std::tuple{"spp", "1", "16"}}) {
        const ImageError w = point_of(knob, worse).error, b = point_of(knob, better).error;
        ASSERT_GT(w.rmse, b.rmse) << knob;  // clearly ordered
        EXPECT_GT(w.one_minus_ssim, b.one_minus_ssim) << knob << "=" << worse << " vs " << better;
    }
    // The CSV's one_minus_ssim column (the 7th) carries each point's 1 - SSIM.
    std::istringstream csv(accuracy_csv(report));
    std::string line;
    std::getline(csv, line);
    for (const AccuracyPoint& p : report.points) {
        ASSERT_TRUE(std::getline(csv, line));
        std::istringstream fields(line);
        std::string field;
        for (int column = 0; column < 7; ++column) std::getline(fields, field, ',');
        EXPECT_NEAR(std::stod(field), p.error.one_minus_ssim,
                    1e-5 * std::max(p.error.one_minus_ssim, 1e-3))
            << line;
    }
}

// The path tracer's sweep: every knob against the one path reference; more samples always lower
// the error (noise falls as 1/sqrt(spp): from 1 to 64 samples RMSE must fall by well over half),
// and the bounce cap of 1 (direct light only) is farther from the reference than 4 bounces, on
// a Menger sponge whose crevices hold interreflected light.
TEST(AccuracySweep, PathModeSweepsNoiseKnobsAgainstALongRender) {
    const ComputeDevice device = open_device(-1);
    ProgramCache cache{std::filesystem::path()};
    const Scene scene = test::built_scene("menger.so");
    AccuracySettings settings;
    settings.width = 40;
    settings.height = 30;
    settings.reference_samples = 256;
    settings.repeats = 1;
    PathSettings base;
    EnvironmentChoice studio;
    studio.kind = EnvironmentKind::Studio;
    base.environment = prepare_environment(studio, scene);
    const AccuracyReport report = run_path_accuracy_sweep(scene, device, cache, settings, base);
    ASSERT_EQ(report.references.size(), 1u);
    EXPECT_EQ(report.references[0].name, "path");
    const auto point_of = [&](const std::string& knob, const std::string& value) {
        for (const AccuracyPoint& p : report.points) {
            if (p.knob == knob && p.value == value) return p;
        }
        ADD_FAILURE() << "no point " << knob << "=" << value;
        return AccuracyPoint{};
    };
    for (const auto& [knob, value] :
         std::vector<std::pair<std::string, std::string>>{{"default", ""},
                                                          {"bounces", "2"},
                                                          {"roulette_depth", "off"},
                                                          {"strategy", "no MIS"},
                                                          {"strategy", "no light sampling"},
                                                          {"strategy", "uniform environment"}}) {
        EXPECT_EQ(point_of(knob, value).reference, "path") << knob;
    }
    const double one = point_of("spp", "1").error.rmse, four = point_of("spp", "4").error.rmse;
    const double many = point_of("spp", "64").error.rmse;
    std::printf("RMSE at 1, 4, 64 spp: %.3f %.3f %.3f\n", one, four, many);
    EXPECT_GT(one, four);
    EXPECT_GT(four, many);
    EXPECT_LT(many, 0.4 * one);
    EXPECT_GT(point_of("bounces", "1").error.rmse, point_of("bounces", "4").error.rmse);
    const std::string csv = accuracy_csv(report);
    EXPECT_NE(csv.find("\nstrategy,no light sampling,path,"), std::string::npos) << csv;
}

TEST(AccuracyCommand, WritesTheCsvScriptAndPlot) {
    test::TempDir dir("fgr_accuracy_test");
    const test::RunResult run =
        test::run_fgr({"bench", "accuracy", "mandelbulb", "--width", "32", "--height", "24",
                       "--reference-spp", "2", "--repeats", "1", "-o", "acc"},
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
